// fuzz_regs — libFuzzer target: register-write sequences interleaved with clocks, hls against
// golden (lxt::dual_axis: lx::laserax_top and golden::laserax_top stepped together and compared on
// every output and tap, plus the position-integrity invariants; the DDS table is reloaded when
// the period or amplitude changes, as a host would).
//
// Input bytes are a program: op = byte % 4; 0 = write register (index byte, 8 value bytes; the
// value is taken modulo the register's width, so every width value is reachable, legal or not;
// table-port registers and registers golden lacks are skipped), 1..3 = run 1..64 clocks of motion
// (direction, edge spacing, switch level and laser-error pulses from the next byte).
// Any mismatch traps (libFuzzer saves the input). Build and run: scripts/fuzz.sh. With FUZZ_TRACE=1
// in the environment the register writes of an input are printed (to read a saved crash).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "host/regmap_table.h"
#include "sysmodel/sim.h"

namespace rm = lxt::regmap;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    lxt::axis_settings s{};
    lxt::dual_axis ax(s);
    size_t i = 0;
    auto next = [&]() -> uint8_t { return i < size ? data[i++] : 0; };
    int64_t pos = 0;
    long long calls = 0;
    while (i < size && calls < 4000) {
        const uint8_t op = next();
        if (op % 4 == 0) {
            const int r = next() % rm::kNumRegs;
            uint64_t bits = 0;
            for (int k = 0; k < 8; ++k) bits = (bits << 8) | next();
            const rm::reg_info& info = rm::kRegs[r];
            if (info.acc == rm::access::port || info.golden_member[0] == '\0') continue;
            lxt::axis_settings ns = s;
            if (!rm::set(ns, r, rm::from_bits(info, bits))) continue;
            s = ns;
            ax.set(s);
            if (std::getenv("FUZZ_TRACE"))
                std::fprintf(stderr, "call %lld: write %s = %llu\n", calls, info.name,
                             static_cast<unsigned long long>(rm::from_bits(info, bits)));
        } else {
            const uint8_t m = next();
            const int n = 1 + (m & 63);
            const int dir = (op % 4 == 1) ? 0 : (op % 4 == 2 ? 1 : -1);
            const int spacing = 1 + ((m >> 6) & 3) * 5;
            for (int k = 0; k < n; ++k, ++calls) {
                if (dir != 0 && calls % spacing == 0) pos += dir;
                lx::axis_pins p;
                const unsigned q = static_cast<unsigned>(pos & 3);
                p.a = q == 1 || q == 2;
                p.b = q == 2 || q == 3;
                p.sw = pos > 40;
                p.lerr = (m & 0x80) && k == n / 2;
                const std::string mis = ax.step(p);
                if (!mis.empty()) {
                    std::fprintf(stderr, "fuzz_regs: call %lld: %s\n", calls, mis.c_str());
                    __builtin_trap();
                }
            }
        }
    }
    return 0;
}
