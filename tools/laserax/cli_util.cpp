#include "tools/laserax/cli_util.h"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lxt {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
int hex_val(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Magnitude of a strict integer text into *mag (saturating at 2^64-1 + overflow flag).
bool parse_mag(const std::string& s, size_t pos, uint64_t* mag, bool* overflow) {
    *overflow = false;
    uint64_t m = 0;
    if (pos >= s.size()) return false;
    if (s.size() - pos > 2 && s[pos] == '0' && (s[pos + 1] == 'x' || s[pos + 1] == 'X')) {
        for (size_t i = pos + 2; i < s.size(); ++i) {
            const int d = hex_val(s[i]);
            if (d < 0) return false;
            if (m > (UINT64_MAX >> 4)) *overflow = true;
            m = (m << 4) | static_cast<uint64_t>(d);
        }
    } else {
        for (size_t i = pos; i < s.size(); ++i) {
            if (!is_digit(s[i])) return false;
            const uint64_t d = static_cast<uint64_t>(s[i] - '0');
            if (m > (UINT64_MAX - d) / 10) *overflow = true;
            m = m * 10 + d;
        }
    }
    *mag = m;
    return true;
}

// [-]digits[.digits][(e|E)[+-]digits]
bool real_syntax(const std::string& s) {
    size_t i = 0;
    if (i < s.size() && s[i] == '-') ++i;
    size_t digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        size_t ed = 0;
        while (i < s.size() && is_digit(s[i])) ++i, ++ed;
        if (ed == 0) return false;
    }
    return i == s.size();
}

std::string fmt_real(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

}  // namespace

bool parse_double(const std::string& s, double* v) {
    if (!real_syntax(s)) return false;
    errno = 0;
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (*end != '\0' || !std::isfinite(x)) return false;
    *v = x;
    return true;
}

bool parse_u64(const std::string& s, uint64_t* v) {
    uint64_t m = 0;
    bool ovf = false;
    if (!parse_mag(s, 0, &m, &ovf) || ovf) return false;
    *v = m;
    return true;
}

bool parse_int(const std::string& s, long long* v) {
    const bool neg = !s.empty() && s[0] == '-';
    uint64_t m = 0;
    bool ovf = false;
    if (!parse_mag(s, neg ? 1 : 0, &m, &ovf) || ovf) return false;
    if (neg) {
        if (m > uint64_t(INT64_MAX) + 1) return false;
        *v = m == uint64_t(INT64_MAX) + 1 ? INT64_MIN : -static_cast<long long>(m);
    } else {
        if (m > uint64_t(INT64_MAX)) return false;
        *v = static_cast<long long>(m);
    }
    return true;
}

bool make_dirs(const std::string& path, const char* who) {
    if (path.empty()) {
        std::fprintf(stderr, "%s: empty output folder name\n", who);
        return false;
    }
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

// ---- cli ------------------------------------------------------------------------------------

cli::cli(std::string cmd, const std::vector<std::string>& args, size_t first, std::string usage, FILE* out, FILE* err)
    : cmd_(std::move(cmd)), usage_(std::move(usage)), out_(out), err_(err), args_(args), i_(first) {}

bool cli::next() {
    if (done_ || i_ >= args_.size()) {
        done_ = true;
        return false;
    }
    opt_ = args_[i_++];
    if (opt_ == "--help" || opt_ == "-h") {
        std::fprintf(out_, "%s", usage_.c_str());
        done_ = true;
        status_ = 0;
        return false;
    }
    return true;
}

void cli::error(const std::string& what) {
    if (done_) return;
    std::fprintf(err_, "%s: %s: %s\n", cmd_.c_str(), opt_.c_str(), what.c_str());
    done_ = true;
    status_ = 2;
}

void cli::unknown() {
    if (done_) return;
    std::fprintf(err_, "%s: unknown option '%s' (--help lists the options)\n", cmd_.c_str(), opt_.c_str());
    done_ = true;
    status_ = 2;
}

bool cli::value(std::string* out) {
    if (done_) return false;
    if (i_ >= args_.size()) {
        error("needs a value");
        return false;
    }
    *out = args_[i_++];
    return true;
}

bool cli::get_int(long long lo, long long hi, long long* out, long long multiple_of) {
    std::string v;
    if (!value(&v)) return false;
    std::string range = std::to_string(lo) + ".." + std::to_string(hi);
    if (multiple_of > 1) range += ", multiple of " + std::to_string(multiple_of);
    const bool neg = !v.empty() && v[0] == '-';
    uint64_t m = 0;
    bool ovf = false;
    if (!parse_mag(v, neg ? 1 : 0, &m, &ovf)) {
        error("'" + v + "' is not an integer (allowed " + range + ")");
        return false;
    }
    // range check on the magnitude before any conversion
    bool in = !ovf;
    if (in) {
        if (neg) in = lo < 0 && m <= static_cast<uint64_t>(-(lo + 1)) + 1;
        else in = hi >= 0 && m <= static_cast<uint64_t>(hi);
    }
    long long x = 0;
    if (in) {
        x = neg ? (m == uint64_t(INT64_MAX) + 1 ? INT64_MIN : -static_cast<long long>(m)) : static_cast<long long>(m);
        in = x >= lo && x <= hi && (multiple_of <= 1 || x % multiple_of == 0);
    }
    if (!in) {
        error(v + " is out of range (allowed " + range + ")");
        return false;
    }
    *out = x;
    return true;
}

bool cli::get_int(long long lo, long long hi, int* out, long long multiple_of) {
    long long x = 0;
    if (lo < INT32_MIN) lo = INT32_MIN;
    if (hi > INT32_MAX) hi = INT32_MAX;
    if (!get_int(lo, hi, &x, multiple_of)) return false;
    *out = static_cast<int>(x);
    return true;
}

bool cli::get_u64(uint64_t lo, uint64_t hi, uint64_t* out) {
    std::string v;
    if (!value(&v)) return false;
    const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
    uint64_t m = 0;
    bool ovf = false;
    if (!parse_mag(v, 0, &m, &ovf)) {
        error("'" + v + "' is not an unsigned integer (allowed " + range + ")");
        return false;
    }
    if (ovf || m < lo || m > hi) {
        error(v + " is out of range (allowed " + range + ")");
        return false;
    }
    *out = m;
    return true;
}

bool cli::get_real(double lo, double hi, double* out, bool lo_open, bool hi_open) {
    std::string v;
    if (!value(&v)) return false;
    const std::string range =
        std::string(lo_open ? "(" : "[") + fmt_real(lo) + ", " + fmt_real(hi) + (hi_open ? ")" : "]");
    double x = 0;
    if (!parse_double(v, &x)) {
        error("'" + v + "' is not a finite number (allowed " + range + ")");
        return false;
    }
    const bool in = (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
    if (!in) {
        error(v + " is out of range (allowed " + range + ")");
        return false;
    }
    *out = x;
    return true;
}

bool cli::get_text(std::string* out) {
    std::string v;
    if (!value(&v)) return false;
    if (v.empty()) {
        error("empty value (a non-empty name is required)");
        return false;
    }
    *out = v;
    return true;
}

bool cli::get_choice(const std::vector<std::string>& allowed, std::string* out) {
    std::string v;
    if (!value(&v)) return false;
    std::string list;
    for (const std::string& a : allowed) {
        if (a == v) {
            *out = v;
            return true;
        }
        list += (list.empty() ? "" : ", ") + a;
    }
    error("'" + v + "' is not allowed (allowed " + list + ")");
    return false;
}

}  // namespace lxt
