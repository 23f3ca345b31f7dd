// vecgen.h — shared frame of the RTL vector generators (stress_vectors.cpp, regmap_vectors.cpp):
// the seeded random source and the command line / write-out of the vector tables.
//
//   PROG --out DIR [--seed N] [--calls 1000..1e7]
// builds the tables with `build`, checks each (lxt::vec_check) and writes DIR/<block>.hex with the
// command line in its header (docs/VECTORS.md). Exit status 0, 1 (build or write failed) or 2
// (usage).
#ifndef LASERAX_RTL_TB_VECGEN_H
#define LASERAX_RTL_TB_VECGEN_H

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "tools/laserax/cli_util.h"
#include "tools/laserax/vectors.h"

namespace vecgen {

struct rng_t {
    std::mt19937_64 g;
    explicit rng_t(uint64_t seed) : g(seed) {}
    uint64_t u() { return g(); }
    // uniform in [lo, hi]
    int64_t range(int64_t lo, int64_t hi) { return lo + static_cast<int64_t>(g() % static_cast<uint64_t>(hi - lo + 1)); }
    bool chance(uint64_t one_in) { return g() % one_in == 0; }
};

// Fills *tables for (rng, calls); false with a message on failure.
using build_fn = std::function<bool(rng_t& r, long long calls, std::vector<lxt::vec_table>* tables, std::string* err)>;

inline int run(int argc, char** argv, const char* prog, uint64_t seed, long long calls, const char* expected_from,
               const build_fn& build) {
    std::string dir;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--out") dir = argv[i + 1];
        else if (a == "--seed") seed = std::strtoull(argv[i + 1], nullptr, 0);
        else if (a == "--calls") calls = std::strtoll(argv[i + 1], nullptr, 0);
        else {
            std::fprintf(stderr, "%s: unknown option %s\n", prog, a.c_str());
            return 2;
        }
    }
    if (dir.empty() || argc % 2 == 0 || calls < 1000 || calls > 10000000) {
        std::fprintf(stderr, "usage: %s --out DIR [--seed N] [--calls 1000..1e7]\n", prog);
        return 2;
    }
    if (!lxt::make_dirs(dir, prog)) return 1;
    const std::string command = std::string(prog) + " --out " + dir + " --seed " + std::to_string(seed) + " --calls " +
                                std::to_string(calls) + " (expected columns from " + expected_from + ")";
    rng_t r(seed);
    std::vector<lxt::vec_table> tables;
    std::string err;
    if (!build(r, calls, &tables, &err)) {
        std::fprintf(stderr, "%s: %s\n", prog, err.c_str());
        return 1;
    }
    for (const lxt::vec_table& t : tables) {
        if (!lxt::vec_check(t, &err)) {
            std::fprintf(stderr, "%s: %s\n", prog, err.c_str());
            return 1;
        }
        const std::string path = dir + "/" + t.block + ".hex";
        std::ofstream f(path);
        f << lxt::vec_to_hex(t, command);
        if (!f) {
            std::fprintf(stderr, "%s: cannot write %s\n", prog, path.c_str());
            return 1;
        }
        std::printf("  %-24s %8zu calls, %2zu fields -> %s\n", t.block.c_str(), t.rows.size(), t.cols.size(),
                    path.c_str());
    }
    return 0;
}

}  // namespace vecgen

#endif  // LASERAX_RTL_TB_VECGEN_H
