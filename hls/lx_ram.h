// lx_ram.h — the block-RAM model of hls/: every table of the models is an lx::ram.
//
// A synchronous FPGA block RAM, as the rtl_ref RAMs and the BRAM that Vitis binds (DESIGN §4.8):
//   * read latency one call: read<P>(addr) issues a read on port P in call t; its word is q<P>()
//     from call t+1 on (the RAM's output register; it holds until the port's next read);
//   * read-first: a read and a write of one call both act at the clock edge that ends the call,
//     so the read returns the word before the write (rtl_ref's RAMs read first). In C++ the
//     block issues its reads of a call before its writes; a read of an address the same call has
//     already written would see the written word in C simulation and in the synthesis view, while
//     the RAM returns the old one, so the model flags it (RAM_V_RAW) instead of hiding it;
//   * ports per call: RAM_1P one access (read or write), RAM_S2P (simple dual port) one read and
//     one write, RAM_T2P (true dual port) two accesses, each read port once. More is flagged
//     (RAM_V_PORTS): Vitis would raise the II of the pipelined top;
//   * power-up contents are the RAM INIT: the storage type Init is a struct with a member
//     `T w[N]` and default member initialisers (the zeros of ram_zero, or a constant table), so
//     the static top stays constant-initialised (CTest hls_const_init): no constructor loop.
// The block calls next_call() once at the start of every call in which it touches the RAM (the
// clock edge between two calls: in C simulation it closes the port counts of the previous call).
//
// C simulation keeps sticky violation flags (violations(), RAM_V_* bits; the block testbenches
// and tb_lx_ram check them): port budget, read data used in the call of its read (q<P>() after
// read<P>() in one call: the data is not there yet), read after a write of the same address, an
// address outside 0..N-1 (clamped: never outside the array). The synthesis view (__SYNTHESIS__)
// is the plain array and the output registers: the flags and counts do not exist there, and the
// BIND_STORAGE pragma of the array sits in the block's step(), where Vitis reads it (the array is
// the member m_.w).
//
// Outside the clocked calls, the C simulation also has the host's side of the configuration:
// load() sets a word as a configuration-time INIT would (no port, not counted; a port whose last
// read was that address returns the loaded word), peek() reads a word. Both exist in the
// synthesis view too (the synthesis top never calls them; there load() leaves the output
// registers), so the testbenches of that view load tables the same way.
#ifndef LASERAX_HLS_LX_RAM_H
#define LASERAX_HLS_LX_RAM_H

#include <cstddef>
#include <type_traits>
#include <utility>

#include "hls/lx_types.h"

namespace lx {

// The zero word of a RAM: T(0) for an integer type (neither vendor integer type zeroes itself,
// lx_types.h), T{} for a struct of fields with default member initialisers.
template <typename T>
constexpr T ram_word_zero(std::true_type) { return T(0); }
template <typename T>
constexpr T ram_word_zero(std::false_type) { return T{}; }
template <typename T>
constexpr T ram_word_zero() { return ram_word_zero<T>(std::is_convertible<int, T>{}); }

// N words of T at zero (the RAM INIT of a table that powers up empty): listed by a pack
// expansion at compile time.
template <typename T, int N>
struct ram_zero {
    static_assert(N >= 1, "lx::ram_zero: at least one word");
    T w[N];
    constexpr ram_zero() : ram_zero(std::make_index_sequence<static_cast<std::size_t>(N)>{}) {}

private:
    template <std::size_t... I>
    constexpr explicit ram_zero(std::index_sequence<I...>) : w{((void)I, ram_word_zero<T>())...} {}
};

// N words of T: word I from L::word(I) (a constexpr function of native integers) for I below
// L::count, zero above (the RAM INIT of a table with power-up contents, e.g. the DDS table).
template <typename T, int N, typename L>
struct ram_list {
    static_assert(L::count >= 0 && L::count <= N, "lx::ram_list: at most N listed words");
    T w[N];
    constexpr ram_list() : ram_list(std::make_index_sequence<static_cast<std::size_t>(N)>{}) {}

private:
    template <std::size_t... I>
    constexpr explicit ram_list(std::index_sequence<I...>)
        : w{(static_cast<int>(I) < L::count ? T(L::word(static_cast<int>(I))) : ram_word_zero<T>())...} {}
};

// The port arrangement (Vitis BIND_STORAGE type ram_1p / ram_s2p / ram_t2p).
enum ram_ports { RAM_1P = 1, RAM_S2P = 2, RAM_T2P = 3 };

// Violation bits (C simulation).
enum ram_violation {
    RAM_V_PORTS = 1,  // more accesses in one call than the ports allow
    RAM_V_EARLY = 2,  // q<P>() in the call of the read<P>() it would return
    RAM_V_RAW = 4,    // read of an address after a write of it in the same call
    RAM_V_ADDR = 8    // address outside 0..N-1
};

template <typename T, int N, int K, typename Init = ram_zero<T, N>>
class ram {
    static_assert(K == RAM_1P || K == RAM_S2P || K == RAM_T2P, "lx::ram: RAM_1P, RAM_S2P or RAM_T2P");
    static_assert(N >= 1, "lx::ram: at least one word");

public:
    static constexpr int depth = N;
    static constexpr int read_ports = K == RAM_T2P ? 2 : 1;

    // The clock edge before a call (see the header).
    void next_call() {
#ifndef __SYNTHESIS__
        st_ = 0;
#endif
    }

    // Read on port P at addr: the word is q<P>() from the next call on.
    template <int P>
    void read(unsigned addr) {
        static_assert(P >= 0 && P < read_ports, "lx::ram::read: no such read port");
#ifndef __SYNTHESIS__
        addr = check_addr(addr);
        const unsigned bit = P == 0 ? S_R0 : S_R1;
        // a port reads once per call; 1P: nothing else in the call; T2P: two accesses in all
        if ((st_ & bit) != 0 || (K == RAM_1P && st_ != 0) || (K == RAM_T2P && accesses() >= 2)) viol_ |= RAM_V_PORTS;
        if ((st_ & S_W1) != 0 && wa_ == addr) viol_ |= RAM_V_RAW;
        st_ = static_cast<unsigned char>(st_ | bit);
        (P == 0 ? la0_ : la1_) = addr;
#endif
        (P == 0 ? q0_ : q1_) = m_.w[addr];
    }

    // The output register of port P: the word of its last read, issued in an earlier call.
    template <int P>
    const T& q() {
        static_assert(P >= 0 && P < read_ports, "lx::ram::q: no such read port");
#ifndef __SYNTHESIS__
        if ((st_ & (P == 0 ? S_R0 : S_R1)) != 0) viol_ |= RAM_V_EARLY;
#endif
        return P == 0 ? q0_ : q1_;
    }

    // Write d at addr in this call (after this call's reads).
    void write(unsigned addr, const T& d) {
#ifndef __SYNTHESIS__
        addr = check_addr(addr);
        // 1P: nothing else in the call; S2P: one write; T2P: two accesses in all
        if ((K == RAM_1P && st_ != 0) || (K == RAM_S2P && (st_ & S_W1) != 0) || (K == RAM_T2P && accesses() >= 2))
            viol_ |= RAM_V_PORTS;
        st_ = static_cast<unsigned char>(st_ | ((st_ & S_W1) != 0 ? S_W2 : S_W1));
        wa_ = addr;
#endif
        m_.w[addr] = d;
    }

    // Host side, between calls (never reached from the synthesis top): a configuration-time word
    // (no port, not counted) and a read of the contents. In C simulation a port whose last read
    // was that address returns the loaded word (the host's load is taken as made before that
    // read: golden's tables change between two calls, e.g. the system model's table reload after
    // an amplitude change while the chain runs); the synthesis view has no such host and keeps
    // the output registers.
    void load(unsigned addr, const T& d) {
        addr = addr < unsigned(N) ? addr : 0u;
        m_.w[addr] = d;
#ifndef __SYNTHESIS__
        if (la0_ == addr) q0_ = d;
        if (la1_ == addr) q1_ = d;
#endif
    }
    const T& peek(unsigned addr) const { return m_.w[addr < unsigned(N) ? addr : 0u]; }
#ifndef __SYNTHESIS__
    int violations() const { return viol_; }
    void clear_violations() { viol_ = 0; }
#endif

private:
#ifndef __SYNTHESIS__
    unsigned check_addr(unsigned addr) {
        if (addr < unsigned(N)) return addr;
        viol_ |= RAM_V_ADDR;
        return 0;
    }
    // the accesses of this call so far (st_ bits)
    enum : unsigned { S_R0 = 1, S_R1 = 2, S_W1 = 4, S_W2 = 8 };
    int accesses() const { return (st_ & 1) + ((st_ >> 1) & 1) + ((st_ >> 2) & 1) + ((st_ >> 3) & 1); }
#endif

public:
    // (public for the BIND_STORAGE pragma of the owning block and for aggregate-free constant
    // initialisation; the blocks access the words only through the ports above)
    Init m_{};

private:
    // output registers of the read ports: at power-up, as if each port had read address 0
    T q0_ = m_.w[0], q1_ = m_.w[0];
#ifndef __SYNTHESIS__
    unsigned char st_ = 0;  // the accesses of this call: S_R0, S_R1 (port read), S_W1, S_W2 (writes)
    unsigned wa_ = 0;       // the address of the call's last write (with S_W1)
    unsigned la0_ = 0, la1_ = 0;  // the address of each port's last read (load(); power-up: 0)
    int viol_ = 0;
#endif
};

}  // namespace lx

#endif  // LASERAX_HLS_LX_RAM_H
