// golden/gantry_model.cpp — see gantry_model.h. Plain double arithmetic; every value here is an
// integer (or an exact half) well below 2^53, so floor/round are exact.
#include "golden/gantry_model.h"

#include <cmath>

namespace golden {

namespace {

double mod_p(double a, double p) {
    const double r = std::fmod(a, p);
    return r < 0 ? r + p : r;
}

double lambda_nm(const gantry_setup& s) { return s.count_nm * s.ratio; }

// Raw laser index of axis i at x (fringe counting on the laser's own grid).
double raw_index(const gantry_setup& s, int i, double x) {
    return std::floor((x - s.grid_nm[i]) / lambda_nm(s));
}

// Real output counts of axis i at x, counted from its laser's ready point: p = floor(N * ratio).
double real_counts(const gantry_setup& s, int i, double x) {
    const double n = raw_index(s, i, x) - raw_index(s, i, s.origin_nm[i]);
    return std::floor(n * s.ratio);
}

double round_half_up(double x) { return std::floor(x + 0.5); }

}  // namespace

double gantry_rephase_amount(int period, double phase_at_a) {
    const double p = period;
    return mod_p(7.0 * p / 8.0 - mod_p(phase_at_a, p), p);
}

double gantry_worst_skew(int period) { return static_cast<double>(period) - 1.0; }

gantry_prediction predict_gantry(const gantry_setup& s) {
    gantry_prediction r;
    const double p = s.period;
    if (s.conventional) {
        // Phase of encoder i at x: (x - Z_i)/count + P/8; the controller counts whole output
        // counts (round of the interpolated phase) and zeroes at phase P/8 of Z's period. The
        // lock keeps the counts' difference, so skew = difference of the rounded phases at the
        // lock position (the machine stays square: no virtual counts).
        for (int i = 0; i < 2; ++i) r.z_nm[i] = s.enc_home_nm[i];
        const double c = s.count_nm;
        r.skew_check = round_half_up((s.start_nm - s.enc_home_nm[0]) / c + p / 8.0) -
                       round_half_up((s.start_nm - s.enc_home_nm[1]) / c + p / 8.0);
        r.lock = r.skew_check;
        r.rephase_skew = 0;
    } else {
        const double lam = lambda_nm(s);
        for (int i = 0; i < 2; ++i) {
            r.a[i] = real_counts(s, i, s.switch_nm[i]);
            r.phase_a[i] = mod_p(r.a[i], p);
            r.d[i] = gantry_rephase_amount(s.period, r.phase_a[i]);
            r.z[i] = r.a[i] + p + p / 4.0;
            const double n0 = raw_index(s, i, s.origin_nm[i]);
            r.z_nm[i] = s.grid_nm[i] + (n0 + std::ceil(r.z[i] / s.ratio)) * lam;
        }
        // A homing after an earlier one starts from the kept adjustment: phase (A + d) mod P.
        auto again = [&](int i) { return gantry_rephase_amount(s.period, r.a[i] + r.d[i]); };
        r.homings[0].push_back(r.d[0]);
        r.homings[1].push_back(r.d[1]);
        switch (s.arm) {
            case gantry_arm::own:  // X2 references while tracking in pass 1, again in pass 2
                r.homings[1].push_back(again(1));
                r.rack[0] = r.d[1] - r.d[0];
                break;
            case gantry_arm::both:  // as own, and X1 re-references while tracking in pass 2
                r.homings[0].push_back(again(0));
                r.homings[1].push_back(again(1));
                r.rack[0] = r.d[1] - r.d[0];
                break;
            case gantry_arm::hold:  // each compensator references in its own pass only
                r.rack[0] = -r.d[0];
                break;
        }
        // Later homings add again(i) == 0 counts: the rack after both passes is d2 - d1.
        r.rack[1] = r.d[1] - r.d[0];
        r.rack[2] = r.rack[1];
        r.lock = real_counts(s, 0, s.start_nm) - real_counts(s, 1, s.start_nm);
        r.rephase_skew = r.d[1] - r.d[0];
        r.skew_check = r.lock + r.rephase_skew - (r.z[0] - r.z[1]);
    }
    r.skew_error = r.skew_check - s.offset;
    r.alarm = std::fabs(r.skew_error) > s.skew_limit;
    r.skew_final = r.alarm ? r.skew_check : s.offset;
    if (s.conventional) {
        r.rack_final_nm = r.skew_final * s.count_nm + (s.enc_home_nm[0] - s.enc_home_nm[1]);
        r.rack_tol_nm = s.count_nm;
    } else {
        const double lam = lambda_nm(s);
        // p1 - p2 = skew + Z1 - Z2; physical x = grid + (N0 + p/ratio + 1/2) * lambda (+- lambda/2)
        const double dp = r.skew_final + r.z[0] - r.z[1];
        r.rack_final_nm = (s.grid_nm[0] - s.grid_nm[1]) +
                          (raw_index(s, 0, s.origin_nm[0]) - raw_index(s, 1, s.origin_nm[1])) * lam +
                          dp / s.ratio * lam;
        r.rack_tol_nm = lam;
    }
    return r;
}

}  // namespace golden
