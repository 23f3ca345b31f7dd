// golden/error_map.cpp — see error_map.h (docs/ERROR_MAP.md).
#include "golden/error_map.h"

#include <cmath>

namespace golden {

error_map::error_map() {
    tbl_[0].assign(kDepth, 0);
    tbl_[1].assign(kDepth, 0);
    reset();
}

void error_map::reset() {
    phase_ = 0;
    calls_ = 0;
    pending_.clear();
    cur_ = out{};
    corr_ = 0;
}

bool error_map::geom_ok(const error_map_geom& g) {
    return g.spacing_log2 >= 4 && g.spacing_log2 <= 20 && g.n_points >= 2 && g.n_points <= kDepth;
}

long double error_map::interp(const std::vector<int32_t>& tbl, const error_map_geom& g, int64_t x, bool* in_range) {
    const long double s = std::ldexp(1.0L, g.spacing_log2);
    const long double unit = std::ldexp(1.0L, -kFrac);
    const long double rel = static_cast<long double>(x - g.origin);  // exact: |x - o| < 2^39
    const long double span = static_cast<long double>(g.n_points - 1) * s;
    const size_t last = static_cast<size_t>(g.n_points - 1);
    *in_range = rel >= 0.0L && rel <= span;
    if (rel < 0.0L) return static_cast<long double>(tbl[0]) * unit;       // hold the first point
    if (rel >= span) return static_cast<long double>(tbl[last]) * unit;   // hold the last point
    const long double fi = std::floor(rel / s);
    const size_t i = static_cast<size_t>(fi);
    const long double u = (rel - fi * s) / s;  // position inside the interval, [0, 1)
    const long double a = static_cast<long double>(tbl[i]) * unit;
    const long double b = static_cast<long double>(tbl[i + 1]) * unit;
    return a + (b - a) * u;
}

error_map::out error_map::step(int64_t p, bool homed, const error_map_regs& r) {
    // output of this call: the last published sample result (the one of call t - (kLat - 1)
    // is published in this call)
    if (!pending_.empty() && pending_.front().first == calls_) {
        cur_ = pending_.front().second;
        pending_.pop_front();
    }
    out o = cur_;
    o.delta = o.corr - corr_;
    corr_ = o.corr;
    const bool sample = phase_ == 0;
    phase_ = (phase_ + 1) % kPeriod;

    // a sample call's inputs, published kLat - 1 calls later (the inputs of other calls are not
    // used)
    const int b = r.bank_sel ? 1 : 0;
    if (sample) {
        const error_map_geom& g = r.geom[b];
        out n;
        const bool ok = r.map_en && geom_ok(g);  // read only with map_en (no check while disabled)
        n.cfg_err = r.map_en && !ok;
        n.active = r.map_en && homed && ok;
        if (n.active) {
            bool inr = false;
            const long double c = interp(tbl_[b], g, p, &inr);
            n.corr = static_cast<int64_t>(std::floor(c + 0.5L));  // floor(c + 1/2): exact (see .h)
            n.in_range = inr;
            n.clamped = !inr;
        }
        pending_.emplace_back(calls_ + kLat - 1, n);  // published by call t + kLat - 1
    }
    ++calls_;

    // Reading: the reads of a call see every write of the earlier calls; the write port of a
    // call acts after that call's reads and only on the bank not selected in the call.
    if (r.we) tbl_[1 - b][static_cast<size_t>(r.addr) % kDepth] = r.data;
    return o;
}

}  // namespace golden
