// golden/dds_sincos.cpp — see dds_sincos.h (DESIGN.md 4.6).
#include "golden/dds_sincos.h"

#include <cmath>

namespace golden {

namespace {

constexpr long double kPi = 3.141592653589793238462643383279502884197L;

// true modulo, result in [0, m) (m > 0; m <= 0 is an invalid configuration, returns 0)
int64_t mod(int64_t x, int64_t m) { return m > 0 ? ((x % m) + m) % m : 0; }

// Exact values of sin/cos(2*pi*j/12), j = 0..11, where they are rational (0, +-1/2, +-1);
// `rational` is false where the value is +-sqrt(3)/2 (irrational: computed with sin/cos).
struct exact_val {
    bool rational;
    long double v;
};
constexpr exact_val kSin12[12] = {{true, 0.0L},  {true, 0.5L},   {false, 0.0L}, {true, 1.0L},
                                  {false, 0.0L}, {true, 0.5L},   {true, 0.0L},  {true, -0.5L},
                                  {false, 0.0L}, {true, -1.0L},  {false, 0.0L}, {true, -0.5L}};
constexpr exact_val kCos12[12] = {{true, 1.0L},  {false, 0.0L}, {true, 0.5L},   {true, 0.0L},
                                  {true, -0.5L}, {false, 0.0L}, {true, -1.0L},  {false, 0.0L},
                                  {true, -0.5L}, {true, 0.0L},  {true, 0.5L},   {false, 0.0L}};

// sin (want_cos = false) or cos (want_cos = true) of 2*pi*k/P, k in [0, P)
long double sincos_turn(int64_t k, int64_t P, bool want_cos) {
    if ((12 * k) % P == 0) {
        const int64_t j = (12 * k) / P;  // angle = j * 30 degrees, j in [0, 12)
        const exact_val e = want_cos ? kCos12[j] : kSin12[j];
        if (e.rational) return e.v;
    }
    const long double x = 2.0L * kPi * static_cast<long double>(k) / static_cast<long double>(P);
    return want_cos ? std::cos(x) : std::sin(x);
}

int64_t rha(long double v) { return static_cast<int64_t>(std::llround(v)); }  // half away from 0

}  // namespace

void dds_sincos::reset() {
    ph_ = 0;
    s1_ = 0;
    c1_ = 0;
    sin_q_ = 0;
    cos_q_ = 0;
}

void dds_sincos::codes(int64_t k, int64_t P, int64_t amplitude, int64_t& s, int64_t& c) {
    const long double amp = static_cast<long double>(amplitude);
    if (P > kMemoMaxP) {
        s = rha(amp * sincos_turn(k, P, false));
        c = rha(amp * sincos_turn(k, P, true));
        return;
    }
    if (P != memo_P_ || amplitude != memo_amp_) {  // a new (P, amp): every entry is stale
        memo_P_ = P;
        memo_amp_ = amplitude;
        if (++memo_gen_ == 0) {  // generation wrapped: clear explicitly
            for (memo_entry& e : memo_) e.gen = 0;
            memo_gen_ = 1;
        }
        if (memo_.size() < static_cast<size_t>(P)) memo_.resize(static_cast<size_t>(P));
    }
    memo_entry& e = memo_[static_cast<size_t>(k)];
    if (e.gen != memo_gen_) {
        e.s = rha(amp * sincos_turn(k, P, false));
        e.c = rha(amp * sincos_turn(k, P, true));
        e.gen = memo_gen_;
    }
    s = e.s;
    c = e.c;
}

dds_sincos::out dds_sincos::step(int ostep, int64_t period, int64_t amplitude) {
    const int64_t P = period;
    sin_q_ = s1_;  // the output stage: the codes of the previous call
    cos_q_ = c1_;
    if (P > 0) {
        // outputs from the phase before this call's update. Reading: amplitude and P of this
        // call; ph is reduced mod the current P (only matters if P changed while running).
        const int64_t k = mod(ph_, P);
        if (!last_ok_ || k != last_k_ || P != last_P_ || amplitude != last_amp_) {
            codes(k, P, amplitude, last_s_, last_c_);
            last_ok_ = true;
            last_k_ = k;
            last_P_ = P;
            last_amp_ = amplitude;
        }
        s1_ = last_s_;
        c1_ = last_c_;
        ph_ = mod(ph_ + ostep, P);
    } else {
        // invalid configuration (never reached through laserax_top): hold, no division by 0
        s1_ = 0;
        c1_ = 0;
        ph_ = 0;
    }
    return out{sin_q_, cos_q_};
}

}  // namespace golden
