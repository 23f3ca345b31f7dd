// cli_util.h — small helpers shared by the laserax subcommands: strict number parsing (the whole
// string must be a finite number) and creating an output folder with its parents.
#ifndef LASERAX_TOOLS_CLI_UTIL_H
#define LASERAX_TOOLS_CLI_UTIL_H

#include <string>

namespace lxt {

bool parse_double(const std::string& s, double* v);
bool parse_int(const std::string& s, long long* v);  // decimal, 0x hex or 0 octal
// mkdir -p; on failure prints "<who>: cannot create <path>: <reason>" to stderr and returns false.
bool make_dirs(const std::string& path, const char* who);

}  // namespace lxt

#endif
