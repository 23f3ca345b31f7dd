// pso_cmd.h — `laserax pso`: the PSO block (hls/pso.h) and its golden model (golden/pso.h) run
// in lock step on a 2D path (line, arc, reversal), with the firing positions compared against
// the ideal continuous path; summary on stdout, out/pso_trace.csv, out/pso_fires.csv and
// out/pso.png (scripts/plot_pso.py).
//
//   laserax pso [--out DIR] [--dist-um D] [--k K] [--pulse-w W] [--speed-mm-s V] [--laser-khz F]
//               [--window-um LO:HI] [--part-speed] [--cpu COUNTS_PER_MM] [--feed-mm-s V]
//               [--seed S] [--no-plot]
//
// Also the shared test support for tb/tb_pso.cpp: the continuous path model (positions in output
// counts, constant speed per segment), register/input conversion to the hls types and the
// output comparison.
#ifndef LASERAX_TOOLS_PSO_CMD_H
#define LASERAX_TOOLS_PSO_CMD_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "golden/pso.h"
#include "hls/pso.h"

namespace lxt {

// A path through 3D space in output counts, travelled at a constant speed per segment
// (counts per call along the path). Lines, circular arcs in any plane, dwells.
class pso_path {
public:
    explicit pso_path(const double start[3]);
    // straight line of length len along the unit vector dir
    void line(const double dir[3], double len, double speed);
    // circular arc starting at the current point: centre = current - r*u, sweep angle (signed,
    // radians) in the plane spanned by the orthonormal u, v (travel starts along +v for sweep > 0)
    void arc(const double u[3], const double v[3], double r, double sweep, double speed);
    void dwell(double calls);

    double duration() const { return t_end_; }   // calls
    double length() const { return s_end_; }     // counts
    // Point and arc length at time tau (calls from the start; clamped to the end).
    void at_time(double tau, double x[3], double* s) const;
    // Point at arc length s (clamped).
    void at_length(double s, double x[3]) const;
    // Speed (counts per call) at time tau.
    double speed_at(double tau) const;
    // Current end point and direction of travel at the end.
    void end_point(double x[3]) const;
    void end_dir(double d[3]) const;

private:
    struct seg {
        int kind;  // 0 line, 1 arc, 2 dwell
        double p0[3], dir[3], len;
        double c[3], u[3], v[3], r, sweep;
        double speed, t0, t1, s0;
    };
    void point_in(const seg& g, double sl, double x[3]) const;  // sl: length into the segment
    void dir_in(const seg& g, double sl, double d[3]) const;
    std::vector<seg> segs_;
    double cur_[3];
    double t_end_ = 0, s_end_ = 0;
};

// Quantised axis positions (floor of the continuous position plus an offset) and their steps.
struct pso_sampler {
    const pso_path* path = nullptr;
    double offset[3] = {0, 0, 0};
    int64_t pos[3] = {0, 0, 0};
    void start(const pso_path& p, const double off[3]);
    // Advances to time tau (one call later than the previous sample); fills the steps; returns
    // false if an axis moved by more than one count (speed too high).
    bool advance(double tau, int step[3]);
};

lx::pso_regs pso_to_hls(const golden::pso_regs& r);
lx::pso_in pso_to_hls(const golden::pso_in& in);
// "" or a message naming the first differing output.
std::string pso_compare(const lx::pso::out_t& h, const golden::pso::out& g);
// One row of the pso vector files (columns: lxt::vec_layout("pso"), every port of hls/pso.h and
// rtl_ref/pso.v): the inputs of the call, then the outputs from the golden model (`laserax
// vectors`) or from hls/ (rtl_stress_vectors).
std::vector<int64_t> pso_vec_row(const golden::pso_in& in, const golden::pso_regs& r, const golden::pso::out& o);
std::vector<int64_t> pso_vec_row(const golden::pso_in& in, const golden::pso_regs& r, const lx::pso::out_t& o);

int cmd_pso(const std::vector<std::string>& args, size_t first);

extern const char* const kPsoUsage;

}  // namespace lxt

#endif
