// const_init.cpp — compile-time proof that the hls/ state starts without a run-time constructor
// (issue 37, finding 2). Compiled as C++20 (constinit) by the CTest hls_const_init; never linked.
//
// Vitis HLS turns a static object's first-call construction into logic (or unrolled RAM writes)
// instead of flip-flop and RAM INIT values. Every block therefore starts at its default member
// initialisers and constant tables: `constinit` makes the compiler reject this file if any of
// these objects needed dynamic initialisation (a constructor body, a loop, a non-constant
// initialiser). hls/ itself stays C++14; only this check uses C++20.
#include "hls/encoder_counter.h"
#include "hls/laserax_top.h"
#include "hls/pso.h"

#if __cplusplus < 202002L
#error "const_init.cpp needs C++20 (constinit)"
#endif

constinit lx::input_filter<8> g_input_filter;
constinit lx::quad_decoder g_quad_decoder;
constinit lx::pulse_multiplier g_pulse_multiplier;
constinit lx::output_pacer g_output_pacer;
constinit lx::rephase g_rephase;
constinit lx::dds_sincos g_dds_sincos;
constinit lx::error_map g_error_map;
constinit lx::laserax_top g_laserax_top;
// the blocks built beside the chain (docs/PSO_COUNTERS.md)
constinit lx::encoder_counter g_encoder_counter;
constinit lx::pso g_pso;
