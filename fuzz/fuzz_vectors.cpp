// fuzz_vectors — libFuzzer target for the strict vector reader (tools/laserax/vectors.cpp).
//
// Input: any bytes, read as a CSV vector file and as a hex file of the quad_decoder layout.
// Properties: the readers never crash; a rejection always carries a message; an accepted file
// round-trips: written again (vec_to_csv / vec_to_hex), read again, the columns and every value
// compare equal, and the CSV and hex forms of it carry the same rows.
// Build and run: scripts/fuzz.sh (make fuzz; a short run is CTest fuzz_short).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "tools/laserax/vectors.h"

namespace {

[[noreturn]] void fail() { __builtin_trap(); }

bool same_cols(const lxt::vec_table& a, const lxt::vec_table& b) {
    if (a.cols.size() != b.cols.size()) return false;
    for (size_t i = 0; i < a.cols.size(); ++i) {
        const lxt::vec_column &x = a.cols[i], &y = b.cols[i];
        if (x.name != y.name || x.bits != y.bits || x.is_signed != y.is_signed || x.is_input != y.is_input) return false;
    }
    return true;
}

void round_trip(const lxt::vec_table& t) {
    std::string err;
    lxt::vec_table back, hex_back;
    if (!lxt::vec_from_csv(lxt::vec_to_csv(t, "fuzz"), back, &err, "rt.csv")) fail();
    if (!same_cols(t, back) || back.rows != t.rows) fail();
    if (!lxt::vec_from_hex(lxt::vec_to_hex(t, "fuzz"), t, hex_back, &err, "rt.hex")) fail();
    if (hex_back.rows != t.rows) fail();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::string err;
    lxt::vec_table t;
    if (lxt::vec_from_csv(text, t, &err, "in.csv")) {
        round_trip(t);
    } else if (err.empty()) {
        fail();
    }
    static const lxt::vec_table layout = [] {
        lxt::vec_table l;
        l.block = "quad_decoder";
        l.cols = lxt::vec_layout("quad_decoder");
        return l;
    }();
    lxt::vec_table h;
    err.clear();
    if (lxt::vec_from_hex(text, layout, h, &err, "in.hex")) {
        round_trip(h);
    } else if (err.empty()) {
        fail();
    }
    return 0;
}
