// compensate_cmd.h — `laserax compensate`: the ratio register and the equivalent encoder-scaling
// parameters for a set of air and workpiece conditions (issue 3; see compensation.h).
//
//   laserax compensate [--wavelength-nm L] [--temp-c T] [--pressure-pa P | --pressure-kpa P]
//                      [--rh H] [--co2-ppm C] [--material NAME | --alpha-ppm X]
//                      [--material-temp-c TM] [--origin-um U] [--equation edlen|ciddor]
//                      [--regs-out FILE]
//
// Prints n from both equations and their difference (ppb), the ratio register (decimal, hex),
// the compensation in ppm relative to lambda_vac / 78.125 nm, the expansion correction in ppm and
// K168/K169, and the register writes of ratio and comp_offset (offset, name, value; regmap.h),
// which --regs-out also writes to FILE as `offset name value` lines. Exit status 0, or 2 for bad
// or out-of-range input or an unwritable FILE (message on stderr).
#ifndef LASERAX_TOOLS_COMPENSATE_CMD_H
#define LASERAX_TOOLS_COMPENSATE_CMD_H

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace lxt {

// args[first..] are the options after the word `compensate`.
int cmd_compensate(const std::vector<std::string>& args, size_t first);
// Same, writing to the given streams (used by the testbench).
int cmd_compensate(const std::vector<std::string>& args, size_t first, FILE* out, FILE* err);

extern const char* const kCompensateUsage;

}  // namespace lxt

#endif
