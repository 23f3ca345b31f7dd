// tb_rephase_directed — directed referencing scenarios through the whole chain (hls == golden on
// every call, and the output never moves more than one count per call):
//   reversal  : back out of Stage 2 past A -> Stage 1 with the adjustment unwound, no jump;
//               the following homing gives the same A, d and Z as a clean run
//   bounce    : a bouncing switch with debounce -> exactly one A, normal homing
//   passes    : later passes over the home point -> the mark recurs on the same real positions,
//               no new rephase (adj, d unchanged)
//   rehome    : rehome command -> Stage 1, homing again at the same A gives d = 0 and the same Z
//   laser err : laser error in Stage 2 -> Stage 1, adjustment frozen, alarm until cleared
//   power-up  : switch already closed at power-up is not a point A
#include <random>
#include <set>

#include "tb/tb_util.h"
#include "sysmodel/sim.h"

namespace {

struct rig {
    lxt::dual_axis ax;
    tbu::result& res;
    std::mt19937_64 rng{3};
    int64_t n = 0;
    int64_t edge = 100;      // switch closed for n >= edge
    int64_t bounce = 0;      // counts past the edge where the switch bounces
    bool lerr = false;
    int64_t last_out = 0;
    int transitions_12 = 0;  // Stage 1 -> 2 transitions seen
    int prev_stage = 1;
    std::set<int64_t> mark_at;  // real positions where the mark was seen (current pass)

    rig(const lxt::axis_settings& s, tbu::result& r) : ax(s), res(r) {}

    void call(const std::string& what) {
        lx::axis_pins p;
        lxt::quad_pins(n, p.a, p.b);
        p.sw = n >= edge && (n >= edge + bounce || (rng() & 1u));
        p.lerr = lerr;
        const std::string m = ax.step(p);
        res.expect(m.empty(), [&] { return what + ": " + m; });
        const lx::axis_out& h = ax.hls();
        const int64_t o = h.out_pos.to_int64();
        res.expect(o - last_out <= 1 && last_out - o <= 1, [&] { return what + ": output jumped by more than one count"; });
        last_out = o;
        if (prev_stage == 1 && h.stage == 2) ++transitions_12;
        prev_stage = h.stage.to_int();
        if (h.rep_mark) mark_at.insert(o - h.adj.to_int64());
    }
    void idle(int k, const std::string& what) {
        for (int i = 0; i < k; ++i) call(what);
    }
    void move_to(int64_t target, const std::string& what) {
        while (n != target) {
            n += target > n ? 1 : -1;
            idle(4, what);
        }
        idle(20, what);
    }
    void pulse(bool rehome, bool clear, const std::string& what) {
        lxt::axis_settings s = ax.settings();
        s.rehome = rehome;
        s.clear = clear;
        ax.set(s);
        call(what);  // presented in this call ...
        s.rehome = s.clear = false;
        ax.set(s);
        call(what);  // ... in force in this one (register stage, DESIGN 4.7)
    }
    const lx::axis_out& h() const { return ax.hls(); }
};

lxt::axis_settings base() {
    lxt::axis_settings s;
    s.ratio = 1ULL << 32;
    s.glitch_n = 0;
    s.sw_debounce = 0;
    s.pace_m = 2;
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    tbu::result res("tb_rephase_directed", tbu::seed_from(argc, argv, 3));
    const int P = 256;

    // reference: a clean homing
    rig ref(base(), res);
    ref.move_to(600, "reference");
    const int64_t ref_a = ref.h().a_pos.to_int64(), ref_z = ref.h().z_pos.to_int64();
    const int64_t ref_d = ref.h().d.to_int64(), ref_adj = ref.h().adj.to_int64();
    res.check(ref.h().stage == 3 && ref_z - ref_a == P + P / 4 && ref_d > 0, "reference homing");

    {  // reversal during Stage 2
        rig r(base(), res);
        r.move_to(ref_a + P / 2, "reversal: forward into Stage 2");
        res.check(r.h().stage == 2 && r.h().adj.to_int64() > 0, "reversal: not in Stage 2 with an adjustment");
        r.move_to(ref_a + P / 4, "reversal: back inside the window");
        res.check(r.h().stage == 2 && r.h().adj.to_int64() == (ref_d * (P / 4)) / P,
                  "reversal: adjustment is not floor(d*tr/P) after going back");
        r.move_to(ref_a - 20, "reversal: back past A");
        res.check(r.h().stage == 1 && r.h().adj == 0, "reversal: not back in Stage 1 with adjustment 0");
        r.move_to(600, "reversal: home");
        res.check(r.h().stage == 3 && r.h().a_pos == ref_a && r.h().d.to_int64() == ref_d && r.h().z_pos == ref_z &&
                      r.h().adj == ref_adj,
                  "reversal: homing after the reversal differs from the clean run");
        res.check(r.transitions_12 == 2, "reversal: expected two passes through A");
    }
    {  // switch bounce with debounce
        lxt::axis_settings s = base();
        s.sw_debounce = 60;
        rig r(s, res);
        r.bounce = 12;
        r.move_to(600, "bounce");
        res.check(r.transitions_12 == 1 && r.h().stage == 3, "bounce: " + std::to_string(r.transitions_12) + " A points");
        res.check(r.h().a_pos.to_int64() >= r.edge + r.bounce && r.h().z_pos - r.h().a_pos == P + P / 4,
                  "bounce: A inside the bounce zone or wrong Z");
    }
    {  // later passes and re-homing
        rig r(base(), res);
        r.move_to(600, "passes: home");
        const std::set<int64_t> first = r.mark_at;
        const int64_t b = r.h().b_pos.to_int64(), c = r.h().c_pos.to_int64();
        res.check(!first.empty() && *first.begin() == b && *first.rbegin() == c &&
                      static_cast<int64_t>(first.size()) == c - b + 1,
                  "passes: mark not exactly on [B, C] on the homing pass");
        for (int pass = 0; pass < 3; ++pass) {
            r.mark_at.clear();
            r.move_to(-50, "passes: back");
            r.move_to(600, "passes: forward");
            res.check(r.mark_at == first && r.h().adj == ref_adj && r.h().d.to_int64() == ref_d && r.h().stage == 3,
                      "passes: pass " + std::to_string(pass) + " mark moved or rephased");
        }
        r.pulse(true, false, "rehome");
        res.check(r.h().stage == 1 && r.h().adj == ref_adj, "rehome: not Stage 1 with the adjustment kept");
        r.move_to(-50, "rehome: back");
        r.mark_at.clear();
        r.move_to(600, "rehome: home again");
        res.check(r.h().stage == 3 && r.h().d == 0 && r.h().z_pos == ref_z && r.mark_at == first,
                  "rehome: second homing at the same A should need d = 0 and give the same Z (d " +
                      std::to_string(r.h().d.to_int64()) + ")");
    }
    {  // laser error during Stage 2
        rig r(base(), res);
        r.move_to(ref_a + P / 2, "lerr: into Stage 2");
        const int64_t adj = r.h().adj.to_int64();
        r.lerr = true;
        r.idle(30, "lerr: error active");
        res.check(r.h().stage == 1 && r.h().lerr_alarm && r.h().alarm && r.h().adj == adj,
                  "lerr: not Stage 1 with alarm and frozen adjustment");
        r.lerr = false;
        r.idle(10, "lerr: error gone");
        res.check(r.h().lerr_alarm, "lerr: alarm cleared without a clear");
        r.pulse(false, true, "lerr: clear");
        r.idle(2, "lerr: after clear");
        res.check(!r.h().lerr_alarm, "lerr: clear did not clear the alarm");
        r.move_to(ref_a - 30, "lerr: back before the switch");
        r.move_to(600, "lerr: home");
        res.check(r.h().stage == 3 && r.h().z_pos - r.h().a_pos == P + P / 4, "lerr: no homing after the error");
    }
    {  // switch closed at power-up
        rig r(base(), res);
        r.edge = -100;
        r.move_to(300, "power-up on the switch");
        res.check(r.h().stage == 1 && r.transitions_12 == 0, "power-up: closed switch taken as point A");
    }
    return res.finish();
}
