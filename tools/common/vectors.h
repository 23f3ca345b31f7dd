// vectors.h — golden vector files: stimulus and expected response of every block and of the
// chain, as CSV and as $readmemh hex (format in docs/VECTORS.md), plus a checked reader.
#ifndef LASERAX_TOOLS_VECTORS_H
#define LASERAX_TOOLS_VECTORS_H

#include <cstdint>
#include <string>
#include <vector>

namespace lxt {

struct vec_column {
    std::string name;
    int bits = 1;
    bool is_signed = false;
    bool is_input = true;  // stimulus (true) or expected response (false)
};

struct vec_table {
    std::string block;
    std::vector<vec_column> cols;
    std::vector<std::vector<int64_t>> rows;
    int col(const std::string& name) const;  // index or -1
};

// Writers. `command` goes into the header of each file.
std::string vec_to_csv(const vec_table& t, const std::string& command);
std::string vec_to_hex(const vec_table& t, const std::string& command);

// Readers: false plus a message naming the file line on any malformed input (missing header,
// wrong field count, non-integer or out-of-range value, unknown column); never throws.
bool vec_from_csv(const std::string& text, vec_table& t, std::string* err);
bool vec_from_hex(const std::string& text, const vec_table& layout, vec_table& t, std::string* err);

bool read_file(const std::string& path, std::string& text, std::string* err);

// Builds every block's table from one seeded scenario (golden models give the expected columns;
// the hls models are stepped alongside and must agree, else err is set).
bool build_vectors(uint64_t seed, long long calls, std::vector<vec_table>& out, std::string* err);
// The same for the motion-synchronised blocks (pso, encoder_counter); appends to `out`.
bool build_motion_vectors(uint64_t seed, long long calls, std::vector<vec_table>& out, std::string* err);

// `laserax vectors` (argument parsing included); returns the process exit code.
int cmd_vectors(const std::vector<std::string>& args, size_t first, const std::string& command);

}  // namespace lxt

#endif
