// quad_decoder.h — 4x quadrature decoder for the laser's A/B lines plus the laser error line.
//
// DESIGN §4.2. Each pin passes an input_filter (synchroniser + glitch filter, length glitch_n).
// Decoding is done with XOR logic on the previous and current filtered levels:
//   only A changed: +1 if A' != B' else -1      only B changed: +1 if A' == B' else -1
//   both changed:   illegal (no count, pulse + saturating counter)
// which is forward (+1) for the sequence (A,B) = 00 -> 10 -> 11 -> 01 (A leads B).
// Edge spacing is measured with a saturating counter of clocks since the last counted edge.
// While the laser error line is active the decoder tracks A/B without counting.
//
// Latency pin edge -> step: max(glitch_n,1) + 1 calls.
#ifndef LASERAX_HLS_QUAD_DECODER_H
#define LASERAX_HLS_QUAD_DECODER_H

#include "hls/axis_config.h"
#include "hls/input_filter.h"

namespace lx {

struct quad_decoder_cfg {
    static constexpr int W_GLITCH = 8;    // glitch filter length register
    static constexpr int W_SPACING = 16;  // minimum edge spacing register, clocks
    static constexpr int W_ERRCNT = 8;    // illegal transition counter (saturating)
    static constexpr int W_RAW = axis_widths::W_RAW;
    static constexpr unsigned long long SINCE_MAX = (1ULL << W_SPACING) - 1;
    static constexpr unsigned long long ERRCNT_MAX = (1ULL << W_ERRCNT) - 1;
    using glitch_t = uint<W_GLITCH>;
    using spacing_t = uint<W_SPACING>;
    using errcnt_t = uint<W_ERRCNT>;
};

class quad_decoder {
public:
    using cfg = quad_decoder_cfg;
    struct out_t {
        step_t step = 0;
        raw_t raw_count = 0;
        bool illegal = false;
        bool ovs = false;
        cfg::errcnt_t err_cnt = 0;
        bool illegal_st = false;
        bool ovs_st = false;
        bool lerr = false;
        bool lerr_alarm = false;
        bool glitch_st = false;  // sticky: the A or B glitch filter suppressed a pulse
    };

    void reset() { *this = quad_decoder{}; }  // every register to its initialiser (the reset value)

    // One clock. The pins pass only into the three input filters (their synchronisers).
    out_t step(bool a, bool b, bool lerr, const cfg::glitch_t& glitch_n, const cfg::spacing_t& min_spacing,
               bool clear) {
        const input_filter<cfg::W_GLITCH>::out_t ra = fa_.step(a, glitch_n);
        const input_filter<cfg::W_GLITCH>::out_t rb = fb_.step(b, glitch_n);
        const input_filter<cfg::W_GLITCH>::out_t re = fe_.step(lerr, glitch_n);

        // Clear acts first; events of this call set their flags again (none is hidden).
        if (clear) {
            illegal_st_ = false;
            ovs_st_ = false;
            glitch_st_ = false;
            err_cnt_ = 0;
            if (!re.f) lerr_alarm_ = false;
        }

        step_t step = 0;
        bool illegal = false;
        if (primed_ && !re.f) {
            const bool da = ra.f != pa_;
            const bool db = rb.f != pb_;
            if (da && db) {
                illegal = true;
            } else if (da) {
                step = (ra.f != rb.f) ? step_t(1) : step_t(-1);
            } else if (db) {
                step = (ra.f == rb.f) ? step_t(1) : step_t(-1);
            }
        }
        const bool lerr_now = primed_ && re.f;
        pa_ = ra.f;
        pb_ = rb.f;
        if (!primed_) primed_ = ra.valid;

        // overspeed: close_ (since + 1 < min_spacing) was decided in the previous call, with that
        // call's min_spacing (DESIGN 4.2: the comparator is a register, off the step path)
        const bool ovs = step != 0 && close_;
        count_since(step != 0, min_spacing);
        if (illegal) {
            illegal_st_ = true;
            if (err_cnt_ != cfg::ERRCNT_MAX) err_cnt_ = err_cnt_ + 1;
        }
        if (ovs) ovs_st_ = true;
        if (ra.glitch || rb.glitch) glitch_st_ = true;
        if (lerr_now) lerr_alarm_ = true;
        raw_ = raw_ + step;

        out_t o;
        o.step = step;
        o.raw_count = raw_;
        o.illegal = illegal;
        o.ovs = ovs;
        o.err_cnt = err_cnt_;
        o.illegal_st = illegal_st_;
        o.ovs_st = ovs_st_;
        o.lerr = lerr_now;
        o.lerr_alarm = lerr_alarm_;
        o.glitch_st = glitch_st_;
        return o;
    }

private:
    // the edge spacing counter (reset by a counted step, saturating) and the registered compare
    void count_since(bool counted, cfg::spacing_t min_spacing) {
        if (counted) {
            since_ = 0;
        } else if (since_ != cfg::SINCE_MAX) {
            since_ = inc_below_max(since_);  // (since < SINCE_MAX: no wrap)
        }
        close_ = uint<cfg::W_SPACING + 1>(since_) + 1 < min_spacing;
    }

    input_filter<cfg::W_GLITCH> fa_, fb_, fe_;
    bool pa_ = false;
    bool pb_ = false;
    bool primed_ = false;
    raw_t raw_ = 0;
    cfg::errcnt_t err_cnt_ = 0;
    cfg::spacing_t since_ = cfg::SINCE_MAX;
    bool close_ = false;  // a step in the next call is closer than min_spacing (of this call); reset:
                          // since + 1 = 65536 is never below min_spacing
    bool illegal_st_ = false;
    bool ovs_st_ = false;
    bool lerr_alarm_ = false;
    bool glitch_st_ = false;
};

}  // namespace lx

#endif  // LASERAX_HLS_QUAD_DECODER_H
