// golden/error_map.h — golden model of docs/ERROR_MAP.md (error_map), written from the
// definition, independent of hls/.
//
// Definition: the correction of a position x (output counts) for a bank with table T (values in
// units of 2^-8 count), origin o, spacing s = 2^k and n points is
//     c(x) = T[0] / 256                                   x < o
//            T[n-1] / 256                                 x > o + (n-1) s
//            (T[i] + (T[i+1] - T[i]) * (x - o - i s) / s) / 256, i = floor((x - o) / s), otherwise
// (at x = o + (n-1) s the last point itself), evaluated in long double and rounded to
// corr = floor(c + 1/2). Only the inputs of the sample calls are used: the first call after a
// reset and every kPeriod-th after it (S_MAP = 32); the value of sample call t is returned by
// calls t + kLat - 1 .. (L_MAP = 50, ERROR_MAP.md §6) until the next one is published, and
// before the first publication the outputs are 0 / inactive; it is 0 when that call was not active (map_en && homed && valid geometry of
// the bank selected in that call). delta = corr(t) - corr(t-1).
//
// Exactness: every table value is an integer times 2^-8 with |T| < 2^23, (x - o - i s) is an
// integer below 2^20 and s is a power of two, so c is an integer multiple of 2^-(8+k) (k <= 20)
// with |c| < 2^15: at most 15 + 28 + 1 = 44 significant bits, and every intermediate (the
// product (T[i+1] - T[i]) * (x - o - i s) < 2^44, the quotients by powers of two, the sums, c +
// 1/2) is such a multiple below 2^45 in magnitude. long double (x86-64: 64-bit significand)
// holds all of them exactly, so floorl gives the exact rounded value.
#pragma once
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

namespace golden {

struct error_map_geom {
    int64_t origin = 0;
    int spacing_log2 = 10;
    int n_points = 1024;
};

struct error_map_regs {
    bool map_en = false;
    bool bank_sel = false;
    error_map_geom geom[2];
    bool we = false;        // writes the bank not selected in this call
    int addr = 0;           // 0..kDepth-1
    int32_t data = 0;       // Q15.8 counts, 24-bit signed range
};

class error_map {
public:
    static constexpr int kDepth = 1024;  // points per bank (ERROR_MAP.md §2)
    static constexpr int kPeriod = 32;   // S_MAP: one sample call in kPeriod
    static constexpr int kLat = 50;      // L_MAP: sample call t -> outputs of calls t + kLat - 1 ..
    static constexpr int kFrac = 8;

    struct out {
        int64_t corr = 0;
        int64_t delta = 0;
        bool active = false;
        bool in_range = false;
        bool clamped = false;
        bool cfg_err = false;
    };

    error_map();
    void reset();  // pipeline only, not the tables
    out step(int64_t p, bool homed, const error_map_regs& r);

    // The definition above for one bank (no activity gating): the exact value c(x) and flag.
    static long double interp(const std::vector<int32_t>& tbl, const error_map_geom& g, int64_t x, bool* in_range);
    static bool geom_ok(const error_map_geom& g);

private:
    std::vector<int32_t> tbl_[2];
    long phase_ = 0;           // calls since reset, modulo kPeriod
    long calls_ = 0;           // calls since reset
    // results of sample calls not yet published, oldest first, each with the call (calls_) of
    // its publication (kLat - 1 > kPeriod: up to two are waiting)
    std::deque<std::pair<long, out>> pending_;
    out cur_;                  // published result
    int64_t corr_ = 0;  // corr returned by the previous call
};

}  // namespace golden
