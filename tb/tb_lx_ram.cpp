// tb_lx_ram — the block-RAM model of hls/lx_ram.h: one call of read latency, read-first, the
// port budget of each arrangement, and every violation flag, each raised by a pattern that breaks
// its rule and left clear by the legal patterns (the block testbenches check the flags of the
// RAMs in the models: tb_dds_sincos, tb_error_map, tb_vectors, sysmodel's dual_axis).
#include <cstdio>
#include <string>

#include "hls/lx_ram.h"
#include "tb/tb_util.h"

namespace {

using word = lx::uint<12>;

struct list3 {
    static constexpr int count = 3;
    static constexpr unsigned word(int i) { return 100u + static_cast<unsigned>(i); }
};

template <int K>
using ram8 = lx::ram<word, 8, K>;

unsigned u(const word& w) { return w.to_uint(); }

}  // namespace

int main(int argc, char** argv) {
    const uint64_t seed = tbu::seed_from(argc, argv, 1);
    tbu::result res("tb_lx_ram", seed);

    // power-up contents and the power-up output registers (as if every port had read address 0)
    {
        lx::ram<word, 8, lx::RAM_T2P, lx::ram_list<word, 8, list3>> m;
        res.check(u(m.peek(0)) == 100 && u(m.peek(2)) == 102 && u(m.peek(3)) == 0 && u(m.peek(7)) == 0,
                  "ram_list: listed words, zeros above");
        m.next_call();
        res.check(u(m.q<0>()) == 100 && u(m.q<1>()) == 100, "power-up output registers: word 0");
        res.check(m.violations() == 0, "power-up: no violation");
    }
    // one call of latency, the register holds until the port's next read, read-first
    {
        ram8<lx::RAM_S2P> m;
        m.next_call();
        m.write(3, 33);
        m.next_call();
        m.read<0>(3);
        m.write(3, 44);  // same call, after the read: the read returns the old word
        m.next_call();
        res.check(u(m.q<0>()) == 33, "read-first: the read of a call does not see its write");
        m.next_call();  // no read: the register holds
        res.check(u(m.q<0>()) == 33, "the output register holds until the next read");
        m.read<0>(3);
        m.next_call();
        res.check(u(m.q<0>()) == 44, "the write landed");
        res.check(m.violations() == 0, "legal s2p pattern flagged: " + std::to_string(m.violations()));
        // host load between calls: the word, and the output register of a port whose last read
        // was that address; another address leaves the output register
        m.load(3, 55);
        res.check(u(m.q<0>()) == 55 && u(m.peek(3)) == 55, "load(): the word and the output register");
        m.load(4, 66);
        res.check(u(m.q<0>()) == 55 && u(m.peek(4)) == 66, "load() of another address changed the output register");
    }
    // the legal maxima of each arrangement
    {
        ram8<lx::RAM_1P> a;
        ram8<lx::RAM_S2P> b;
        ram8<lx::RAM_T2P> c;
        for (int call = 0; call < 16; ++call) {
            a.next_call();
            b.next_call();
            c.next_call();
            if (call % 2 == 0) a.read<0>(unsigned(call % 8));
            else a.write(unsigned(call % 8), word(call));
            b.read<0>(unsigned(call % 8));
            b.write(unsigned((call + 1) % 8), word(call));
            if (call % 2 == 0) {
                c.read<0>(unsigned(call % 8));
                c.read<1>(unsigned((call + 5) % 8));
            } else {
                c.read<0>(unsigned(call % 8));
                c.write(unsigned((call + 3) % 8), word(call));
            }
        }
        res.check(a.violations() == 0 && b.violations() == 0 && c.violations() == 0,
                  "legal maxima flagged: 1p " + std::to_string(a.violations()) + ", s2p " + std::to_string(b.violations()) +
                      ", t2p " + std::to_string(c.violations()));
    }
    // each rule broken once: exactly its flag
    struct broken {
        const char* what;
        int want;
        int got;
    };
    auto one = [](auto& m, auto f) {
        m.next_call();
        f(m);
        return m.violations();
    };
    const broken cases[] = {
        {"1p: read and write in one call", lx::RAM_V_PORTS,
         [&] { ram8<lx::RAM_1P> m; return one(m, [](ram8<lx::RAM_1P>& r) { r.read<0>(1); r.write(2, 1); }); }()},
        {"1p: two writes", lx::RAM_V_PORTS,
         [&] { ram8<lx::RAM_1P> m; return one(m, [](ram8<lx::RAM_1P>& r) { r.write(1, 1); r.write(2, 1); }); }()},
        {"s2p: two reads", lx::RAM_V_PORTS,
         [&] { ram8<lx::RAM_S2P> m; return one(m, [](ram8<lx::RAM_S2P>& r) { r.read<0>(1); r.read<0>(2); }); }()},
        {"s2p: two writes", lx::RAM_V_PORTS,
         [&] { ram8<lx::RAM_S2P> m; return one(m, [](ram8<lx::RAM_S2P>& r) { r.write(1, 1); r.write(2, 1); }); }()},
        {"t2p: three accesses", lx::RAM_V_PORTS,
         [&] { ram8<lx::RAM_T2P> m; return one(m, [](ram8<lx::RAM_T2P>& r) { r.read<0>(1); r.read<1>(2); r.write(3, 1); }); }()},
        {"t2p: one port read twice", lx::RAM_V_PORTS,
         [&] { ram8<lx::RAM_T2P> m; return one(m, [](ram8<lx::RAM_T2P>& r) { r.read<1>(1); r.read<1>(2); }); }()},
        {"read data used in the call of its read", lx::RAM_V_EARLY,
         [&] { ram8<lx::RAM_S2P> m; return one(m, [](ram8<lx::RAM_S2P>& r) { r.read<0>(1); (void)r.q<0>(); }); }()},
        {"read after a write of the same address", lx::RAM_V_RAW,
         [&] { ram8<lx::RAM_S2P> m; return one(m, [](ram8<lx::RAM_S2P>& r) { r.write(5, 1); r.read<0>(5); }); }()},
        {"address outside the RAM", lx::RAM_V_ADDR,
         [&] { ram8<lx::RAM_S2P> m; return one(m, [](ram8<lx::RAM_S2P>& r) { r.read<0>(8); }); }()},
    };
    for (const broken& b : cases)
        res.check(b.got == b.want, std::string(b.what) + ": flags " + std::to_string(b.got) + ", want " + std::to_string(b.want));
    // a port budget counts per call: the same pattern spread over two calls is legal
    {
        ram8<lx::RAM_1P> m;
        m.next_call();
        m.read<0>(1);
        m.next_call();
        m.write(2, 1);
        res.check(m.violations() == 0, "1p: a read and a write in two calls flagged");
        // without the clock edge the two accesses are one call
        m.read<0>(3);
        res.check(m.violations() == lx::RAM_V_PORTS, "1p: a missing next_call() not counted as one call");
    }
    // the flags are sticky
    {
        ram8<lx::RAM_S2P> m;
        m.next_call();
        m.read<0>(9);
        m.next_call();
        m.read<0>(1);
        res.check(m.violations() == lx::RAM_V_ADDR, "flags are sticky across calls");
        m.clear_violations();
        res.check(m.violations() == 0, "clear_violations()");
    }
    std::printf("  %zu broken patterns, each with its flag\n", sizeof cases / sizeof cases[0]);
    return res.finish();
}
