// lx_types.h — fixed-width integer layer for the laserax HLS models.
//
// Two back ends, one spelling:
//   default                      lx::sint<W> / lx::uint<W> are the project's own wrapping
//                                integer classes (W <= 128), built on the standard library only;
//   -DLASERAX_USE_AP_TYPES       lx::sint<W> = ap_int<W>, lx::uint<W> = ap_uint<W> (Vitis HLS,
//                                <ap_int.h>);
//   -DLASERAX_USE_AC_TYPES       lx::sint<W> = ac_int<W, true>, lx::uint<W> = ac_int<W, false>
//                                (Catapult HLS, <ac_int.h>).
//
// Neither vendor type zeroes itself: a default-constructed ap_int / ac_int holds an undefined
// value (only the own back end starts at 0). Every value the models create is therefore
// initialised explicitly: every member of an out_t / register struct has a default member
// initialiser, every class member is assigned in reset() (called by the constructor), every
// local is initialised where it is declared. `make test` runs the bit-exact testbenches with both
// vendor types, with ap_int also at -O0 (how Vitis csim_design builds), see CMakeLists.txt.
//
// The models use only the subset that both back ends share:
//   * construction and assignment from integers and from other lx types (truncating wrap to W
//     bits, two's complement for sint: the AP_WRAP / AP_TRN behaviour of ap_int);
//   * arithmetic and comparison through conversion to a native integer (own back end) or
//     through ap_int's width-growing operators (Vitis); both give the same value as long as the
//     exact result fits the native type — every product of two W-bit operands is first widened to
//     the result type by an explicit cast, e.g. acc_t(n) * r;
//   * .to_int(), .to_uint(), .to_int64(), .to_uint64() for explicit narrowing.
// Single bits are plain bool on both back ends.
#ifndef LASERAX_HLS_LX_TYPES_H
#define LASERAX_HLS_LX_TYPES_H

#include <cstdint>
#include <type_traits>

#if defined(LASERAX_USE_AP_TYPES) && defined(LASERAX_USE_AC_TYPES)
#error "lx_types.h: define at most one of LASERAX_USE_AP_TYPES and LASERAX_USE_AC_TYPES"
#endif

// The vendor headers are included as system headers by the build, but GCC reports its
// flow-based -W(maybe-)uninitialized warnings after inlining, at the vendor's source line
// (e.g. ap_private::clearUnusedBits() reading VAL through a volatile access while a value is
// constructed): the system-header rule does not cover them. Diagnostic state is bound to source
// locations, so switching these two off around the #include silences them inside the vendor
// header only; in the models' own lines they stay errors.
#if defined(__GNUC__) && !defined(__clang__) && !defined(__SYNTHESIS__)
#define LASERAX_VENDOR_HEADER_BEGIN                                   \
    _Pragma("GCC diagnostic push")                                    \
    _Pragma("GCC diagnostic ignored \"-Wuninitialized\"")             \
    _Pragma("GCC diagnostic ignored \"-Wmaybe-uninitialized\"")
#define LASERAX_VENDOR_HEADER_END _Pragma("GCC diagnostic pop")
#else
#define LASERAX_VENDOR_HEADER_BEGIN
#define LASERAX_VENDOR_HEADER_END
#endif

#if defined(LASERAX_USE_AP_TYPES)
LASERAX_VENDOR_HEADER_BEGIN
#include <ap_int.h>
LASERAX_VENDOR_HEADER_END
namespace lx {
template <int W> using sint = ap_int<W>;
template <int W> using uint = ap_uint<W>;
}  // namespace lx
#elif defined(LASERAX_USE_AC_TYPES)
LASERAX_VENDOR_HEADER_BEGIN
#include <ac_int.h>
LASERAX_VENDOR_HEADER_END
namespace lx {
template <int W> using sint = ac_int<W, true>;
template <int W> using uint = ac_int<W, false>;
}  // namespace lx
#else
namespace lx {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

template <int W, bool S>
class fixed_int {
    static_assert(W >= 1 && W <= 128, "lx::fixed_int supports 1..128 bits");
    static constexpr bool kWide = W > 64;
    using ustore = typename std::conditional<kWide, u128, uint64_t>::type;

public:
    using store_t = typename std::conditional<
        S, typename std::conditional<kWide, i128, int64_t>::type, ustore>::type;

    constexpr fixed_int() : v_(0) {}
    // Any integer or lx value: keep the low W bits (two's complement wrap), like ap_int.
    template <typename T, typename = typename std::enable_if<!std::is_floating_point<T>::value>::type>
    constexpr fixed_int(T x) : v_(from(x)) {}  // by value: no ODR-use of constants

    constexpr operator store_t() const { return v_; }

    constexpr int to_int() const { return static_cast<int>(v_); }
    constexpr unsigned to_uint() const { return static_cast<unsigned>(v_); }
    constexpr int64_t to_int64() const { return static_cast<int64_t>(v_); }
    constexpr uint64_t to_uint64() const { return static_cast<uint64_t>(v_); }

    static constexpr int width = W;
    static constexpr bool is_signed = S;

    // A value the caller knows to lie in the range of W bits (no wrap; see lx::cat_s).
    static constexpr fixed_int exact(store_t v) { return fixed_int(v, exact_tag{}); }

private:
    struct exact_tag {};
    constexpr fixed_int(store_t v, exact_tag) : v_(v) {}

    // Width and signedness of a source type: lx types by their W and S (their value always lies
    // in that range), native integers by their size (bool: 1 bit unsigned).
    template <typename T, typename = void>
    struct src {
        using type = T;
        static constexpr int bits = std::is_same<T, bool>::value ? 1 : static_cast<int>(sizeof(T) * 8);
        static constexpr bool sgn = std::is_same<T, i128>::value || std::is_signed<T>::value;
    };
    template <typename T>
    struct src<T, typename std::enable_if<!std::is_integral<T>::value && !std::is_same<T, i128>::value &&
                                          !std::is_same<T, u128>::value>::type> {
        using type = typename T::store_t;
        static constexpr int bits = T::width;
        static constexpr bool sgn = T::is_signed;
    };

    // The value conversion, specialised at compile time by the source range (the result is the
    // same in every branch: the low W bits, two's complement):
    //   * a source whose every value fits W bits (same signedness and not wider, or unsigned and
    //     narrower than a signed W) is copied: no masking;
    //   * otherwise the low W bits are kept, in 64-bit arithmetic when the source and W fit 64
    //     bits, in 128-bit arithmetic only when one of them is wider.
    template <typename I>
    static constexpr int mode() {
        return ((I::sgn == S && I::bits <= W) || (!I::sgn && S && I::bits < W)) ? 0 : (!kWide && I::bits <= 64) ? 1 : 2;
    }
    template <typename T>
    static constexpr store_t from(T x) {
        using I = src<T>;
        return conv_(static_cast<typename I::type>(x), std::integral_constant<int, mode<I>()>{});
    }
    template <typename N>
    static constexpr store_t conv_(N n, std::integral_constant<int, 0>) { return static_cast<store_t>(n); }
    template <typename N>  // negative to unsigned: modular (well defined)
    static constexpr store_t conv_(N n, std::integral_constant<int, 1>) { return wrap64(static_cast<uint64_t>(n)); }
    template <typename N>
    static constexpr store_t conv_(N n, std::integral_constant<int, 2>) { return wrap(static_cast<u128>(n)); }

    // W <= 64: sign extension by a left shift of the unsigned pattern and an arithmetic right
    // shift (GCC / Clang: conversion to int64_t is modular, >> of a negative value is arithmetic).
    static constexpr store_t wrap64(uint64_t u) {
        return W == 64 ? static_cast<store_t>(u)
               : S     ? static_cast<store_t>(static_cast<int64_t>(u << ((64 - W) % 64)) >> ((64 - W) % 64))
                       : static_cast<store_t>(u & ((uint64_t(1) << (W % 64)) - 1));
    }

    static constexpr store_t wrap(u128 x) {
        const ustore mask = W == (kWide ? 128 : 64) ? ~ustore(0) : ((ustore(1) << (W % (kWide ? 128 : 64))) - 1);
        const ustore u = static_cast<ustore>(x) & mask;
        if (!S) return static_cast<store_t>(u);
        const ustore sign = ustore(1) << (W - 1);
        return static_cast<store_t>((u ^ sign) - sign);  // sign extension, no shift of negatives
    }

    store_t v_;
};

template <int W> using sint = fixed_int<W, true>;
template <int W> using uint = fixed_int<W, false>;

// Mixed-sign arithmetic. The models' arithmetic runs on the native store types: a sint converts
// to int64_t (i128 above 64 bits), a uint to uint64_t (u128). A signed operand meeting an
// unsigned one of the same rank is then converted to unsigned by the usual arithmetic conversions
// (Clang's -Wconversion reports it, -Wsign-conversion; GCC's does not), e.g. hi + T_hi + carry in
// pulse_multiplier.h. The operators below do that conversion explicitly and give the result the
// signedness ap_int gives it (ap_int<W1> + ap_uint<W2> is an ap_int), for a signed operand (a sint,
// or a signed 64-bit or 128-bit native value: what a sum of sints is) with a uint<W2> whose every
// value the signed result type holds (int64_t for W2 < 64 and a sint of <= 64 bits, else i128 for
// W2 < 128). The sum, difference or product is formed modulo 2^64 (2^128) in the unsigned type,
// as the built-in operators did, and read as the signed type: the same bit pattern as before (so
// the same value once narrowed to an lx type), and no signed overflow. Only +, - and *; native
// operands narrower than 64 bits (literals: u + 1, u - 1) keep the built-in operators, and so do
// division, remainder, shifts, the bitwise operators and comparisons (mixed-sign comparisons are
// -Wsign-compare errors in both compilers).
namespace detail {
// the signed operand: its width class (64 or 128), 0 for any other type
template <typename T>
struct mix_s : std::integral_constant<int, (std::is_integral<T>::value && std::is_signed<T>::value &&
                                            sizeof(T) == 8) ? 64 : 0> {};
template <> struct mix_s<i128> : std::integral_constant<int, 128> {};
template <int W> struct mix_s<fixed_int<W, true>> : std::integral_constant<int, (W <= 64 ? 64 : 128)> {};
// the unsigned operand: a uint<W>, its width; 0 for any other type
template <typename T> struct mix_u : std::integral_constant<int, 0> {};
template <int W> struct mix_u<fixed_int<W, false>> : std::integral_constant<int, W> {};
// the width of the result for signed SO and unsigned UO: 64, 128, or 0 (no mixed-sign operator)
template <typename SO, typename UO>
struct mix_su : std::integral_constant<int, (mix_s<SO>::value == 0 || mix_u<UO>::value == 0) ? 0
                                            : (mix_s<SO>::value == 64 && mix_u<UO>::value < 64) ? 64
                                            : (mix_u<UO>::value < 128) ? 128 : 0> {};
// either order of the operands
template <typename A, typename B>
struct mix : std::integral_constant<int, mix_su<A, B>::value != 0 ? mix_su<A, B>::value : mix_su<B, A>::value> {};
template <int N> struct mix_types {};  // N = 0: no type, the operators drop out (SFINAE)
template <> struct mix_types<64> { using s = int64_t; using u = uint64_t; };
template <> struct mix_types<128> { using s = i128; using u = u128; };
// an operand's value as a native integer
template <typename T> constexpr T mix_native(T x) { return x; }
template <int W, bool S>
constexpr typename fixed_int<W, S>::store_t mix_native(const fixed_int<W, S>& x) {
    return static_cast<typename fixed_int<W, S>::store_t>(x);
}
}  // namespace detail

template <typename A, typename B, int N = detail::mix<A, B>::value>
constexpr typename detail::mix_types<N>::s operator+(const A& a, const B& b) {
    using U = typename detail::mix_types<N>::u;
    return static_cast<typename detail::mix_types<N>::s>(static_cast<U>(detail::mix_native(a)) +
                                                         static_cast<U>(detail::mix_native(b)));
}
template <typename A, typename B, int N = detail::mix<A, B>::value>
constexpr typename detail::mix_types<N>::s operator-(const A& a, const B& b) {
    using U = typename detail::mix_types<N>::u;
    return static_cast<typename detail::mix_types<N>::s>(static_cast<U>(detail::mix_native(a)) -
                                                         static_cast<U>(detail::mix_native(b)));
}
template <typename A, typename B, int N = detail::mix<A, B>::value>
constexpr typename detail::mix_types<N>::s operator*(const A& a, const B& b) {
    using U = typename detail::mix_types<N>::u;
    return static_cast<typename detail::mix_types<N>::s>(static_cast<U>(detail::mix_native(a)) *
                                                         static_cast<U>(detail::mix_native(b)));
}

}  // namespace lx
#endif

// LASERAX_FLATTEN: on the per-call step() of a chain, inlines every call in its body (GCC /
// Clang, own integer back end, C simulation only): the block outputs then pass in registers
// instead of through memory (a compiler setting of the C build). No effect on what is computed; empty
// for synthesis and with the vendor types (their deep class hierarchies would make every chain
// step one very large function to compile, at -O0 too).
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__SYNTHESIS__) && !defined(LASERAX_USE_AP_TYPES) && \
    !defined(LASERAX_USE_AC_TYPES)
#define LASERAX_FLATTEN __attribute__((flatten))
#else
#define LASERAX_FLATTEN
#endif

// LX_CONSTEXPR: constexpr with the own integer back end, whose operations are constant
// expressions, so that a function that forms an initial value (e.g. the configuration check of the
// reset registers) leaves the static top constant-initialised (no run-time constructor, CTest
// hls_const_init); empty with the vendor types, whose operators are not constexpr.
#if defined(LASERAX_USE_AP_TYPES) || defined(LASERAX_USE_AC_TYPES)
#define LX_CONSTEXPR
#else
#define LX_CONSTEXPR constexpr
#endif

// LX_LOOP(name) names the loop that follows it for Vitis HLS, whose reports and directives refer
// to a loop by its label. Only the synthesis front end sees the label: GCC and Clang warn of a
// label no goto uses (-Wunused-label, an error in this build), so the C++ build drops it.
#ifdef __SYNTHESIS__
#define LX_LOOP(name) name:
#else
#define LX_LOOP(name)
#endif

namespace lx {
// hi * 2^WL + lo as sint<WH + WL> (hi signed WH bits, lo unsigned WL bits): the concatenation of
// the two bit patterns, always in range (own back end: no wrap of the sum; the vendor types: the
// same value through their operators). WH + WL <= 64.
template <int WH, int WL>
inline sint<WH + WL> cat_s(const sint<WH>& hi, const uint<WL>& lo) {
    static_assert(WH + WL <= 64, "lx::cat_s: at most 64 bits");
#if defined(LASERAX_USE_AP_TYPES) || defined(LASERAX_USE_AC_TYPES)
    return sint<WH + WL>(sint<WH + WL>(hi) * (int64_t(1) << WL) + lo);
#else
    return sint<WH + WL>::exact(static_cast<int64_t>(hi) * (int64_t(1) << WL) + static_cast<int64_t>(lo));
#endif
}

// u + 1 for a u the caller knows below 2^W - 1, and u - 1 for a u it knows above 0, as uint<W>
// (own back end: no wrap of the result, as cat_s; the vendor types: the same value through their
// operators). E.g. a saturating counter's increment, a nonzero timer's decrement.
template <int W>
inline uint<W> inc_below_max(const uint<W>& u) {
    static_assert(W <= 64, "lx::inc_below_max: at most 64 bits");
#if defined(LASERAX_USE_AP_TYPES) || defined(LASERAX_USE_AC_TYPES)
    return uint<W>(u + 1);
#else
    return uint<W>::exact(static_cast<uint64_t>(u) + 1);
#endif
}
template <int W>
inline uint<W> dec_above_zero(const uint<W>& u) {
    static_assert(W <= 64, "lx::dec_above_zero: at most 64 bits");
#if defined(LASERAX_USE_AP_TYPES) || defined(LASERAX_USE_AC_TYPES)
    return uint<W>(u - 1);
#else
    return uint<W>::exact(static_cast<uint64_t>(u) - 1);
#endif
}

// Number of bits needed to hold values 0..v; usable with both back ends for derived widths.
// (compile-time only; a loop rather than recursion to keep the hls/ lint simple).
constexpr int clog2p1(unsigned long long v) {
    int n = 1;
    while (v >= 2ULL) {
        v >>= 1;
        ++n;
    }
    return n;
}
}  // namespace lx

#endif  // LASERAX_HLS_LX_TYPES_H
