// dds_table.h — host-side generator of the dds_sincos quarter-wave table (DESIGN §4.6).
//
// T[k] = round-half-away-from-zero(amp * sin(2 pi k / P)), k = 0 .. P/4 - 1, evaluated in long
// double. Used by tools/lutgen (generated files) and by the testbenches (table loads). This is
// neither hls/ nor golden/ code: it produces the contents of a RAM, like a host driver would.
#ifndef LASERAX_TOOLS_DDS_TABLE_H
#define LASERAX_TOOLS_DDS_TABLE_H

#include <cstdint>
#include <string>
#include <vector>

namespace lxt {

// Returns the P/4 table words, or an empty vector (and a message in err) for an invalid request.
std::vector<uint32_t> dds_table(int period, int amplitude, std::string* err = nullptr);

// The C header with the power-up table (a macro holding all TBL_DEPTH initialisers).
std::string dds_table_header(int period, int amplitude, int depth, const std::string& command);

// $readmemh file: one hex word per line, `depth` lines (unused words are 0), '//' header lines.
std::string dds_table_hex(int period, int amplitude, int depth, const std::string& command);

}  // namespace lxt

#endif
