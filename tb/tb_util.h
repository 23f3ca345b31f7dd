// tb_util.h — small helpers every testbench uses: a failure counter that prints the first few
// failures with their context, the seed (printed on failure), and the closing PASS/FAIL line.
#ifndef LASERAX_TB_UTIL_H
#define LASERAX_TB_UTIL_H

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace tbu {

struct result {
    const char* name;
    uint64_t seed;
    long checks = 0;
    long failures = 0;

    result(const char* n, uint64_t s) : name(n), seed(s) {}

    // Records one check; prints the first 10 failures.
    bool check(bool ok, const std::string& what) {
        ++checks;
        if (!ok) {
            ++failures;
            if (failures <= 10) std::printf("[%s] FAIL (seed %llu): %s\n", name, (unsigned long long)seed, what.c_str());
        }
        return ok;
    }
    // Same, but builds the message only on failure: what() is a callable returning a string.
    template <typename F>
    bool expect(bool ok, F&& what) {
        if (ok) {
            ++checks;
            return true;
        }
        return check(false, what());
    }
    // Prints the closing line and returns the process exit code.
    int finish() const {
        if (failures == 0) {
            std::printf("[%s] PASS: %ld checks (seed %llu)\n", name, checks, (unsigned long long)seed);
            return 0;
        }
        std::printf("[%s] FAIL: %ld of %ld checks failed (seed %llu; rerun with --seed %llu)\n", name, failures,
                    checks, (unsigned long long)seed, (unsigned long long)seed);
        return 1;
    }
};

// --seed N on the command line, else LASERAX_SEED, else the default.
inline uint64_t seed_from(int argc, char** argv, uint64_t def) {
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--seed") == 0) return std::strtoull(argv[i + 1], nullptr, 0);
    if (const char* e = std::getenv("LASERAX_SEED")) return std::strtoull(e, nullptr, 0);
    return def;
}

// --NAME N on the command line, else the default.
inline long long arg_ll(int argc, char** argv, const char* name, long long def) {
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], name) == 0) return std::strtoll(argv[i + 1], nullptr, 0);
    return def;
}

}  // namespace tbu

#endif
