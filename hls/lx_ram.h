// lx_ram.h — storage of the table RAMs of hls/ with constant power-up contents.
//
// A RAM of hls/ starts with contents that are part of the configuration (the RAM INIT of the
// FPGA), never written by a run-time constructor loop: Vitis HLS would turn such a loop into
// logic or thousands of unrolled writes (issue 37). Neither vendor integer type zeroes itself
// (a default-constructed ap_int / ac_int holds an undefined value, lx_types.h), so a table that
// powers up at zero lists its zeros: ram_zero<T, N> is N words of T, each initialised from 0 by
// a pack expansion at compile time (std::index_sequence; constant initialisation with the own
// integer back end, CTest hls_const_init).
// (The block-RAM model with one call of read latency and per-call port counts is the next step
// of issue 37; this is only its storage.)
#ifndef LASERAX_HLS_LX_RAM_H
#define LASERAX_HLS_LX_RAM_H

#include <cstddef>
#include <utility>

#include "hls/lx_types.h"

namespace lx {

template <typename T, int N>
struct ram_zero {
    static_assert(N >= 1, "lx::ram_zero: at least one word");
    T w[N];
    constexpr ram_zero() : ram_zero(std::make_index_sequence<static_cast<std::size_t>(N)>{}) {}

private:
    template <std::size_t... I>
    constexpr explicit ram_zero(std::index_sequence<I...>) : w{((void)I, T(0))...} {}
};

}  // namespace lx

#endif  // LASERAX_HLS_LX_RAM_H
