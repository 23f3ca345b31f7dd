// stress_vectors.cpp — extra vector files for the rtl_ref/ testbenches, expected values from the
// bit-true hls/ models (which tb/ checks against golden/ elsewhere).
//
// `laserax vectors` covers the scenario of docs/VECTORS.md. These files add what that scenario
// never does, so that the RTL is compared with the C++ model there too:
//   laserax_top_stress      a directed prologue of glitch_n / min_spacing pairs at the corners of
//                           the count-integrity check; then
//                           period changes (the safe-state call of the period-change rule) with the
//                           table reloaded through the write port while the chain runs, stray table
//                           writes that the DDS reads in the same call (write-first), every period
//                           preset up to P = 4096 (the 1024-word quarter), amplitude / dac_width
//                           changes, invalid-configuration windows of every kind (and stale-table
//                           windows: dac_width 12 / amplitude 2047, DAC range guard), frequent clears and
//                           rehomes, laser-error bursts, register changes of every field, and more
//                           output taps (step, delta, backlog, pstep, ostep, adj, a/b/c/z, rep_mark),
//                           and the error map (docs/ERROR_MAP.md §8): table words written into the
//                           inactive bank, bank flips, enables, new and invalid geometries, extreme
//                           table values (corr, map_delta, map_cfg_err);
//   input_filter_stress     random filter lengths 0..8 and pulse widths;
//   quad_decoder_stress     random glitch_n / min_spacing, clears during laser error, illegal steps;
//   pulse_multiplier_stress preset rows (N near +-2^31, so the 32-bit raw counter wraps) and large
//                           ratio changes;
//   output_pacer_stress     large deltas, every M including 0 and 1, clears while over threshold;
//   rephase_stress          random homing, reversals inside the window, rehome/unhome, periods and
//                           mark lengths;
//   dds_sincos_stress       table writes while running, every period preset up to 4096, amplitudes;
//   error_map_stress        both banks written in full, every spacing k = 4..20 (n = 2, TBL_DEPTH = 1024, random),
//                           random reloads of the inactive bank and flips, extreme words, invalid
//                           geometries, motion over both table ends with reversals and jumps,
//                           map_en / homed toggles (see error_map_stress below);
//   encoder_counter_stress  segments with every register re-drawn: quadrature or simulated counting
//                           at up to the 25 MHz limit, presets next to +-2^31 (wraps both ways),
//                           resets now and at a trigger (trigger in the request call too), waits on
//                           either channel either way with values across the wrap, scales and
//                           counters at the extremes (largest product), corr_period 32..65535
//                           changed live (a product restarted), qstep = -2, invalid sources, rates
//                           and periods (see encoder_counter_stress below).
//   pso_stress              segments with every register re-drawn: tracking on any axes with every K,
//                           part-speed at rates above the 24 MHz clamp, arrays of 1..64 entries
//                           (wrap or done) written while disabled and while running (the entry of
//                           the next fire too), windows on every source, spacing and frequency
//                           flags, enable drops, invalid configurations of every kind, fires as
//                           close as the minimum distance allows (see pso_stress below).
// Every file has the column layout of the golden file of its block (lxt::vec_layout(), shared with
// `laserax vectors`), so one testbench rtl_ref/tb/tb_<block>.v runs both sets. The columns the
// golden sets hold at 0 are exercised here: pulse_multiplier `preset, preset_n` (a row with
// preset = 1 first loads N = preset_n and R = ratio, as pulse_multiplier::preset(), then steps) and
// the table port `tbl_we, tbl_addr, tbl_data` of dds_sincos and laserax_top.
//
// Usage: rtl_stress_vectors --out DIR [--seed N] [--calls N]   writes DIR/<block>_stress.hex

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "hls/laserax_top.h"
#include "hls/encoder_counter.h"
#include "hls/pso.h"
#include "tools/laserax/pso_cmd.h"
#include "rtl_ref/tb/vecgen.h"
#include "host/dds_table.h"
#include "tools/laserax/vectors.h"

namespace {

using lxt::vec_table;
using vecgen::rng_t;

int64_t i64(bool b) { return b ? 1 : 0; }


const int kPresets[] = {256, 320, 512, 640, 1280, 4096, 8, 64, 1024};

// ---- laserax_top ----------------------------------------------------------------------------

vec_table top_stress(rng_t& r, long long calls) {
    vec_table t{"laserax_top_stress", lxt::vec_layout("laserax_top"), {}};

    lx::laserax_top core;  // power-up: P = 256 table, period register history 256
    lx::axis_regs g;     // register values the host has written (reset values, then changes)
    g.glitch_n = 1;
    g.sw_debounce = 3;
    g.pace_m = 2;
    g.backlog_thr = 200;
    g.min_spacing = 2;

    // host table load in progress (one word per call), then period/amplitude set in one call
    std::vector<uint32_t> load;
    size_t load_pos = 0;
    int load_period = 256, load_amp = 32767;
    int cur_period = 256;

    int64_t n = 0;  // raw laser count driven on the pins
    int dir = 1;
    long long wait = 0, spacing = 40, seg_left = 0;
    const int64_t sw_pos = 60;
    int glitch_left = 0, lerr_left = 0, bad_cfg_left = 0;
    bool cam_low = false;
    lx::axis_regs saved = g;
    // error map registers (kept apart from g: the invalid-configuration windows leave them alone)
    // and driven by their own generator, so the draws of the scenario above are those of the
    // set without the map
    std::mt19937_64 mr_seed = r.g;  // a copy: r itself is not advanced
    rng_t mr(mr_seed() ^ 0x6572726f725f6d61ULL);
    lx::error_map_regs mp;
    bool csync = false;  // comp_sync register (commit framing of ratio / comp_offset)
    unsigned pin_cfg = 8;  // pin_cfg register (digital pins)
    auto new_geom = [&mr](lx::error_map_geom& gm) {
        gm.origin = mr.range(-2500, 1500);
        gm.spacing_log2 = static_cast<unsigned>(mr.range(4, 9));
        gm.n_points = static_cast<unsigned>(mr.range(2, 300));
        if (mr.chance(5)) {  // an invalid geometry: map_cfg_err while enabled
            if (mr.chance(2)) gm.spacing_log2 = static_cast<unsigned>(mr.chance(2) ? mr.range(0, 3) : mr.range(21, 31));
            else gm.n_points = static_cast<unsigned>(mr.chance(2) ? mr.range(0, 1) : mr.range(lx::error_map_cfg::TBL_DEPTH + 1, (1 << lx::error_map_cfg::W_N) - 1));
        }
    };
    new_geom(mp.geom[0]);
    new_geom(mp.geom[1]);

    for (long long k = 0; k < calls; ++k) {
        bool rehome = false, clear = false, we = false;
        unsigned addr = 0, data = 0;

        // --- host activity ---
        const bool loading = load_pos < load.size();
        if (loading) {
            we = true;
            addr = static_cast<unsigned>(load_pos);
            data = load[load_pos];
            if (++load_pos == load.size()) {
                // table loaded: period, tbl_period, amplitude, mark_len, dac_width in this call
                g.period = static_cast<unsigned>(load_period);
                g.tbl_period = static_cast<unsigned>(load_period);
                g.amplitude = static_cast<unsigned>(load_amp);
                g.mark_len = static_cast<unsigned>(r.range(load_period / 4, load_period));
                if (load_amp > 32767) g.dac_width = 18;
                else if (load_amp > 2047) g.dac_width = static_cast<unsigned>(r.range(16, 18));
                else g.dac_width = static_cast<unsigned>(r.range(12, 18));
                cur_period = load_period;
            }
        } else if (bad_cfg_left == 0 && r.chance(9000)) {
            // a new period and/or amplitude: the table is written while the chain runs
            load_period = kPresets[r.range(0, static_cast<int64_t>(sizeof kPresets / sizeof kPresets[0]) - 1)];
            load_amp = r.chance(3) ? static_cast<int>(r.range(1, 131071)) : 32767;
            load = lxt::dds_table(load_period, load_amp);
            load_pos = 0;
        } else if (r.chance(1200)) {
            // stray write: the DDS may read this word in this very call (write-first)
            we = true;
            addr = static_cast<unsigned>(r.range(0, cur_period / 4 - 1));
            data = static_cast<unsigned>(r.u() & 0x1ffff);
        } else if (bad_cfg_left == 0 && r.chance(4000)) {
            // repair the table: rewrite it for the current period and amplitude
            load_period = cur_period;
            load_amp = static_cast<int>(g.amplitude.to_uint());
            load = lxt::dds_table(load_period, load_amp);
            load_pos = 0;
        }
        if (!loading && bad_cfg_left == 0 && r.chance(4000)) {
            saved = g;
            bad_cfg_left = static_cast<int>(r.range(1, 40));
            switch (r.range(0, 10)) {
                case 0: g.dac_width = static_cast<unsigned>(r.chance(2) ? 11 : 19); break;
                case 1: g.amplitude = (1u << (g.dac_width.to_uint() - 1)); break;
                case 2: g.amplitude = 0; break;
                case 3: g.pace_m = static_cast<unsigned>(r.range(0, 1)); break;
                case 4: g.ratio = 0; break;
                case 5: g.mark_len = g.period.to_uint() / 4 - 1; break;
                case 6: g.mark_len = g.period.to_uint() + 1; break;
                case 7: g.tbl_period = g.period.to_uint() + 8; break;
                case 8:  // count integrity: min_spacing <= max(glitch_n, 1) (DESIGN §4.2)
                    g.min_spacing = g.glitch_n.to_uint() < 1 ? 1u : g.glitch_n.to_uint();
                    break;
                case 9:  // valid, but the table in use does not fit: DAC range guard (clamp, dac_clip_st)
                    g.dac_width = 12;
                    g.amplitude = 2047;
                    break;
                default: g.period = static_cast<unsigned>(r.chance(2) ? 4104 : 260); break;  // and a change
            }
        } else if (bad_cfg_left > 0 && --bad_cfg_left == 0) {
            g = saved;  // back to the valid set (a period window also changes the period back)
        }
        if (bad_cfg_left == 0 && !loading) {
            // glitch_n / min_spacing stay legal here (min_spacing > max(glitch_n, 1)); the illegal
            // pair is one of the invalid-configuration windows above
            const auto spacing_floor = [&g] { return g.glitch_n.to_uint() < 1 ? 1u : g.glitch_n.to_uint(); };
            if (r.chance(3000)) {
                g.glitch_n = static_cast<unsigned>(r.range(0, 3));
                if (g.min_spacing.to_uint() <= spacing_floor()) g.min_spacing = spacing_floor() + 1;
            }
            if (r.chance(3000)) g.sw_debounce = static_cast<unsigned>(r.range(0, 12));
            if (r.chance(3000)) g.min_spacing = static_cast<unsigned>(r.range(spacing_floor() + 1, 6));
            if (r.chance(3000)) g.pace_m = static_cast<unsigned>(r.range(2, 4));
            if (r.chance(3000)) g.backlog_thr = static_cast<unsigned>(r.range(5, 400));
            if (r.chance(5000)) {
                const uint64_t base = lx::laserax_top_cfg::RATIO_DEFAULT;
                g.ratio = base - base / 20 + r.u() % (base / 10);  // +-5 %
            }
            if (r.chance(5000)) {  // thermal origin term, sometimes the register extremes
                const uint64_t ko = r.u() % 8;
                g.comp_offset = ko == 0 ? INT64_MIN : ko == 1 ? INT64_MAX
                                                            : static_cast<int64_t>(r.u() % (1ULL << 50)) - (int64_t(1) << 49);
            }
            if (r.chance(6000)) g.mark_len = static_cast<unsigned>(r.range(g.period.to_uint() / 4, g.period.to_uint()));
        }
        if (r.chance(700)) clear = true;
        if (r.chance(15000)) rehome = true;
        lx::axis_regs regs = g;
        // directed prologue: the count-integrity check min_spacing > max(glitch_n, 1) at its
        // corners (glitch_n at both ends, min_spacing around glitch_n and in both bytes), two
        // calls per pair, on top of the scenario's registers
        {
            static const unsigned kGn[] = {0, 1, 2, 254, 255};
            static const unsigned kMs[] = {0, 1, 2, 3, 253, 254, 255, 256, 257, 300, 511, 512, 65535};
            const long long nGn = sizeof kGn / sizeof kGn[0], nMs = sizeof kMs / sizeof kMs[0];
            if (k < 2 * nGn * nMs) {
                regs.glitch_n = kGn[(k / 2) % nGn];
                regs.min_spacing = kMs[(k / 2) / nGn];
            }
        }
        regs.rehome = rehome;
        regs.clear = clear;
        regs.tbl_we = we;
        regs.tbl_addr = addr;
        regs.tbl_data = data;

        // --- commit framing (own generator): comp_sync toggles now and then; while it is 1 the
        // ratio / comp_offset changes above act only at a comp_commit pulse, and a half-written
        // offset (low word only, this call) must have no effect at all
        if (mr.chance(20000)) csync = !csync;
        regs.comp_sync = csync;
        regs.comp_commit = mr.chance(1500);
        if (csync && !regs.comp_commit && mr.chance(400)) {
            const uint64_t cur = static_cast<uint64_t>(regs.comp_offset.to_int64());
            regs.comp_offset = static_cast<int64_t>((cur & ~uint64_t(0xFFFFFFFF)) | (mr.u() & 0xFFFFFFFFu));
        }

        // --- error map: table words into the inactive bank, flips, enables, new geometries ---
        if (mr.chance(mp.map_en ? 15000 : 1500)) mp.map_en = !mp.map_en;  // mostly enabled
        if (k == calls / 20) mp.map_en = true;
        if (mr.chance(2500)) mp.bank_sel = !mp.bank_sel;
        if (mr.chance(1500)) new_geom(mp.geom[mr.range(0, 1)]);
        mp.we = mr.chance(3);
        if (mp.we) {
            mp.addr = static_cast<unsigned>(mr.chance(50) ? mr.range(0, lx::error_map_cfg::TBL_DEPTH - 1) : mr.range(0, 299));
            const int64_t lim = mr.chance(30) ? (int64_t{1} << 23) - 1 : 3000;
            mp.data = mr.chance(400) ? (mr.chance(2) ? lim : -lim - 1) : mr.range(-lim, lim);
        }
        regs.emap = mp;
        // --- digital pins: any pin_cfg now and then (qz_window, ab_rot, hiz_alarm; DESIGN 4.7) ---
        if (mr.chance(3000)) pin_cfg = static_cast<unsigned>(mr.range(0, 15));
        regs.pin_cfg = pin_cfg;

        // --- motion on the pins ---
        if (seg_left-- <= 0) {
            // raw counts are ~8 output counts each and the pacer emits one per pace_m calls, so
            // most segments are slow; a few are fast (backlog and edge-spacing alarms)
            seg_left = r.range(300, 6000);
            dir = r.chance(2) ? 1 : -1;
            spacing = r.range(20, 60);
            if (r.chance(10)) {
                spacing = r.range(1, 3);
                seg_left = r.range(50, 400);
            }
            if (r.chance(6)) spacing = 1000000;  // stand still
            if (wait > spacing) wait = spacing;
        }
        {
            // stay within reach of the switch (enough to home at the current period)
            const int64_t reach = 40 + 2 * cur_period / 8;
            if (n > sw_pos + reach) dir = -1;
            if (n < sw_pos - reach) dir = 1;
        }
        if (wait-- <= 0) {
            n += dir;
            wait = spacing;
        }
        if (r.chance(5000)) n += 2;  // illegal transition
        bool a = false, b = false;
        {
            const int i = static_cast<int>(((n % 4) + 4) % 4);
            a = i == 1 || i == 2;
            b = i == 2 || i == 3;
        }
        if (glitch_left == 0 && r.chance(400)) glitch_left = static_cast<int>(r.range(1, 3));
        if (glitch_left > 0) {
            if (r.chance(2)) a = !a; else b = !b;
            --glitch_left;
        }
        if (lerr_left == 0 && r.chance(15000)) lerr_left = static_cast<int>(r.range(1, 60));
        const bool lerr = lerr_left > 0;
        if (lerr_left > 0) --lerr_left;
        if (r.chance(15000)) cam_low = !cam_low;  // the switch closes below the cam: homing backwards
        bool sw = cam_low ? n <= sw_pos : n >= sw_pos;
        if (n >= sw_pos - 2 && n <= sw_pos + 2 && r.chance(3)) sw = !sw;  // contact bounce

        lx::axis_pins p;
        p.a = a;
        p.b = b;
        p.sw = sw;
        p.lerr = lerr;
        const lx::axis_out o = core.step(p, regs);
        t.rows.push_back({i64(a), i64(b), i64(sw), i64(lerr), static_cast<int64_t>(regs.period.to_uint64()),
                          static_cast<int64_t>(regs.ratio.to_uint64()), regs.comp_offset.to_int64(), i64(regs.comp_sync),
                          i64(regs.comp_commit),
                          static_cast<int64_t>(regs.glitch_n.to_uint64()),
                          static_cast<int64_t>(regs.sw_debounce.to_uint64()),
                          static_cast<int64_t>(regs.min_spacing.to_uint64()), static_cast<int64_t>(regs.pace_m.to_uint64()),
                          static_cast<int64_t>(regs.backlog_thr.to_uint64()), static_cast<int64_t>(regs.mark_len.to_uint64()),
                          static_cast<int64_t>(regs.dac_width.to_uint64()), static_cast<int64_t>(regs.amplitude.to_uint64()),
                          static_cast<int64_t>(regs.tbl_period.to_uint64()), i64(regs.rehome), i64(regs.clear),
                          i64(regs.tbl_we), static_cast<int64_t>(regs.tbl_addr.to_uint64()),
                          static_cast<int64_t>(regs.tbl_data.to_uint64()), i64(regs.emap.map_en),
                          i64(regs.emap.bank_sel), regs.emap.geom[0].origin.to_int64(),
                          static_cast<int64_t>(regs.emap.geom[0].spacing_log2.to_uint64()),
                          static_cast<int64_t>(regs.emap.geom[0].n_points.to_uint64()), regs.emap.geom[1].origin.to_int64(),
                          static_cast<int64_t>(regs.emap.geom[1].spacing_log2.to_uint64()),
                          static_cast<int64_t>(regs.emap.geom[1].n_points.to_uint64()), i64(regs.emap.we),
                          static_cast<int64_t>(regs.emap.addr.to_uint64()), regs.emap.data.to_int64(),
                          static_cast<int64_t>(regs.pin_cfg.to_uint64()),
                          o.sin.to_int64(), o.cos.to_int64(), i64(o.ref_mark), i64(o.qa), i64(o.qb), i64(o.qz),
                          i64(o.q_oe),
                          i64(o.cfg_err), static_cast<int64_t>(o.stage.to_uint64()), i64(o.homed), i64(o.lerr_alarm),
                          i64(o.illegal_st), static_cast<int64_t>(o.err_cnt.to_uint64()), i64(o.ovs_edge_st),
                          i64(o.ovs_backlog_st), i64(o.glitch_st), i64(o.alarm), o.raw_count.to_int64(),
                          o.comp_pos.to_int64(), o.paced_pos.to_int64(), o.out_pos.to_int64(),
                          static_cast<int64_t>(o.d.to_uint64()), o.step.to_int64(), o.delta.to_int64(),
                          o.backlog.to_int64(), o.pstep.to_int64(), o.ostep.to_int64(), o.adj.to_int64(),
                          o.a_pos.to_int64(), o.b_pos.to_int64(), o.c_pos.to_int64(), o.z_pos.to_int64(),
                          i64(o.rep_mark), i64(o.map_cfg_err), o.corr.to_int64(), o.map_delta.to_int64()});
    }
    return t;
}

// ---- blocks ---------------------------------------------------------------------------------

vec_table filter_stress(rng_t& r, long long calls) {
    vec_table t{"input_filter_stress", lxt::vec_layout("input_filter"), {}};
    lx::input_filter<8> f;
    bool pin = false;
    long long run = 0;
    unsigned n = 2;
    for (long long k = 0; k < calls; ++k) {
        if (run-- <= 0) {
            pin = !pin;
            run = r.chance(3) ? r.range(0, 3) : r.range(1, 14);
        }
        if (r.chance(800)) n = static_cast<unsigned>(r.chance(10) ? r.range(9, 255) : r.range(0, 8));
        const lx::input_filter<8>::out_t o = f.step(pin, n);
        t.rows.push_back({i64(pin), n, i64(o.f), i64(o.valid), i64(o.glitch)});
    }
    return t;
}

vec_table decoder_stress(rng_t& r, long long calls) {
    vec_table t{"quad_decoder_stress", lxt::vec_layout("quad_decoder"), {}};
    lx::quad_decoder d;
    int64_t n = 0;
    int dir = 1;
    long long wait = 0, spacing = 3;
    unsigned gn = 1, ms = 3;
    bool lerr = false;
    for (long long k = 0; k < calls; ++k) {
        if (r.chance(500)) dir = -dir;
        if (r.chance(300)) spacing = r.chance(3) ? 0 : r.range(1, 8);
        if (wait-- <= 0) {
            n += dir;
            wait = spacing;
        }
        if (r.chance(700)) n += 2;
        if (r.chance(900)) gn = static_cast<unsigned>(r.range(0, 4));
        if (r.chance(900)) ms = static_cast<unsigned>(r.range(0, 9));
        if (r.chance(400)) lerr = !lerr;
        const int i = static_cast<int>(((n % 4) + 4) % 4);
        bool a = i == 1 || i == 2, b = i == 2 || i == 3;
        if (r.chance(150)) a = !a;
        if (r.chance(150)) b = !b;
        const bool clear = r.chance(60);
        const lx::quad_decoder::out_t o = d.step(a, b, lerr, gn, ms, clear);
        t.rows.push_back({i64(a), i64(b), i64(lerr), gn, ms, i64(clear), o.step.to_int64(), o.raw_count.to_int64(),
                          i64(o.illegal), i64(o.ovs), static_cast<int64_t>(o.err_cnt.to_uint64()), i64(o.illegal_st),
                          i64(o.ovs_st), i64(o.lerr), i64(o.lerr_alarm), i64(o.glitch_st)});
    }
    return t;
}

vec_table multiplier_stress(rng_t& r, long long calls) {
    vec_table t{"pulse_multiplier_stress", lxt::vec_layout("pulse_multiplier"), {}};
    lx::pulse_multiplier m;
    uint64_t ratio = lx::laserax_top_cfg::RATIO_DEFAULT;
    int64_t off = 0;
    int dir = 1;
    for (long long k = 0; k < calls; ++k) {
        bool preset = false;
        int64_t pn = 0;
        if (r.chance(700)) {
            preset = true;
            const int64_t edge = r.chance(2) ? 2147483647LL : -2147483648LL;
            pn = edge - (edge > 0 ? r.range(0, 40) : -r.range(0, 40));
            dir = edge > 0 ? 1 : -1;  // run towards the wrap
            if (r.chance(5)) pn = static_cast<int64_t>(static_cast<int32_t>(r.u()));
        }
        if (r.chance(400)) ratio = (r.u() & ((1ULL << 37) - 1));
        if (r.chance(400)) ratio = lx::laserax_top_cfg::RATIO_DEFAULT + (r.u() % 1000000ULL);
        if (r.chance(300)) {
            const uint64_t ko = r.u() % 6;
            off = ko == 0 ? INT64_MIN : ko == 1 ? INT64_MAX : ko == 2 ? static_cast<int64_t>(r.u())
                                                                  : static_cast<int64_t>(r.u() % (1ULL << 56)) - (int64_t(1) << 55);
        }
        if (r.chance(200)) dir = -dir;
        int st = r.chance(3) ? 0 : dir;
        if (r.chance(50)) st = -st;
        if (preset) m.preset(lx::raw_t(pn), lx::ratio_t(ratio), lx::offset_t(off));
        const lx::pulse_multiplier::out_t o = m.step(lx::step_t(st), lx::ratio_t(ratio), lx::offset_t(off));
        t.rows.push_back({st, static_cast<int64_t>(ratio), off, i64(preset), pn, o.comp.to_int64(), o.delta.to_int64()});
    }
    return t;
}

vec_table pacer_stress(rng_t& r, long long calls) {
    vec_table t{"output_pacer_stress", lxt::vec_layout("output_pacer"), {}};
    lx::output_pacer p;
    unsigned m = 3;
    uint64_t thr = 20;
    bool wide = false;
    for (long long k = 0; k < calls; ++k) {
        if (r.chance(300)) wide = !wide;  // rephase's window (stage 2): a slot after each count
        int64_t delta = 0;
        if (r.chance(4)) delta = r.range(-1, 1);
        if (r.chance(500)) delta = r.range(-60, 60);
        if (r.chance(5000)) delta = r.range(-(1LL << 37), (1LL << 37));
        if (r.chance(700)) m = static_cast<unsigned>(r.chance(8) ? r.range(0, 1) : r.range(2, 7));
        if (r.chance(700)) thr = static_cast<uint64_t>(r.chance(10) ? static_cast<int64_t>(r.u() & 0xffffffffULL) : r.range(0, 60));
        const bool clear = r.chance(40);
        const lx::output_pacer::out_t o = p.step(lx::delta_t(delta), 0, m, static_cast<uint32_t>(thr), clear, wide);
        t.rows.push_back({delta, m, static_cast<int64_t>(thr), i64(clear), i64(wide), o.pstep.to_int64(), i64(o.slot),
                          o.paced.to_int64(),
                          o.backlog.to_int64(), i64(o.ovs), i64(o.ovs_st)});
    }
    return t;
}

vec_table rephase_stress(rng_t& r, long long calls) {
    vec_table t{"rephase_stress", lxt::vec_layout("rephase"), {}};
    lx::rephase rp;
    int64_t pos = 0, sw_pos = 40;
    int dir = 1;
    long long gap = 0, slot_in = -1;
    unsigned period = 64, mark_len = 16;
    bool sw_valid = false, unhome = false;
    for (long long k = 0; k < calls; ++k) {
        if (k > 3) sw_valid = true;
        if (r.chance(600)) dir = -dir;
        if (pos > sw_pos + 3 * static_cast<int64_t>(period)) dir = -1;
        if (pos < sw_pos - 3 * static_cast<int64_t>(period)) dir = 1;
        int ps = 0;
        bool slot = false;
        if (gap-- <= 0) {
            ps = dir;
            pos += dir;
            gap = r.range(1, 4);  // real counts >= 2 calls apart, as the pacer guarantees
            slot_in = r.range(1, gap);  // and a slot after each, before the next count
        } else if (--slot_in == 0) {
            slot = true;
        }
        if (r.chance(2000)) slot = !slot;  // out of contract now and then: hls and rtl_ref alike
        if (r.chance(4000)) {
            period = static_cast<unsigned>(kPresets[r.range(0, 8)]);
            if (period > 1280) period = 1280;  // keep the homing window short enough to finish
            mark_len = static_cast<unsigned>(r.range(period / 4, period));
            sw_pos = pos + (r.chance(2) ? 5 : -5);
        }
        if (r.chance(3000)) mark_len = static_cast<unsigned>(r.range(period / 4, period));
        if (r.chance(2500)) unhome = !unhome;
        if (unhome && r.chance(50)) unhome = false;
        bool sw = pos >= sw_pos;
        if (r.chance(700)) sw = !sw;
        const bool rehome = r.chance(3000);
        const lx::rephase::out_t o = rp.step(lx::step_t(ps), slot, sw, sw_valid, rehome, unhome, period, mark_len);
        t.rows.push_back({ps, i64(slot), i64(sw), i64(sw_valid), i64(rehome), i64(unhome), period, mark_len, o.ostep.to_int64(),
                          o.out_pos.to_int64(), i64(o.mark), i64(o.index), static_cast<int64_t>(o.stage.to_uint64()), o.a.to_int64(),
                          static_cast<int64_t>(o.d.to_uint64()), o.b.to_int64(), o.c.to_int64(), o.z.to_int64(),
                          o.adj.to_int64(), i64(o.homed)});
    }
    return t;
}

vec_table dds_stress(rng_t& r, long long calls) {
    vec_table t{"dds_sincos_stress", lxt::vec_layout("dds_sincos"), {}};
    lx::dds_sincos d;  // power-up table: P = 256, amp = 32767
    // periods only grow, so the offset r always stays below the new quarter (no reset here)
    const int periods[] = {256, 320, 512, 640, 1280, 4096};
    size_t pi = 0;
    unsigned period = 256, amp = 32767;
    std::vector<uint32_t> load;
    size_t load_pos = 0;
    unsigned next_amp = amp;
    int dir = 1;
    for (long long k = 0; k < calls; ++k) {
        bool we = false;
        unsigned addr = 0, data = 0;
        if (load_pos < load.size()) {
            we = true;
            addr = static_cast<unsigned>(load_pos);
            data = load[load_pos];
            ++load_pos;
            if (load_pos == load.size()) {
                period = static_cast<unsigned>(periods[pi]);
                amp = next_amp;
            }
        } else if (k > 2000 && pi + 1 < sizeof periods / sizeof periods[0] && r.chance(static_cast<uint64_t>(calls / 8))) {
            ++pi;
            next_amp = r.chance(2) ? static_cast<unsigned>(r.range(1, 131071)) : 32767u;
            load = lxt::dds_table(periods[pi], static_cast<int>(next_amp));
            load_pos = 0;
        } else if (r.chance(300)) {
            we = true;  // stray write; may hit the address read in this call
            addr = static_cast<unsigned>(r.range(0, static_cast<int64_t>(period / 4) - 1));
            data = static_cast<unsigned>(r.u() & 0x1ffff);
        }
        if (r.chance(300)) dir = -dir;
        const int os = r.chance(3) ? 0 : dir;
        if (we) d.write(addr, data);
        const lx::dds_sincos::out_t o = d.step(lx::step_t(os), period, amp);
        t.rows.push_back({os, period, amp, i64(we), addr, data, o.sin.to_int64(), o.cos.to_int64()});
    }
    return t;
}

// ---- error_map ------------------------------------------------------------------------------
// Both banks are written in full first (the RTL RAM has no power-up contents, the C++ tables start
// at 0: no call may be active on a word that was never written), then every spacing k = 4..20 is
// swept in turn, then random operation. Every call is one row; expected columns from hls/.
//   A  bank 0 selected and inactive (homed 0, map_en 0 or an invalid geometry: cfg_err) while all
//      TBL_DEPTH words of bank 1 are written
//   B  bank 1 active (random valid geometry), positions sweeping across and beyond its table,
//      while all TBL_DEPTH words of bank 0 (the inactive bank) are written
//   C  k = 4..20 in turn, alternating banks: a new geometry (n = 2, TBL_DEPTH or random) for the
//      inactive bank, a few words into it, the flip, a sweep from below the table to both ends
//      (exactly) and beyond, and back
//   E  16 flips, each at another phase of the sample period, each followed at once by writes of
//      new values into the words around the parked position in the bank the flip releases
//   D  random: reloads of the inactive bank (random geometry, invalid 1 in 6; table kinds: smooth
//      walk, full-range noise, alternating extremes, constant) followed by a flip (1 in 3 of the
//      next reloads start within 30 calls of it, into the bank just released), stray writes,
//      motion at 0 .. 4 points per call with reversals, dwells and jumps (38-bit extremes
//      included) over both table ends, map_en and homed toggles and pulses, changes of the
//      selected bank's origin while active
struct map_host {
    lx::error_map_regs r;
    int64_t p = 0;
    bool homed = false;
};

int64_t map_span(const lx::error_map_geom& g) {
    return lx::error_map_geom_ok(g) ? static_cast<int64_t>(g.n_points.to_uint() - 1) << g.spacing_log2.to_uint() : 0;
}

vec_table error_map_stress(rng_t& r, long long calls) {
    using C = lx::error_map_cfg;
    vec_table t{"error_map_stress", lxt::vec_layout("error_map"), {}};
    const int64_t wmax = (int64_t{1} << 23) - 1, wmin = -(int64_t{1} << 23);
    const int64_t pmax = (int64_t{1} << 37) - 1, pmin = -(int64_t{1} << 37);
    lx::error_map m;
    map_host h;
    const size_t end = static_cast<size_t>(calls);
    // pending words for the inactive bank (one per call; a call may skip)
    std::vector<std::pair<unsigned, int64_t>> wq;
    size_t wq_pos = 0;
    int skip_one_in = 0;  // 0: a word every call, else skip with probability 1/skip_one_in
    auto call = [&]() {
        if (t.rows.size() >= end) return;
        lx::error_map_regs c = h.r;
        c.we = false;
        if (wq_pos < wq.size() && (skip_one_in == 0 || !r.chance(static_cast<uint64_t>(skip_one_in)))) {
            c.we = true;
            c.addr = wq[wq_pos].first;
            c.data = wq[wq_pos].second;
            ++wq_pos;
        } else if (r.chance(40)) {  // a stray write into the inactive bank
            c.we = true;
            c.addr = static_cast<unsigned>(r.range(0, C::TBL_DEPTH - 1));
            c.data = r.chance(8) ? (r.chance(2) ? wmax : wmin) : r.range(wmin, wmax);
        }
        if (h.p > pmax) h.p = pmax;
        if (h.p < pmin) h.p = pmin;
        const lx::error_map::out_t o = m.step(lx::pos_t(h.p), h.homed, c);
        t.rows.push_back({h.p, i64(h.homed), i64(c.map_en), i64(c.bank_sel), c.geom[0].origin.to_int64(),
                          static_cast<int64_t>(c.geom[0].spacing_log2.to_uint64()),
                          static_cast<int64_t>(c.geom[0].n_points.to_uint64()), c.geom[1].origin.to_int64(),
                          static_cast<int64_t>(c.geom[1].spacing_log2.to_uint64()),
                          static_cast<int64_t>(c.geom[1].n_points.to_uint64()), i64(c.we),
                          static_cast<int64_t>(c.addr.to_uint64()), c.data.to_int64(), o.corr.to_int64(),
                          o.delta.to_int64(), i64(o.active), i64(o.in_range), i64(o.clamped), i64(o.cfg_err)});
    };
    auto done = [&]() { return t.rows.size() >= end; };
    auto go = [&](int64_t target, int64_t speed) {  // lands on target exactly
        if (target > pmax) target = pmax;
        if (target < pmin) target = pmin;
        while (h.p != target && !done()) {
            const int64_t d = target - h.p;
            h.p += d > speed ? speed : (d < -speed ? -speed : d);
            call();
        }
    };
    // table words of one kind: 0 smooth walk, 1 full-range noise, 2 alternating extremes, 3 constant
    auto words = [&](int kind, size_t n) {
        std::vector<int64_t> w(n);
        const int64_t slope = int64_t{1} << r.range(2, 20);
        int64_t v = r.range(wmin / 2, wmax / 2);
        const bool start = r.chance(2);
        const int64_t cst = r.range(wmin, wmax);
        for (size_t i = 0; i < n; ++i) {
            if (kind == 0) {
                v += r.range(-slope, slope);
                v = v < wmin ? wmin : (v > wmax ? wmax : v);
                w[i] = v;
            } else if (kind == 1) {
                w[i] = r.range(wmin, wmax);
            } else if (kind == 2) {
                w[i] = ((i & 1) != 0) == start ? wmax : wmin;
            } else {
                w[i] = cst;
            }
            if (r.chance(60)) w[i] = r.chance(2) ? wmax : wmin;
        }
        return w;
    };
    auto queue_all = [&](const std::vector<int64_t>& w, size_t first) {
        wq.clear();
        wq_pos = 0;
        for (size_t i = 0; i < w.size(); ++i) wq.push_back({static_cast<unsigned>(first + i), w[i]});
    };
    auto valid_geom = [&](int k, int n) {
        lx::error_map_geom g;
        g.spacing_log2 = static_cast<unsigned>(k);
        g.n_points = static_cast<unsigned>(n);
        g.origin = h.p + r.range(-(int64_t{1} << (k + 3)), int64_t{1} << (k + 3));
        return g;
    };
    auto random_n = [&]() -> int {
        const int64_t c = r.range(0, 7);
        return static_cast<int>(c < 2   ? 2
                                : c < 4 ? C::TBL_DEPTH
                                : c < 6 ? r.range(3, 40)
                                        : r.range(41, C::TBL_DEPTH - 1));
    };
    auto bad_geom = [&](lx::error_map_geom& g) {
        switch (r.range(0, 3)) {
            case 0: g.spacing_log2 = static_cast<unsigned>(r.range(0, C::K_MIN - 1)); break;
            case 1: g.spacing_log2 = static_cast<unsigned>(r.range(C::K_MAX + 1, 31)); break;
            case 2: g.n_points = static_cast<unsigned>(r.range(0, 1)); break;
            default: g.n_points = static_cast<unsigned>(r.range(C::TBL_DEPTH + 1, (1 << C::W_N) - 1)); break;
        }
    };
    // a sweep of the selected bank's table: from below it to both ends (exactly), beyond, back
    auto sweep = [&](int64_t calls_per_span) {
        const lx::error_map_geom& g = h.r.geom[h.r.bank_sel ? 1 : 0];
        const int64_t o = g.origin.to_int64(), span = map_span(g), s = int64_t{1} << g.spacing_log2.to_uint();
        const int64_t speed = 1 + span / calls_per_span;
        go(o - r.range(1, 3 * s), speed);
        go(o, speed);
        go(o + span, speed);
        go(o + span + r.range(1, 3 * s), speed);
        go(o + r.range(0, span), speed);
    };

    // A: bank 0 selected and inactive while bank 1 is written in full
    h.r.bank_sel = false;
    queue_all(words(static_cast<int>(r.range(0, 3)), C::TBL_DEPTH), 0);
    while (wq_pos < wq.size() && !done()) {
        if (r.chance(150)) {  // one reason to be inactive, changed now and then
            h.homed = r.chance(2);
            h.r.map_en = !h.homed || r.chance(2);
            h.r.geom[0] = valid_geom(static_cast<int>(r.range(4, 20)), random_n());
            if (h.homed || r.chance(2)) bad_geom(h.r.geom[0]);
            if (h.homed && h.r.map_en && lx::error_map_geom_ok(h.r.geom[0])) h.r.map_en = false;
        }
        h.p += r.range(-50, 50);
        call();
    }
    // B: bank 1 active and swept while bank 0 is written in full
    h.r.geom[1] = valid_geom(static_cast<int>(r.range(4, 12)), C::TBL_DEPTH);
    h.r.geom[1].origin = h.p - 100;
    h.r.bank_sel = true;
    h.r.map_en = true;
    h.homed = true;
    queue_all(words(static_cast<int>(r.range(0, 3)), C::TBL_DEPTH), 0);
    while (wq_pos < wq.size() && !done()) sweep(r.range(100, 600));
    // C: every spacing, alternating banks
    for (int k = C::K_MIN; k <= C::K_MAX && !done(); ++k) {
        const int nb = h.r.bank_sel ? 0 : 1;  // the inactive bank
        const int n = k % 3 == 0 ? 2 : k % 3 == 1 ? C::TBL_DEPTH : static_cast<int>(r.range(3, C::TBL_DEPTH - 1));
        h.r.geom[nb] = valid_geom(k, n);
        const std::vector<int64_t> w = words(static_cast<int>(r.range(0, 3)), static_cast<size_t>(r.range(2, 40)));
        queue_all(w, static_cast<size_t>(r.range(0, n - 1)) % static_cast<size_t>(C::TBL_DEPTH - w.size()));
        while (wq_pos < wq.size() && !done()) {
            h.p += r.range(-20, 20);
            call();
        }
        h.r.bank_sel = nb == 1;
        call();
        sweep(r.range(20, 80));
        sweep(r.range(20, 80));
    }
    // E: a flip, then at once a reload of the bank it releases, at the words the samples taken
    //    before the flip still read (position parked inside that table; the flip in each phase
    //    of the sample period in turn): the write port's delay must outlast those samples
    h.r.map_en = true;
    h.homed = true;
    for (int j = 0; j < 16 && !done(); ++j) {
        const int cb = h.r.bank_sel ? 1 : 0;  // the active bank, released by the flip below
        const lx::error_map_geom& g = h.r.geom[cb];
        if (!lx::error_map_geom_ok(g)) {
            h.r.bank_sel = !h.r.bank_sel;  // C left a valid table in one of the banks
            continue;
        }
        const int64_t o = g.origin.to_int64();
        const int ks = static_cast<int>(g.spacing_log2.to_uint()), n = static_cast<int>(g.n_points.to_uint());
        const int64_t i = r.range(0, n - 2);
        go(o + (i << ks) + r.range(1, (int64_t{1} << ks) - 1), int64_t{1} << ks);
        for (int c = 0; c < 90 && !done(); ++c) call();      // settled on the active table
        for (int c = 0; c < 2 * j + (j % 3) && !done(); ++c) call();  // another phase each time
        h.r.bank_sel = !h.r.bank_sel;
        wq.clear();
        wq_pos = 0;
        for (int64_t a = i - 2; a <= i + 3; ++a)
            if (a >= 0 && a < n) wq.push_back({static_cast<unsigned>(a), r.range(wmin, wmax)});
        for (int c = 0; c < 100 && !done(); ++c) call();
        h.r.bank_sel = !h.r.bank_sel;  // back to the reloaded table for the next round
        for (int c = 0; c < 10 && !done(); ++c) call();
    }
    // D: random operation
    skip_one_in = 4;
    long long idle = r.range(50, 400), seg_left = 0, dwell = 0;
    int64_t target = h.p, speed = 1;
    while (!done()) {
        // host: reload of the inactive bank, then the flip
        if (wq_pos >= wq.size() && idle > 0 && --idle == 0) {
            const int nb = h.r.bank_sel ? 0 : 1;
            const int n = random_n();
            h.r.geom[nb] = valid_geom(static_cast<int>(r.range(C::K_MIN, C::K_MAX)), n);
            if (r.chance(6)) bad_geom(h.r.geom[nb]);
            const size_t cnt = static_cast<size_t>(r.range(1, n < 300 ? n : 300));
            queue_all(words(static_cast<int>(r.range(0, 3)), cnt),
                      static_cast<size_t>(r.range(0, C::TBL_DEPTH - static_cast<int64_t>(cnt))));
            if (r.chance(2)) wq.push_back({static_cast<unsigned>(n - 1), r.chance(2) ? wmax : wmin});  // last point
            idle = -r.range(1, 60);  // < 0: flip that many calls after the last word
        } else if (wq_pos >= wq.size() && idle < 0 && ++idle == 0) {
            h.r.bank_sel = !h.r.bank_sel;
            // the next reload: mostly much later, 1 in 3 within 30 calls, while the samples
            // taken before the flip still have to read the bank it releases (the write port's
            // delay must outlast them: ERROR_MAP.md §4)
            idle = r.chance(3) ? r.range(1, 30) : r.range(50, 700);
            seg_left = 0;  // new motion towards the new table
        }
        if (r.chance(1500)) h.r.map_en = !h.r.map_en;
        if (!h.r.map_en && r.chance(30)) h.r.map_en = true;  // mostly enabled, short pulses
        if (r.chance(1200)) h.homed = !h.homed;
        if (!h.homed && r.chance(30)) h.homed = true;
        const lx::error_map_geom& g = h.r.geom[h.r.bank_sel ? 1 : 0];
        if (r.chance(3000) && lx::error_map_geom_ok(g))  // the selected bank's origin moves while active
            h.r.geom[h.r.bank_sel ? 1 : 0].origin = g.origin.to_int64() + r.range(-300, 300);
        // motion
        if (seg_left-- <= 0) {
            const int64_t o = g.origin.to_int64(), span = map_span(g);
            const int64_t s = lx::error_map_geom_ok(g) ? int64_t{1} << g.spacing_log2.to_uint() : 16;
            const int64_t kind = r.range(0, 19);
            target = kind == 0 ? (r.chance(2) ? pmax : pmin)
                     : kind < 3 ? (r.chance(2) ? o : o + span)
                                : r.range(o - span / 4 - 3 * s, o + span + span / 4 + 3 * s);
            speed = r.chance(3) ? r.range(1, 3) : r.range(1, 4 * s);
            if (kind == 0) {
                h.p = target;  // a jump to a 38-bit extreme
            } else if (r.chance(60)) {
                h.p = r.range(pmin, pmax) / (r.chance(2) ? 1 : 1024);  // a jump
            } else if (h.p < o - 8 * (span + s) || h.p > o + 9 * (span + s)) {
                h.p = r.range(o - 4 * s, o + span + 4 * s);  // far away after a jump: back near the table
            }
            seg_left = kind == 0 ? r.range(1, 8) : r.range(20, 600);
            dwell = r.chance(5) ? r.range(1, 40) : 0;
        }
        if (dwell > 0) {
            --dwell;
            call();
        } else if (h.p == target) {
            call();
        } else {
            const int64_t d = target - h.p;
            h.p += d > speed ? speed : (d < -speed ? -speed : d);
            call();
        }
    }
    return t;
}


// ---- encoder_counter ------------------------------------------------------------------------
// Segments of 50..1500 calls; at each segment start every register is re-drawn (sources, rates,
// directions, scales, rst_on_trig, corr_period; one segment in 6 is short and has an invalid
// source, rate or period). Per call: quadrature steps (random walk with a per-channel probability, -2 one call in
// 2000), triggers, reset requests, presets next to the wrap or anywhere, wait arms (value behind,
// ahead, across the wrap, equal, 2^31 away), live corr_period changes, random positions. The first
// 16 calls are directed: a wait reached by a -2 step; on each channel a reset in the call of a
// simulation carry.
vec_table encoder_counter_stress(rng_t& r, long long calls) {
    using C = lx::encoder_counter_cfg;
    vec_table t{"encoder_counter_stress", lxt::vec_layout("encoder_counter"), {}};
    const int64_t kMax = 2147483647LL, kMin = -2147483648LL;
    lx::encoder_counter m;
    lx::encoder_counter_regs g;  // segment registers (pulses cleared)
    double prob[2] = {0.5, 0.5};
    int dir[2] = {1, -1};
    long long seg_end = 0;
    int64_t cnt[2] = {0, 0};  // outputs of the previous call
    auto wrap32 = [](int64_t v) { return static_cast<int64_t>(static_cast<int32_t>(static_cast<uint32_t>(v))); };
    auto draw_scale = [&]() -> int64_t {
        switch (r.range(0, 5)) {
            case 0: return kMin;
            case 1: return kMax;
            case 2: return 0;
            case 3: return r.range(-(int64_t{1} << 24), int64_t{1} << 24);
            default: return wrap32(static_cast<int64_t>(r.u())) >> r.range(0, 24);
        }
    };
    auto draw_period = [&]() -> int64_t {
        switch (r.range(0, 5)) {
            case 0: return C::CORR_LAT;
            case 1: return C::CORR_LAT + r.range(1, 3);
            case 2: return 1000;
            case 3: return r.range(C::CORR_LAT, 200);
            case 4: return r.chance(4) ? 65535 : r.range(C::CORR_LAT, 5000);
            default: return r.range(C::CORR_LAT, 100);
        }
    };
    for (long long n = 0; n < calls; ++n) {
        if (n >= seg_end) {
            seg_end = n + r.range(50, 1500);
            for (int c = 0; c < 2; ++c) {
                g.src[c] = r.chance(2) ? 1 : 0;
                switch (r.range(0, 4)) {
                    case 0: g.sim_inc[c] = C::SIM_INC_DEFAULT; break;
                    case 1: g.sim_inc[c] = C::SIM_INC_MAX; break;
                    case 2: g.sim_inc[c] = static_cast<uint64_t>(r.range(0, static_cast<int64_t>(C::SIM_INC_MAX))); break;
                    case 3: g.sim_inc[c] = C::SIM_INC_MAX + 1 + r.u() % 3000000000ULL; break;  // legal on src 0 only
                    default: g.sim_inc[c] = static_cast<uint64_t>(r.range(0, 1 << 24)); break;
                }
                if (g.src[c] == 1 && g.sim_inc[c] > C::SIM_INC_MAX) g.sim_inc[c] = C::SIM_INC_MAX - static_cast<uint64_t>(r.range(0, 5));
                g.sim_down[c] = r.chance(2);
                g.scale[c] = draw_scale();
                prob[c] = r.chance(3) ? 1.0 : static_cast<double>(r.range(0, 1000)) / 1000.0;
            }
            g.rst_on_trig = r.chance(2);
            g.corr_period = static_cast<uint64_t>(draw_period());
            if (r.chance(6)) {  // an invalid segment, short
                seg_end = n + r.range(1, 60);
                switch (r.range(0, 3)) {
                    case 0: g.src[r.range(0, 1)] = static_cast<uint64_t>(r.range(2, 3)); break;
                    case 1: {
                        const int c = static_cast<int>(r.range(0, 1));
                        g.src[c] = 1;
                        g.sim_inc[c] = C::SIM_INC_MAX + 1 + (r.chance(2) ? 0 : r.u() % 1000000ULL);
                        break;
                    }
                    case 2: g.corr_period = static_cast<uint64_t>(r.range(0, C::CORR_LAT - 1)); break;
                    default: g.corr_period = 0; break;
                }
            }
        }
        lx::encoder_counter_regs x = g;
        lx::encoder_counter_in in{};
        for (int c = 0; c < 2; ++c) {
            if (r.chance(3000)) dir[c] = -dir[c];
            const bool stepping = static_cast<double>(r.u() % 1000000) < prob[c] * 1000000.0;
            in.qstep[c] = r.chance(2000) ? -2 : stepping ? dir[c] : 0;
            in.pos[c] = r.chance(8) ? (r.chance(2) ? kMax : kMin) : wrap32(static_cast<int64_t>(r.u()));
            x.rst_req[c] = r.chance(700);
            x.load[c] = r.chance(500);
            if (x.load[c]) {
                switch (r.range(0, 3)) {
                    case 0: x.load_val[c] = kMax - r.range(0, 60); break;
                    case 1: x.load_val[c] = kMin + r.range(0, 60); break;
                    case 2: x.load_val[c] = r.chance(2) ? kMax : kMin; break;
                    default: x.load_val[c] = wrap32(static_cast<int64_t>(r.u())); break;
                }
            } else {
                x.load_val[c] = r.chance(4) ? wrap32(static_cast<int64_t>(r.u())) : 0;
            }
        }
        in.trig = r.chance(120);
        if (r.chance(400)) x.rst_on_trig = !g.rst_on_trig;  // a one-call change
        if (r.chance(1500)) g.corr_period = static_cast<uint64_t>(draw_period());  // live change
        x.corr_period = g.corr_period;
        x.wait_arm = r.chance(150);
        x.wait_ch = r.chance(2);
        x.wait_down = r.chance(2);
        const int64_t cw = cnt[x.wait_ch ? 1 : 0];
        switch (r.range(0, 6)) {
            case 0: x.wait_val = wrap32(cw + r.range(-50, 50)); break;
            case 1: x.wait_val = wrap32(cw + (x.wait_down ? -1 : 1) * r.range(1, 3000)); break;
            case 2: x.wait_val = r.chance(2) ? kMax - r.range(0, 300) : kMin + r.range(0, 300); break;
            case 3: x.wait_val = cw; break;
            case 4: x.wait_val = wrap32(cw + (int64_t{1} << 31)); break;
            case 5: x.wait_val = r.chance(2) ? kMax : kMin; break;
            default: x.wait_val = wrap32(static_cast<int64_t>(r.u())); break;
        }
        if (n < 8) {  // directed prologue: a -2 step onto val + 1 then past val (wait down)
            x = lx::encoder_counter_regs{};
            in = lx::encoder_counter_in{};
            x.load[0] = n == 0;
            x.load_val[0] = 11;
            x.wait_arm = n == 1;
            x.wait_val = 8;
            x.wait_down = true;
            in.qstep[0] = (n >= 2 && n < 5) ? -2 : 0;  // 11 -> 9 -> 7 (reached) -> 5
            // channel 1 simulated at 2^30 (a carry every 4 calls): a reset in the carry call (3)
            // drops that carry (no count in call 4)
            x.src[1] = 1;
            x.sim_inc[1] = C::SIM_INC_MAX;
            x.rst_req[1] = n == 3;
        } else if (n < 16) {  // the same on channel 0: reset in call 8 (phase 0), carry call 12
            x = lx::encoder_counter_regs{};
            in = lx::encoder_counter_in{};
            x.src[0] = 1;
            x.sim_inc[0] = C::SIM_INC_MAX;
            x.rst_req[0] = n == 8 || n == 12;
        }
        const lx::encoder_counter::out_t o = m.step(in, x);
        cnt[0] = o.cnt[0].to_int64();
        cnt[1] = o.cnt[1].to_int64();
        t.rows.push_back({in.qstep[0].to_int64(), in.qstep[1].to_int64(), i64(in.trig), in.pos[0].to_int64(),
                          in.pos[1].to_int64(), static_cast<int64_t>(x.src[0].to_uint64()),
                          static_cast<int64_t>(x.src[1].to_uint64()), static_cast<int64_t>(x.sim_inc[0].to_uint64()),
                          static_cast<int64_t>(x.sim_inc[1].to_uint64()), i64(x.sim_down[0]), i64(x.sim_down[1]),
                          x.scale[0].to_int64(), x.scale[1].to_int64(), i64(x.rst_req[0]), i64(x.rst_req[1]),
                          i64(x.load[0]), i64(x.load[1]), x.load_val[0].to_int64(), x.load_val[1].to_int64(),
                          i64(x.rst_on_trig), static_cast<int64_t>(x.corr_period.to_uint64()), i64(x.wait_arm),
                          i64(x.wait_ch), x.wait_val.to_int64(), i64(x.wait_down), o.cnt[0].to_int64(),
                          o.cnt[1].to_int64(), o.step[0].to_int64(), o.step[1].to_int64(), i64(o.rst_done[0]),
                          i64(o.rst_done[1]), i64(o.rst_pending[0]), i64(o.rst_pending[1]), o.corr[0].to_int64(),
                          o.corr[1].to_int64(), i64(o.tick), i64(o.waiting), i64(o.reached), i64(o.cfg_err)});
    }
    return t;
}

// ---- pso --------------------------------------------------------------------------------------
// Segments of 30..2500 calls; at each segment start every register is re-drawn: tracking (any
// axis mask, K 1..16) or part-speed (rates up to 2^32 - 1: clamped, rate_over; INC_MAX and
// INC_MAX + 1), firing distance 4 counts exactly .. 200 counts with a random fraction, array
// mode (length 1..64, wrap or not, entries rewritten while disabled), pulse width 1..80, the
// window on any source with edges next to the current position, laser minimum period 0..300
// (freq_err; spacing_err in part-speed). One segment in 7 is short and invalid (K 0 or 17..31,
// distance or an entry below 4 counts, length 0 or 65..127, no axis, pulse width 0, low > high,
// source 3 without part-speed). Per call: steps of a random walk per axis (speed up to one count
// per call on every axis: fires two or three calls apart at small distances; reversals), enable
// drops of 1..3 calls, clears, live distance changes, array writes while running (to the entry
// of the next fire and the ones after it, too: the prefetch and RAM forwarding of the RTL,
// whose three read copies cover next(idx) .. next^3(idx) of the index two calls before; one
// segment in 3 writes there in half of its calls). The first 120
// calls are directed: an array run in part-speed with a spacing check, dropped for one call at
// idx != 0 while entry 0 is rewritten, then restarted (the first call of a run samples entry 0
// for the spacing check); again with entry 0 rewritten in the first call of the run. Calls
// 120..319: one count per call on x, an array of 3 entries without wrap (done, idx stays at the
// last entry), then emits exactly 4 calls apart with min_period 4 (not early) and 5 (freq_err).
// Calls 320..359: a 3D diagonal with K = 1 (sqrt3 per call) on an array of three 4-count entries
// without wrap: fires two or three calls apart (the closest possible) up to done, and the call
// after done would fire again.
// Calls 360..439: part-speed at INC_MAX with min_period 9 and the threshold exactly one 2^-32
// count below INC_MAX x 9 (flagged), then exactly equal (not flagged): the product's last bit.
// Calls 440..539: part-speed at INC_MAX, min_period 20 (4.8 counts), an array of 4 and 6 counts
// without wrap: the spacing samples after done keep the last threshold (6: not flagged; the
// fire that makes the array done takes none, entry 0 would be flagged). Calls 540..599: a 3D
// diagonal with K = 1 on an array of five distinct entries just above 4 counts with wrap: fires
// two or three calls apart, every index move picking a different entry (the prefetch's deepest
// read, next^3 of the index two calls before, after a move two calls apart). Calls 600..699: the
// same with an entry rewritten in every call (4 .. 4.05 counts, at every offset 0..4 from the
// index shown): writes presented with each of the three reads and forwarded into the thresholds. Calls
// 700..759: a tracking run on x with each kind of invalid configuration presented for one call
// in every sixth call (K 0, K 17, distance below 4 counts, length 0 and 65, no axis, pulse
// width 0, low > high, source 3 without part-speed, an array with an entry not written). Calls
// 760..899: one count per call on x with K = 1 on an array of four 4- or 5-count entries with
// wrap (fires 4 or 5 calls apart) and an entry rewritten in every call at offsets 0..3 from the
// index shown: writes presented in the call of an index move, forwarded into the thresholds of
// the fire after the next. Calls 900..999: one count per call on x, an array of four 8-count
// entries with wrap; from call 930 arr_en is off (the check then covers fire_dist) while the run
// keeps its array, and the entries are rewritten to 1 .. 1.75 counts: a fire every second call,
// never two in a row (docs/PSO_COUNTERS.md §2.7).
vec_table pso_stress(rng_t& r, long long calls) {
    using C = lx::pso_cfg;
    vec_table t{"pso_stress", lxt::vec_layout("pso"), {}};
    lx::pso m;
    golden::pso_regs g;  // segment registers (pulses cleared)
    double prob[3] = {0.5, 0.5, 0.5};
    int dir[3] = {1, 1, 1};
    int64_t pos[3] = {0, 0, 0};
    uint64_t inc = 0;
    long long seg_end = 0;
    int rewrite = 0;   // calls left of an array rewrite (enable low)
    int off = 0;       // calls left of an enable drop
    int64_t last_idx = 0;
    bool hammer = false;
    long long drop_call = -1;  // directed prologue: the first call from 60 on with idx != 0  // this segment writes the entries at idx .. idx + 2 in most calls
    long long repair_at = -1;  // a bad entry written while running is rewritten (>= 4 counts) in
    int repair_addr = 0;       //   this call or the first later call without a write
    auto draw_dist = [&]() -> uint64_t {
        switch (r.range(0, 4)) {
            case 0: return C::MIN_DIST;
            case 1: return C::MIN_DIST + static_cast<uint64_t>(r.range(1, 3));
            case 2: return (static_cast<uint64_t>(r.range(2, 4)) << 32) + (r.u() & 0xffffffffULL);
            default: return (static_cast<uint64_t>(r.range(2, 200)) << 32) + (r.u() & 0xffffffffULL);
        }
    };
    auto draw_inc = [&]() -> uint64_t {
        switch (r.range(0, 5)) {
            case 0: return C::INC_MAX;
            case 1: return C::INC_MAX + 1;
            case 2: return r.u() & 0xffffffffULL;
            case 3: return static_cast<uint64_t>(r.range(0, static_cast<int64_t>(C::INC_MAX)));
            default: return static_cast<uint64_t>(r.range(0, 1 << 28));
        }
    };
    for (long long n = 0; n < calls; ++n) {
        if (n >= seg_end) {
            seg_end = n + r.range(30, 2500);
            golden::pso_regs x;
            x.enable = !r.chance(10);
            x.part_speed = r.chance(2);
            x.axis_mask = static_cast<unsigned>(r.range(1, 7));
            x.win_k = r.chance(3) ? 16 : static_cast<int>(r.range(1, 16));
            x.fire_dist = draw_dist();
            x.arr_en = r.chance(3);
            x.arr_len = r.chance(5) ? 64 : r.chance(2) ? static_cast<int>(r.range(1, 8)) : static_cast<int>(r.range(1, 64));
            x.arr_wrap = r.chance(2);
            x.pulse_w = r.chance(4) ? 1 : static_cast<int>(r.range(1, 80));
            x.win_en = r.chance(2);
            x.win_src = static_cast<int>(r.range(0, x.part_speed ? 3 : 2));
            const int64_t c = x.win_src == 3 ? 0 : pos[x.win_src];
            x.win_low = c - r.range(-50, 400);
            x.win_high = x.win_low + r.range(0, 800);
            x.min_period = r.chance(3) ? 0 : static_cast<int>(r.range(1, 300));
            for (int a = 0; a < 3; ++a) {
                prob[a] = r.chance(4) ? 1.0 : static_cast<double>(r.range(0, 1000)) / 1000.0;
                if (r.chance(2)) dir[a] = -dir[a];
            }
            inc = draw_inc();
            hammer = r.chance(3);
            if (hammer && r.chance(2)) {  // fast 3D tracking with small entries: fires a call or two apart
                x.part_speed = false;
                x.axis_mask = 7;
                for (int a = 0; a < 3; ++a) prob[a] = 1.0;
            }
            if (r.chance(7)) {  // an invalid segment, short
                seg_end = n + r.range(1, 40);
                switch (r.range(0, 8)) {
                    case 0: x.win_k = r.chance(2) ? 0 : static_cast<int>(r.range(17, 31)); break;
                    case 1: x.arr_en = false; x.fire_dist = static_cast<uint64_t>(r.range(0, static_cast<int64_t>(C::MIN_DIST - 1))); break;
                    case 2: x.arr_en = true; x.arr_len = r.chance(2) ? 0 : static_cast<int>(r.range(65, 127)); break;
                    case 3: x.part_speed = false; x.axis_mask = 0; break;
                    case 4: x.pulse_w = 0; break;
                    case 5: x.win_en = true; x.win_high = x.win_low - r.range(1, 5); break;
                    case 6: x.win_en = true; x.part_speed = false; x.win_src = 3; break;
                    default: x.arr_en = true; x.arr_len = 64; break;  // an entry never written or below 2
                }
            }
            g = x;
            if (g.arr_en && g.arr_len >= 1 && g.arr_len <= 64 && !r.chance(4))
                rewrite = g.arr_len + 1;  // rewrite the used entries while disabled (one per call)
        }
        golden::pso_regs x = g;
        golden::pso_in in;
        // motion
        for (int a = 0; a < 3; ++a) {
            if (r.chance(400)) dir[a] = -dir[a];
            const bool stepping = static_cast<double>(r.u() % 1000000) < prob[a] * 1000000.0;
            in.step[a] = stepping ? dir[a] : 0;
            pos[a] += in.step[a];
            in.pos[a] = pos[a];
        }
        if (r.chance(300)) inc = draw_inc();
        in.ps_inc = inc;
        if (rewrite > 0) {  // enable low while the array is (re)written
            --rewrite;
            x.enable = false;
            if (rewrite < g.arr_len) {
                x.arr_we = true;
                x.arr_addr = rewrite;
                x.arr_data = r.chance(400) ? static_cast<uint64_t>(r.range(0, static_cast<int64_t>(C::MIN_DIST - 1)))
                                           : draw_dist();
            }
        } else {
            if (off == 0 && r.chance(700)) off = static_cast<int>(r.range(1, 3));
            if (off > 0) {
                --off;
                x.enable = false;
            }
            if (r.chance(hammer ? 2 : 50)) {  // a write while running: often the entry of the next fire or the one after
                x.arr_we = true;
                x.arr_addr = static_cast<int>(r.chance(2) ? (last_idx + r.range(0, 4)) % 64 : r.range(0, 63));
                x.arr_data = r.chance(30) ? static_cast<uint64_t>(r.range(0, static_cast<int64_t>(C::MIN_DIST - 1)))
                             : hammer    ? C::MIN_DIST + (r.u() & 0x1ffffffffULL)
                                         : draw_dist();
                if (x.arr_data < C::MIN_DIST) {  // bad: the run is invalid while the entry is in use
                    repair_addr = x.arr_addr;
                    repair_at = n + 1 + n % 24;  // (no draw)
                } else if (x.arr_addr == repair_addr) {
                    repair_at = -1;              // rewritten by the stream itself
                }
            } else if (repair_at >= 0 && n >= repair_at) {
                // the repair: a bad entry written while running makes 1..24 invalid calls, not
                // the rest of its segment (without it, which of these writes hit a used entry,
                // and so how many calls ran, moved with the model's index: 6782 of 30000 calls
                // invalid after the writes were widened to next^4, 2981 before)
                x.arr_we = true;
                x.arr_addr = repair_addr;
                x.arr_data = C::MIN_DIST + ((static_cast<uint64_t>(n) * 0x9e3779b9ULL) & 0xffffffffULL);
                repair_at = -1;
            }
            if (r.chance(800)) g.fire_dist = draw_dist();  // live change
            x.fire_dist = g.fire_dist;
            x.clear = r.chance(500);
        }
        if (n < 120) {  // directed prologue (see above)
            x = golden::pso_regs{};
            in.ps_inc = C::INC_MAX;
            x.part_speed = true;
            x.arr_en = true;
            x.arr_len = 3;
            x.arr_wrap = true;
            x.min_period = 20;   // 0.24 * 20 = 4.8 counts: entries below it are flagged
            x.pulse_w = 2;
            if (n < 3) {
                x.arr_we = true;
                x.arr_addr = static_cast<int>(n);
                x.arr_data = (4ULL << 32) + (static_cast<uint64_t>(n) << 30);  // 4, 4.25, 4.5 counts
            }
            if (drop_call < 0 && n >= 60 && last_idx != 0) drop_call = n;
            x.enable = n >= 3 && n != drop_call && n != 90;
            if (n == drop_call) {  // dropped at idx != 0; entry 0 rewritten in that call (6 counts: not
                            // flagged; entries 1, 2 would be)
                x.arr_we = true;
                x.arr_addr = 0;
                x.arr_data = 6ULL << 32;
            }
            if (n == 91) {  // first call of the next run: entry 0 rewritten in this call (4 counts: flagged)
                x.arr_we = true;
                x.arr_addr = 0;
                x.arr_data = 4ULL << 32;
            }
        }
        if (n >= 120 && n < 320) {  // directed: x moves one count per call
            x = golden::pso_regs{};
            in = golden::pso_in{};
            in.step[0] = 1;
            in.pos[0] = n;
            x.axis_mask = 1;
            x.pulse_w = 1;
            x.enable = n != 120 && n != 200 && n != 260;
            if (n < 200) {  // an array of 3 entries without wrap: done after the third fire
                x.arr_en = true;
                x.arr_len = 3;
                if (n < 123) {
                    x.arr_we = true;
                    x.arr_addr = static_cast<int>(n - 120);
                    x.arr_data = (n == 121 ? 5ULL << 32 : 4ULL << 32) + (n == 122 ? 0x80000000ULL : 0);
                }
            } else {  // emits exactly 4 calls apart: min_period 4 is not early, 5 is
                x.fire_dist = C::MIN_DIST;
                x.min_period = n < 260 ? 4 : 5;
            }
        }
        if (n >= 320 && n < 360) {  // directed: fires two or three calls apart (the closest) up to done
            x = golden::pso_regs{};
            in = golden::pso_in{};
            x.axis_mask = 7;
            x.win_k = 1;
            x.pulse_w = 1;
            x.arr_en = true;
            x.arr_len = 3;
            x.enable = n >= 324;
            if (n < 323) {
                x.arr_we = true;
                x.arr_addr = static_cast<int>(n - 320);
                x.arr_data = C::MIN_DIST;
            }
            for (int a = 0; a < 3; ++a) {
                in.step[a] = 1;
                in.pos[a] = n;
            }
        }
        if (n >= 360 && n < 440) {  // directed: the spacing compare at its boundary
            x = golden::pso_regs{};
            in = golden::pso_in{};
            in.ps_inc = C::INC_MAX;
            x.part_speed = true;
            x.min_period = 9;
            x.pulse_w = 1;
            x.enable = n != 360 && n != 400;
            x.fire_dist = C::INC_MAX * 9 - (n < 400 ? 1 : 0);
        }
        if (n >= 440 && n < 540) {  // directed: spacing samples after done
            x = golden::pso_regs{};
            in = golden::pso_in{};
            in.ps_inc = C::INC_MAX;
            x.part_speed = true;
            x.min_period = 20;
            x.pulse_w = 1;
            x.arr_en = true;
            x.arr_len = 2;
            x.enable = n >= 443;
            if (n < 442) {
                x.arr_we = true;
                x.arr_addr = static_cast<int>(n - 440);
                x.arr_data = (n == 440 ? 4ULL : 6ULL) << 32;
            }
        }
        // calls 540..699: a 3D diagonal with K = 1 on a wrapping array of five entries
        const auto diagonal_on_array5 = [&] {
            x = golden::pso_regs{};
            in = golden::pso_in{};
            x.axis_mask = 7;
            x.win_k = 1;
            x.pulse_w = 1;
            x.arr_en = true;
            x.arr_len = 5;
            x.arr_wrap = true;
            for (int a = 0; a < 3; ++a) {
                in.step[a] = 1;
                in.pos[a] = n;
            }
        };
        if (n >= 540 && n < 600) {  // directed: the closest fires (two or three calls apart) on distinct entries
            diagonal_on_array5();
            x.enable = n >= 546;
            if (n < 545) {
                x.arr_we = true;
                x.arr_addr = static_cast<int>(n - 540);
                x.arr_data = C::MIN_DIST + (static_cast<uint64_t>(n - 540) << 20);
            }
        }
        if (n >= 600 && n < 700) {  // directed: the closest fires while every call rewrites an entry
            diagonal_on_array5();
            x.enable = n >= 606;
            x.arr_we = n < 605 || n >= 608;
            x.arr_addr = static_cast<int>(n < 605 ? n - 600 : (last_idx + n % 5) % 5);
            x.arr_data = C::MIN_DIST + (static_cast<uint64_t>(n % 4) << 26);   // 4 .. 4.05 counts
        }
        if (n >= 760 && n < 900) {  // directed: fires 4 or 5 calls apart while every call rewrites an entry
            x = golden::pso_regs{};
            in = golden::pso_in{};
            x.axis_mask = 1;
            x.win_k = 1;
            x.pulse_w = 1;
            x.arr_en = true;
            x.arr_len = 4;
            x.arr_wrap = true;
            in.step[0] = 1;
            in.pos[0] = n;
            x.enable = n >= 766;
            x.arr_we = true;
            const uint64_t h = (static_cast<uint64_t>(n) * 2654435761ULL) >> 9;   // (no draw)
            x.arr_addr = static_cast<int>(n < 764 ? n - 760 : (last_idx + static_cast<int64_t>(h % 4)) % 4);
            x.arr_data = (n < 764 || ((h >> 2) & 1) == 0 ? 4 : 5) * C::ONE;
        }
        if (n >= 900 && n < 1000) {  // directed: a latched array below the minimum (no fire after a fire)
            x = golden::pso_regs{};
            in = golden::pso_in{};
            x.axis_mask = 1;
            x.pulse_w = 1;
            x.arr_len = 4;
            x.arr_wrap = true;
            in.step[0] = 1;
            in.pos[0] = n;
            x.enable = n >= 905;
            x.arr_en = n < 930;   // off while the run keeps its array: the check covers fire_dist
            if (n < 904) {
                x.arr_we = true;
                x.arr_addr = static_cast<int>(n - 900);
                x.arr_data = 8 * C::ONE;
            }
            if (n >= 930 && n < 934) {   // 1 .. 1.75 counts: a fire every second call
                x.arr_we = true;
                x.arr_addr = static_cast<int>(n - 930);
                x.arr_data = C::ONE + (static_cast<uint64_t>(n - 930) << 30);
            }
        }
        if (n >= 700 && n < 760) {  // directed: each kind of invalid configuration for one call
            x = golden::pso_regs{};
            in = golden::pso_in{};
            x.enable = n != 700;
            x.fire_dist = C::MIN_DIST + (1ULL << 31);
            x.pulse_w = 2;
            in.step[0] = 1;
            in.pos[0] = n;
            if (n % 6 == 5) {
                switch ((n - 700) / 6) {
                    case 0: x.win_k = 0; break;
                    case 1: x.win_k = 17; break;
                    case 2: x.fire_dist = C::MIN_DIST - 1; break;
                    case 3: x.arr_en = true; x.arr_len = 0; break;
                    case 4: x.arr_en = true; x.arr_len = 65; break;
                    case 5: x.axis_mask = 0; break;
                    case 6: x.pulse_w = 0; break;
                    case 7: x.win_en = true; x.win_low = 1; x.win_high = 0; break;
                    case 8: x.win_en = true; x.win_src = 3; break;
                    default: x.arr_en = true; x.arr_len = 64; break;   // entries never written or bad
                }
            }
        }
        const lx::pso::out_t o = m.step(lxt::pso_to_hls(in), lxt::pso_to_hls(x));
        last_idx = static_cast<int64_t>(o.idx.to_uint64());
        t.rows.push_back(lxt::pso_vec_row(in, x, o));
    }
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    return vecgen::run(argc, argv, "rtl_stress_vectors", 4, 30000, "hls/",
                       [](rng_t& r, long long calls, std::vector<vec_table>* tables, std::string*) {
                           tables->push_back(filter_stress(r, calls));
                           tables->push_back(decoder_stress(r, calls));
                           tables->push_back(multiplier_stress(r, calls));
                           tables->push_back(pacer_stress(r, calls));
                           tables->push_back(rephase_stress(r, calls));
                           tables->push_back(dds_stress(r, calls));
                           tables->push_back(top_stress(r, 3 * calls));
                           tables->push_back(error_map_stress(r, calls));
                           tables->push_back(encoder_counter_stress(r, calls));
                           tables->push_back(pso_stress(r, calls));
                           return true;
                       });
}
