// ctest-args-O0: --calls 40000
// ctest-args-valgrind: --calls 12000
// tb_hls_csim — testbench of the synthesis top function laserax_axil() (also the Vitis HLS C
// simulation testbench of scripts/run_hls.tcl). It drives the top the way software drives the HLS
// IP: through a model of its s_axilite slave (the generated header-only
// sysmodel/laserax_axil_call.h: every register a 32-bit word, all 0 at power-up, as an s_axilite
// argument has no initial value), written by the host's initialisation call (host/ip_init.h). It
// uses only the top function, that slave model, host/ip_init and the register table it reads, the
// golden chain and the standard library, so it compiles the same with -DLASERAX_USE_AP_TYPES.
//
// 1. Without the initialisation: the core started on its power-up registers (all 0) stays in the
//    safe state: cfg_err and alarm in every call after the power-up call, stage 1, never homed,
//    sin = cos = 0 and the digital outputs low, while the pins move and the switch toggles.
//    Then the core is stopped (0 to the block-control word).
// 2. lxt::init_registers with the reset image (lxt::axis_settings{}) through the slave: exactly
//    lxt::init_register_writes() writes, none of them ignored by the slave, and afterwards every
//    register word holds the reset value of regmap/laserax_regs.csv as host/laserax_regs_c.h spells
//    it (its X-macro, a spelling of the CSV independent of the host table init_registers reads).
// 3. lxt::start_core, then one homing through the switch at the reset values (P = 256, ratio for a
//    HeNe laser in standard air) at the power-up table contents: the first call after the start
//    still runs on the registers in force before the stop (zeros: cfg_err); the core must leave
//    cfg_err in the next call (the register stage, DESIGN §4.7) and never set it again; the pins,
//    the status and the error-map outputs compared with the golden chain on every call from that
//    call on (the golden chain's power-up call is aligned with the first call after the start),
//    and the debug taps (raw_count .. rep_mark) too when the top is built with
//    LASERAX_HLS_DEBUG_TAPS = 1 (CTest tb_hls_csim_taps), else they must be 0 in every call (the
//    default build, CTest tb_hls_csim: the switch drops them); then Z - A = 320 and sin == cos > 0
//    with the mark active at Z (positions from the golden chain's taps).
// Returns 1 on failure, like the Vitis examples. Optional argument `--calls N` (calls of part 3,
// default 400000; homing and Z are reached within the first 10000 calls): the shorter run of the
// valgrind test and of co-simulation.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "golden/laserax_top.h"
#include "hls/laserax_axil.h"
#include "host/ip_init.h"
#include "host/laserax_regs_c.h"
#include "sysmodel/laserax_axil_call.h"

namespace {

const bool kQa[4] = {false, true, true, false};
const bool kQb[4] = {false, false, true, true};
const long kNoInitCalls = 3000;  // part 1

long g_fails = 0;
void check(bool ok, const char* what, long t) {
    if (ok) return;
    if (g_fails < 10) std::printf("call %ld: %s\n", t, what);
    ++g_fails;
}

// part 2: the register word(s) at `offset` hold `reset` in `width` bits, low word first
void check_reset_words(lxt::laserax_axil_slave& bus, const char* name, uint32_t offset, int width, long long reset) {
    const uint64_t bits = width == 64 ? static_cast<uint64_t>(reset)
                                      : static_cast<uint64_t>(reset) & ((uint64_t(1) << width) - 1);
    for (int w = 0; w * 32 < width; ++w) {
        const uint32_t want = static_cast<uint32_t>(bits >> (32 * w));
        const uint32_t got = bus.word(offset + 4u * static_cast<uint32_t>(w));
        if (got != want) {
            std::printf("after init_registers: %s word 0x%02X holds 0x%08X, CSV reset word 0x%08X\n", name,
                        static_cast<unsigned>(offset + 4u * static_cast<uint32_t>(w)), static_cast<unsigned>(got),
                        static_cast<unsigned>(want));
            ++g_fails;
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    long calls = 400000;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--calls") == 0 && i + 1 < argc) {
            calls = std::strtol(argv[++i], nullptr, 10);
        } else {
            std::printf("usage: tb_hls_csim [--calls N]\n");
            return 2;
        }
    }
    if (calls < 10000) {
        std::printf("tb_hls_csim: --calls must be >= 10000 (homing and Z need them)\n");
        return 2;
    }
    lxt::laserax_axil_slave bus;  // the HLS IP: registers 0, core stopped
    long n_writes = 0, n_ignored = 0;
    const lxt::bus_write_fn write = [&](uint32_t offset, uint32_t value) {
        ++n_writes;
        if (!bus.write(offset, value)) ++n_ignored;
    };
    lx::axis_out o;

    // ---- 1. started without the initialisation ----------------------------------------------
    lxt::start_core(write);
    long n = 0;  // raw fringe index
    bool no_init_safe = true;
    for (long t = 0; t < kNoInitCalls; ++t) {
        if (t % 5 == 0) ++n;
        const bool sw = (t / 700) % 2 == 1;
        if (!bus.clock(kQa[n & 3], kQb[n & 3], sw, false, o)) {
            check(false, "the started core did not run", t);
            break;
        }
        const bool safe = o.stage == 1 && !o.homed && o.sin == 0 && o.cos == 0 && !o.ref_mark && !o.qa && !o.qb &&
                          !o.qz && (t == 0 || (o.cfg_err && o.alarm));  // call 0: the power-up call
        if (!safe) no_init_safe = false;
        check(safe, "without init_registers the core left the safe state (cfg_err, stage 1, sin = cos = 0)", t);
    }
    write(lxt::kApCtrlOffset, 0);  // stop
    check(!bus.clock(false, false, false, false, o), "the stopped core ran", kNoInitCalls);

    // ---- 2. the initialisation ------------------------------------------------------------------
    n_writes = 0;
    n_ignored = 0;
    std::string err;
    const bool init_ok = lxt::init_registers(lxt::axis_settings{}, write, &err);
    if (!init_ok) std::printf("init_registers: %s\n", err.c_str());
    check(init_ok, "init_registers refused the reset image", 0);
    check(n_writes == lxt::init_register_writes(), "init_registers: not init_register_writes() writes", 0);
    check(n_ignored == 0, "init_registers: a write the slave ignored (not a register word)", 0);
    check(!bus.running(), "init_registers started the core", 0);
    const long init_writes = n_writes;
    const long fails_before_words = g_fails;
#define LX_TB_CHECK_RESET(NAME, OFFSET, WIDTH, SIGNED, RESET) \
    check_reset_words(bus, #NAME, OFFSET, WIDTH, static_cast<long long>(RESET));
    LASERAX_REGS(LX_TB_CHECK_RESET)
#undef LX_TB_CHECK_RESET
    const bool words_ok = g_fails == fails_before_words;

    // ---- 3. started after it: homing, every call against the golden chain --------------------
    // (pace_m 4 instead of its reset value 61, one word written before the start, so that the
    // homing fits the valgrind run: at 61 the referencing window's P counts are 2 * 61 calls
    // apart, 31000 calls; DESIGN 4.4)
    write(LASERAX_REG_PACE_M_OFFSET, 4);
    lxt::start_core(write);
    golden::laserax_top gold;
    gold.reset();
    golden::axis_regs gregs;  // reset values, pace_m as written
    gregs.pace_m = 4;
    long mismatches = 0, first_run = -1;
    long long a = 0, z = 0;
    bool homed = false, z_ok = false;
    n = 0;
    long tap_nonzero = 0;  // golden taps != 0: the taps-off check compares against non-zero values
    golden::axis_out prev2{}, prev1{};
    for (long t = 0; t < calls && mismatches < 5; ++t) {
        if (t > 100 && t % 60 == 0 && n < 130) ++n;
        const bool sw = n >= 30;
        if (!bus.clock(kQa[n & 3], kQb[n & 3], sw, false, o)) {
            check(false, "the started core did not run", t);
            break;
        }
        golden::axis_pins gp;
        gp.a = kQa[n & 3];
        gp.b = kQb[n & 3];
        gp.sw = sw;
        const golden::axis_out g = gold.step(gp, gregs);
        if (first_run < 0 && !o.cfg_err) first_run = t;
        if (t == 0) {
            check(o.cfg_err, "the first call after the start did not run on the registers before it (zeros)", t);
            continue;
        }
        check(!o.cfg_err, "cfg_err after init_registers and the register stage", t);
        // the pins, the status and the error-map outputs: in both builds
        const long long hv[] = {o.sin.to_int64(), o.cos.to_int64(), o.ref_mark, o.qa, o.qb, o.qz, o.q_oe, o.cfg_err,
                                o.stage.to_int64(), o.homed, o.lerr_alarm, o.illegal_st, o.err_cnt.to_int64(),
                                o.ovs_edge_st, o.ovs_backlog_st, o.glitch_st, o.alarm, o.dac_clip_st, o.map_cfg_err,
                                o.corr.to_int64(), o.map_delta.to_int64()};
        const long long gv[] = {g.sin, g.cos, g.ref_mark, g.qa, g.qb, g.qz, g.q_oe, g.cfg_err, g.stage, g.homed, g.lerr_alarm,
                                g.illegal_st, g.err_cnt, g.ovs_edge_st, g.ovs_backlog_st, g.glitch_st, g.alarm,
                                g.dac_clip_st, g.map_cfg_err, g.corr, g.map_delta};
        const char* names[] = {"sin", "cos", "ref_mark", "qa", "qb", "qz", "q_oe", "cfg_err", "stage", "homed", "lerr_alarm",
                               "illegal_st", "err_cnt", "ovs_edge_st", "ovs_backlog_st", "glitch_st", "alarm",
                               "dac_clip_st", "map_cfg_err", "corr", "map_delta"};
        for (int k = 0; k < 21; ++k) {
            if (hv[k] != gv[k]) {
                std::printf("call %ld signal %s: expected %lld got %lld\n", t, names[k], gv[k], hv[k]);
                ++mismatches;
            }
        }
        // the debug taps (the registered block outputs; rtl_ref's DEBUG_TAPS set): equal to the
        // golden chain's with LASERAX_HLS_DEBUG_TAPS = 1, 0 in every call without
        const long long htap[] = {o.raw_count.to_int64(), o.step.to_int64(), o.comp_pos.to_int64(),
                                  o.delta.to_int64(), o.backlog.to_int64(), o.pstep.to_int64(),
                                  o.paced_pos.to_int64(), o.ostep.to_int64(), o.out_pos.to_int64(),
                                  o.adj.to_int64(), o.a_pos.to_int64(), o.b_pos.to_int64(), o.c_pos.to_int64(),
                                  o.z_pos.to_int64(), o.d.to_int64(), o.rep_mark};
        const long long gtap[] = {g.raw_count, g.step, g.comp_pos, g.delta, g.backlog, g.pstep, g.paced_pos, g.ostep,
                                  g.out_pos, g.adj, g.a_pos, g.b_pos, g.c_pos, g.z_pos, g.d, g.rep_mark};
        const char* tap_names[] = {"raw_count", "step", "comp_pos", "delta", "backlog", "pstep", "paced_pos", "ostep",
                                   "out_pos", "adj", "a_pos", "b_pos", "c_pos", "z_pos", "d", "rep_mark"};
        for (int k = 0; k < 16; ++k) {
            const long long want = LASERAX_HLS_DEBUG_TAPS ? gtap[k] : 0;
            if (htap[k] != want) {
                std::printf("call %ld tap %s: expected %lld got %lld (LASERAX_HLS_DEBUG_TAPS = %d)\n", t, tap_names[k],
                            want, htap[k], LASERAX_HLS_DEBUG_TAPS);
                ++mismatches;
            }
            if (gtap[k] != 0) ++tap_nonzero;
        }
        // the positions from the golden chain's taps (equal to the top's, compared above, when it
        // has them)
        if (o.homed && !homed) {
            homed = true;
            a = g.a_pos;
            z = g.z_pos;
        }
        // sin/cos of this call belong to the rephase outputs of two calls ago
        if (prev2.homed && prev2.out_pos - prev2.adj == prev2.z_pos && prev2.ostep == 0 && prev2.adj == g.adj)
            z_ok = z_ok || (o.sin == o.cos && o.sin > 0 && o.ref_mark);
        prev2 = prev1;
        prev1 = g;
    }
    check(first_run == 1, "the core did not leave cfg_err in the call after the register stage", first_run);
    check(tap_nonzero > 0, "the golden taps were 0 in every call", calls);
    const bool ok = g_fails == 0 && mismatches == 0 && homed && z - a == 320 && z_ok;
    std::printf("[tb_hls_csim] %s (debug taps %s): without init cfg_err held %ld calls: %d; init_registers %ld writes, register "
                "words = CSV reset: %d; after the start cfg_err left at call %ld (bound 1); homed %d, Z - A = %lld, "
                "sin == cos > 0 with mark at Z: %d, %ld mismatches, %ld failed checks\n",
                ok ? "PASS" : "FAIL", LASERAX_HLS_DEBUG_TAPS ? "on, compared" : "off, all 0", kNoInitCalls, no_init_safe ? 1 : 0, init_writes, words_ok ? 1 : 0,
                first_run, homed ? 1 : 0, z - a, z_ok ? 1 : 0, mismatches, g_fails);
    return ok ? 0 : 1;
}
