// pso.h — position-synchronised output (PSO): vector-distance tracking of up to three axes, a
// firing comparator with remainder carry, pulse output of programmable width, a position window,
// an array of firing distances and the part-speed pulse generator (24 MHz limit).
//
// docs/PSO_COUNTERS.md §2 is the normative per-call description (§2.4 the seven stages); in short:
//
//   stage A  (this call's inputs)  tracking window: per-axis signed travel D since the window
//                                  start (|D| <= K_MAX); a reversal of a tracked axis closes the
//                                  window at the previous position, |D_i| reaching K closes it at
//                                  the current one; the squares D_i^2 of the travel after the step.
//                                  Part-speed: phase accumulator (Q0.32 counts/clock, clamped to
//                                  24 MHz), one distance count per carry; the minimum-spacing
//                                  check as a sequenced shift-add product (17 calls per sample).
//   stage Q  (A of the last call)  the chord ROM address s = sum D_i^2, into the ROM's block RAM
//                                  (its address register; the word is in the RAM's output
//                                  register in the next call).
//   stage R  (Q of the last call)  chord = ROM[s] = round(sqrt(s) * 2^32), the estimate step
//                                  Y = chord + one - (the open chord, unless a reversal closed it).
//   stage B1 (R of the last call)  Y - thr for two candidate thresholds of the fire after the
//                                  next (entries next, next^2 of the index of the last call,
//                                  before its move: the prefetch, below).
//   stage P  (B1 of the last call) the loop operands: Y, and the difference for the index after
//                                  the moves B2 decided up to the last call, picked by "the index
//                                  moved in one of the last two calls" (at most one can).
//   stage B2 (P of the last call)  the loop on u = value - thr: decide the entry in u (fire when
//                                  u >= 0 and the last call did not fire) and add the next
//                                  entry's operand, picked by that decision (u + Y - thr' after a
//                                  fire, u + Y otherwise: the threshold is taken at a fire,
//                                  docs/PSO_COUNTERS.md §2.5). Thresholds >= 4 counts (MIN_DIST)
//                                  keep fires two calls apart, so a fire never follows a move of
//                                  the last call and one candidate per stage is enough.
//   stage B3 (B2 of the last call) apply the decision: fire / emit outputs, pulse timer, flags,
//                                  counters, dist = u (+ thr without a fire), index outputs.
//
// Threshold prefetch (every call, as rtl_ref): the firing-distance array is three copies of
// a 64 x 56 block RAM (RAM_S2P: one read and the shared write port per call each), read at
// next, next^2, next^3 of the call's index. In the next call the three words (with the write
// presented in the read call forwarded: the RAM reads first) are shifted by the read call's
// index move, the write presented in this call is forwarded, and entries next(idx), next^2(idx)
// of this call (or fire_dist) are registered for B1 of the next call: the RAM data land in
// registers only. Entry 0 has a register copy (the start threshold of a run).
//
// With K = 1 every step closes its window and the increment is the per-call magnitude
// 0, 1, sqrt2, sqrt3 of the step vector; larger K measures the chord over up to K counts, which
// removes the staircase over-estimate of diagonal moves (see the document for figures).
//
// Widths (all derived from the primaries in pso_cfg): distances Q24.32 (56 bits unsigned),
// u (value - thr) and dist 58 bits signed, chord 37 bits, window travel 6 bits signed, ROM 769 x 37 bits
// (K_MAX = 16). Register values presented in call t are in force in call t+1 (REG_LAT, a register
// stage; the configuration check is formed on the presented values and registered).
// Latency: a step at call t can fire at call t+7 (FIRE_LAT; the fire/emit/pulse
// outputs of call t+7); rate_over is an output of the command's call; spacing_err of run call
// 17 j (j >= 1) is the check of the command sampled 17 calls earlier.
#ifndef LASERAX_HLS_PSO_H
#define LASERAX_HLS_PSO_H

#include "hls/axis_config.h"
#include "hls/lx_ram.h"

namespace lx {

struct pso_cfg {
    // primary
    static constexpr int N_AXES = 3;
    static constexpr int D_FRAC = 32;       // fraction bits of every distance (2^-32 count)
    static constexpr int D_INT = 24;        // distance registers: < 2^24 counts (1.31 m)
    static constexpr int K_MAX = 16;        // longest tracking window, counts on one axis (ROM: 10 BRAMs)
    static constexpr int ARR_DEPTH = 64;    // firing-distance array (three block-RAM copies)
    static constexpr int W_PW = 16;         // pulse width register, clocks
    static constexpr int W_GAP = 16;        // laser minimum pulse period register, clocks
    static constexpr int W_INC = 32;        // part-speed rate, Q0.32 counts per clock
    static constexpr int W_FCNT = 32;       // emitted-pulse counter (wraps)
    static constexpr int W_OVL = 16;        // overlap counter (saturating)
    static constexpr int CLOCK_HZ = 100000000;
    static constexpr int PULSE_HZ_MAX = 24000000;  // pulse generator limit (Aerotech Part-Speed PSO)
    // derived
    static constexpr int W_DIST = D_INT + D_FRAC;                    // 56, unsigned
    static constexpr int W_REM = D_INT + 2 + D_FRAC;                 // 58, signed
    static constexpr int W_K = clog2p1(K_MAX);                       // 5, K register
    static constexpr int W_WIN = W_K + 1;                            // 6, signed travel -K..K
    static constexpr int S_MAX = N_AXES * K_MAX * K_MAX;             // 768
    static constexpr int W_S = clog2p1(S_MAX);                       // 10, ROM address
    static constexpr int W_SQ = clog2p1(K_MAX * K_MAX);              // 9, |Dn_i|^2 (a term of s)
    static constexpr int W_CHORD = clog2p1(2 * K_MAX - 1) + D_FRAC;  // 37: sqrt(3)*K < 2K - 1
    static constexpr int W_INCR = W_CHORD + 1;                       // 38: Y, estimate step (< 2 chords)
    static constexpr int W_ADDR = clog2p1(ARR_DEPTH - 1);            // 6
    static constexpr int W_LEN = clog2p1(ARR_DEPTH);                 // 7
    static constexpr int W_PROD = W_INC + W_GAP;                     // 48, inc * min_period
    static constexpr int W_SPHI = W_INC + 1;                         // 33, upper part of the shift-add
    static constexpr int FIRE_LAT = 7;                               // calls from a step to its fire
    static constexpr int REG_LAT = 1;                                // calls from presenting a register to its use
    static constexpr int SP_LAT = W_GAP + 1;                         // 17: sample, 16 steps
    static constexpr int W_SPK = clog2p1(W_GAP);                     // 5, spacing step counter
    static constexpr unsigned long long ONE = 1ULL << D_FRAC;        // one count
    static constexpr unsigned long long MIN_DIST = 4ULL << D_FRAC;   // smallest legal threshold (> 2 sqrt3)
    // floor(24 MHz / 100 MHz * 2^32): the largest increment whose carry rate is <= 24 MHz
    static constexpr unsigned long long INC_MAX =
        (static_cast<unsigned long long>(PULSE_HZ_MAX) << W_INC) / static_cast<unsigned long long>(CLOCK_HZ);
    static constexpr unsigned long long GAP_MAX = (1ULL << W_GAP) - 1;
    static constexpr unsigned long long OVL_MAX = (1ULL << W_OVL) - 1;

    using dist_t = uint<W_DIST>;
    using rem_t = sint<W_REM>;
    using chord_t = uint<W_CHORD>;
    using win_t = sint<W_WIN>;
    using s_t = uint<W_S>;
    using sq_t = uint<W_SQ>;
    using k_t = uint<W_K>;
    using pw_t = uint<W_PW>;
    using gap_t = uint<W_GAP>;
    using inc_t = uint<W_INC>;
    using fcnt_t = uint<W_FCNT>;
    using ovl_t = uint<W_OVL>;
    using addr_t = uint<W_ADDR>;
    using len_t = uint<W_LEN>;
    using prod_t = uint<W_PROD>;
    using incr_t = uint<W_INCR>;
    using sphi_t = uint<W_SPHI>;
    using spk_t = uint<W_SPK>;
    using mask_t = uint<N_AXES>;
    static constexpr int W_SRC = 2;                                  // window source register
    using src_t = uint<W_SRC>;  // window source: 0..2 axis position, 3 part-speed pulse count
    using bad_t = uint<ARR_DEPTH>;
};

// Chord ROM: chord[s] = round(sqrt(s) * 2^D_FRAC), s = 0..S_MAX, computed at compile time with
// the digit-by-digit integer square root (two radicand bits per iteration, 64-bit arithmetic: the
// partial remainder stays below 2 * root + 1 < 2^40). Ties cannot occur (sqrt(s) * 2^32 is an
// integer or irrational), so "round to nearest" needs no tie rule: root + 1 when the remainder
// x - root^2 exceeds root. The words are the INIT of the ROM's block RAM (lx::ram_list: count,
// word(s)); the ROM is pso_chord_rom_t, 769 words of W_CHORD = 37 bits, read-only, one port.
struct pso_chord_rom {
    static constexpr uint64_t round_sqrt(uint64_t s) {
        constexpr int s_pairs = (pso_cfg::W_S + 1) / 2;
        uint64_t root = 0;
        uint64_t rem = 0;
        for (int i = 0; i < s_pairs + pso_cfg::D_FRAC; ++i) {
            const uint64_t pair = i < s_pairs ? (s >> (2 * (s_pairs - 1 - i))) & 3u : 0u;
            rem = (rem << 2) | pair;
            const uint64_t trial = (root << 2) | 1u;
            if (rem >= trial) {
                rem -= trial;
                root = (root << 1) | 1u;
            } else {
                root <<= 1;
            }
        }
        return rem > root ? root + 1 : root;
    }
    static constexpr int count = pso_cfg::S_MAX + 1;
    static constexpr uint64_t word(int s) { return round_sqrt(static_cast<uint64_t>(s)); }
};
// W_CHORD is the real width of the words: the largest word needs all of its bits
static_assert(pso_chord_rom::round_sqrt(pso_cfg::S_MAX) < (1ULL << pso_cfg::W_CHORD) &&
                  pso_chord_rom::round_sqrt(pso_cfg::S_MAX) >= (1ULL << (pso_cfg::W_CHORD - 1)),
              "chord ROM: the largest word is W_CHORD bits wide");
using pso_chord_rom_t = ram<pso_cfg::chord_t, pso_chord_rom::count, RAM_1P,
                            ram_list<pso_cfg::chord_t, pso_chord_rom::count, pso_chord_rom>>;

// Register block (s_axilite). part_speed, arr_en, arr_len, arr_wrap and axis_mask are latched
// at the rising edge of the run state (enable with a valid configuration); the others act live.
// Every value is in force one call after it is presented (the block's register stage).
struct pso_regs {
    bool enable = false;
    bool part_speed = false;
    pso_cfg::mask_t axis_mask = 3;
    pso_cfg::k_t win_k = 16;
    pso_cfg::dist_t fire_dist = 128ULL << pso_cfg::D_FRAC;  // 128 counts = 10 um
    bool arr_en = false;
    pso_cfg::len_t arr_len = 1;
    bool arr_wrap = false;
    bool arr_we = false;  // array write port (acts in every call, also while disabled)
    pso_cfg::addr_t arr_addr = 0;
    pso_cfg::dist_t arr_data = 0;
    pso_cfg::pw_t pulse_w = 10;
    bool win_en = false;
    pso_cfg::src_t win_src = 0;
    pos_t win_low = 0;
    pos_t win_high = 0;
    pso_cfg::gap_t min_period = 0;  // laser minimum pulse period in clocks, 0 = no check
    bool clear = false;             // clears the sticky flags and the overlap counter
};

// Per-axis arrays are listed element by element: neither vendor integer type zeroes itself, so
// an array member needs an initialiser for each element.
static_assert(pso_cfg::N_AXES == 3, "the per-axis initialisers below list three axes");

struct pso_in {
    step_t step[pso_cfg::N_AXES] = {0, 0, 0};  // tracked axis steps (-1, 0, +1)
    pos_t pos[pso_cfg::N_AXES] = {0, 0, 0};    // axis positions after the step (window comparison)
    pso_cfg::inc_t ps_inc = 0;                 // part-speed commanded vector rate, Q0.32 counts per clock
};

// Configuration check (combinational, every call; a constant expression with the own integer
// types, so that the register stage's initial check is a constant).
inline LX_CONSTEXPR bool pso_config_ok(const pso_regs& r, pso_cfg::bad_t arr_bad) {
    const bool k_ok = r.win_k >= 1 && r.win_k <= pso_cfg::K_MAX;
    const bool axes_ok = r.part_speed || r.axis_mask != 0;
    bool thr_ok = false;
    if (r.arr_en) {
        const bool len_ok = r.arr_len >= 1 && r.arr_len <= pso_cfg::ARR_DEPTH;
        pso_cfg::bad_t used = ~pso_cfg::bad_t(0);
        if (len_ok && r.arr_len < pso_cfg::ARR_DEPTH) used = (pso_cfg::bad_t(1) << r.arr_len.to_uint()) - 1;
        thr_ok = len_ok && (arr_bad & used) == 0;
    } else {
        thr_ok = r.fire_dist >= pso_cfg::MIN_DIST;
    }
    const bool win_ok = !r.win_en || (r.win_low <= r.win_high && (r.win_src != 3 || r.part_speed));
    return k_ok && axes_ok && thr_ok && win_ok && r.pulse_w >= 1;
}

// The registers of lx::pso, grouped by their reset as the always blocks of rtl_ref/pso.v. The
// default member initialisers are the reset values (the power-up state: no constructor, CTest
// hls_const_init); a reset of a group assigns its initialisers:
//   pso_track_regs  the tracking state: reset by enable = 0, an invalid configuration and i_rst
//                   (rtl_ref rst_trk; there the index registers take the array length presented)
//   pso_count_regs  counters and sticky flags: reset by an invalid configuration and i_rst
//                   (rtl_ref rst_cfg; kept while disabled)
//   pso_stage_regs  the register stage, its check, the bad-entry map and the copy of entry 0:
//                   reset by i_rst only
// The RAMs and the registers without a reset (the threshold prefetch, the thresholds) are members
// of lx::pso itself.
struct pso_track_regs {
    using cfg = pso_cfg;
    // stage A
    cfg::win_t trav_[cfg::N_AXES] = {0, 0, 0};
    bool a_rev_ = false, a_kclose_ = false, a_pulse_ = false, a_inwin_ = false, a_v_ = false;
    cfg::sq_t a_sq_[cfg::N_AXES] = {0, 0, 0};  // |Dn_i|^2 of this call's travel (the ROM address's terms)
    cfg::inc_t ph_ = 0;
    pos_t ps_cnt_ = 0;
    // minimum-spacing product (sequenced)
    cfg::spk_t sp_k_ = 0;
    bool sp_full_ = false;
    cfg::inc_t sp_inc_ = 0;
    cfg::gap_t sp_min_ = 0;
    cfg::dist_t sp_thr_ = 0;
    cfg::sphi_t sp_hi_ = 0;
    cfg::gap_t sp_lo_ = 0;
    // stage Q (the ROM address itself is in the ROM's block RAM)
    bool q_rev_ = false, q_kclose_ = false, q_pulse_ = false, q_inwin_ = false, q_v_ = false;
    // stage R
    cfg::incr_t r_y_ = 0;    // Y: the estimate step of the entry
    cfg::chord_t part_ = 0;  // chord of the open window
    bool r_inwin_ = false, r_v_ = false;
    // stage B1 (the differences for the two prefetched thresholds)
    cfg::incr_t p_y_ = 0;
    cfg::rem_t p_d1_ = 0, p_d2_ = 0;  // Y - th1, Y - th2
    bool p_inwin_ = false, p_v_ = false;
    // stage P (the loop operands)
    cfg::incr_t b_y_ = 0;
    cfg::rem_t b_opF0_ = 0;  // Y - thF0
    bool b_inwin_ = false, b_v_ = false;
    // stage B2 (the loop, the decision and the state it moves)
    cfg::rem_t u_ = 0;       // value - thr of the entry held (the next to be decided)
    bool u_v_ = false, u_inwin_ = false;
    bool adv_ = false;       // the last call's decision moved the index
    bool mv_ = false;        // the index moved in one of the last two calls (P's pick)
    cfg::len_t idx_p_ = 0;   // the index before the last call's move, and next .. next^4 of it
    cfg::len_t nx_p_ = 0, nx2_p_ = 0, nx3_p_ = 0, nx4_p_ = 0;
    bool stop0_ = false;     // a fire ends the array (arr_en, no wrap, the last entry) at this
                             //   call's index without the last call's move
    bool done_ = false;
    bool c_fire_ = false, c_inwin_ = false, c_live_ = false;
    cfg::rem_t c_u_ = 0;     // u of the decision
    cfg::dist_t c_tm_ = 0;   // its threshold if it did not fire, else 0
    // stage B3 (outputs)
    cfg::rem_t dist_ = 0;
    cfg::len_t idx_o_ = 0;
    bool done_o_ = false;
    cfg::pw_t timer_ = 0;
    cfg::gap_t since_ = cfg::GAP_MAX;  // (the first emit is never early)
    // run state and latched mode registers
    bool run_q_ = false, ps_q_ = false, arr_en_q_ = false, arr_wrap_q_ = false;
    cfg::mask_t mask_q_ = 0;
    cfg::len_t arr_len_q_ = 1;
};

struct pso_count_regs {
    pso_cfg::fcnt_t fire_cnt_ = 0;
    pso_cfg::ovl_t ovl_cnt_ = 0;
    bool overlap_st_ = false, rate_over_st_ = false, spacing_st_ = false, freq_st_ = false;
};

struct pso_stage_regs {
    // the register values in force (presented in the last call) and their configuration check
    pso_regs rq_;
    bool ok_q_ = pso_config_ok(pso_regs{}, ~pso_cfg::bad_t(0));  // (true: the reset values are legal)
    // "entry below the minimum distance" bitmap, after the writes presented so far (one call
    // ahead of the RAM): every entry at power-up (the RAM content is not a legal distance)
    pso_cfg::bad_t arr_bad_ = ~pso_cfg::bad_t(0);
    pso_cfg::dist_t entry0_ = 0;  // copy of entry 0 as the RAM stands (the start threshold in array mode)
};

class pso : private pso_track_regs, private pso_count_regs, private pso_stage_regs {
public:
    using cfg = pso_cfg;
    struct out_t {
        bool fire = false;          // the tracked distance crossed the threshold (stage B3)
        bool emit = false;          // fire inside the window: a pulse starts
        bool pulse = false;         // output level (pulse_w calls from the emit)
        bool in_win = false;        // window condition used by this call's fire
        cfg::rem_t dist = 0;    // distance since the last fire, Q.32 counts (after this call's fire)
        cfg::len_t idx = 0;     // array: index of the entry that gives the next threshold
        bool arr_done = false;      // array without wrap: every entry has fired
        cfg::fcnt_t fire_cnt = 0;     // emitted pulses (wraps)
        cfg::ovl_t overlap_cnt = 0;   // emits while the previous pulse was still high (saturating)
        bool overlap = false, overlap_st = false;
        bool rate_over = false, rate_over_st = false;   // part-speed command above 24 MHz (clamped)
        bool spacing_err = false, spacing_st = false;   // threshold below rate * min_period (part-speed)
        bool freq_err = false, freq_st = false;         // emit fewer than min_period calls after the previous one
        bool ps_pulse = false;                  // pulse-generator output of this call
        pos_t ps_count = 0;                 // pulse-generator count since the run started
        bool cfg_err = false;
    };

    // rtl_ref i_rst: the register stage at the reset values (a legal configuration), every array
    // entry "not written", the tracking state, counters and flags in reset. The RAM contents are
    // kept (no RAM reset), and so are the registers rtl_ref does not reset (the prefetch and the
    // thresholds: nothing reads them before they are loaded again).
    void reset() {
        static_cast<pso_stage_regs&>(*this) = pso_stage_regs{};
        static_cast<pso_track_regs&>(*this) = pso_track_regs{};
        static_cast<pso_count_regs&>(*this) = pso_count_regs{};
    }

    // rp: the register values presented in this call; they are in force in the next call
    // (register stage, docs/PSO_COUNTERS.md §2.2), with their configuration check formed now.
    out_t step(const pso_in& in, const pso_regs& rp) {
#pragma HLS BIND_STORAGE variable = rom_.m_.w type = rom_1p impl = bram
#pragma HLS BIND_STORAGE variable = arr1_.m_.w type = ram_s2p impl = bram
#pragma HLS BIND_STORAGE variable = arr2_.m_.w type = ram_s2p impl = bram
#pragma HLS BIND_STORAGE variable = arr3_.m_.w type = ram_s2p impl = bram
        rom_.next_call();
        arr1_.next_call();
        arr2_.next_call();
        arr3_.next_call();
        const pso_regs r = rq_;    // the values in force (presented in the last call)
        const bool cfg_ok = ok_q_; // their check, formed in the last call
        const bool run = run_q_;   // the last call ran (this one continues the run)
        // ---- every call, as rtl_ref (no reset, no enable): the RAM ports, the threshold
        // prefetch, the threshold registers. The stages below read these registers as they were
        // before the call:
        const cfg::dist_t th1 = th1_, th2 = th2_;    // B1's thresholds (prefetched in the last call)
        const cfg::dist_t thr = thr_;                // the threshold of the next fire
        const cfg::dist_t thr_now = run ? thr : st_; // the same in a run's first call (spacing sample)
        const bool mv = mv_;                         // P's pick: the index moved in one of the last two calls
        // chord ROM: stage R's chord is the word read in the last call; stage Q's address
        // s = sum |Dn_i|^2 of stage A's squares goes into the ROM's address register now (its
        // word is stage R's chord in the next call)
        const cfg::chord_t chord = rom_.q<0>();
        const cfg::s_t s = cfg::s_t(cfg::s_t(a_sq_[0]) + a_sq_[1]) + a_sq_[2];
        rom_.read<0>(s.to_uint());
        // the array index of this call (after the decisions up to the last call): the index
        // registers hold the index before the last call's move and next .. next^4 of it, adv_ is
        // that move (a decision goes into the one register adv_)
        const cfg::len_t idx_l = adv_ ? nx_p_ : idx_p_;
        const cfg::len_t nx_l = adv_ ? nx2_p_ : nx_p_;
        const cfg::len_t nx2_l = adv_ ? nx3_p_ : nx2_p_;
        const cfg::len_t nx3_l = adv_ ? nx4_p_ : nx3_p_;
        const cfg::len_t nx4_l = adv_ ? next_idx(nx4_p_, arr_len_q_) : nx4_p_;
        // threshold prefetch for the next call's B1: the words the three array copies returned
        // (entries next .. next^3 of the last call's index) with the write presented in the last
        // call forwarded (made after the read: read-first), shifted by the last call's move:
        // entries next(idx), next^2(idx) of this call, as the RAM stands in this call; then the
        // write presented now (in force in the next call) forwarded into them, or fire_dist
        // presented now outside array mode. The first operands of a run take the start
        // threshold thr (nf: the next call's B1 makes them).
        const cfg::dist_t e1 = fw1_ ? f_data_ : arr1_.q<0>();
        const cfg::dist_t e2 = fw2_ ? f_data_ : arr2_.q<0>();
        const cfg::dist_t e3 = fw3_ ? f_data_ : arr3_.q<0>();
        const bool arr_en_e = run ? arr_en_q_ : r.arr_en;  // array mode of this call (latched in a run)
        const bool nf = q_v_ && !r_v_;
        const bool pw1 = rp.arr_we && arr_en_e && !nf && rp.arr_addr == cfg::addr_t(nx_l);
        const bool pw2 = rp.arr_we && arr_en_e && rp.arr_addr == cfg::addr_t(nx2_l);
        const cfg::dist_t q1 = nf ? thr : arr_en_e ? (adv_ ? e2 : e1) : rp.fire_dist;
        const cfg::dist_t q2 = arr_en_e ? (adv_ ? e3 : e2) : rp.fire_dist;
        th1_ = pw1 ? rp.arr_data : q1;
        th2_ = pw2 ? rp.arr_data : q2;
        // the array: one read per copy (next, next^2, next^3 of this call's index), then the write
        // presented now into all three (after the reads: read-first, so a read of the written
        // address returns the old word; fwk_ marks it for the forward above in the next call)
        arr1_.read<0>(cfg::addr_t(nx_l).to_uint());
        arr2_.read<0>(cfg::addr_t(nx2_l).to_uint());
        arr3_.read<0>(cfg::addr_t(nx3_l).to_uint());
        fw1_ = rp.arr_we && rp.arr_addr == cfg::addr_t(nx_l);
        fw2_ = rp.arr_we && rp.arr_addr == cfg::addr_t(nx2_l);
        fw3_ = rp.arr_we && rp.arr_addr == cfg::addr_t(nx3_l);
        f_data_ = rp.arr_data;
        if (rp.arr_we) {
            arr1_.write(rp.arr_addr.to_uint(), rp.arr_data);
            arr2_.write(rp.arr_addr.to_uint(), rp.arr_data);
            arr3_.write(rp.arr_addr.to_uint(), rp.arr_data);
        }
        // the threshold of the next fire: in every call without a run the start threshold st_
        // (so thr_ holds it from a run's call 1 on), in a run the threshold of a take, decided
        // from the B2 registers (u >= 0, operands held, no fire in the last call, not done, the
        // fire would not end the array: a fire or the run start takes the next threshold)
        const bool take = u_ >= 0 && b_v_ && !c_fire_ && !done_ && !stop0_;
        if (!run) {
            thr_ = st_;
        } else if (take) {
            thr_ = b_thF0_;
        }
        // the start threshold of a run beginning in the next call: fire_dist presented now, or
        // entry 0 after the write presented now (entry0_, a register copy of entry 0)
        st_ = start_thr(rp);
        if (rp.arr_we && rp.arr_addr == 0) entry0_ = rp.arr_data;
        // register stage: the bad-entry map after the presented write (one call ahead of the
        // RAM), the check of the presented values against it
        if (rp.arr_we) {
            const cfg::bad_t bit = cfg::bad_t(1) << rp.arr_addr.to_uint();
            arr_bad_ = (rp.arr_data < cfg::MIN_DIST) ? cfg::bad_t(arr_bad_ | bit) : cfg::bad_t(arr_bad_ & ~bit);
        }
        ok_q_ = pso_config_ok(rp, arr_bad_);
        rq_ = rp;
        out_t o;  // every field 0 / false (default member initialisers)
        if (!cfg_ok) {  // everything but the RAMs, the register stage and the bad-entry map
            reset_track(rp);
            reset_counts();
            o.cfg_err = true;
            return o;
        }
        if (r.clear) {  // clear acts first; an event of this call sets its flag again
            overlap_st_ = false;
            rate_over_st_ = false;
            spacing_st_ = false;
            freq_st_ = false;
            ovl_cnt_ = 0;
        }
        if (!r.enable) {
            reset_track(rp);
            fill_status(o);
            return o;
        }
        if (!run_q_) {  // start of a run: latch the mode registers
            ps_q_ = r.part_speed;
            mask_q_ = r.axis_mask;
            arr_en_q_ = r.arr_en;
            arr_len_q_ = r.arr_len;
            arr_wrap_q_ = r.arr_wrap;
            run_q_ = true;
        }
        // ---- stage B3 (from the B2 registers): apply the decision of the last call ----
        const bool fire = c_fire_;
        const bool emit = fire && c_inwin_;
        const bool overlap = emit && timer_ != 0;
        const bool freq_err = emit && r.min_period != 0 && since_ + 1 < r.min_period;
        if (emit) {
            timer_ = r.pulse_w;
            since_ = 0;
            fire_cnt_ = fire_cnt_ + 1;
        } else {
            if (timer_ != 0) timer_ = timer_ - 1;
            if (since_ != cfg::GAP_MAX) since_ = since_ + 1;
        }
        if (overlap) {
            overlap_st_ = true;
            if (ovl_cnt_ != cfg::OVL_MAX) ovl_cnt_ = ovl_cnt_ + 1;
        }
        if (freq_err) freq_st_ = true;
        const bool in_win_used = c_inwin_;
        // c_u_ is u of the last decision, c_tm_ its threshold if it did not fire (else 0)
        if (c_live_) dist_ = c_u_ + cfg::rem_t(c_tm_.to_uint64());
        idx_o_ = idx_l;
        done_o_ = done_;

        // ---- stage B2 (from the P registers): the loop on u, decision, array index ----
        // (no fire in the call after a fire: `fire` is the last call's decision. With thresholds
        // >= MIN_DIST it never acts, u < 0 after a fire; so a fire never follows a move of the
        // last call: b_opF0_ is the operand for the index as it stands, and stop0_, formed in
        // the last call for the index without its move, says whether this decision ends the
        // array. The take of the next threshold is above, with the threshold register.)
        const bool pos = u_ >= 0 && !fire;
        const bool dec = u_v_ && !done_ && pos;  // value - thr >= 0
        const bool moved = dec && arr_en_q_ && !stop0_;
        c_fire_ = dec;
        c_inwin_ = u_inwin_;
        c_live_ = u_v_ && !done_;
        c_u_ = u_;
        c_tm_ = pos ? cfg::dist_t(0) : thr;
        u_ = pos ? cfg::rem_t(u_.to_int64() + b_opF0_.to_int64()) : cfg::rem_t(u_.to_int64() + static_cast<int64_t>(b_y_.to_uint64()));
        if (dec && stop0_) done_ = true;
        // the index registers: this call's index and next .. next^4 of it; the move goes into
        // adv_ alone; "a fire here ends the array" for the next call (its index without a move)
        idx_p_ = idx_l;
        nx_p_ = nx_l;
        nx2_p_ = nx2_l;
        nx3_p_ = nx3_l;
        nx4_p_ = nx4_l;
        stop0_ = arr_en_q_ && !arr_wrap_q_ && nx_l == 0;
        mv_ = moved || adv_;
        adv_ = moved;
        u_v_ = b_v_;
        u_inwin_ = b_inwin_;

        // ---- stage P (from the B1 registers): the loop operands, picked by the index moves of
        // the last two calls (at most one of them moved: no fire in two calls in a row; B1's
        // candidates are for the index before both) ----
        b_y_ = p_y_;
        b_opF0_ = mv ? p_d2_ : p_d1_;
        b_thF0_ = mv ? p_th2_ : p_th1_;
        b_inwin_ = p_inwin_;
        b_v_ = p_v_;

        // ---- stage B1 (from the R registers and the prefetch): Y - th for the two prefetched
        // thresholds (entries next, next^2 of the last call's index before its move, or
        // fire_dist; 0 until R holds data) ----
        if (r_v_) {
            const int64_t y_v = static_cast<int64_t>(r_y_.to_uint64());
            p_y_ = r_y_;
            p_d1_ = y_v - static_cast<int64_t>(th1.to_uint64());
            p_d2_ = y_v - static_cast<int64_t>(th2.to_uint64());
        } else {
            p_y_ = 0;
            p_d1_ = 0;
            p_d2_ = 0;
        }
        p_th1_ = th1;
        p_th2_ = th2;
        p_inwin_ = r_v_ && r_inwin_;
        p_v_ = r_v_;

        // ---- stage R: the ROM word of stage Q's address (read in the last call), the estimate
        // step; 0 while Q holds no data (the ROM's output register is not reset) ----
        if (q_v_) {
            const uint64_t one = q_pulse_ ? cfg::ONE : 0;
            // Y = est - est of the previous entry: this entry's chord (plus a generator pulse),
            // less the open chord it extends (a reversal closed that one, a K close left none); >= 0
            r_y_ = chord.to_uint64() + one - (q_rev_ ? uint64_t(0) : part_.to_uint64());
            part_ = q_kclose_ ? cfg::chord_t(0) : chord;
        } else {
            r_y_ = 0;
            part_ = 0;
        }
        r_inwin_ = q_inwin_;
        r_v_ = q_v_;

        // ---- stage Q: the flags of the ROM word read above (its address from stage A's squares) ----
        q_rev_ = a_rev_;
        q_kclose_ = a_kclose_;
        q_pulse_ = a_pulse_;
        q_inwin_ = a_inwin_;
        q_v_ = a_v_;

        // ---- stage A: part-speed generator and tracking window for this call's steps ----
        bool ps_pulse = false;
        bool rate_over = false;
        bool spacing_err = false;
        if (ps_q_) {
            rate_over = in.ps_inc > cfg::INC_MAX;
            const cfg::inc_t inc = rate_over ? cfg::inc_t(cfg::INC_MAX) : in.ps_inc;
            const uint<cfg::W_INC + 1> sum = uint<cfg::W_INC + 1>(ph_) + inc;
            ps_pulse = (sum >> cfg::W_INC) != 0;
            ph_ = sum;  // keeps the low W_INC bits
            if (ps_pulse) ps_cnt_ = ps_cnt_ + 1;
            // minimum spacing, sequenced: a sample call (k = 0) shows the check of the previous
            // sample and loads the operands; steps i = 0..15 in the next 16 calls (one 33-bit add
            // each, LSB first: hi += bit i of min_period ? inc : 0, then {hi, lo} >>= 1)
            if (sp_k_ == 0) {
                const uint64_t prod = (sp_hi_.to_uint64() << cfg::W_GAP) | sp_lo_.to_uint64();
                spacing_err = sp_full_ && sp_min_ != 0 && sp_thr_.to_uint64() < prod;
                sp_full_ = true;
                sp_inc_ = inc;
                sp_min_ = r.min_period;
                sp_thr_ = thr_now;
                sp_hi_ = 0;
                sp_lo_ = 0;
                sp_k_ = 1;
            } else {
                const unsigned i = sp_k_.to_uint() - 1;
                const cfg::sphi_t sh = sp_hi_ + (((sp_min_ >> i) & 1) != 0 ? sp_inc_ : cfg::inc_t(0));
                sp_lo_ = (sp_lo_ >> 1) | (cfg::gap_t(sh & 1) << (cfg::W_GAP - 1));
                sp_hi_ = sh >> 1;
                sp_k_ = sp_k_ == cfg::W_GAP ? cfg::spk_t(0) : cfg::spk_t(sp_k_ + 1);
            }
        }
        if (rate_over) rate_over_st_ = true;
        if (spacing_err) spacing_st_ = true;

        bool rev = false;
        cfg::win_t d[cfg::N_AXES];
#pragma hls_unroll yes
        LX_LOOP(axis_step) for (int i = 0; i < cfg::N_AXES; ++i) {
#pragma HLS UNROLL
            const bool tracked = !ps_q_ && ((mask_q_ >> i) & 1) != 0;
            d[i] = tracked ? cfg::win_t(in.step[i]) : cfg::win_t(0);
            if (d[i] != 0 && trav_[i] != 0 && (d[i] > 0) != (trav_[i] > 0)) rev = true;
        }
        bool kclose = false;
        cfg::win_t dn[cfg::N_AXES];
#pragma hls_unroll yes
        LX_LOOP(axis_travel) for (int i = 0; i < cfg::N_AXES; ++i) {
#pragma HLS UNROLL
            dn[i] = (rev ? cfg::win_t(0) : trav_[i]) + d[i];
            const cfg::k_t mag = dn[i] < 0 ? cfg::k_t(-dn[i]) : cfg::k_t(dn[i]);
            if (mag >= r.win_k) kclose = true;
            a_sq_[i] = cfg::sq_t(uint<2 * cfg::W_K>(mag) * mag);  // a 5-bit square: a table
        }
#pragma hls_unroll yes
        LX_LOOP(axis_close) for (int i = 0; i < cfg::N_AXES; ++i) {
#pragma HLS UNROLL
            trav_[i] = kclose ? cfg::win_t(0) : dn[i];
        }
        a_rev_ = rev;
        a_kclose_ = kclose;
        a_pulse_ = ps_pulse;
        a_v_ = true;
        bool inw = true;
        if (r.win_en) {
            const pos_t wp = r.win_src == 3 ? ps_cnt_ : in.pos[r.win_src.to_uint()];
            inw = r.win_low <= wp && wp <= r.win_high;
        }
        a_inwin_ = inw;

        o.fire = fire;
        o.emit = emit;
        o.in_win = in_win_used;
        o.overlap = overlap;
        o.rate_over = rate_over;
        o.spacing_err = spacing_err;
        o.freq_err = freq_err;
        o.ps_pulse = ps_pulse;
        fill_status(o);
        return o;
    }

    // the host's side (C simulation and tests, between calls; never reached from the synthesis
    // top): a word of the chord ROM as stored, and the sticky RAM-rule flags (lx_ram.h)
    cfg::chord_t chord_word(unsigned s) const { return rom_.peek(s); }
#ifndef __SYNTHESIS__
    int ram_violations() const {
        return rom_.violations() | arr1_.violations() | arr2_.violations() | arr3_.violations();
    }
#endif

private:
    // The threshold a run starting in the next call takes: fire_dist presented now, or entry 0
    // after the write presented now (entry0_ holds entry 0 as the RAM stands in this call).
    cfg::dist_t start_thr(const pso_regs& rp) const {
        if (!rp.arr_en) return rp.fire_dist;
        return (rp.arr_we && rp.arr_addr == 0) ? rp.arr_data : entry0_;
    }

    // the array index after i: i + 1, or 0 after the last entry of an array of len entries
    static cfg::len_t next_idx(const cfg::len_t& i, const cfg::len_t& len) {
        const unsigned n = i.to_uint() + 1u;
        return n >= len.to_uint() ? cfg::len_t(0) : cfg::len_t(n);
    }

    // the counters and sticky flags (reset by an invalid configuration, kept while disabled)
    void reset_counts() { static_cast<pso_count_regs&>(*this) = pso_count_regs{}; }

    // The tracking state in reset (enable = 0, an invalid configuration), with the index
    // registers at index 0 and next .. next^4 of it for the array length presented now (in force
    // in the next call, which may start a run and latch it).
    void reset_track(const pso_regs& rp) {
        static_cast<pso_track_regs&>(*this) = pso_track_regs{};
        nx_p_ = next_idx(0, rp.arr_len);
        nx2_p_ = next_idx(nx_p_, rp.arr_len);
        nx3_p_ = next_idx(nx2_p_, rp.arr_len);
        nx4_p_ = next_idx(nx3_p_, rp.arr_len);
        stop0_ = rp.arr_en && !rp.arr_wrap && nx_p_ == 0;
    }

    void fill_status(out_t& o) const {
        o.pulse = timer_ != 0;
        o.dist = dist_;
        o.idx = idx_o_;
        o.arr_done = done_o_;
        o.fire_cnt = fire_cnt_;
        o.overlap_cnt = ovl_cnt_;
        o.overlap_st = overlap_st_;
        o.rate_over_st = rate_over_st_;
        o.spacing_st = spacing_st_;
        o.freq_st = freq_st_;
        o.ps_count = ps_cnt_;
    }

    // chord ROM (block RAM, RAM_1P read-only: one read per call, its output register is stage R's
    // chord)
    pso_chord_rom_t rom_;
    // firing-distance array: three copies (block RAM, RAM_S2P: one read and the shared write per
    // call each), read at next, next^2, next^3 of the index; their power-up contents are zero
    // ("not written": arr_bad_)
    using arr_ram_t = ram<cfg::dist_t, cfg::ARR_DEPTH, RAM_S2P>;
    arr_ram_t arr1_, arr2_, arr3_;
    // registers without a reset in rtl_ref (0 at power-up)
    bool fw1_ = false, fw2_ = false, fw3_ = false;  // the write presented with the read hit its address
    cfg::dist_t f_data_ = 0;         // the data of that write
    cfg::dist_t th1_ = 0, th2_ = 0;  // B1's thresholds: entries next(idx), next^2(idx) of the last
                                     //   call (before its move), or fire_dist (rtl_ref: inverted)
    cfg::dist_t p_th1_ = 0, p_th2_ = 0;  // B1's copy of them (used by a take only: valid operands)
    cfg::dist_t b_thF0_ = 0;         // P's pick: the threshold after a fire
    cfg::dist_t thr_ = 0;            // threshold of the next fire (taken at a fire, st_ without a run)
    cfg::dist_t st_ = 0;             // the start threshold of a run beginning in this call
};

}  // namespace lx

#endif  // LASERAX_HLS_PSO_H
