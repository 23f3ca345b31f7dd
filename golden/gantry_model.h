// golden/gantry_model.h — floating-point golden model of the twin-axis (gantry) referencing
// sequence of docs/GANTRY.md: X1 homed as master with X2 tracking, X2 homed with X1 tracking,
// X1 master again, skew check against a limit with an offset parameter, deskew by X2 alone.
//
// Written from the reasoning of Laser scale referencing (docs/SOURCES.md), not from hls/ and not
// from the cycle-accurate simulation (sysmodel/gantry): every quantity is a closed-form function
// of the physical set-up, in double.
//
//   * Each compensator counts real output counts p(x) from the moment its laser became ready
//     (pulse multiplication: p = floor(N * ratio), N = raw laser counts since ready).
//   * Point A is the count of the reference switch edge, A = p(S). Its output phase is A mod P
//     (plus any adjustment kept from an earlier homing), and the rephase amount that puts the
//     phase at Z = A + 5P/4 onto P/8 (sin == cos > 0) is d = (7P/8 - phase_A) mod P, 0 <= d < P.
//   * The controller holds the measured positions of the two axes locked (tracking moves keep
//     m1 - m2 constant), and measured = real + rephase adjustment. So the real counts of the two
//     axes drift apart by exactly the adjustments: (p1 - p2) = lock - d1 + d2 once both are homed
//     (the note: X2 moves d1 further while X1 is rephased, X1 moves d2 further while X2 is).
//   * Homing zeroes each controller counter at its own Z, so the skew the controller measures is
//       skew = (p1 - Z1) - (p2 - Z2) = lock - d1 + d2 - (Z1 - Z2),
//     a geometric term (switch offset) plus the temporary rephase skew d2 - d1, |d2 - d1| < P.
//   * Alarm when |skew - offset| > limit; otherwise X2 alone is moved until skew == offset.
//
// Conventional encoders (the baseline): the sin/cos phase is fixed to the scale, the mark is at a
// fixed physical position; there is no rephase, so the skew is the geometric term only.
#ifndef LASERAX_GOLDEN_GANTRY_MODEL_H
#define LASERAX_GOLDEN_GANTRY_MODEL_H

#include <vector>

namespace golden {

// How the controller arms the compensators with the `rehome` register (docs/GANTRY.md §4):
//   own  : before each homing pass, a rehome pulse for the axis about to be homed only; the
//          tracking axis' compensator is left alone (it may reference on its own switch while it
//          tracks; the controller ignores that mark and re-arms the axis before its own pass).
//   both : before each homing pass, rehome pulses for both axes (also re-arms an axis the
//          controller has already homed; it re-references with d = 0 at the same switch point).
//   hold : rehome pulse for the axis about to be homed; rehome held asserted on a tracking axis
//          that is not yet homed, so its compensator cannot reference while it tracks.
enum class gantry_arm { own = 0, both = 1, hold = 2 };

struct gantry_setup {
    int period = 256;             // P, output counts per sin/cos period
    double count_nm = 78.125;     // one output count
    double ratio = 1.0;           // output counts per raw laser count (pulse multiplication)
    bool conventional = false;    // true: conventional encoders instead of laser + compensator
    gantry_arm arm = gantry_arm::own;
    // Physical set-up (nm, along the axis; homing is towards +x). Positions of both rails are in
    // the square frame: the gantry is square when x1 == x2.
    double switch_nm[2] = {0, 0};     // reference switch edges (closed for x >= edge)
    double grid_nm[2] = {0, 0};       // laser fringe grid: raw index floor((x - grid) / lambda)
    double origin_nm[2] = {0, 0};     // where each laser became ready (its counter's zero)
    double start_nm = 0;              // where the square gantry stands when the controller locks
    double enc_home_nm[2] = {0, 0};   // conventional: physical home points Z
    // Controller parameters (output counts)
    double offset = 0;                // expected ctrl1 - ctrl2 of the square machine
    double skew_limit = 0;            // alarm when |skew - offset| > skew_limit
};

struct gantry_prediction {
    // Laser axes (counts on each compensator's real stream, from its laser's ready point).
    double a[2] = {0, 0};         // point A
    double phase_a[2] = {0, 0};   // output phase at A, A mod P (the power-up phase)
    double d[2] = {0, 0};         // rephase amount of the first homing
    double z[2] = {0, 0};         // point Z = A + 5P/4 (the controller zeroes its counter here)
    double z_nm[2] = {0, 0};      // physical start of the count Z (conventional: the mark's Z)
    // Every completed compensator homing of each axis in order, as its rephase amount d.
    std::vector<double> homings[2];
    double lock = 0;              // m1 - m2 held by the controller (counts)
    // Rack in real counts, (p1 - p2) minus its value at the lock, after pass 1, after pass 2 and
    // at the check (conventional: 0).
    double rack[3] = {0, 0, 0};
    double skew_check = 0;        // ctrl1 - ctrl2 at the check
    double skew_error = 0;        // skew_check - offset: what the deskew removes
    double rephase_skew = 0;      // the part caused by rephasing: d2 - d1
    bool alarm = false;
    double skew_final = 0;        // ctrl1 - ctrl2 at the end
    double rack_final_nm = 0;     // physical x1 - x2 at the end (within rack_tol_nm)
    double rack_tol_nm = 0;       // one raw count (laser) or one output count (conventional)
};

gantry_prediction predict_gantry(const gantry_setup& s);

// Rephase amount for forward homing: (7P/8 - phase_at_a) mod P, in [0, P).
double gantry_rephase_amount(int period, double phase_at_a);

// The note's bound on the temporary skew: the largest |d2 - d1| over all power-up phases, P - 1
// (d takes every value 0..P-1). In output counts.
double gantry_worst_skew(int period);

}  // namespace golden

#endif  // LASERAX_GOLDEN_GANTRY_MODEL_H
