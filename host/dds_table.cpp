#include "host/dds_table.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace lxt {

std::vector<uint32_t> dds_table(int period, int amplitude, std::string* err) {
    std::vector<uint32_t> t;
    if (period < 8 || period > 4096 || period % 8 != 0) {
        if (err) *err = "period must be 8..4096 and a multiple of 8, got " + std::to_string(period);
        return t;
    }
    if (amplitude < 1 || amplitude > (1 << 17) - 1) {
        if (err) *err = "amplitude must be 1..131071, got " + std::to_string(amplitude);
        return t;
    }
    const long double two_pi = 6.283185307179586476925286766559L;
    const int quarter = period / 4;
    t.reserve(static_cast<size_t>(quarter));
    for (int k = 0; k < quarter; ++k) {
        // sin(30 deg) = 1/2 is the only rational non-zero value inside the quarter (Niven): take it
        // exactly, so an odd amplitude meets a true tie and rounds half away from zero.
        const long double s = (12 * k == period) ? 0.5L
                              : std::sin(two_pi * static_cast<long double>(k) / static_cast<long double>(period));
        const long double v = static_cast<long double>(amplitude) * s;
        t.push_back(static_cast<uint32_t>(std::llround(v)));  // v >= 0: llround = half away
    }
    return t;
}

std::string dds_table_header(int period, int amplitude, int depth, const std::string& command) {
    const std::vector<uint32_t> t = dds_table(period, amplitude);
    std::ostringstream os;
    os << "// dds_table_default.h — power-up contents of the dds_sincos table RAM.\n"
       << "// GENERATED FILE, do not edit. Command: " << command << "\n"
       << "// T[k] = round-half-away(" << amplitude << " * sin(2*pi*k/" << period << ")), k = 0.."
       << period / 4 - 1 << "; the remaining words of the " << depth << "-word RAM are 0.\n"
       << "#ifndef LASERAX_HLS_DDS_TABLE_DEFAULT_H\n#define LASERAX_HLS_DDS_TABLE_DEFAULT_H\n\n"
       << "#define LASERAX_DDS_TABLE_DEFAULT_PERIOD " << period << "\n"
       << "#define LASERAX_DDS_TABLE_DEFAULT_AMPLITUDE " << amplitude << "\n"
       << "#define LASERAX_DDS_TABLE_DEFAULT \\\n";
    for (size_t k = 0; k < t.size(); ++k) {
        os << "    " << t[k] << (k + 1 < t.size() ? ", \\\n" : "\n");
    }
    os << "\n#endif\n";
    return os.str();
}

std::string dds_table_hex(int period, int amplitude, int depth, const std::string& command) {
    const std::vector<uint32_t> t = dds_table(period, amplitude);
    std::ostringstream os;
    os << "// dds_sincos quarter-wave table, P=" << period << " amp=" << amplitude << ", " << depth
       << " words of 17 bits.\n// GENERATED FILE. Command: " << command << "\n";
    char buf[16];
    for (int k = 0; k < depth; ++k) {
        const uint32_t w = k < static_cast<int>(t.size()) ? t[static_cast<size_t>(k)] : 0u;
        std::snprintf(buf, sizeof buf, "%05x\n", w);
        os << buf;
    }
    return os.str();
}

}  // namespace lxt
