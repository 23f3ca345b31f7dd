// regmap_table.h — the s_axilite register map (docs/REGISTERS.md) for host code: a constexpr
// table of every register, the host settings struct lxt::axis_settings (one member per register,
// plain integers, reset values) and accessors that read or write one register of it by index.
// Host code only: nothing from hls/ or golden/ (the model register structs are converted in
// sysmodel/regmap_models.h).
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
//
// Values are int64: the register's value (sign-extended for signed registers); the bits as they
// appear on the bus are to_bits(value). Hand-written users: host/regmap.h (register
// image, physical settings <-> registers).
#ifndef LASERAX_HOST_REGMAP_TABLE_H
#define LASERAX_HOST_REGMAP_TABLE_H

#include <cstdint>

namespace lxt {

// Every register of the map in plain integers, as a controller's software holds them: the member
// paths are those of the hls register struct (hls_member below), the defaults the reset values.
// A member may hold a value outside its register's width (image_from, host/regmap.h, reports it).
struct axis_settings {
    int64_t period = 256LL;  // period
    int64_t tbl_period = 256LL;  // tbl_period
    uint64_t ratio = 34789620252ULL;  // ratio
    int64_t comp_offset = 0LL;  // comp_offset
    int64_t glitch_n = 2LL;  // glitch_n
    int64_t sw_debounce = 16LL;  // sw_debounce
    int64_t min_spacing = 8LL;  // min_spacing
    int64_t pace_m = 61LL;  // pace_m
    uint64_t backlog_thr = 4096ULL;  // backlog_thr
    int64_t mark_len = 64LL;  // mark_len
    int64_t dac_width = 16LL;  // dac_width
    int64_t amplitude = 32767LL;  // amplitude
    bool rehome = false;  // rehome
    bool clear = false;  // clear
    bool tbl_we = false;  // tbl_we
    int64_t tbl_addr = 0LL;  // tbl_addr
    int64_t tbl_data = 0LL;  // tbl_data
    struct emap_t {
        bool map_en = false;  // map_en
        bool bank_sel = false;  // bank_sel
        struct geom_t {
            int64_t origin = 0LL;  // map_origin1
            int64_t spacing_log2 = 10LL;  // map_k1
            int64_t n_points = 1024LL;  // map_n1
        } geom[2];
        bool we = false;  // map_we
        int64_t addr = 0LL;  // map_addr
        int64_t data = 0LL;  // map_data
    } emap;
    bool comp_sync = false;  // comp_sync
    bool comp_commit = false;  // comp_commit
    int64_t pin_cfg = 8LL;  // pin_cfg
};

namespace regmap {

enum class access { rw, pulse, port };  // pulse: the host writes 1 then 0; port: table write port
enum class check { none, cfg, map };    // cfg: outside the range -> cfg_err; map: -> map_cfg_err

struct reg_info {
    const char* name;
    uint32_t offset;  // byte offset of the low word
    int width;        // bits (1..64)
    bool is_signed;
    int64_t reset;
    access acc;
    const char* units;
    bool any_range;   // every value of the width is legal as far as min/max go
    int64_t min, max; // legal range (the width's range when any_range)
    int64_t step;     // legal values are multiples of step (1: any)
    check chk;
    const char* rule;           // cross-register constraint, "" if none
    const char* hls_member;     // path inside lxt::axis_settings and lx::axis_regs
    const char* golden_member;  // path inside the golden model's register struct, "" if it has none
    const char* description;
    constexpr int words() const { return (width + 31) / 32; }
};

constexpr int kNumRegs = 31;
constexpr uint32_t kFirstOffset = 0x10;
constexpr uint32_t kEndOffset = 0x130;  // one past the last word (the last reserved word)

// Register indices (offset order).
namespace idx {
constexpr int period = 0;
constexpr int tbl_period = 1;
constexpr int ratio = 2;
constexpr int comp_offset = 3;
constexpr int glitch_n = 4;
constexpr int sw_debounce = 5;
constexpr int min_spacing = 6;
constexpr int pace_m = 7;
constexpr int backlog_thr = 8;
constexpr int mark_len = 9;
constexpr int dac_width = 10;
constexpr int amplitude = 11;
constexpr int rehome = 12;
constexpr int clear = 13;
constexpr int tbl_we = 14;
constexpr int tbl_addr = 15;
constexpr int tbl_data = 16;
constexpr int map_en = 17;
constexpr int bank_sel = 18;
constexpr int map_origin0 = 19;
constexpr int map_k0 = 20;
constexpr int map_n0 = 21;
constexpr int map_origin1 = 22;
constexpr int map_k1 = 23;
constexpr int map_n1 = 24;
constexpr int map_we = 25;
constexpr int map_addr = 26;
constexpr int map_data = 27;
constexpr int comp_sync = 28;
constexpr int comp_commit = 29;
constexpr int pin_cfg = 30;
}  // namespace idx

// One table for the program in C++17 (an inline variable); a C++14 translation unit (the Vitis
// C simulation compiles its testbench files, host/ip_init.cpp among them, as C++14) has a copy of
// its own of the constant table.
#if __cplusplus >= 201703L
#define LXT_REGMAP_INLINE_VAR inline
#else
#define LXT_REGMAP_INLINE_VAR
#endif
LXT_REGMAP_INLINE_VAR constexpr reg_info kRegs[kNumRegs] = {
    {"period", 0x10, 13, false, 256LL, access::rw, "output counts", false, 8LL, 4096LL, 8LL, check::cfg, "tbl_period == period; mark_len in period/4 .. period", "period", "period",
     "sin/cos period P (20 um = 256 counts); a change while running restarts the chain (one safe-state call). Bad value: outside 8..4096, not a multiple of 8, != tbl_period or mark_len outside period/4..period -> cfg_err (safe state)"},
    {"tbl_period", 0x18, 13, false, 256LL, access::rw, "output counts", false, 8LL, 4096LL, 8LL, check::cfg, "== period", "tbl_period", "tbl_period",
     "period the quarter-wave table was computed for; written after loading the table. Bad value: != period -> cfg_err (the safe-state window of a table load)"},
    {"ratio", 0x20, 37, false, 34789620252LL, access::rw, "Q5.32 output counts per raw count", false, 1LL, 137438953471LL, 1LL, check::cfg, "", "ratio", "ratio",
     "pulse multiplier ratio R: comp = floor((N * R + comp_offset) / 2^32); reset = rha(632.991 / 1.000271 / 78.125 * 2^32). Bad value: 0 -> cfg_err; a wrong non-zero ratio scales every position (nothing in the core can see it: host side, lxt::compensation)"},
    {"comp_offset", 0x30, 64, true, 0LL, access::rw, "Q32.32 output counts", true, (-9223372036854775807LL - 1), 9223372036854775807LL, 1LL, check::none, "", "comp_offset", "comp_offset",
     "offset added to N * R in the pulse multiplier (thermal origin: rha(-K168 * K169 * 1e-5 * 2^32), 0 = none). Bad value: none (every value legal); a wrong offset shifts every position (host side)"},
    {"glitch_n", 0x40, 8, false, 2LL, access::rw, "clock cycles", false, 0LL, 255LL, 1LL, check::cfg, "max(glitch_n, 1) < min_spacing", "glitch_n", "glitch_n",
     "glitch filter length N of the A/B/LERR inputs (0 and 1 = pass after one clock); shorter pulses are suppressed and set glitch_st. Bad value: N >= min_spacing puts the chain in the safe state (cfg_err), since a pulse the filter passes could then lose 4 counts silently (DESIGN 4.2)"},
    {"sw_debounce", 0x48, 16, false, 16LL, access::rw, "clock cycles", true, 0LL, 65535LL, 1LL, check::none, "", "sw_debounce", "sw_debounce",
     "debounce length of the reference switch input. Bad value: none; too short lets switch bounce through (extra homing edges), too long delays homing"},
    {"min_spacing", 0x50, 16, false, 8LL, access::rw, "clock cycles", false, 2LL, 65535LL, 1LL, check::cfg, "> max(glitch_n, 1)", "min_spacing", "min_spacing",
     "minimum spacing of counted A/B edges; closer edges set ovs_edge_st. Every filter-passing pulse shorter than 2 * min_spacing that changes the count is flagged; set it below the shortest real edge spacing (reset 8 = 80 ns at 100 MHz). Bad value: min_spacing <= max(glitch_n, 1) puts the chain in the safe state (cfg_err); too large a value flags real motion with ovs_edge_st"},
    {"pace_m", 0x58, 16, false, 61LL, access::rw, "clock cycles", false, 2LL, 65535LL, 1LL, check::cfg, "", "pace_m", "pace_m",
     "output pacer: consecutive output counts at least M clocks apart in every stage (each qa/qb state lasts >= M clocks; real counts 2M apart in the referencing window); choose M for the controller input (docs/CONTROLLER.md). Reset 61: safe for every input of that table (a hostmot2 counter at LinuxCNC's defaults needs 61), up to 128 mm/s of output at P = 256; faster motion builds a backlog (ovs_backlog_st), never a lost count. Bad value: below 2 -> cfg_err; a large M lets the backlog grow (ovs_backlog_st above backlog_thr, never a lost count)"},
    {"backlog_thr", 0x60, 32, false, 4096LL, access::rw, "output counts", true, 0LL, 4294967295LL, 1LL, check::none, "", "backlog_thr", "backlog_thr",
     "pacer backlog alarm threshold (|backlog| > thr sets ovs_backlog_st). Bad value: none; a large threshold delays the backlog alarm, 0 raises it at any backlog"},
    {"mark_len", 0x68, 13, false, 64LL, access::rw, "output counts", false, 2LL, 4096LL, 1LL, check::cfg, "period/4 .. period", "mark_len", "mark_len",
     "reference mark length: the mark is active from B to C = B + mark_len. Bad value: outside period/4..period -> cfg_err"},
    {"dac_width", 0x70, 5, false, 16LL, access::rw, "bits", false, 12LL, 18LL, 1LL, check::cfg, "", "dac_width", "dac_width",
     "width of the sin/cos DAC codes; limits the amplitude. Bad value: outside 12..18 -> cfg_err; a table in use that does not fit (dac_width lowered without reloading the table) -> sin/cos clamped to +-(2^(dac_width-1)-1) and sticky dac_clip_st (part of alarm)"},
    {"amplitude", 0x78, 18, false, 32767LL, access::rw, "DAC codes", false, 1LL, 131071LL, 1LL, check::cfg, "<= 2^(dac_width-1)-1", "amplitude", "amplitude",
     "sin/cos amplitude (the table value at a quarter period). Bad value: 0 or above 2^(dac_width-1)-1 -> cfg_err; a value that differs from the amplitude the table was computed for is not seen by the check: reload the table (lxt::program_dds); table words above the DAC range are clamped and flagged (dac_clip_st)"},
    {"rehome", 0x80, 1, false, 0LL, access::pulse, "-", true, 0LL, 1LL, 1LL, check::none, "", "rehome", "rehome",
     "back to stage 1 (un-homed) without a phase jump; a new switch edge homes again. Bad value: held at 1, the chain stays un-homed (stage 1) until it returns to 0"},
    {"clear", 0x88, 1, false, 0LL, access::pulse, "-", true, 0LL, 1LL, 1LL, check::none, "", "clear", "clear",
     "clears the sticky flags illegal_st / ovs_edge_st / ovs_backlog_st / glitch_st / lerr_alarm and err_cnt (an event in the same clock wins). Bad value: held at 1, the flags are cleared every clock but every event still sets its flag in its own clock (never hidden)"},
    {"tbl_we", 0x90, 1, false, 0LL, access::port, "-", false, 0LL, 0LL, 1LL, check::cfg, "", "tbl_we", "tbl_we",
     "quarter-wave table write enable: writes tbl_data to tbl_addr in every clock while 1; each such clock and the clock after it are in the safe state (cfg_err: DESIGN 4.6), so load the table while tbl_period != period. Bad value: a write while running puts that clock and the next in the safe state (cfg_err, the chain restarts un-homed); the table is never changed under a running chain without a flag"},
    {"tbl_addr", 0x98, 10, false, 0LL, access::port, "table words", true, 0LL, 1023LL, 1LL, check::none, "", "tbl_addr", "",
     "quarter-wave table address 0 .. P/4-1. Bad value: an address >= P/4 writes a word the current period does not read"},
    {"tbl_data", 0xA0, 17, false, 0LL, access::port, "DAC codes", true, 0LL, 131071LL, 1LL, check::none, "", "tbl_data", "",
     "quarter-wave table word rha(amplitude * sin(2 pi k / P)). Bad value: a wrong word gives a wrong code (within the DAC range: clamped and dac_clip_st beyond it)"},
    {"map_en", 0xA8, 1, false, 0LL, access::rw, "-", true, 0LL, 1LL, 1LL, check::none, "", "emap.map_en", "emap.map_en",
     "error map enable (docs/ERROR_MAP.md); active only while homed and the selected bank's geometry is valid. Bad value: 1 with an invalid geometry of the selected bank -> map_cfg_err, map inactive"},
    {"bank_sel", 0xB0, 1, false, 0LL, access::rw, "-", true, 0LL, 1LL, 1LL, check::none, "", "emap.bank_sel", "emap.bank_sel",
     "active error-map bank; the map write port writes the other bank. Bad value: selecting a bank that is not loaded applies its words (host side: load, then flip)"},
    {"map_origin0", 0xC0, 38, true, 0LL, access::rw, "output counts", true, -137438953472LL, 137438953471LL, 1LL, check::none, "", "emap.geom[0].origin", "emap.geom[0].origin",
     "position of table point 0 of bank 0 (comp coordinates). Bad value: none; a wrong origin shifts the correction (host side)"},
    {"map_k0", 0xD0, 5, false, 10LL, access::rw, "log2 output counts", false, 4LL, 20LL, 1LL, check::map, "", "emap.geom[0].spacing_log2", "emap.geom[0].spacing_log2",
     "bank 0 point spacing 2^k counts (16 counts = 1.25 um .. 2^20 counts = 81.9 mm). Bad value: outside 4..20 -> map_cfg_err while map_en and bank 0 selected (map inactive)"},
    {"map_n0", 0xD8, 11, false, 1024LL, access::rw, "points", false, 2LL, 1024LL, 1LL, check::map, "", "emap.geom[0].n_points", "emap.geom[0].n_points",
     "number of table points used in bank 0. Bad value: outside 2..1024 -> map_cfg_err while map_en and bank 0 selected (map inactive)"},
    {"map_origin1", 0xE0, 38, true, 0LL, access::rw, "output counts", true, -137438953472LL, 137438953471LL, 1LL, check::none, "", "emap.geom[1].origin", "emap.geom[1].origin",
     "position of table point 0 of bank 1 (comp coordinates). Bad value: none; a wrong origin shifts the correction (host side)"},
    {"map_k1", 0xF0, 5, false, 10LL, access::rw, "log2 output counts", false, 4LL, 20LL, 1LL, check::map, "", "emap.geom[1].spacing_log2", "emap.geom[1].spacing_log2",
     "bank 1 point spacing 2^k counts. Bad value: outside 4..20 -> map_cfg_err while map_en and bank 1 selected (map inactive)"},
    {"map_n1", 0xF8, 11, false, 1024LL, access::rw, "points", false, 2LL, 1024LL, 1LL, check::map, "", "emap.geom[1].n_points", "emap.geom[1].n_points",
     "number of table points used in bank 1. Bad value: outside 2..1024 -> map_cfg_err while map_en and bank 1 selected (map inactive)"},
    {"map_we", 0x100, 1, false, 0LL, access::port, "-", true, 0LL, 1LL, 1LL, check::none, "", "emap.we", "emap.we",
     "error-map table write enable: writes map_data to map_addr of bank !bank_sel in every clock while 1. Bad value: none (writes go to the bank not selected)"},
    {"map_addr", 0x108, 10, false, 0LL, access::port, "table points", true, 0LL, 1023LL, 1LL, check::none, "", "emap.addr", "emap.addr",
     "error-map table address 0 .. 1023. Bad value: an address >= map_n of that bank writes a word the map does not read"},
    {"map_data", 0x110, 24, true, 0LL, access::port, "Q15.8 output counts", true, -8388608LL, 8388607LL, 1LL, check::none, "", "emap.data", "emap.data",
     "error-map table word: correction at that point in 1/256 output count. Bad value: a wrong word gives a wrong correction, limited to the 17-bit corr range"},
    {"comp_sync", 0x118, 1, false, 0LL, access::rw, "-", true, 0LL, 1LL, 1LL, check::none, "", "comp_sync", "comp_sync",
     "1: ratio and comp_offset take effect only in a clock with comp_commit = 1 (a bus host writes their words, then pulses comp_commit: no half-written value ever reaches the multiplier); 0: from the clock after they are written (register stage). Bad value: 1 without comp_commit pulses keeps the old ratio / comp_offset in force"},
    {"comp_commit", 0x120, 1, false, 0LL, access::pulse, "-", true, 0LL, 1LL, 1LL, check::none, "", "comp_commit", "comp_commit",
     "with comp_sync = 1: loads ratio and comp_offset into the multiplier in this clock (both together). Bad value: a commit between the words of a wide register loads a half-written value (host side: words first, then commit)"},
    {"pin_cfg", 0x128, 4, false, 8LL, access::rw, "-", true, 0LL, 15LL, 1LL, check::none, "", "pin_cfg", "pin_cfg",
     "digital output pins (DESIGN 4.7, docs/CONTROLLER.md): bit 0 qz_window (0: qz is the index, one quadrature state at the home point Z; 1: qz is the reference window B..C, as ref_mark); bits 2:1 ab_rot (qa/qb encode out_pos + ab_rot: the A/B levels of the index state are those of (P/8 + ab_rot) mod 4, (0,0) at 0 and (1,1) at 2 for P a multiple of 32); bit 3 hiz_alarm (1: q_oe, the A/B/Z driver enable, is low while alarm is set). Reset 8: index at Z, no rotation, drivers off on alarm. Bad value: none (every value legal); a wrong ab_rot moves the A/B state of the index, so a gated counter misses it (its rising edge ungated still homes at Z)"},
};
#undef LXT_REGMAP_INLINE_VAR

// Smallest / largest value of the register's width.
constexpr int64_t width_min(const reg_info& r) {
    return r.is_signed ? (r.width == 64 ? INT64_MIN : -(int64_t(1) << (r.width - 1))) : 0;
}
constexpr int64_t width_max(const reg_info& r) {
    return r.is_signed ? (r.width == 64 ? INT64_MAX : (int64_t(1) << (r.width - 1)) - 1)
                       : (int64_t(1) << r.width) - 1;  // unsigned registers have at most 63 bits
}
constexpr bool fits(const reg_info& r, int64_t v) { return v >= width_min(r) && v <= width_max(r); }
// min..max and the step (cross-register rules are not evaluated here).
constexpr bool legal(const reg_info& r, int64_t v) { return v >= r.min && v <= r.max && v % r.step == 0; }
// value -> the register's bits (two's complement, width bits) and back.
constexpr uint64_t to_bits(const reg_info& r, int64_t v) {
    return r.width == 64 ? static_cast<uint64_t>(v) : static_cast<uint64_t>(v) & ((uint64_t(1) << r.width) - 1);
}
constexpr int64_t from_bits(const reg_info& r, uint64_t bits) {
    if (r.width == 64) return static_cast<int64_t>(bits);
    const uint64_t m = (uint64_t(1) << r.width) - 1;
    const uint64_t u = bits & m;
    if (!r.is_signed) return static_cast<int64_t>(u);
    const uint64_t sign = uint64_t(1) << (r.width - 1);
    return static_cast<int64_t>(u ^ sign) - static_cast<int64_t>(sign);
}

// Index of a register by name, -1 if there is none.
int find(const char* name);

// lxt::axis_settings: every register. get() returns the member as it is (it may lie outside the
// register's width); set() is false (s unchanged) if the value does not fit the width.
int64_t get(const axis_settings& s, int i);
bool set(axis_settings& s, int i, int64_t value);

}  // namespace regmap
}  // namespace lxt

#endif  // LASERAX_HOST_REGMAP_TABLE_H
