// regmap.h — host helper for the s_axilite register map (docs/REGISTERS.md, generated from
// regmap/laserax_regs.csv): a register image as a driver writes it, its conversion to and from the
// host settings struct, and physical settings <-> register values (issue 3, item 5). Part of the
// host driver library (host/): nothing from hls/, golden/, tools/ or tb/.
//
//   reg_image         the 32-bit words of the map by byte offset (reset values at construction);
//                     write/read a register by name (error for an unknown name or a value outside
//                     the register's width); the word writes of a register, low word first.
//   image <-> settings lxt::axis_settings (every register), through the generated accessors of
//                     host/regmap_table.h (the model register structs lx::axis_regs and
//                     golden::axis_regs: sysmodel/model_regs.h).
//   initialisation    the whole image written before the core is started (init_registers,
//                     host/ip_init.h: the HLS IP's registers start at 0, not at the reset values).
//   compensation      comp_inputs (air T, p, RH, CO2, wavelength, equation, alpha, material T,
//                     origin) -> ratio and comp_offset (compute_compensation, compensation.h);
//                     back: ratio -> scale/ppm, and with the quantities a register cannot hold
//                     (air T, RH, CO2, equation, alpha, material T) the pressure (the air-index
//                     equation inverted by bisection over its pressure range) and the origin.
//   error map         a correction table (origin and spacing 2^k in output counts, corrections in
//                     counts or um) -> geometry of the bank not selected by bank_sel, its Q15.8
//                     words (docs/ERROR_MAP.md §3) and the register write sequence that loads them
//                     through the map write port; back: geometry + words -> corrections.
//   DDS table         a period / amplitude (+ mark_len, dac_width) -> the quarter-wave table words
//                     of lxt::dds_table (host/dds_table.h) and the register write sequence
//                     that loads them through the table write port and switches the chain to them,
//                     with one documented safe-state window (program_dds, below).
//
// Quantisation of the round trips (tb/tb_regmap checks them):
//   ratio        |R - 2^32 s| <= 1/2, s = lambda/n/78.125 (1+g): the relative error of n is at most
//                0.5/R (1.4e-11); the pressure comes back within 0.5/R * n / (dn/dp) (~6 mPa on
//                the shop floor, dn/dp ~ 2.6e-9 /Pa).
//   comp_offset  |comp_offset + K168 g 2^32| <= 1/2: the origin (K168, whole counts) comes back
//                within 0.5 / (2^32 |g|) counts; with g = 0 it is not recoverable (origin_known
//                false). K168 itself is origin_um rounded to whole counts (compute_compensation).
//   map words    rha(c * 256): within 1/512 count of the correction c.
#ifndef LASERAX_HOST_REGMAP_H
#define LASERAX_HOST_REGMAP_H

#include <cstdint>
#include <string>
#include <vector>

#include "host/air_index.h"
#include "host/compensation.h"
#include "host/ip_init.h"
#include "host/regmap_table.h"

namespace lxt {

// One 32-bit bus write. name: the register, with the bit range for registers wider than 32 bits
// ("ratio[31:0]", "ratio[36:32]").
struct reg_write {
    uint32_t offset = 0;
    std::string name;
    uint32_t value = 0;
};

class reg_image {
public:
    reg_image();  // every register at its reset value, reserved words 0

    // By name. false and a message (image unchanged) for an unknown name or a value that does not
    // fit the register's width. Legality (min..max, rules) is not checked here: that is the
    // core's configuration check (lx::axis_config_ok) or regmap::legal().
    bool write(const std::string& name, int64_t value, std::string* err = nullptr);
    bool read(const std::string& name, int64_t* value, std::string* err = nullptr) const;
    // By index (regmap::idx::...); set() is false if the value does not fit.
    bool set(int i, int64_t value);
    int64_t get(int i) const;

    // Raw words: offset must be a word of the map (aligned, kFirstOffset <= offset < kEndOffset).
    bool write_word(uint32_t offset, uint32_t value, std::string* err = nullptr);
    uint32_t word(uint32_t offset) const;  // 0 outside the map

    // The bus writes that set register i to its image value, low word first.
    std::vector<reg_write> writes(int i) const;

private:
    std::vector<uint32_t> w_;  // word (offset - kFirstOffset) / 4
};

// Writes that set the given registers (in the given order) to their values in img.
std::vector<reg_write> writes_for(const reg_image& img, const std::vector<int>& regs);
// "0x0018 ratio[31:0] 0x19A0B21C" per write (the --regs-out format).
std::string format_writes(const std::vector<reg_write>& w);

// "13 bits unsigned: 0 .. 8191": the width's range of a register, for messages.
std::string range_text(const regmap::reg_info& r);

// ---- image <-> host settings -----------------------------------------------------------------
// false (and a message naming the register; *img unchanged) if a member holds a value outside its
// register's width.
bool image_from(const axis_settings& s, reg_image* img, std::string* err = nullptr);
axis_settings settings_from(const reg_image& img);

// ---- initialisation before the core is started (host/ip_init.h) ------------------------------
// init_registers(settings_from(img), write, err): the whole image img through the caller's
// register write, in the order of host/ip_init.h (the HLS IP's registers start at 0, not at the
// reset values: write the image, then lxt::start_core).
bool init_registers(const reg_image& img, const bus_write_fn& write, std::string* err = nullptr);

// Points per error-map bank: the largest map_n0 / map_n1 (lx::error_map_cfg::TBL_DEPTH in hls/,
// checked in sysmodel/model_regs.cpp).
constexpr int kMapDepth = static_cast<int>(regmap::kRegs[regmap::idx::map_n0].max);

// ---- compensation: physical <-> ratio, comp_offset -------------------------------------------
// compute_compensation(in) and, if ok, ratio and comp_offset written into img. false with the
// message for out-of-range input (img unchanged). *out (optional) gets every computed quantity.
bool apply_compensation(const comp_inputs& in, reg_image* img, comp_outputs* out = nullptr, std::string* err = nullptr);
// The bus writes of ratio and comp_offset, framed for an atomic update: comp_sync = 1, the words
// of both registers (low word first), comp_commit = 1, comp_commit = 0.
std::vector<reg_write> compensation_writes(const reg_image& img);

// What the registers cannot hold; needed to read pressure and origin back.
struct comp_knowns {
    double wavelength_nm = 632.991;
    double air_temp_c = 20.0;
    double rh_percent = 50.0;
    double co2_ppm = 450.0;
    lxt::air_equation equation = lxt::air_equation::ciddor;
    double alpha_ppm_per_c = 0.0;
    double material_temp_c = 20.0;
};

struct comp_readback {
    bool ok = false;
    std::string error;
    long double scale = 0.0L;    // ratio / 2^32, output counts per raw count
    double register_ppm = 0.0;   // scale relative to lambda_vac / 78.125 nm, ppm
    double expansion = 0.0;      // g = alpha (20 - T) of the knowns (quantised as compute_compensation does)
    double n = 0.0;              // air index the ratio implies, given g
    double pressure_pa = 0.0;    // the pressure at which the equation gives n
    bool origin_known = false;   // false when g == 0: comp_offset is 0 whatever the origin
    double origin_counts = 0.0;  // thermal origin (K168), output counts
    double origin_um = 0.0;
};
// ratio, comp_offset of img + knowns -> the physical settings. ok = false with a message for
// invalid knowns or a ratio whose air index lies outside the equation's pressure range.
comp_readback compensation_from_image(const reg_image& img, const comp_knowns& k);

// ---- error map -------------------------------------------------------------------------------
enum class map_units { counts, um };  // output counts (78.125 nm) or micrometres

struct map_table {
    int64_t origin = 0;        // position of point 0, output counts (comp coordinates)
    int spacing_log2 = 10;     // points are 2^k output counts apart (4..20)
    std::vector<double> corr;  // correction at each point (2..kMapDepth points)
    map_units units = map_units::counts;
};

// One correction (output counts) -> Q15.8 table word rha(c * 256); false outside the 24-bit range.
bool map_word_from_counts(double counts, int32_t* word, std::string* err = nullptr);
double map_counts_from_word(int32_t word);  // word / 256

struct map_load {
    int bank = 0;                // the bank loaded: the one not selected by bank_sel before
    std::vector<int32_t> words;  // its table words, point 0 first
    std::vector<reg_write> seq;  // every bus write, in order
};
// Loads table t into the bank not selected by img's bank_sel: its geometry registers, then per
// point map_addr, map_data, map_we = 1, map_we = 0; with activate, then bank_sel flipped and
// map_en = 1. img ends in the state after the sequence. false with a message (img unchanged) for
// an invalid geometry, a non-finite correction or one outside the Q15.8 range.
bool program_map(const map_table& t, bool activate, reg_image* img, map_load* out, std::string* err = nullptr);

// The two error-map banks as the core holds them (host-side model of the write port).
struct map_ram {
    std::vector<int32_t> bank[2] = {std::vector<int32_t>(kMapDepth, 0), std::vector<int32_t>(kMapDepth, 0)};
};
// Replays bus writes into img; while map_we is 1 after a write, map_data is stored at map_addr of
// the bank not selected by bank_sel (the core writes every clock, so a held enable rewrites the
// same word). false for a write outside the map.
bool replay(const std::vector<reg_write>& seq, reg_image* img, map_ram* ram, std::string* err = nullptr);

// Geometry of bank b from img and its words -> the table (corrections in the given units).
// false with a message for an invalid geometry (map_cfg_err) or fewer words than points.
bool map_from_image(const reg_image& img, int bank, const std::vector<int32_t>& words, map_units units, map_table* out,
                    std::string* err = nullptr);

// ---- DDS quarter-wave table: load and switch (DESIGN §4.6, §4.7) ---------------------------
struct dds_setting {
    int period = 256;       // P, output counts: 8 .. 4096, step 8
    int amplitude = 32767;  // sin/cos amplitude (the value at a quarter period): 1 .. 2^(dac_width-1) - 1
    int mark_len = 0;       // reference mark length, P/4 .. P; 0: P/4
    int dac_width = 0;      // 12 .. 18; 0: img's width if the amplitude fits it, else the smallest that does
};

struct dds_load {
    std::vector<uint32_t> words;  // lxt::dds_table(period, amplitude): the P/4 words, word 0 first
    std::vector<reg_write> seq;   // every bus write, in order
};

// Loads the table for s and switches the chain to it, for a period change as for a new amplitude
// at the same period. The bus writes, in this order:
//   1. tbl_period = 0: marks the table as being rewritten. From the call after this write the
//      configuration check fails (tbl_period != period), so the chain is in the safe state
//      (cfg_err = 1, sin = cos = 0, every block in reset, counts not counted) and the DDS never
//      reads a half-written table (DESIGN §4.6: the table is written only while tbl_period !=
//      period).
//   2. per word k = 0 .. P/4-1: tbl_addr = k, tbl_data = T[k], tbl_we = 1, tbl_we = 0 (the port
//      writes the word in every clock the enable is 1; it is written in the safe state too).
//   3. period, mark_len, dac_width, amplitude (all four, whatever img held: the sequence does not
//      rely on the host's copy being in step with the slave).
//   4. tbl_period = P: the configuration is valid again from the call after this write.
// P + 6 writes in all. The sequence accepts exactly one safe-state window: with its first write
// completing at edge t0 and its last at edge t1, cfg_err = 1 in calls t0+1 .. t1 and 0 from call
// t1+1 on (a write completing at edge t acts in call t+1; docs/REGISTERS.md, "RTL slave").
// Nothing in between can make the configuration valid early, whatever the old and new period,
// mark_len, dac_width and amplitude (tbl_period = 0 matches no legal period). Leaving the window the
// chain starts from reset with the new period (coming out of an invalid configuration costs no
// extra safe-state call, DESIGN §4.7): raw_count restarts at 0 and the axis is un-homed (stage 1)
// until the next rising edge of the switch homes it with the new period. Not touched: the
// compensation pair in force, the error-map tables and every other register; the chain runs after
// the window only if those are valid too (ratio, pace_m).
// img ends in the state after the sequence (tbl_we = 0, tbl_addr / tbl_data hold the last word).
// false with a message (img unchanged) for a setting outside the legal ranges or rules.
bool program_dds(const dds_setting& s, reg_image* img, dds_load* out, std::string* err = nullptr);

}  // namespace lxt

#endif
