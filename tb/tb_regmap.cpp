// tb_regmap — the register map (regmap/laserax_regs.csv -> docs/REGISTERS.md) and the host helper
// host/regmap.h.
//
// 1. Defaults: a default-constructed lx::axis_regs and golden::axis_regs, read through the
//    generated accessors, equal the table's reset values (this ties the hand-written structs to
//    the single source); the reset image equals the image of either struct.
// 2. Round trip image <-> struct, exact, for random values of every register (uniform over the
//    width, plus 0, +-1 and the width's extremes): by index and by name, raw words low word first,
//    hls and golden structs, and the generated to_hls(); the C header agrees with the table.
// 3. Legal ranges: every register with check=cfg is swept (exhaustively up to 18 bits, else min,
//    max, their neighbours, off-step and random values) with its dependent registers set per its
//    rule; lx::axis_config_ok must be true exactly for the legal values. check=map the same through
//    lx::error_map_geom_ok; check=none registers never change either.
// 4. Physical -> image -> physical over a seeded random sweep of the shop floor (15..30 degC,
//    90..110 kPa, 0..90 %RH, CO2 300..600, alpha 0..25 ppm/degC, material 10..30 degC, origin
//    within +-2 m, both equations):
//      pressure within 0.5/R * n / (dn/dp) + 1e-6 Pa  (the ratio register's half LSB as a
//        relative error of n; dn/dp evaluated at each point; 1e-6 Pa covers the bisection and
//        double rounding);
//      origin within 0.5 / (2^32 |g|) + 1e-6 counts of K168 (comp_offset's half LSB), and K168
//        within 1/2 count of the requested origin; not recoverable (flagged) when g = 0;
//    error-map tables (random geometry, corrections in counts or um) through program_map, a replay
//    of the bus writes and map_from_image: geometry exact, every correction within 1/512 count.
// 5. Errors, not values: out-of-range physical input, unknown register names, values outside a
//    register's width, words outside the map, bad map tables, bad DDS settings; `laserax
//    compensate --regs-out` writes exactly the helper's register writes.
// 6. DDS table load (lxt::program_dds): a chain of loads (period changes 256 -> 640 and to the
//    extremes 8 / 4096, amplitude changes at the same period, dac_width kept, widened, set) is
//    replayed write by write into a reg_image and an hls laserax_top (1..3 calls per write) while
//    the axis moves: cfg_err must be 1 in exactly the documented window (from the call after the
//    first write up to the call of the last write) and 0 before and after it; afterwards the
//    image equals program_dds's, the table RAM holds lxt::dds_table(P, amp), the axis homes with
//    the new period (Z = A + P + P/4, output phase P/8 at Z, sin == cos > 0 there) and in every
//    running call sin/cos equal the words of lxt::dds_table at the phase out_pos(t-2) mod P (the
//    quadrant mapping of DESIGN §4.6), every phase 0..P-1 visited. Negative controls: the same
//    load with one tbl_addr off by one, and without its first write, must fail those checks.
// 7. Host settings: lxt::axis_settings (host/regmap_table.h, the host library's own settings type)
//    defaults equal the CSV resets; image <-> settings exact; to_hls / to_golden of the settings
//    equal hls_from / golden_from of the image; a member outside its width is refused by name.
// 8. HLS IP initialisation (lxt::init_registers, host/ip_init.h): the documented write order and
//    count; on a word image of zeros (the HLS IP's registers at power-up) the writes leave exactly
//    the image, for the reset image and random ones; pulse registers / table write enables at 1
//    and a value outside its width are refused before any write.
// Each topic is one function (test_defaults .. test_init_registers), run in this order by main().
// ctest-args: --seed 5 --samples 3000
// ctest-args-O0: --seed 5 --samples 300
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "host/air_index.h"
#include "host/thermal.h"
#include "hls/laserax_top.h"
#include "hls/error_map.h"
#include "hls/laserax_regmap.h"
#include "tb/tb_util.h"
#include "host/dds_table.h"
#include "tools/laserax/compensate_cmd.h"
#include "host/laserax_regs_c.h"
#include "host/ip_init.h"
#include "host/regmap.h"
#include "sysmodel/model_regs.h"
#include "host/regmap_table.h"
#include "sysmodel/sim.h"

namespace {

namespace rm = lxt::regmap;

std::string s64(int64_t v) { return std::to_string(static_cast<long long>(v)); }

bool same_words(const lxt::reg_image& a, const lxt::reg_image& b, std::string* where) {
    for (uint32_t o = rm::kFirstOffset; o < rm::kEndOffset; o += 4)
        if (a.word(o) != b.word(o)) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "word 0x%02X: 0x%08X vs 0x%08X", o, a.word(o), b.word(o));
            *where = buf;
            return false;
        }
    return true;
}

// Sets register i to v and its dependent registers so that only register i can make the
// configuration invalid (per the rule text of the CSV). false if the rule has no recipe here.
bool set_with_rule(lxt::reg_image& img, int i, int64_t v) {
    const rm::reg_info& r = rm::kRegs[i];
    const std::string rule = r.rule;
    img.set(i, v);
    const auto fit13 = [](int64_t p) { return p < 0 ? int64_t(0) : (p > 8191 ? int64_t(8191) : p); };
    if (rule.empty()) return true;
    if (std::strcmp(r.name, "period") == 0 || rule == "== period") {
        // period and tbl_period move together, mark_len = v/4 (legal for every legal period)
        img.set(rm::idx::period, fit13(v));
        img.set(rm::idx::tbl_period, fit13(v));
        img.set(rm::idx::mark_len, fit13(v) / 4);
        return true;
    }
    if (rule == "period/4 .. period") {
        // the period closest to v that allows it: ceil(v / 8) * 8 within 8 .. 4096
        int64_t p = (v + 7) / 8 * 8;
        if (p < 8) p = 8;
        if (p > 4096) p = 4096;
        img.set(rm::idx::period, p);
        img.set(rm::idx::tbl_period, p);
        return true;
    }
    if (std::strcmp(r.name, "glitch_n") == 0) {
        img.set(rm::idx::min_spacing, rm::kRegs[rm::idx::min_spacing].max);  // every glitch_n below it
        return true;
    }
    if (std::strcmp(r.name, "min_spacing") == 0) {
        img.set(rm::idx::glitch_n, 0);  // max(0, 1) = 1: every min_spacing >= 2 is legal
        return true;
    }
    if (rule.find("dac_width") != std::string::npos) {
        img.set(rm::idx::dac_width, rm::kRegs[rm::idx::dac_width].max);  // the widest: the largest amplitude
        return true;
    }
    return false;
}

// Base image for the legality sweep: reset values, with amplitude 1 so that every dac_width in
// its range accepts it.
lxt::reg_image legal_base() {
    lxt::reg_image img;
    img.set(rm::idx::amplitude, 1);
    return img;
}

// ---- DDS table load (section 6) ----------------------------------------------------------------

// The pins of an axis at raw count n (quadrature index n mod 4, DESIGN §4.2); the reference switch
// closes at n >= kSwPos. move_toward() steps one raw count every `spacing` calls.
constexpr int64_t kSwPos = 20;
struct axis_motion {
    int64_t n = 0;
    long wait = 0;
    lx::axis_pins pins() const {
        const int i = static_cast<int>(((n % 4) + 4) % 4);
        lx::axis_pins p;
        p.a = i == 1 || i == 2;
        p.b = i == 2 || i == 3;
        p.sw = n >= kSwPos;
        return p;
    }
    void move_toward(int64_t target, long spacing) {
        if (n == target) return;
        if (wait-- <= 0) {
            n += target > n ? 1 : -1;
            wait = spacing;
        }
    }
};

// sin/cos of the DDS at phase ph from the quarter-wave words t (DESIGN §4.6: T[r] and T[P/4 - r],
// the amplitude register standing in for T[P/4]).
void table_sincos(const std::vector<uint32_t>& t, int period, int64_t amp, int ph, int64_t* sn, int64_t* cs) {
    const int quarter = period / 4;
    const int r = ph % quarter;
    const int64_t dir = t[static_cast<size_t>(r)];
    const int64_t mir = r == 0 ? amp : static_cast<int64_t>(t[static_cast<size_t>(quarter - r)]);
    switch (ph / quarter) {
        case 0: *sn = dir; *cs = mir; break;
        case 1: *sn = mir; *cs = -dir; break;
        case 2: *sn = -dir; *cs = -mir; break;
        default: *sn = -mir; *cs = dir; break;
    }
}

struct load_stats {
    long calls = 0, window_calls = 0;
    long err_outside = 0;  // calls with cfg_err before or after the window
    long ok_inside = 0;    // calls in the window without cfg_err
    long sincos_checked = 0, sincos_bad = 0;
    std::string first_bad;
    int phases = 0;  // distinct phases whose sin/cos were checked
    bool homed = false, z_ok = false, sin_eq_cos_at_z = false;
    std::string z_text;
};

// Replays the bus writes seq into img and core (each write acts from the next call on, 1..3
// calls per write) while the axis moves below the switch, then homes the axis with the period
// and amplitude the image holds at the end and runs it over more than a period, checking cfg_err
// against the window and sin/cos against lxt::dds_table in every call.
load_stats run_load(lx::laserax_top& core, lxt::reg_image& img, axis_motion& ax, const std::vector<lxt::reg_write>& seq,
                    std::mt19937_64& rng) {
    load_stats st;
    const int64_t n_lo = kSwPos - 8;
    const auto spacing_for = [&]() {  // calls per raw count so that the pacer keeps up
        const double cpr = static_cast<double>(img.get(rm::idx::ratio)) / 4294967296.0;
        return static_cast<long>(static_cast<double>(img.get(rm::idx::pace_m)) * cpr) + 4;
    };
    // register stage (DESIGN 4.7): a call runs on the registers presented in the previous call,
    // so each call is judged by the window state of the previous one
    bool prev_in_window = false;
    const auto call = [&](bool presented_in_window) {
        const lx::axis_out o = core.step(ax.pins(), lxt::hls_from(img));
        const bool in_window = prev_in_window;
        prev_in_window = presented_in_window;
        ++st.calls;
        if (in_window) {
            ++st.window_calls;
            st.ok_inside += o.cfg_err ? 0 : 1;
        } else {
            st.err_outside += o.cfg_err ? 1 : 0;
        }
        return o;
    };
    // before: the old configuration runs, the axis heads below the switch
    for (int k = 0; k < 20; ++k) {
        ax.move_toward(n_lo, spacing_for());
        call(false);
    }
    // the window: every write but the last is followed by 1..3 calls that must be in the safe state
    for (size_t i = 0; i < seq.size(); ++i) {
        std::string e;
        if (!img.write_word(seq[i].offset, seq[i].value, &e)) {
            st.first_bad = "write " + std::to_string(i) + ": " + e;
            ++st.sincos_bad;
            return st;
        }
        if (i + 1 == seq.size()) break;
        for (int64_t k = std::uniform_int_distribution<int64_t>(1, 3)(rng); k > 0; --k) {
            ax.move_toward(n_lo, spacing_for());
            call(true);
        }
    }
    // after: the chain runs from reset with the new period; the axis waits below the switch,
    // then drives through it far enough for A + P + P/4 and a full period past it
    const int period = static_cast<int>(img.get(rm::idx::period));
    const int64_t amp = img.get(rm::idx::amplitude);
    const std::vector<uint32_t> words = lxt::dds_table(period, static_cast<int>(amp));
    const double cpr = static_cast<double>(img.get(rm::idx::ratio)) / 4294967296.0;
    const int64_t n_hi = kSwPos + static_cast<int64_t>((2.5 * period + 64.0) / cpr) + 2;
    std::vector<char> seen(static_cast<size_t>(period), 0);
    // the codes of call t belong to out_pos of call t-3 (DESIGN 4.7); out_pos of the three calls
    // before the first running one
    std::vector<int64_t> out_hist = {0, 0, 0};
    long below = 0, at_top = 0, tz = -1;
    bool first_run = true;
    for (long t = 0; t < 2000000; ++t) {
        if (below < 200) {
            ax.move_toward(n_lo, spacing_for());
            below = ax.n == n_lo ? below + 1 : 0;
        } else {
            ax.move_toward(n_hi, spacing_for());
        }
        const lx::axis_out o = call(false);
        if (o.cfg_err) {
            out_hist.push_back(0);
            first_run = true;
            continue;
        }
        const int64_t out = o.out_pos.to_int64();
        // the first running call after the safe state still shows the reset codes 0/0 of the DDS
        // output stage (DESIGN 4.6/4.7); the table codes follow from the second one on
        if (first_run) {
            first_run = false;
            if ((o.sin.to_int64() != 0 || o.cos.to_int64() != 0) && st.sincos_bad++ == 0)
                st.first_bad = "first running call: codes not 0/0";
            out_hist.push_back(out);
            continue;
        }
        const int ph = static_cast<int>(((out_hist[out_hist.size() - 3] % period) + period) % period);
        int64_t sn = 0, cs = 0;
        table_sincos(words, period, amp, ph, &sn, &cs);
        ++st.sincos_checked;
        seen[static_cast<size_t>(ph)] = 1;
        if (o.sin.to_int64() != sn || o.cos.to_int64() != cs) {
            if (st.sincos_bad++ == 0)
                st.first_bad = "running call " + std::to_string(t) + ", phase " + std::to_string(ph) + ": sin/cos " +
                               std::to_string(o.sin.to_int64()) + "/" + std::to_string(o.cos.to_int64()) +
                               ", table words give " + std::to_string(sn) + "/" + std::to_string(cs);
        }
        out_hist.push_back(out);
        if (o.stage == 3 && !st.homed) {
            st.homed = true;
            st.z_ok = o.z_pos.to_int64() == o.a_pos.to_int64() + period + period / 4;
            st.z_text = "A " + std::to_string(o.a_pos.to_int64()) + ", Z " + std::to_string(o.z_pos.to_int64());
        }
        if (st.homed && tz < 0 && out - o.adj.to_int64() == o.z_pos.to_int64()) {  // the paced position at Z
            tz = t;
            st.z_ok = st.z_ok && ((out % period) + period) % period == period / 8;
            st.z_text += ", output phase at Z " + std::to_string(((out % period) + period) % period);
        }
        if (tz >= 0 && t == tz + 3) st.sin_eq_cos_at_z = o.sin == o.cos && o.sin > 0;  // the codes of Z
        at_top = (ax.n == n_hi && o.backlog == 0) ? at_top + 1 : 0;
        if (at_top > 50) break;
    }
    for (char c : seen) st.phases += c;
    return st;
}


// What every topic of main() shares, in the order main() runs them: one result, one random
// stream (the topics draw from it in turn, as when they were one function), the seed and the
// sample count.
struct ctx {
    tbu::result& res;
    std::mt19937_64& rng;
    uint64_t seed;
    long long samples;
};

    // ---- 1. defaults ---------------------------------------------------------------------------
void test_defaults(ctx& topic) {
    [[maybe_unused]] tbu::result& res = topic.res;
    [[maybe_unused]] std::mt19937_64& rng = topic.rng;
    [[maybe_unused]] const uint64_t seed = topic.seed;
    [[maybe_unused]] const long long samples = topic.samples;
    [[maybe_unused]] auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    [[maybe_unused]] auto unii = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    const lx::axis_regs h{};
    const golden::axis_regs g{};
    int n_golden = 0;
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const rm::reg_info& r = rm::kRegs[i];
        res.check(rm::get(h, i) == r.reset, std::string("lx::axis_regs default of ") + r.hls_member + " = " +
                                                s64(rm::get(h, i)) + ", CSV reset of " + r.name + " = " +
                                                s64(r.reset));
        int64_t v = 0;
        const bool has = rm::get(g, i, &v);
        res.check(has == (r.golden_member[0] != '\0'), std::string("golden accessor presence for ") + r.name);
        if (has) {
            ++n_golden;
            res.check(v == r.reset, std::string("golden::axis_regs default of ") + r.golden_member + " = " +
                                        s64(v) + ", CSV reset of " + r.name + " = " + s64(r.reset));
        }
        res.check(rm::legal(r, r.reset), std::string("reset of ") + r.name + " is not legal");
    }
    std::string where;
    lxt::reg_image from_g;
    res.expect(same_words(lxt::reg_image(), lxt::image_from(h), &where),
               [&] { return "reset image != image of lx::axis_regs{}: " + where; });
    res.expect(lxt::image_from(g, &from_g) && same_words(lxt::reg_image(), from_g, &where),
               [&] { return "reset image != image of golden::axis_regs{}: " + where; });
    res.check(lx::axis_config_ok(lxt::hls_from(lxt::reg_image())), "reset image is not a valid configuration");
    std::printf("  defaults: %d registers (%d in golden::axis_regs) reset as in the CSV\n", rm::kNumRegs, n_golden);
}

    // ---- 2. round trips --------------------------------------------------------------------------
void test_round_trips(ctx& topic) {
    [[maybe_unused]] tbu::result& res = topic.res;
    [[maybe_unused]] std::mt19937_64& rng = topic.rng;
    [[maybe_unused]] const uint64_t seed = topic.seed;
    [[maybe_unused]] const long long samples = topic.samples;
    [[maybe_unused]] auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    [[maybe_unused]] auto unii = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    // generated constants agree with the table (C header X-macro, lx::regmap)
    struct c_reg {
        const char* name;
        unsigned offset;
        int width, is_signed;
        long long reset;
    };
#define LASERAX_TB_ROW(N, OFF, W, S, R) {#N, OFF, W, S, R},
    const c_reg c_regs[] = {LASERAX_REGS(LASERAX_TB_ROW)};
#undef LASERAX_TB_ROW
    res.check(sizeof(c_regs) / sizeof(c_regs[0]) == static_cast<size_t>(rm::kNumRegs) &&
                  LASERAX_REG_COUNT == rm::kNumRegs && lx::regmap::N_REGS == rm::kNumRegs,
              "register count differs between the C header, lx::regmap and the table");
    for (int i = 0; i < rm::kNumRegs && i < LASERAX_REG_COUNT; ++i) {
        const rm::reg_info& r = rm::kRegs[i];
        std::string up = r.name;
        for (char& ch : up) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        res.check(up == c_regs[i].name && r.offset == c_regs[i].offset && r.width == c_regs[i].width &&
                      r.is_signed == (c_regs[i].is_signed != 0) && r.reset == c_regs[i].reset,
                  std::string("C header row ") + std::to_string(i) + " differs from the table (" + r.name + ")");
        res.check(rm::find(r.name) == i, std::string("find(") + r.name + ")");
    }
    static_assert(
        lx::regmap::RATIO_OFFSET == LASERAX_REG_RATIO_OFFSET &&
            lx::regmap::RATIO_RESET == LASERAX_REG_RATIO_RESET &&
            static_cast<unsigned long long>(rm::kRegs[rm::idx::ratio].reset) == lx::laserax_top_cfg::RATIO_DEFAULT,
        "ratio constants");
    res.check(lx::regmap::FIRST_OFFSET == rm::kFirstOffset && lx::regmap::END_OFFSET == rm::kEndOffset &&
                  LASERAX_REG_END_OFFSET == rm::kEndOffset,
              "first/end offsets");

    auto random_value = [&](const rm::reg_info& r) -> int64_t {
        switch (unii(0, 7)) {
            case 0: return rm::width_min(r);
            case 1: return rm::width_max(r);
            case 2: return 0;
            case 3: return r.is_signed ? -1 : (r.width > 1 ? 1 : 0);
            case 4: return r.reset;
            default: return rm::from_bits(r, rng());  // uniform over the width
        }
    };
    long trips = 0;
    for (long long t = 0; t < samples; ++t) {
        lxt::reg_image img;
        std::vector<int64_t> v(rm::kNumRegs);
        for (int i = 0; i < rm::kNumRegs; ++i) {
            v[static_cast<size_t>(i)] = random_value(rm::kRegs[i]);
            std::string err;
            const bool ok = (t & 1) ? img.set(i, v[static_cast<size_t>(i)])
                                    : img.write(rm::kRegs[i].name, v[static_cast<size_t>(i)], &err);
            res.expect(ok, [&] {
                return std::string("write ") + rm::kRegs[i].name + " " + s64(v[static_cast<size_t>(i)]) + ": " +
                       err;
            });
        }
        // words: low word first, bits above the width 0
        for (int i = 0; i < rm::kNumRegs; ++i) {
            const rm::reg_info& r = rm::kRegs[i];
            const uint64_t bits = rm::to_bits(r, v[static_cast<size_t>(i)]);
            for (int w = 0; w < r.words(); ++w) {
                const uint32_t got = img.word(r.offset + 4u * static_cast<uint32_t>(w));
                res.expect(got == static_cast<uint32_t>(bits >> (32 * w)), [&] {
                    return std::string(r.name) + " word " + std::to_string(w) + " = " + std::to_string(got);
                });
            }
            int64_t back = 0;
            res.expect(img.read(r.name, &back) && back == v[static_cast<size_t>(i)], [&] {
                return std::string("read ") + r.name + " = " + s64(back) + ", wrote " +
                       s64(v[static_cast<size_t>(i)]);
            });
        }
        // hls struct
        const lx::axis_regs h = lxt::hls_from(img);
        for (int i = 0; i < rm::kNumRegs; ++i)
            res.expect(rm::get(h, i) == v[static_cast<size_t>(i)], [&] {
                return std::string("lx::axis_regs::") + rm::kRegs[i].hls_member + " = " + s64(rm::get(h, i)) +
                       ", image " + s64(v[static_cast<size_t>(i)]);
            });
        std::string where;
        res.expect(same_words(img, lxt::image_from(h), &where),
                   [&] { return "image -> lx::axis_regs -> image: " + where; });
        // raw words into a fresh image give the same registers
        lxt::reg_image raw;
        for (uint32_t o = rm::kFirstOffset; o < rm::kEndOffset; o += 4) raw.write_word(o, img.word(o));
        res.expect(same_words(img, raw, &where), [&] { return "raw word copy: " + where; });
        // golden struct: registers golden has come back, the others are at reset
        const golden::axis_regs g = lxt::golden_from(img);
        lxt::reg_image gi;
        res.expect(lxt::image_from(g, &gi), [] { return std::string("image_from(golden) failed"); });
        for (int i = 0; i < rm::kNumRegs; ++i) {
            const bool has = rm::kRegs[i].golden_member[0] != '\0';
            const int64_t want = has ? v[static_cast<size_t>(i)] : rm::kRegs[i].reset;
            res.expect(gi.get(i) == want, [&] {
                return std::string("image -> golden -> image: ") + rm::kRegs[i].name + " = " + s64(gi.get(i)) +
                       ", want " + s64(want);
            });
        }
        // the generated to_hls agrees with the accessors
        const lx::axis_regs th = lxt::to_hls(g);
        for (int i = 0; i < rm::kNumRegs; ++i) {
            const bool has = rm::kRegs[i].golden_member[0] != '\0';
            const int64_t want = has ? v[static_cast<size_t>(i)] : rm::kRegs[i].reset;
            res.expect(rm::get(th, i) == want,
                       [&] { return std::string("to_hls: ") + rm::kRegs[i].name + " = " + s64(rm::get(th, i)); });
        }
        ++trips;
    }
    std::printf(
        "  round trips: %ld random images (every register, extremes included), hls and golden structs, exact\n",
        trips);
}

    // ---- 3. legal ranges -------------------------------------------------------------------------
void test_legal_ranges(ctx& topic) {
    [[maybe_unused]] tbu::result& res = topic.res;
    [[maybe_unused]] std::mt19937_64& rng = topic.rng;
    [[maybe_unused]] const uint64_t seed = topic.seed;
    [[maybe_unused]] const long long samples = topic.samples;
    [[maybe_unused]] auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    [[maybe_unused]] auto unii = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    long n_cfg = 0, n_map = 0, n_none = 0, values = 0;
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const rm::reg_info& r = rm::kRegs[i];
        std::vector<int64_t> vals;
        if (r.width <= 18) {
            for (int64_t v = rm::width_min(r); v <= rm::width_max(r); ++v) vals.push_back(v);
        } else {
            for (int64_t v :
                 {r.min, r.max, r.min + r.step, r.max - r.step, rm::width_min(r), rm::width_max(r), int64_t(0)})
                vals.push_back(v);
            if (r.min > rm::width_min(r)) vals.push_back(r.min - 1);
            if (r.max < rm::width_max(r)) vals.push_back(r.max + 1);
            if (r.step > 1) vals.push_back(r.min + r.step / 2);
            for (int k = 0; k < 200; ++k) vals.push_back(rm::from_bits(r, rng()));
        }
        if (r.chk == rm::check::cfg) {
            ++n_cfg;
            lxt::reg_image probe = legal_base();
            res.check(set_with_rule(probe, i, r.reset),
                      std::string("no test recipe for the rule '") + r.rule + "' of " + r.name);
            bool saw_min = false, saw_max = false, saw_below = false, saw_above = false, saw_off = false;
            for (int64_t v : vals) {
                if (!rm::fits(r, v)) continue;
                lxt::reg_image img = legal_base();
                set_with_rule(img, i, v);
                const bool ok = lx::axis_config_ok(lxt::hls_from(img));
                res.expect(ok == rm::legal(r, v), [&] {
                    return std::string(r.name) + " = " + s64(v) + ": axis_config_ok " + (ok ? "true" : "false") +
                           ", table says " + (rm::legal(r, v) ? "legal" : "illegal");
                });
                saw_min = saw_min || v == r.min;
                saw_max = saw_max || v == r.max;
                saw_below = saw_below || v == r.min - 1;
                saw_above = saw_above || v == r.max + 1;
                saw_off = saw_off || (v > r.min && v < r.max && v % r.step != 0);
                ++values;
            }
            res.check(saw_min && saw_max, std::string(r.name) + ": min/max not probed");
            res.check(saw_below || r.min == rm::width_min(r), std::string(r.name) + ": min-1 not probed");
            res.check(saw_above || r.max == rm::width_max(r), std::string(r.name) + ": max+1 not probed");
            res.check(saw_off || r.step == 1, std::string(r.name) + ": no off-step value probed");
        } else if (r.chk == rm::check::map) {
            ++n_map;
            for (int64_t v : vals) {
                lxt::reg_image img = legal_base();
                img.set(i, v);
                const lx::axis_regs h = lxt::hls_from(img);
                const bool ok0 = lx::error_map_geom_ok(h.emap.geom[0]), ok1 = lx::error_map_geom_ok(h.emap.geom[1]);
                res.expect((ok0 && ok1) == rm::legal(r, v), [&] {
                    return std::string(r.name) + " = " + s64(v) + ": error_map_geom_ok " +
                           ((ok0 && ok1) ? "true" : "false");
                });
                res.expect(lx::axis_config_ok(h),
                           [&] { return std::string(r.name) + " put the chain in the safe state"; });
                ++values;
            }
        } else {
            ++n_none;
            res.check(r.any_range && r.step == 1, std::string(r.name) + ": check none with a range");
            for (int64_t v : vals) {
                lxt::reg_image img = legal_base();
                img.set(i, v);
                const lx::axis_regs h = lxt::hls_from(img);
                res.expect(lx::axis_config_ok(h) && lx::error_map_geom_ok(h.emap.geom[0]) &&
                               lx::error_map_geom_ok(h.emap.geom[1]),
                           [&] {
                               return std::string(r.name) + " = " + s64(v) +
                                      " (check none) changed a configuration check";
                           });
                ++values;
            }
        }
    }
    std::printf(
        "  legal ranges: %ld cfg, %ld map, %ld unchecked registers, %ld values against axis_config_ok / "
        "error_map_geom_ok\n",
        n_cfg, n_map, n_none, values);
}

    // ---- 4. physical -> image -> physical --------------------------------------------------------
void test_physical_round_trip(ctx& topic) {
    [[maybe_unused]] tbu::result& res = topic.res;
    [[maybe_unused]] std::mt19937_64& rng = topic.rng;
    [[maybe_unused]] const uint64_t seed = topic.seed;
    [[maybe_unused]] const long long samples = topic.samples;
    [[maybe_unused]] auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    [[maybe_unused]] auto unii = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    double bound_min = 1e9, bound_max = 0, worst_p = 0, worst_p_ratio = 0, worst_o = 0, worst_o_ratio = 0,
           worst_k168 = 0;
    long n_ok = 0, n_g0 = 0, n_neg_inside = 0;
    for (long long t = 0; t < samples; ++t) {
        lxt::comp_inputs in;
        in.air_temp_c = uni(15, 30);
        in.pressure_pa = uni(90e3, 110e3);
        in.rh_percent = uni(0, 90);
        in.co2_ppm = uni(300, 600);
        in.equation = (t % 2) ? lxt::air_equation::edlen : lxt::air_equation::ciddor;
        in.alpha_ppm_per_c = (t % 17 == 0) ? 0.0 : uni(0, 25);
        in.material_temp_c = (t % 23 == 0) ? 20.0 : uni(10, 30);
        in.origin_um = uni(-2e6, 2e6);
        lxt::reg_image img;
        lxt::comp_outputs co;
        std::string err;
        if (!res.expect(lxt::apply_compensation(in, &img, &co, &err),
                        [&] { return std::string("apply_compensation failed: ") + err; }))
            continue;
        res.check(img.get(rm::idx::ratio) == static_cast<int64_t>(co.ratio) &&
                      img.get(rm::idx::comp_offset) == co.comp_offset,
                  "image does not hold ratio/comp_offset");
        lxt::comp_knowns k;
        k.wavelength_nm = in.wavelength_nm;
        k.air_temp_c = in.air_temp_c;
        k.rh_percent = in.rh_percent;
        k.co2_ppm = in.co2_ppm;
        k.equation = in.equation;
        k.alpha_ppm_per_c = in.alpha_ppm_per_c;
        k.material_temp_c = in.material_temp_c;
        const lxt::comp_readback b = lxt::compensation_from_image(img, k);
        if (!res.check(b.ok, "compensation_from_image: " + b.error)) continue;
        res.check(b.register_ppm == co.register_ppm, "register ppm differs");
        // pressure bound from the ratio LSB
        lxt::air_input ai;
        ai.wavelength_nm = in.wavelength_nm;
        ai.temp_c = in.air_temp_c;
        ai.rh_percent = in.rh_percent;
        ai.co2_ppm = in.co2_ppm;
        ai.pressure_pa = in.pressure_pa + 50.0;
        const double n_up = lxt::air_index(in.equation, ai).n;
        ai.pressure_pa = in.pressure_pa - 50.0;
        const double n_dn = lxt::air_index(in.equation, ai).n;
        const double dndp = (n_up - n_dn) / 100.0;
        const double bound_p = 0.5 / static_cast<double>(co.ratio) * co.n / dndp + 1e-6;
        bound_min = std::min(bound_min, bound_p);
        bound_max = std::max(bound_max, bound_p);
        const double ep = std::fabs(b.pressure_pa - in.pressure_pa);
        worst_p = std::max(worst_p, ep);
        worst_p_ratio = std::max(worst_p_ratio, ep / bound_p);
        res.expect(ep <= bound_p, [&] {
            char buf[200];
            std::snprintf(buf, sizeof buf, "pressure %.6f Pa came back as %.6f Pa (|error| %.3g > bound %.3g Pa)",
                          in.pressure_pa, b.pressure_pa, ep, bound_p);
            return std::string(buf);
        });
        // negative control: a ratio 2 LSB off moves n by ~5.7e-11, i.e. ~22 mPa, which the bound
        // (~5.5 mPa) must catch every time
        lxt::reg_image off = img;
        off.set(rm::idx::ratio, img.get(rm::idx::ratio) + 2);
        const lxt::comp_readback bo = lxt::compensation_from_image(off, k);
        if (bo.ok && std::fabs(bo.pressure_pa - in.pressure_pa) <= bound_p) ++n_neg_inside;
        // origin
        const double k168 = static_cast<double>(co.scaling.k168);
        worst_k168 = std::max(worst_k168, std::fabs(k168 - in.origin_um * 12.8));
        res.check(std::fabs(k168 - in.origin_um * 12.8) <= 0.5 + 1e-9, "K168 is not the origin rounded to a count");
        if (co.scaling.k169_e7 == 0) {
            ++n_g0;
            res.check(!b.origin_known, "origin reported known with g = 0");
        } else {
            const double g = static_cast<double>(co.scaling.k169_e7) * 1e-12;
            const double bound_o = 0.5 / (4294967296.0 * std::fabs(g)) + 1e-6;
            const double eo = std::fabs(b.origin_counts - k168);
            worst_o = std::max(worst_o, eo);
            worst_o_ratio = std::max(worst_o_ratio, eo / bound_o);
            res.expect(b.origin_known && eo <= bound_o, [&] {
                char buf[200];
                std::snprintf(buf, sizeof buf, "origin K168 = %.0f came back as %.6f counts (bound %.3g, g = %.3g)",
                              k168, b.origin_counts, bound_o, g);
                return std::string(buf);
            });
            res.check(std::fabs(b.origin_um * 12.8 - b.origin_counts) < 1e-6, "origin um/counts");
        }
        ++n_ok;
    }
    res.check(n_neg_inside == 0, "negative control: a ratio 2 LSB off stayed within the pressure bound " +
                                     std::to_string(n_neg_inside) + " times");
    std::printf(
        "  physical round trip: %ld points; pressure max |error| %.3g Pa (%.4f of its bound; bound %.3g .. %.3g "
        "Pa); origin max |error| %.3g counts (%.4f of its bound); K168 max %.3f count from the origin; %ld "
        "points with g = 0 (origin not recoverable, flagged); ratio + 2 LSB outside the pressure bound every "
        "time\n",
        n_ok, worst_p, worst_p_ratio, bound_min, bound_max, worst_o, worst_o_ratio, worst_k168, n_g0);

    // error map
    double worst_c = 0;
    long n_maps = 0, n_words = 0;
    for (long long t = 0; t < samples / 10 + 5; ++t) {
        lxt::map_table tb;
        tb.spacing_log2 = static_cast<int>(unii(4, 20));
        const int npts = static_cast<int>(t % 7 == 0 ? (t % 2 ? 2 : lx::error_map_cfg::TBL_DEPTH) : unii(2, 300));
        tb.origin = (t % 11 == 0) ? (t % 2 ? rm::width_max(rm::kRegs[rm::idx::map_origin0])
                                           : rm::width_min(rm::kRegs[rm::idx::map_origin0]))
                                  : unii(-(int64_t(1) << 36), int64_t(1) << 36);
        tb.units = (t % 2) ? lxt::map_units::um : lxt::map_units::counts;
        const double lim = tb.units == lxt::map_units::um ? 2500.0 : 32767.0;
        double walk = uni(-lim / 4, lim / 4);
        for (int p = 0; p < npts; ++p) {
            walk += uni(-lim / 100, lim / 100);
            if (walk > lim) walk = lim;
            if (walk < -lim) walk = -lim;
            tb.corr.push_back((t % 5 == 0) ? uni(-lim, lim) : walk);
        }
        lxt::reg_image img;
        img.set(rm::idx::bank_sel, unii(0, 1));
        const lxt::reg_image before = img;
        lxt::map_load ld;
        std::string err;
        if (!res.expect(lxt::program_map(tb, true, &img, &ld, &err),
                        [&] { return std::string("program_map: ") + err; }))
            continue;
        res.check(ld.bank == (before.get(rm::idx::bank_sel) ? 0 : 1), "program_map loaded the selected bank");
        // replay the bus writes from the state before: same final image, words in the right bank
        lxt::reg_image rep = before;
        lxt::map_ram ram;
        std::string where;
        res.expect(lxt::replay(ld.seq, &rep, &ram, &err), [&] { return std::string("replay: ") + err; });
        res.expect(same_words(rep, img, &where),
                   [&] { return "replayed image differs from program_map's: " + where; });
        res.check(
            img.get(rm::idx::bank_sel) == ld.bank && img.get(rm::idx::map_en) == 1 && img.get(rm::idx::map_we) == 0,
            "bank not activated / write enable left on");
        bool other_zero = true;
        for (int32_t w : ram.bank[1 - ld.bank]) other_zero = other_zero && w == 0;
        res.check(other_zero, "replay wrote the selected bank");
        const lx::axis_regs h = lxt::hls_from(img);
        res.check(lx::error_map_geom_ok(h.emap.geom[ld.bank]) && lx::axis_config_ok(h),
                  "programmed geometry invalid");
        lxt::map_table back;
        if (!res.expect(lxt::map_from_image(img, ld.bank, ram.bank[ld.bank], tb.units, &back, &err),
                        [&] { return std::string("map_from_image: ") + err; }))
            continue;
        res.check(
            back.origin == tb.origin && back.spacing_log2 == tb.spacing_log2 && back.corr.size() == tb.corr.size(),
            "map geometry did not come back");
        const double to_counts = tb.units == lxt::map_units::um ? 12.8 : 1.0;
        for (size_t p = 0; p < tb.corr.size() && p < back.corr.size(); ++p) {
            const double e = std::fabs(back.corr[p] - tb.corr[p]) * to_counts;
            worst_c = std::max(worst_c, e);
            res.expect(e <= 1.0 / 512.0 + 1e-9, [&] {
                char buf[160];
                std::snprintf(buf, sizeof buf, "map point %zu: %.9f came back as %.9f (%.3g counts off)", p,
                              tb.corr[p], back.corr[p], e);
                return std::string(buf);
            });
            ++n_words;
        }
        ++n_maps;
    }
    std::printf("  error map round trip: %ld tables, %ld points, max |error| %.6f counts (bound 1/512 = %.6f)\n",
                n_maps, n_words, worst_c, 1.0 / 512.0);
}

    // ---- 5. errors, not values --------------------------------------------------------------------
void test_errors(ctx& topic) {
    [[maybe_unused]] tbu::result& res = topic.res;
    [[maybe_unused]] std::mt19937_64& rng = topic.rng;
    [[maybe_unused]] const uint64_t seed = topic.seed;
    [[maybe_unused]] const long long samples = topic.samples;
    [[maybe_unused]] auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    [[maybe_unused]] auto unii = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    lxt::reg_image img;
    const lxt::reg_image ref;
    std::string err, where;
    int64_t v = 0;
    res.expect(!img.write("bogus", 1, &err) && err.find("unknown register") != std::string::npos,
               [&] { return std::string("write of an unknown name: ") + err; });
    res.expect(!img.read("periode", &v, &err) && err.find("unknown register") != std::string::npos,
               [&] { return std::string("read of an unknown name: ") + err; });
    res.expect(!img.write("period", 8192, &err) && err.find("does not fit") != std::string::npos,
               [&] { return std::string("period 8192 accepted: ") + err; });
    res.check(!img.write("map_origin0", int64_t(1) << 37, &err), "map_origin0 2^37 accepted");
    res.check(!img.write("map_data", -(int64_t(1) << 23) - 1, &err), "map_data -2^23-1 accepted");
    res.check(!img.write("rehome", 2, &err), "rehome 2 accepted");
    res.check(!img.write("ratio", -1, &err), "ratio -1 accepted");
    res.check(!img.write_word(0x0C, 1, &err) && !img.write_word(rm::kEndOffset, 1, &err) &&
                  !img.write_word(0x12, 1, &err),
              "word outside the map accepted");
    res.expect(same_words(img, ref, &where), [&] { return "a rejected write changed the image: " + where; });
    golden::axis_regs g;
    g.period = 100000;
    lxt::reg_image gi;
    res.expect(!lxt::image_from(g, &gi, &err) && err.find("period") != std::string::npos,
               [&] { return std::string("golden period 100000 accepted: ") + err; });

    const auto bad_phys = [&](const char* what, lxt::comp_inputs in, const char* word) {
        lxt::reg_image im;
        std::string e;
        const bool ok = lxt::apply_compensation(in, &im, nullptr, &e);
        res.check(!ok && e.find(word) != std::string::npos && same_words(im, ref, &where),
                  std::string("out-of-range ") + what + " gave a value or no message: '" + e + "'");
    };
    lxt::comp_inputs in;
    in.pressure_pa = 5000;
    bad_phys("pressure", in, "pressure");
    in = lxt::comp_inputs{};
    in.air_temp_c = 150;
    bad_phys("air temperature", in, "temperature");
    in = lxt::comp_inputs{};
    in.rh_percent = 120;
    bad_phys("humidity", in, "humidity");
    in = lxt::comp_inputs{};
    in.alpha_ppm_per_c = 500;
    bad_phys("alpha", in, "expansion");
    in = lxt::comp_inputs{};
    in.origin_um = 2e9;
    bad_phys("origin", in, "origin");

    lxt::comp_knowns k;
    lxt::reg_image im;
    im.set(rm::idx::ratio,
           static_cast<int64_t>(lxt::ratio_for(632.991, 1.0, 78.125)));  // vacuum: no pressure gives n = 1
    lxt::comp_readback b = lxt::compensation_from_image(im, k);
    res.check(!b.ok && b.error.find("pressure") != std::string::npos, "vacuum ratio gave a pressure: " + b.error);
    k.material_temp_c = 95;
    b = lxt::compensation_from_image(lxt::reg_image(), k);
    res.check(!b.ok && !b.error.empty(), "material 95 degC knowns accepted");
    k = lxt::comp_knowns{};
    k.air_temp_c = 150;
    b = lxt::compensation_from_image(lxt::reg_image(), k);
    res.check(!b.ok && b.error.find("temperature") != std::string::npos,
              "air 150 degC knowns accepted: " + b.error);

    const auto bad_map = [&](const char* what, const lxt::map_table& t) {
        lxt::reg_image m;
        lxt::map_load ld;
        std::string e;
        res.check(!lxt::program_map(t, true, &m, &ld, &e) && !e.empty() && same_words(m, ref, &where),
                  std::string("bad map (") + what + ") accepted");
    };
    lxt::map_table mt;
    mt.corr = {0.0, 1.0};
    mt.spacing_log2 = 3;
    bad_map("k = 3", mt);
    mt.spacing_log2 = 21;
    bad_map("k = 21", mt);
    mt.spacing_log2 = 10;
    mt.corr = {1.0};
    bad_map("1 point", mt);
    mt.corr.assign(2049, 0.0);
    bad_map("2049 points", mt);
    mt.corr = {0.0, 32768.0};
    bad_map("32768 counts", mt);
    mt.corr = {0.0, std::nan("")};
    bad_map("NaN", mt);
    mt.corr = {0.0, 1.0};
    mt.origin = int64_t(1) << 40;
    bad_map("origin 2^40", mt);
    lxt::map_table back;
    lxt::reg_image bad_geom;
    bad_geom.set(rm::idx::map_k1, 2);
    res.check(!lxt::map_from_image(bad_geom, 1, std::vector<int32_t>(lx::error_map_cfg::TBL_DEPTH, 0), lxt::map_units::counts, &back, &err),
              "map_from_image accepted an invalid geometry");

    const auto bad_dds = [&](const char* what, int period, int amp, int mark_len, int dac_width, const char* word) {
        lxt::reg_image m;
        lxt::dds_load ld;
        std::string e;
        lxt::dds_setting ds;
        ds.period = period;
        ds.amplitude = amp;
        ds.mark_len = mark_len;
        ds.dac_width = dac_width;
        res.check(!lxt::program_dds(ds, &m, &ld, &e) && e.find(word) != std::string::npos &&
                      same_words(m, ref, &where),
                  std::string("bad DDS setting (") + what + ") accepted or no message: '" + e + "'");
    };
    bad_dds("period 0", 0, 32767, 0, 0, "period");
    bad_dds("period 4104", 4104, 32767, 0, 0, "period");
    bad_dds("period 260", 260, 32767, 0, 0, "period");
    bad_dds("amplitude 0", 256, 0, 0, 0, "amplitude");
    bad_dds("amplitude 131072", 256, 131072, 0, 0, "amplitude");
    bad_dds("mark_len P/4 - 1", 640, 32767, 159, 0, "mark_len");
    bad_dds("mark_len P + 1", 640, 32767, 641, 0, "mark_len");
    bad_dds("dac_width 11", 256, 100, 0, 11, "dac_width");
    bad_dds("dac_width 19", 256, 100, 0, 19, "dac_width");
    bad_dds("amplitude 40000 at dac_width 16", 256, 40000, 0, 16, "dac_width");
}

    // ---- `laserax compensate --regs-out` ---------------------------------------------------------
void test_compensate_regs_out(ctx& topic) {
    [[maybe_unused]] tbu::result& res = topic.res;
    [[maybe_unused]] std::mt19937_64& rng = topic.rng;
    [[maybe_unused]] const uint64_t seed = topic.seed;
    [[maybe_unused]] const long long samples = topic.samples;
    [[maybe_unused]] auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    [[maybe_unused]] auto unii = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    const std::string path =
        "/tmp/laserax_tb_regmap_" + std::to_string(seed) + "_" + std::to_string(rng() % 1000000) + ".txt";
    const std::vector<std::string> args = {
        "compensate", "--temp-c", "25",          "--pressure-kpa", "98.5",       "--rh", "40",
        "--material", "steel",    "--origin-um", "-150000",        "--regs-out", path};
    FILE* fo = std::tmpfile();
    FILE* fe = std::tmpfile();
    const int rc = lxt::cmd_compensate(args, 1, fo, fe);
    std::string out;
    std::rewind(fo);
    for (int ch; (ch = std::fgetc(fo)) != EOF;) out += static_cast<char>(ch);
    std::fclose(fo);
    std::fclose(fe);
    lxt::comp_inputs in;
    in.air_temp_c = 25;
    in.pressure_pa = 98500;
    in.rh_percent = 40;
    in.alpha_ppm_per_c = lxt::find_material("steel")->alpha_ppm_per_c;
    in.material_temp_c = 25;
    in.origin_um = -150000;
    lxt::reg_image img;
    res.check(rc == 0 && lxt::apply_compensation(in, &img), "compensate failed");
    const std::string want = lxt::format_writes(lxt::compensation_writes(img));
    std::string file;
    if (FILE* f = std::fopen(path.c_str(), "r")) {
        for (int ch; (ch = std::fgetc(f)) != EOF;) file += static_cast<char>(ch);
        std::fclose(f);
    }
    std::remove(path.c_str());
    res.check(file == want, "--regs-out file:\n" + file + "expected:\n" + want);
    res.check(out.find("ratio[31:0]") != std::string::npos && out.find("comp_offset[63:32]") != std::string::npos,
              "register writes not printed");
    res.check(img.get(rm::idx::comp_offset) != 0, "steel at 25 degC with an origin gave comp_offset 0");
    std::printf("  laserax compensate --regs-out:\n%s", file.c_str());
    const std::vector<std::string> bad = {"compensate", "--regs-out", "/nonexistent-dir/x.txt"};
    fo = std::tmpfile();
    fe = std::tmpfile();
    res.check(lxt::cmd_compensate(bad, 1, fo, fe) == 2 && std::ftell(fo) == 0, "unwritable --regs-out accepted");
    std::fclose(fo);
    std::fclose(fe);
}

    // ---- 6. DDS table load through the bus (lxt::program_dds) ---------------------------------------
void test_dds_table_load(ctx& topic) {
    [[maybe_unused]] tbu::result& res = topic.res;
    [[maybe_unused]] std::mt19937_64& rng = topic.rng;
    [[maybe_unused]] const uint64_t seed = topic.seed;
    [[maybe_unused]] const long long samples = topic.samples;
    [[maybe_unused]] auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    [[maybe_unused]] auto unii = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    lxt::reg_image img;  // the chain's registers as the slave holds them
    img.set(rm::idx::pace_m, 2);
    img.set(rm::idx::glitch_n, 1);
    img.set(rm::idx::sw_debounce, 4);
    lx::laserax_top core;  // power-up table: P = 256, amp = 32767 (as the reset image)
    axis_motion ax;
    for (int k = 0; k < 100; ++k) core.step(ax.pins(), lxt::hls_from(img));
    struct plan_t {
        lxt::dds_setting s;
        int want_width;  // dac_width after the load
    };
    const auto setting = [](int p, int a, int m, int w) {
        lxt::dds_setting x;
        x.period = p;
        x.amplitude = a;
        x.mark_len = m;
        x.dac_width = w;
        return x;
    };
    std::vector<plan_t> plan = {
        {setting(640, 32767, 0, 0), 16},    // 256 -> 640 (the preset change)
        {setting(640, 20000, 400, 0), 16},  // amplitude change, same period, new mark_len
        {setting(640, 131071, 0, 0), 18},   // widest amplitude: dac_width widened 16 -> 18
        {setting(256, 1, 256, 12), 12},     // back to 256, amplitude 1, narrowest width
        {setting(8, 3, 0, 0), 12},          // shortest period (P/4 = 2 words)
        {setting(4096, 65535, 0, 0), 17},   // longest period (1024 words), width 12 -> 17
        {setting(1000, 2047, 0, 12), 12},   // 1000 counts, the largest amplitude of 12 bits
    };
    for (int k = 0; k < 2; ++k) {  // random settings
        const int p = static_cast<int>(unii(2, 256)) * 8;
        const int a = static_cast<int>(unii(1, 131071));
        plan.push_back({setting(p, a, static_cast<int>(unii(p / 4, p)), 0), 0});
    }
    plan.push_back({setting(256, 32767, 64, 16), 16});  // back to the reset configuration
    long n_loads = 0, n_calls = 0, n_window = 0, n_sincos = 0;
    for (size_t li = 0; li < plan.size(); ++li) {
        const lxt::dds_setting& ds = plan[li].s;
        const std::string tag = "DDS load " + std::to_string(li) + " (P " + std::to_string(ds.period) + ", amp " +
                                std::to_string(ds.amplitude) + ")";
        lxt::reg_image target = img;
        lxt::dds_load ld;
        std::string err;
        if (!res.expect(lxt::program_dds(ds, &target, &ld, &err), [&] { return tag + ": " + err; })) continue;
        const rm::reg_info& tp = rm::kRegs[rm::idx::tbl_period];
        res.check(ld.words == lxt::dds_table(ds.period, ds.amplitude), tag + ": words are not lxt::dds_table's");
        res.check(ld.seq.size() == static_cast<size_t>(ds.period) + 6, tag + ": not P + 6 writes");
        res.check(!ld.seq.empty() && ld.seq.front().offset == tp.offset && ld.seq.front().value == 0 &&
                      ld.seq.back().offset == tp.offset &&
                      ld.seq.back().value == static_cast<uint32_t>(ds.period),
                  tag + ": the sequence does not open with tbl_period = 0 and close with tbl_period = P");
        if (plan[li].want_width != 0)
            res.check(target.get(rm::idx::dac_width) == plan[li].want_width,
                      tag + ": dac_width " + s64(target.get(rm::idx::dac_width)) + ", expected " +
                          std::to_string(plan[li].want_width));
        res.check(target.get(rm::idx::tbl_we) == 0 && lx::axis_config_ok(lxt::hls_from(target)),
                  tag + ": enable left on or invalid configuration after the sequence");

        if (li == 0) {  // negative controls, from copies of the state before the load
            std::vector<lxt::reg_write> off = ld.seq;  // tbl_addr 1 written as 2
            for (lxt::reg_write& w : off)
                if (w.offset == rm::kRegs[rm::idx::tbl_addr].offset && w.value == 1) {
                    w.value = 2;
                    break;
                }
            lx::laserax_top c1 = core;
            lxt::reg_image i1 = img;
            axis_motion a1 = ax;
            const load_stats m1 = run_load(c1, i1, a1, off, rng);
            res.check(m1.sincos_bad > 0, tag + ": negative control: a table word written one address off went "
                                               "unnoticed by the sin/cos check");
            const std::vector<lxt::reg_write> late(ld.seq.begin() + 1, ld.seq.end());  // no tbl_period = 0
            lx::laserax_top c2 = core;
            lxt::reg_image i2 = img;
            axis_motion a2 = ax;
            const load_stats m2 = run_load(c2, i2, a2, late, rng);
            res.check(m2.ok_inside > 0, tag + ": negative control: without tbl_period = 0 first the chain still "
                                              "stayed in the safe state while the table was written");
        }

        const load_stats st = run_load(core, img, ax, ld.seq, rng);
        std::string where;
        res.expect(same_words(img, target, &where), [&] { return tag + ": replayed image differs: " + where; });
        res.check(st.err_outside == 0, tag + ": " + std::to_string(st.err_outside) +
                                           " calls with cfg_err outside the window");
        res.check(st.ok_inside == 0, tag + ": " + std::to_string(st.ok_inside) +
                                         " calls of the window ran (no cfg_err)");
        bool ram_ok = true;
        for (size_t k = 0; k < ld.words.size(); ++k)
            ram_ok = ram_ok && core.dds().read(static_cast<unsigned>(k)) == ld.words[k];
        res.check(ram_ok, tag + ": the table RAM does not hold lxt::dds_table's words");
        res.check(st.sincos_bad == 0, tag + ": " + std::to_string(st.sincos_bad) + " calls with sin/cos off the "
                                               "table, first: " + st.first_bad);
        res.check(st.phases == ds.period, tag + ": " + std::to_string(st.phases) + " of " +
                                              std::to_string(ds.period) + " phases checked");
        res.check(st.homed && st.z_ok && st.sin_eq_cos_at_z,
                  tag + ": homing with the new period: homed " + std::to_string(st.homed) + ", " + st.z_text +
                      " (expected Z = A + P + P/4, phase P/8), sin == cos > 0 at Z " +
                      std::to_string(st.sin_eq_cos_at_z));
        ++n_loads;
        n_calls += st.calls;
        n_window += st.window_calls;
        n_sincos += st.sincos_checked;
    }
    std::printf("  DDS table loads: %ld loads replayed (%ld calls, %ld in the safe-state windows), sin/cos "
                "checked against lxt::dds_table in %ld calls, homed after each; negative controls (address "
                "off by one, no tbl_period = 0) caught\n",
                n_loads, n_calls, n_window, n_sincos);
}

// ---- 7. host settings (lxt::axis_settings: the host library's own type) --------------------
// Its defaults are the CSV reset values; image <-> settings is exact for every register value;
// to_hls / to_golden of the settings equal hls_from / golden_from of the same image; a member
// outside its register's width is reported by name. Its own random stream (1..6 draw as before).
void test_host_settings(ctx& topic) {
    tbu::result& res = topic.res;
    std::mt19937_64 rng(topic.seed ^ 0x5e771465ull);
    const lxt::axis_settings s0{};
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const rm::reg_info& r = rm::kRegs[i];
        res.check(rm::get(s0, i) == r.reset, std::string("lxt::axis_settings default of ") + r.hls_member + " = " +
                                                 s64(rm::get(s0, i)) + ", CSV reset of " + r.name + " = " + s64(r.reset));
    }
    std::string where, err;
    lxt::reg_image from_s;
    res.expect(lxt::image_from(s0, &from_s) && same_words(lxt::reg_image(), from_s, &where),
               [&] { return "reset image != image of lxt::axis_settings{}: " + where; });
    long trips = 0;
    for (int t = 0; t < 2000; ++t) {
        lxt::reg_image img;
        for (int i = 0; i < rm::kNumRegs; ++i) {
            const rm::reg_info& r = rm::kRegs[i];
            const int64_t v = std::uniform_int_distribution<int64_t>(rm::width_min(r), rm::width_max(r))(rng);
            res.check(img.set(i, v), std::string("image set ") + r.name);
        }
        const lxt::axis_settings s = lxt::settings_from(img);
        lxt::reg_image back;
        res.expect(lxt::image_from(s, &back, &err) && same_words(img, back, &where),
                   [&] { return "image -> settings -> image differs: " + where + err; });
        res.expect(same_words(lxt::image_from(lxt::to_hls(s)), lxt::image_from(lxt::hls_from(img)), &where),
                   [&] { return "to_hls(settings) != hls_from(image): " + where; });
        lxt::reg_image gs, gi;
        res.expect(lxt::image_from(lxt::to_golden(s), &gs) && lxt::image_from(lxt::golden_from(img), &gi) &&
                       same_words(gs, gi, &where),
                   [&] { return "to_golden(settings) != golden_from(image): " + where; });
        ++trips;
    }
    lxt::axis_settings bad{};
    bad.period = int64_t(1) << 13;  // 13-bit register
    lxt::reg_image untouched;
    untouched.set(rm::idx::pace_m, 7);
    const lxt::reg_image before = untouched;
    err.clear();
    res.check(!lxt::image_from(bad, &untouched, &err) && err.find("period") != std::string::npos &&
                  same_words(before, untouched, &where),
              "a settings member outside its width must be refused by name, image unchanged: '" + err + "'");
    std::printf("  host settings: defaults as in the CSV, %ld random images through lxt::axis_settings exact, "
                "equal to the model structs' conversions\n", trips);
}

// ---- 8. initialisation before the start (lxt::init_registers, host/ip_init.h) ----------------
// The documented order: comp_sync = 1 first; then the words of every register but comp_sync and
// comp_commit, each once, in offset order (low word first); comp_commit = 1, comp_commit = 0;
// comp_sync = 0 last; init_register_writes() writes. Replayed into a word image of zeros (the HLS
// IP at power-up) they leave exactly the image (comp_sync 0), for the reset image and random images
// (every register random in its width, the pulse registers and table write enables 0); the
// reg_image overload writes the same sequence. Refused with nothing written: a pulse register or a
// table write enable at 1, a member outside its register's width. Its own random stream.
void test_init_registers(ctx& topic) {
    tbu::result& res = topic.res;
    std::mt19937_64 rng(topic.seed ^ 0x1417a11ull);
    struct bus_log {
        std::vector<std::pair<uint32_t, uint32_t>> w;
        lxt::bus_write_fn fn() {
            return [this](uint32_t offset, uint32_t value) { w.emplace_back(offset, value); };
        }
    };
    const uint32_t sync_off = rm::kRegs[rm::idx::comp_sync].offset;
    const uint32_t commit_off = rm::kRegs[rm::idx::comp_commit].offset;
    std::vector<uint32_t> body;  // the register words of step 2, in offset order
    for (int i = 0; i < rm::kNumRegs; ++i)
        if (i != rm::idx::comp_sync && i != rm::idx::comp_commit)
            for (int w = 0; w < rm::kRegs[i].words(); ++w) body.push_back(rm::kRegs[i].offset + 4u * static_cast<uint32_t>(w));
    res.check(static_cast<int>(body.size()) + 4 == lxt::init_register_writes(),
              "init_register_writes() != the words of the map + 4");
    std::string where, err;
    long images = 0;
    for (int t = 0; t < 500; ++t) {
        lxt::axis_settings s{};  // t == 0: the reset image
        if (t > 0) {
            for (int i = 0; i < rm::kNumRegs; ++i) {
                const rm::reg_info& r = rm::kRegs[i];
                const bool action = r.acc == rm::access::pulse || (r.acc == rm::access::port && r.width == 1);
                const int64_t v = action ? 0 : std::uniform_int_distribution<int64_t>(rm::width_min(r), rm::width_max(r))(rng);
                res.check(rm::set(s, i, v), std::string("settings set ") + r.name);
            }
        }
        bus_log log;
        err.clear();
        if (!res.expect(lxt::init_registers(s, log.fn(), &err), [&] { return "init_registers refused an image: " + err; }))
            continue;
        const auto& w = log.w;
        bool order = w.size() == body.size() + 4 && w.front() == std::make_pair(sync_off, 1u) &&
                     w.back() == std::make_pair(sync_off, 0u);
        if (order) {
            order = w[w.size() - 3] == std::make_pair(commit_off, 1u) && w[w.size() - 2] == std::make_pair(commit_off, 0u);
            for (size_t k = 0; k < body.size(); ++k) order = order && w[k + 1].first == body[k];
        }
        res.check(order, "init_registers: the writes are not in the documented order (image " + std::to_string(t) + ")");
        lxt::reg_image want, got;
        res.check(lxt::image_from(s, &want), "image_from");
        want.set(rm::idx::comp_sync, 0);
        for (uint32_t off = rm::kFirstOffset; off < rm::kEndOffset; off += 4) got.write_word(off, 0);
        for (const auto& x : w) res.check(got.write_word(x.first, x.second, &err), "init_registers wrote outside the map: " + err);
        res.expect(same_words(want, got, &where), [&] { return "init_registers on zeros does not leave the image: " + where; });
        bus_log log2;
        // (want holds comp_sync = 0, s maybe 1: the image's comp_sync is not written, the same writes)
        res.check(lxt::init_registers(want, log2.fn()) && log2.w == w,
                  "init_registers(reg_image) differs from init_registers(settings)");
        ++images;
    }
    // refused, nothing written
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const rm::reg_info& r = rm::kRegs[i];
        const bool action = r.acc == rm::access::pulse || (r.acc == rm::access::port && r.width == 1);
        if (!action) continue;
        lxt::axis_settings s{};
        rm::set(s, i, 1);
        bus_log log;
        err.clear();
        res.check(!lxt::init_registers(s, log.fn(), &err) && log.w.empty() && err.find(r.name) != std::string::npos,
                  std::string("init_registers accepted ") + r.name + " = 1 (or wrote before refusing): '" + err + "'");
    }
    lxt::axis_settings wide{};
    wide.period = int64_t(1) << 13;  // 13-bit register
    bus_log log;
    err.clear();
    res.check(!lxt::init_registers(wide, log.fn(), &err) && log.w.empty() && err.find("period") != std::string::npos,
              "init_registers accepted period = 2^13 (or wrote before refusing): '" + err + "'");
    std::printf("  init_registers: %ld images (the reset image and random ones) in the documented order, %d writes "
                "each, leaving the image on zeros; pulses / write enables at 1 and a value outside its width refused\n",
                images, lxt::init_register_writes());
}

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 5);
    const long long samples = tbu::arg_ll(argc, argv, "--samples", 3000);
    tbu::result res("tb_regmap", seed);
    std::mt19937_64 rng(seed);
    ctx c{res, rng, seed, samples};
    test_defaults(c);             // 1.
    test_round_trips(c);          // 2.
    test_legal_ranges(c);         // 3.
    test_physical_round_trip(c);  // 4.
    test_errors(c);               // 5.
    test_compensate_regs_out(c);  // 5. (laserax compensate --regs-out)
    test_dds_table_load(c);       // 6.
    test_host_settings(c);        // 7.
    test_init_registers(c);       // 8.
    return res.finish();
}
