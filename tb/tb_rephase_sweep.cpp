// tb_rephase_sweep — the homing sequence for every preset, both directions, all P power-up phases.
//
// The whole chain runs with ratio 1.0 (one output count per raw count), so the switch can be
// placed at any raw count and the phase at A takes every value 0..P-1 exactly once per sweep.
// For each of 256, 320, 512, 640, 1280 counts, each direction and each phase, a run homes the
// axis and checks, call by call, hls == golden on every output and tap, and at the end:
//   * stage 3 reached, B = A + dir*P, Z = A + dir*(P + P/4);
//   * the controller saw P + d counts between A and B with 0 <= d < P;
//   * at Z (settled), sin == cos > 0 and the reference mark is active;
//   * the phase at A covered all P values.
// `--phase-step S` (default 1) runs only the switch positions k = 0, S, 2S, ... (the -O0 type
// back-end build; each run keeps every check, the coverage check then asks for P/S distinct
// phases at A).
// ctest-args-types: --phase-step 4
// ctest-args-O0: --phase-step 32
#include <deque>
#include <vector>

#include "tb/tb_util.h"
#include "sysmodel/sim.h"

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 1);  // deterministic sweep; seed unused
    tbu::result res("tb_rephase_sweep", seed);
    const int presets[5] = {256, 320, 512, 640, 1280};
    const int kSpacing = 4;  // calls per raw count
    const long long phase_step = tbu::arg_ll(argc, argv, "--phase-step", 1);
    if (phase_step < 1 || phase_step > 64) {
        std::printf("tb_rephase_sweep: --phase-step must be 1..64\n");
        return 2;
    }
    const int kStep = static_cast<int>(phase_step);
    long runs = 0;
    for (int P : presets) {
        for (int dir = 1; dir >= -1; dir -= 2) {
            std::vector<bool> seen(static_cast<size_t>(P), false);
            int k_runs = 0;
            for (int k = 0; k < P && res.failures < 10; k += kStep) {
                ++k_runs;
                lxt::axis_settings s;
                s.period = s.tbl_period = P;
                s.mark_len = P / 4;
                s.ratio = 1ULL << 32;
                s.glitch_n = 0;
                s.sw_debounce = 0;
                s.pace_m = 2;
                lxt::dual_axis ax(s);
                const int64_t edge = 16 + k;  // switch closes at dir*n >= edge
                const int64_t end = edge + P + P / 4 + 24;
                int64_t n = 0;
                std::deque<lx::axis_out> hist;
                int64_t out_at_a = 0, out_at_b = 0;
                bool got_a = false, got_b = false, z_checked = false;
                int prev_stage = 1;
                for (long t = 0; dir * n < end || t % kSpacing != 0 || hist.size() < 2; ++t) {
                    if (t > 40 && t % kSpacing == 0 && dir * n < end) n += dir;
                    lx::axis_pins p;
                    lxt::quad_pins(n, p.a, p.b);
                    p.sw = dir * n >= edge;
                    const std::string m = ax.step(p);
                    if (!m.empty()) {
                        res.check(false, "P=" + std::to_string(P) + " dir " + std::to_string(dir) + " phase run " +
                                             std::to_string(k) + " call " + std::to_string(t) + ": " + m);
                        break;
                    }
                    const lx::axis_out& h = ax.hls();
                    if (prev_stage == 1 && h.stage == 2) {
                        got_a = true;
                        out_at_a = h.out_pos.to_int64();
                        const int64_t ph = ((h.a_pos.to_int64() % P) + P) % P;
                        seen[static_cast<size_t>(ph)] = true;
                    }
                    if (prev_stage == 2 && h.stage == 3) got_b = true;
                    if (got_b && h.out_pos - h.adj == h.b_pos && h.ostep == 0) out_at_b = h.out_pos.to_int64();
                    prev_stage = h.stage.to_int();
                    hist.push_back(h);
                    if (hist.size() > 3) hist.pop_front();
                    // sin/cos of this call belong to the rephase state of two calls ago; the
                    // rephase block's own real position is out_pos - adj (the paced_pos tap is
                    // the pacer's output, one call ahead of it)
                    if (hist.size() == 3) {
                        const lx::axis_out& r2 = hist[0];
                        if (r2.homed && r2.out_pos - r2.adj == r2.z_pos && r2.ostep == 0 && r2.adj == h.adj) {
                            z_checked = true;
                            res.check(h.sin == h.cos && h.sin > 0 && h.ref_mark,
                                      "P=" + std::to_string(P) + " run " + std::to_string(k) + ": at Z sin " +
                                          std::to_string(h.sin.to_int64()) + " cos " + std::to_string(h.cos.to_int64()) +
                                          " mark " + std::to_string(h.ref_mark));
                        }
                    }
                }
                ++runs;
                const lx::axis_out& h = ax.hls();
                const int64_t a = h.a_pos.to_int64();
                const std::string tag = "P=" + std::to_string(P) + " dir " + std::to_string(dir) + " run " + std::to_string(k);
                res.check(got_a && got_b && h.stage == 3, tag + ": did not home (stage " + std::to_string(h.stage.to_int()) + ")");
                res.check(h.b_pos.to_int64() - a == dir * P, tag + ": B - A != dir*P");
                res.check(h.z_pos.to_int64() - a == dir * (P + P / 4), tag + ": Z - A != dir*(P + P/4)");
                const int64_t seen_ab = dir * (out_at_b - out_at_a);
                res.check(seen_ab >= P && seen_ab < 2 * P && seen_ab == P + h.d.to_int64(),
                          tag + ": controller saw " + std::to_string(seen_ab) + " counts from A to B, d = " +
                              std::to_string(h.d.to_int64()));
                res.check(z_checked, tag + ": Z never observed settled");
            }
            int covered = 0;
            for (bool b : seen) covered += b ? 1 : 0;
            res.check(covered == k_runs, "P=" + std::to_string(P) + " dir " + std::to_string(dir) +
                                             ": phases at A covered " + std::to_string(covered) + " of " +
                                             std::to_string(k_runs));
        }
    }
    std::printf("  %ld homing runs\n", runs);
    return res.finish();
}
