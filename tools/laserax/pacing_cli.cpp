#include "tools/laserax/pacing_cli.h"

#include <cstdio>

#include "host/pacing.h"

namespace lxt {

const char* const kControllerUsage =
    "  --controller-sample-mhz F  the controller's counter samples the pins at F MHz, (0, 1000]\n"
    "  --controller-filter N      through an N-sample digital filter, 0..65535 (0 or 1: off); give\n"
    "                    both or neither: pace_m below the smallest safe value for that input is\n"
    "                    refused (docs/CONTROLLER.md)\n"
    "  --force-pace      accept an unsafe pace_m anyway (a warning on stderr instead)\n";

bool parse_controller_option(cli& c, controller_opts* o) {
    if (c.is("--controller-sample-mhz")) o->have_mhz = c.get_real(0.0, 1000.0, &o->sample_mhz, true) || o->have_mhz;
    else if (c.is("--controller-filter")) o->have_filter = c.get_int(0, 65535, &o->filter) || o->have_filter;
    else if (c.is("--force-pace")) o->force = true;
    else return false;
    return true;
}

int check_controller_pacing(const char* cmd, const controller_opts& o, long long pace_m, double clock_mhz,
                            const std::string& how_given, const std::string& hint) {
    if (!o.have_mhz && !o.have_filter) return 0;
    if (o.have_mhz != o.have_filter) {
        std::fprintf(stderr, "%s: %s: needs %s as well (give both controller options or neither)\n", cmd,
                     o.have_mhz ? "--controller-sample-mhz" : "--controller-filter",
                     o.have_mhz ? "--controller-filter" : "--controller-sample-mhz");
        return 2;
    }
    const pacing_result r = min_safe_pace_m(o.sample_mhz, o.filter, clock_mhz);
    if (!r.ok) {
        std::fprintf(stderr, "%s: --controller-filter: %s\n", cmd, r.error.c_str());
        return 2;
    }
    char input[160];
    if (o.filter <= 1)
        std::snprintf(input, sizeof input, "a controller sampling at %g MHz with its filter off (%lld)", o.sample_mhz,
                      o.filter);
    else
        std::snprintf(input, sizeof input, "a controller sampling at %g MHz through a %lld-sample filter", o.sample_mhz,
                      o.filter);
    if (pace_m >= r.pace_m) {
        const pacing_speed s = max_speed_for_pace_m(pace_m, clock_mhz);
        std::printf("  pacing: %s needs pace_m >= %d; %s is safe (at most %.0f counts/s = %.2f mm/s)\n", input, r.pace_m,
                    how_given.c_str(), s.counts_per_s, s.mm_per_s);
        return 0;
    }
    if (o.force) {
        std::fprintf(stderr,
                     "%s: warning: %s is below the smallest safe pace_m %d for %s; forced (--force-pace): the "
                     "controller may lose counts\n",
                     cmd, how_given.c_str(), r.pace_m, input);
        return 0;
    }
    std::fprintf(stderr,
                 "%s: %s is unsafe for %s: the smallest safe pace_m is %d (it allows at most %.0f counts/s = %.2f "
                 "mm/s)%s%s\n",
                 cmd, how_given.c_str(), input, r.pace_m, r.max_counts_per_s, r.max_mm_per_s, hint.empty() ? "" : "; ",
                 hint.c_str());
    return 2;
}

}  // namespace lxt
