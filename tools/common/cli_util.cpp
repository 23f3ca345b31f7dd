#include "tools/common/cli_util.h"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lxt {

bool parse_double(const std::string& s, double* v) {
    if (s.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(x)) return false;
    *v = x;
    return true;
}

bool parse_int(const std::string& s, long long* v) {
    if (s.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const long long x = std::strtoll(s.c_str(), &end, 0);
    if (end == s.c_str() || *end != '\0' || errno == ERANGE) return false;
    *v = x;
    return true;
}

bool make_dirs(const std::string& path, const char* who) {
    std::string acc;
    for (size_t i = 0; i <= path.size(); ++i) {
        if ((i == path.size() || path[i] == '/') && !acc.empty()) {
            if (mkdir(acc.c_str(), 0755) != 0 && errno != EEXIST) {
                std::fprintf(stderr, "%s: cannot create %s: %s\n", who, acc.c_str(), std::strerror(errno));
                return false;
            }
        }
        if (i < path.size()) acc += path[i];
    }
    return true;
}

}  // namespace lxt
