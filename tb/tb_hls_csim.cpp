// ctest-args-O0: --calls 40000
// ctest-args-valgrind: --calls 12000
// tb_hls_csim — testbench of the synthesis top function laserax_axil() (also the Vitis HLS C
// simulation testbench of scripts/run_hls.tcl). It uses only the top function (through the
// generated header-only sysmodel/laserax_axil_call.h, which passes the registers of an
// lx::axis_regs as the top's one-scalar-per-register arguments), the golden chain and the standard
// library, so it compiles the same with -DLASERAX_USE_AP_TYPES.
//
// One homing through the switch with the reset register values (P = 256, ratio for a HeNe laser
// in standard air) at the power-up table contents: every output compared with the golden chain
// on every call; then Z - A = 320 and sin == cos > 0 with the mark active at Z. Returns 1 on
// failure, like the Vitis examples. Optional argument `--calls N` (default 400000; homing and Z
// are reached within the first 10000 calls): the shorter run of the valgrind test.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "golden/laserax_top.h"
#include "hls/laserax_axil.h"
#include "sysmodel/laserax_axil_call.h"

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
    const lx::axis_regs regs;  // reset values
    golden::laserax_top gold;
    gold.reset();
    const golden::axis_regs gregs;
    long fails = 0;
    long long a = 0, z = 0;
    bool homed = false, z_ok = false;
    long long n = 0;                     // raw fringe index
    lx::axis_out prev2{}, prev1{};
    for (long t = 0; t < calls && fails < 5; ++t) {
        if (t > 100 && t % 60 == 0 && n < 130) ++n;
        static const bool qa[4] = {false, true, true, false};
        static const bool qb[4] = {false, false, true, true};
        const bool sw = n >= 30;
        lx::axis_out o;
        lxt::laserax_axil_regs(qa[n & 3], qb[n & 3], sw, false, regs, o);
        golden::axis_pins gp;
        gp.a = qa[n & 3];
        gp.b = qb[n & 3];
        gp.sw = sw;
        const golden::axis_out g = gold.step(gp, gregs);
        const long long hv[] = {o.sin.to_int64(), o.cos.to_int64(), o.ref_mark, o.qa, o.qb, o.stage.to_int64(),
                                o.alarm, o.raw_count.to_int64(), o.comp_pos.to_int64(), o.out_pos.to_int64()};
        const long long gv[] = {g.sin, g.cos, g.ref_mark, g.qa, g.qb, g.stage, g.alarm, g.raw_count, g.comp_pos, g.out_pos};
        const char* names[] = {"sin", "cos", "ref_mark", "qa", "qb", "stage", "alarm", "raw_count", "comp_pos", "out_pos"};
        for (int k = 0; k < 10; ++k) {
            if (hv[k] != gv[k]) {
                std::printf("cycle %ld signal %s: expected %lld got %lld\n", t, names[k], gv[k], hv[k]);
                ++fails;
            }
        }
        if (o.homed && !homed) {
            homed = true;
            a = o.a_pos.to_int64();
            z = o.z_pos.to_int64();
        }
        // sin/cos of this call belong to the rephase outputs of two calls ago
        if (prev2.homed && prev2.out_pos - prev2.adj == prev2.z_pos && prev2.ostep == 0 && prev2.adj == o.adj)
            z_ok = z_ok || (o.sin == o.cos && o.sin > 0 && o.ref_mark);
        prev2 = prev1;
        prev1 = o;
    }
    const bool ok = fails == 0 && homed && z - a == 320 && z_ok;
    std::printf("[tb_hls_csim] %s: homed %d, Z - A = %lld, sin == cos > 0 with mark at Z: %d, %ld mismatches\n",
                ok ? "PASS" : "FAIL", homed ? 1 : 0, z - a, z_ok ? 1 : 0, fails);
    return ok ? 0 : 1;
}
