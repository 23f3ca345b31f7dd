// pacing_cli.h — the controller options of `laserax run` and `laserax vectors` (issue 36,
// docs/CONTROLLER.md): --controller-sample-mhz F and --controller-filter N (both or neither)
// describe the controller's counter input; a pace_m below the smallest safe value for it
// (host/pacing.h) is refused, unless --force-pace (then a warning on stderr).
#ifndef LASERAX_TOOLS_PACING_CLI_H
#define LASERAX_TOOLS_PACING_CLI_H

#include <string>

#include "tools/laserax/cli_util.h"

namespace lxt {

struct controller_opts {
    bool have_mhz = false, have_filter = false, force = false;
    double sample_mhz = 0;
    long long filter = 0;
};

// The usage lines of the three options (for the usage texts).
extern const char* const kControllerUsage;

// Consumes one of the three options if c is at one (true), else returns false.
bool parse_controller_option(cli& c, controller_opts* o);

// After parsing: checks pace_m (how_given names it in the messages, e.g. "--pace-m 4" or "the
// vectors' pace_m 3") against the controller. Returns 0 when no controller was given or pace_m
// is safe (one line on stdout then), or when forced (a warning on stderr); 2 with a message on
// stderr when only one of the two options was given, the controller is out of the calculation's
// range, or pace_m is unsafe. cmd: "laserax run". hint: what to do instead (may be empty).
int check_controller_pacing(const char* cmd, const controller_opts& o, long long pace_m, double clock_mhz,
                            const std::string& how_given, const std::string& hint);

}  // namespace lxt

#endif
