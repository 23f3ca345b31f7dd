// tb_latency — the chain's pin-to-output latency (DESIGN §4.7), measured on hls and golden alike.
//
// After reset and a quiet settling time (filters valid, the power-up re-base of the multiplier
// done), one forward quadrature edge on A is presented in call t0; the first call whose sin/cos
// differ from the call before is t0 + L. DESIGN §4.7: L = 12 calls with glitch_n <= 1 (decoder 2,
// multiplier 1 + L_MUL = 4, pacer 2, rephase 1, dds 3), and max(glitch_n, 1) - 1 more for a longer
// glitch filter (4.1); the issue-11 budget is L <= 12 at glitch_n <= 1. Checked for glitch_n 0..8,
// both directions of the edge, and with the digital A/B outputs (same call as sin/cos).
#include <cstdio>
#include <string>

#include "golden/laserax_top.h"
#include "hls/laserax_top.h"
#include "tb/tb_util.h"

namespace {
constexpr int kLatency = 12;  // DESIGN §4.7, glitch_n <= 1

// Calls from the edge to the first change of sin/cos (and of qa/qb), or -1.
struct lat_result {
    int sc_hls = -1, sc_gold = -1, q_hls = -1;
};
lat_result measure(int glitch_n, bool backward) {
    lx::laserax_top h;
    golden::laserax_top g;
    g.reset();
    lx::axis_regs hr;
    golden::axis_regs gr;
    hr.glitch_n = glitch_n;
    gr.glitch_n = glitch_n;
    const int spacing = (glitch_n > 1 ? glitch_n : 1) + 2;  // legal edge spacing for this filter
    hr.min_spacing = spacing;
    gr.min_spacing = spacing;
    // quadrature index 1 (A=1, B=0) at rest; the edge goes to index 2 (forward) or 0 (backward)
    lx::axis_pins hp;
    golden::axis_pins gp;
    hp.a = gp.a = true;
    lat_result r;
    lx::axis_out ho_prev = h.step(hp, hr);  // call 0
    golden::axis_out go_prev = g.step(gp, gr);
    const int settle = 400, t0 = settle, end = settle + 60;
    for (int t = 1; t < end; ++t) {
        if (t == t0) {
            if (backward) hp.a = gp.a = false;  // index 0
            else hp.b = gp.b = true;            // index 2
        }
        const lx::axis_out ho = h.step(hp, hr);
        const golden::axis_out go = g.step(gp, gr);
        if (t > t0) {
            if (r.sc_hls < 0 && (ho.sin != ho_prev.sin || ho.cos != ho_prev.cos)) r.sc_hls = t - t0;
            if (r.sc_gold < 0 && (go.sin != go_prev.sin || go.cos != go_prev.cos)) r.sc_gold = t - t0;
            if (r.q_hls < 0 && (ho.qa != ho_prev.qa || ho.qb != ho_prev.qb)) r.q_hls = t - t0;
        } else if (t > settle / 2) {
            // quiet before the edge: nothing moves
            if (ho.sin != ho_prev.sin || go.sin != go_prev.sin) r.sc_hls = r.sc_gold = -2;
        }
        ho_prev = ho;
        go_prev = go;
    }
    return r;
}
}  // namespace

int main(int argc, char** argv) {
    tbu::result res("tb_latency", tbu::seed_from(argc, argv, 0));
    for (int n = 0; n <= 8; ++n) {
        for (int back = 0; back < 2; ++back) {
            const lat_result r = measure(n, back != 0);
            const int want = kLatency + (n > 1 ? n - 1 : 0);
            const std::string what = "glitch_n " + std::to_string(n) + (back ? " backward" : " forward") +
                                     ": latency hls " + std::to_string(r.sc_hls) + ", golden " + std::to_string(r.sc_gold) +
                                     ", A/B " + std::to_string(r.q_hls) + ", want " + std::to_string(want);
            res.check(r.sc_hls == want && r.sc_gold == want && r.q_hls == want, what);
            if (n <= 1) res.check(r.sc_hls <= 12, "issue-11 budget: latency <= 12 at glitch_n <= 1");
            if (n == 0 && !back) std::printf("[tb_latency] %s\n", what.c_str());
        }
    }
    return res.finish();
}
