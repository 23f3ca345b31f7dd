// gantry_cmd.h — `laserax gantry`: the twin-axis (gantry) referencing sequence of
// docs/GANTRY.md on the cycle-accurate system (sysmodel/gantry), checked against the golden
// model (golden/gantry_model). Prints the per-stage table (positions of X1 and X2 as the
// controller sees them and as they really are, skew, alarm) and writes into the output folder:
//   gantry_trace.csv     the sequence over time (decimated)
//   gantry_skew_map.csv  the skew at the check over a grid of power-up phases (X1 x X2)
//   gantry_sequence.png, gantry_skew_map.png   via /usr/bin/python3 scripts/plot_gantry.py
//
//   laserax gantry [--period P] [--seed S | --phase1 N --phase2 N] [--skew-limit L] [--offset O]
//                  [--switch-offset O] [--compliance C] [--resolution R] [--arm own|both|hold]
//                  [--conventional] [--map-grid N | --no-map] [--no-plot] [--out DIR]
//
// Exit status: 0 when the sequence ran and agreed with the golden model (a skew alarm is a valid
// outcome), 1 otherwise, 2 for a usage error.
#ifndef LASERAX_TOOLS_GANTRY_CMD_H
#define LASERAX_TOOLS_GANTRY_CMD_H

#include <cstddef>
#include <string>
#include <vector>

namespace lxt {

int cmd_gantry(const std::vector<std::string>& args, size_t first);

extern const char* const kGantryUsage;

}  // namespace lxt

#endif  // LASERAX_TOOLS_GANTRY_CMD_H
