// cli_util.h — the one strict command-line parser shared by every laserax subcommand, plus
// creating an output folder with its parents.
//
// Numbers: the whole string must be the number (no leading/trailing blanks, no leading '+', no
// trailing text); integers are decimal (optional '-') or 0x hex, never octal; reals are
// [-]digits[.digits][e[+-]digits] (no inf, nan, hex floats). The range is checked on the exact
// value before it is converted to the target type, so a conversion can never overflow. A value
// outside the range is an error, never "the default": no 0 or -1 magic from the user.
// Messages name the command, the option, the bad value and the allowed range:
//   "laserax run: --period: 4294967552 is out of range (allowed 8..4096, multiple of 8)"
#ifndef LASERAX_TOOLS_CLI_UTIL_H
#define LASERAX_TOOLS_CLI_UTIL_H

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace lxt {

bool parse_double(const std::string& s, double* v);  // strict real, finite
bool parse_int(const std::string& s, long long* v);  // strict integer (decimal or 0x hex)
// Strict unsigned 64-bit integer (decimal or 0x hex); false on any other text or overflow.
bool parse_u64(const std::string& s, uint64_t* v);
// mkdir -p; on failure prints "<who>: cannot create <path>: <reason>" to stderr and returns false.
bool make_dirs(const std::string& path, const char* who);

// The argument list of one subcommand. Usage:
//   cli c("laserax run", args, first, usage_text);
//   while (c.next()) {
//       if (c.is("--period")) c.get_int(8, 4096, &period, 8);
//       else if (c.is("--speed")) c.get_real(0.01, 1000, &speed);
//       else if (c.is("--no-plot")) plot = false;
//       else c.unknown();
//   }
//   if (c.failed()) return c.status();   // 0 after --help (usage printed), 2 after an error
// Every error prints one line to stderr naming the option and the allowed range and stops the
// loop; --help / -h prints the usage to stdout and stops the loop.
class cli {
public:
    // out / err: where --help and the error messages go (stdout / stderr unless given)
    cli(std::string cmd, const std::vector<std::string>& args, size_t first, std::string usage, FILE* out = stdout,
        FILE* err = stderr);
    bool next();                           // false at the end, after an error or after --help
    bool is(const char* opt) const { return opt_ == opt; }
    const std::string& opt() const { return opt_; }
    // value getters: consume the option's value, check it, store it only when valid
    bool get_int(long long lo, long long hi, long long* out, long long multiple_of = 1);
    bool get_int(long long lo, long long hi, int* out, long long multiple_of = 1);
    bool get_u64(uint64_t lo, uint64_t hi, uint64_t* out);
    bool get_real(double lo, double hi, double* out, bool lo_open = false, bool hi_open = false);
    bool get_text(std::string* out);       // non-empty
    bool get_choice(const std::vector<std::string>& allowed, std::string* out);
    bool value(std::string* out);          // raw value (for option-specific parsing)
    void unknown();                        // "unknown option"
    void error(const std::string& what);   // "<cmd>: <opt>: <what>"
    bool failed() const { return done_ && status_ >= 0; }
    int status() const { return status_ < 0 ? 0 : status_; }

private:
    std::string cmd_, usage_, opt_;
    FILE* out_;
    FILE* err_;
    const std::vector<std::string>& args_;
    size_t i_;
    bool done_ = false;
    int status_ = -1;  // -1 running / finished normally, 0 help, 2 error
};

}  // namespace lxt

#endif
