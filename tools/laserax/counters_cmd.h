// counters_cmd.h — `laserax counters`: the encoder counter block (hls/encoder_counter.h) and its
// golden model run in lock step on a demo: counter 0 from the encoder simulation (1 MHz) with a
// reset at the next start trigger and a wait-for-encoder; counter 1 from a quadrature encoder
// (through the quad decoder) preset just below +2^31 so that it wraps; on-the-fly correction
// every 10 us with scale factors from the calibration helpers. Summary on stdout,
// out/counters_trace.csv and out/counters.png (scripts/plot_pso.py counters).
//
//   laserax counters [--out DIR] [--rate-hz F] [--k-bits-mm K] [--v-mm-s V] [--enc-counts-mm I]
//                    [--enc-speed C] [--wait N] [--calls N] [--no-plot]
//
// Also the shared test support: register/input conversion to the hls types and the comparison.
#ifndef LASERAX_TOOLS_COUNTERS_CMD_H
#define LASERAX_TOOLS_COUNTERS_CMD_H

#include <cstddef>
#include <string>
#include <vector>

#include "golden/encoder_counter.h"
#include "hls/encoder_counter.h"

namespace lxt {

lx::encoder_counter_regs counters_to_hls(const golden::encoder_counter_regs& r);
lx::encoder_counter_in counters_to_hls(const golden::encoder_counter_in& in);
// "" or a message naming the first differing output.
std::string counters_compare(const lx::encoder_counter::out_t& h, const golden::encoder_counter::out& g);

int cmd_counters(const std::vector<std::string>& args, size_t first);

extern const char* const kCountersUsage;

}  // namespace lxt

#endif
