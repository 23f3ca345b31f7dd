// ctest-args-types: --seeds 8 --presets 2
// ctest-args-O0: --seeds 8 --presets 1
// ctest-labels: slow_asan
// tb_repeatability — the point of rephasing: whatever the power-up phase, Z lands at the same
// physical position to within one raw count.
//
// The default scenario (realistic physics: HeNe wavelength in air, ratio ~8.1, switch debounce,
// glitch filter, pacing) is run for many seeds, i.e. many power-up positions and fringe phases,
// for every preset and both directions. For each run: hls == golden on every clock, Z - A =
// P + P/4 real counts, sin == cos > 0 with the mark active at Z; across the seeds of one
// (preset, direction) Z's true position must stay within one raw count (~633 nm) of the nominal
// home point, switch edge + dir * (P + P/4) * 78.125 nm (plus the switch filter delay), allowing
// one output count for the floor of the multiplier: the raw count quantises where A is seen
// (up to one raw count late) and where Z is reached (up to one raw count late), so the deviation
// lies in (-lambda - 1 count, +lambda). The phase at A (A mod P) must vary widely over the seeds,
// so the test could fail if rephasing did not work.
#include <algorithm>
#include <cmath>

#include "tb/tb_util.h"
#include "sysmodel/homing.h"

int main(int argc, char** argv) {
    const uint64_t seed0 = tbu::seed_from(argc, argv, 100);
    const long long seeds = tbu::arg_ll(argc, argv, "--seeds", 12);
    // --presets N: the first N period presets only (the -O0 type back-end build)
    const long long n_presets = tbu::arg_ll(argc, argv, "--presets", 5);
    tbu::result res("tb_repeatability", seed0);
    if (n_presets < 1 || n_presets > 5) {
        std::printf("tb_repeatability: --presets must be 1..5\n");
        return 2;
    }
    const int presets[5] = {256, 320, 512, 640, 1280};
    for (int pi = 0; pi < n_presets; ++pi) {
        const int P = presets[pi];
        for (int dir = 1; dir >= -1; dir -= 2) {
            double zmin = 1e300, zmax = -1e300, dmax = 0;
            int ph_min = P, ph_max = -1;
            double lambda = 0;
            for (long long k = 0; k < seeds; ++k) {
                lxt::homing_params p;
                p.period = P;
                p.dir = dir;
                p.seed = seed0 + static_cast<uint64_t>(k);
                p.speed_mm_s = 100.0;  // 6 m/min: short runs, one output count per ~78 clocks
                // pacer M = 4: the pacer keeps up at that speed (the reset value 61 would space the
                // window's counts 122 clocks apart and move Z by the backlog; DESIGN 4.4)
                p.pace_m = 4;
                const lxt::homing_result r = lxt::run_homing(p);
                lambda = r.lambda_nm;
                const std::string tag = "P=" + std::to_string(P) + " dir " + std::to_string(dir) + " seed " + std::to_string(p.seed);
                res.check(r.mismatch.empty(), tag + ": " + r.mismatch);
                const lxt::homing_event& a = r.events[0];
                const lxt::homing_event& z = r.events[2];
                if (!res.check(a.cycle >= 0 && z.cycle >= 0, tag + ": did not home")) continue;
                res.check(dir * (z.paced - a.paced) == P + P / 4, tag + ": Z - A != P + P/4");
                res.check(r.sin_at_z == r.cos_at_z && r.sin_at_z > 0 && r.mark_at_z, tag + ": not sin == cos > 0 at Z");
                zmin = std::min(zmin, z.true_nm);
                zmax = std::max(zmax, z.true_nm);
                const double delay_nm = (p.sw_debounce + 4) * p.speed_mm_s * 1e6 / p.clock_hz;
                const double nominal = r.switch_edge_nm + dir * (delay_nm + (P + P / 4) * lxt::kOutputCountNm);
                const double dev = dir * (z.true_nm - nominal);
                dmax = std::max(dmax, std::fabs(dev));
                res.check(dev > -(r.lambda_nm + lxt::kOutputCountNm) && dev < r.lambda_nm,
                          tag + ": Z is " + std::to_string(dev) + " nm from the nominal home point");
                const int ph = static_cast<int>(((a.out_pos % P) + P) % P);
                ph_min = std::min(ph_min, ph);
                ph_max = std::max(ph_max, ph);
            }
            std::printf("  P=%4d dir %+d: Z true position spread %.1f nm, max |deviation| %.1f nm over %lld seeds "
                        "(one raw count = %.1f nm), phase at A %d..%d\n",
                        P, dir, zmax - zmin, dmax, seeds, lambda, ph_min, ph_max);
            res.check(ph_max - ph_min > P / 2, "P=" + std::to_string(P) + ": power-up phases did not vary enough");
        }
    }
    return res.finish();
}
