// bench — simulation speed of the models and of the vector writer (numbers, not a pass/fail test).
//
// Prints simulated calls (clocks) per second for: the hls single-axis chain, each hls block alone,
// the golden chain, the two chains side by side as the testbenches run them, and golden-vector
// rows written per second (build + CSV + hex). Stimulus: a moving axis with a ratio of ~8.1.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>

#include "golden/laserax_top.h"
#include "hls/laserax_top.h"
#include "sysmodel/sim.h"
#include "tools/laserax/vectors.h"

namespace {

using clk = std::chrono::steady_clock;

double secs(clk::time_point a) { return std::chrono::duration<double>(clk::now() - a).count(); }

volatile long long sink;

// A value the compiler cannot see (read back from a volatile): the register inputs of the block
// items, so that a step inlined into a bench loop is not specialised for constant registers.
template <typename T>
T opaque(T v) {
    volatile T x = v;
    return x;
}
const char* g_only = nullptr;
// heap_note: the models of the chain, golden and testbench items live on the heap. On the stack of
// main their placement relative to the loop's temporaries changes with every change of any item's
// code, and on the bench machine (AMD EPYC) some placements halved the clocks per second of the
// unchanged golden model (4K aliasing of stores and loads; issue 13). Instruction counts are not
// affected.  // --only KEY: run only the items whose name contains KEY

// The chain item calls the chain through this non-inlined function, as a testbench does: the whole
// axis_out is produced (inlined into the bench loop, the unused outputs would not be computed). It
// uses the interface the testbenches use (lxt::dual_axis): registers through the write port,
// laserax_top::tick(), the outputs by reference (issue 13).
__attribute__((noinline)) const lx::axis_out& chain_step(lx::laserax_top& core, const lx::axis_pins& p) {
    return core.tick(p);
}

template <typename F>
void report(const char* name, long long n, F&& body) {
    if (g_only && !std::strstr(name, g_only)) return;
    const clk::time_point t0 = clk::now();
    const std::clock_t c0 = std::clock();
    body(n);
    const double s = secs(t0);
    // processor time as well: on a shared machine the wall-clock rate includes time spent waiting
    const double cs = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::printf("  %-34s %12.3f M calls/s   (%lld calls in %.3f s; %.3f M calls per CPU second)\n", name,
                static_cast<double>(n) / s / 1e6, n, s, cs > 0 ? static_cast<double>(n) / cs / 1e6 : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
    // bench [CALLS] [--only KEY]: CALLS per item (default 2e7); --only runs the matching items
    // alone (scripts/bench_ipc.sh counts their instructions per call under callgrind)
    long long n = 20000000;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--only" && i + 1 < argc) {
            g_only = argv[++i];
        } else {
            char* end = nullptr;
            n = std::strtoll(argv[i], &end, 10);
            if (end == argv[i] || *end != '\0' || n < 1) {
                std::fprintf(stderr, "bench: usage: bench [CALLS >= 1] [--only KEY]\n");
                return 2;
            }
        }
    }
    std::printf("laserax bench (%lld calls per item; 1 call = 1 clock)\n", n);
    // The register block is read through a pointer the compiler cannot see through (as in a
    // testbench, whose registers change): a chain step inlined into a loop here must not be
    // specialised for the reset values.
    lx::axis_regs regs_store;
    lx::axis_regs* volatile regs_ptr = &regs_store;
    const lx::axis_regs& regs = *regs_ptr;
    auto pins_at = [](long long t, lx::axis_pins& p) {
        lxt::quad_pins(t / 37, p.a, p.b);
        p.sw = (t / 37) > 5000;
    };
    report("hls laserax_top (full chain)", n, [&](long long k) {
        const std::unique_ptr<lx::laserax_top> core_p(new lx::laserax_top);  // on the heap: see heap_note
        lx::laserax_top& core = *core_p;
        core.write_regs(regs);
        long long acc = 0;
        for (long long t = 0; t < k; ++t) {
            lx::axis_pins p;
            pins_at(t, p);
            acc += chain_step(core, p).sin.to_int64();
        }
        sink = acc;
    });
    report("hls quad_decoder", n, [&](long long k) {
        lx::quad_decoder d;
        const bool no = opaque(false);
        const lx::quad_decoder_cfg::glitch_t glitch_n = opaque(2);
        const lx::quad_decoder_cfg::spacing_t spacing = opaque(0);
        long long acc = 0;
        for (long long t = 0; t < k; ++t) {
            lx::axis_pins p;
            pins_at(t, p);
            acc += d.step(p.a, p.b, no, glitch_n, spacing, no).raw_count.to_int64();
        }
        sink = acc;
    });
    report("hls pulse_multiplier", n, [&](long long k) {
        lx::pulse_multiplier m;
        const lx::ratio_t ratio = opaque(34789620252ULL);
        const lx::offset_t offset = opaque(0LL);
        long long acc = 0;
        for (long long t = 0; t < k; ++t) acc += m.step((t % 37) == 0 ? 1 : 0, ratio, offset).delta.to_int64();
        sink = acc;
    });
    report("hls output_pacer", n, [&](long long k) {
        lx::output_pacer pc;
        const lx::output_pacer_cfg::pace_t pace = opaque(4);
        const lx::output_pacer_cfg::thr_t thr = opaque(4096);
        const bool no = opaque(false);
        long long acc = 0;
        for (long long t = 0; t < k; ++t) acc += pc.step((t % 37) == 0 ? 8 : 0, 0, pace, thr, no, no).pstep.to_int64();
        sink = acc;
    });
    report("hls rephase", n, [&](long long k) {
        lx::rephase r;
        const bool yes = opaque(true), no = opaque(false);
        const lx::period_t period = opaque(256), mark_len = opaque(64);
        long long acc = 0;
        for (long long t = 0; t < k; ++t)
            acc += r.step((t % 5) == 0 ? 1 : 0, (t % 5) == 2, (t / 5) % 100000 > 3000, yes, no, no, period, mark_len).out_pos.to_int64();
        sink = acc;
    });
    report("hls dds_sincos", n, [&](long long k) {
        lx::dds_sincos d;
        const lx::period_t period = opaque(256);
        const lx::dds_sincos_cfg::amp_t amp = opaque(32767);
        long long acc = 0;
        for (long long t = 0; t < k; ++t) acc += d.step((t % 3) == 0 ? 1 : 0, period, amp).sin.to_int64();
        sink = acc;
    });
    report("golden laserax_top", n / 4, [&](long long k) {
        const std::unique_ptr<golden::laserax_top> g_p(new golden::laserax_top);  // see heap_note
        golden::laserax_top& g = *g_p;
        g.reset();
        const golden::axis_regs gr;
        long long acc = 0;
        for (long long t = 0; t < k; ++t) {
            lx::axis_pins p;
            pins_at(t, p);
            golden::axis_pins gp;
            gp.a = p.a;
            gp.b = p.b;
            gp.sw = p.sw;
            acc += g.step(gp, gr).sin;
        }
        sink = acc;
    });
    report("hls + golden + compare (tb style)", n / 4, [&](long long k) {
        const std::unique_ptr<lxt::dual_axis> ax_p(new lxt::dual_axis{lxt::axis_settings{}});  // see heap_note
        lxt::dual_axis& ax = *ax_p;
        long long bad = 0;
        for (long long t = 0; t < k; ++t) {
            lx::axis_pins p;
            pins_at(t, p);
            bad += ax.step(p).empty() ? 0 : 1;
        }
        sink = bad;
    });
    if (g_only) return 0;
    {
        const long long rows = 200000;
        const clk::time_point t0 = clk::now();
        std::vector<lxt::vec_table> tables;
        std::string err;
        lxt::build_vectors(1, rows, tables, &err);
        size_t bytes = 0, total_rows = 0;
        for (const lxt::vec_table& t : tables) {
            bytes += lxt::vec_to_csv(t, "bench").size() + lxt::vec_to_hex(t, "bench").size();
            total_rows += t.rows.size();
        }
        const double s = secs(t0);
        std::printf("  %-34s %12.3f M rows/s    (%zu rows over %zu files x 2 formats, %.1f MB, %.3f s)%s\n",
                    "golden vectors (build+CSV+hex)", static_cast<double>(total_rows) / s / 1e6, total_rows,
                    tables.size(), static_cast<double>(bytes) / 1e6, s, err.empty() ? "" : (" ERROR: " + err).c_str());
    }
    std::printf("  model state: sizeof(laserax_top) = %zu bytes (of which the table RAM image %zu)\n", sizeof(lx::laserax_top),
                sizeof(lx::tbl_word_t) * lx::axis_widths::TBL_DEPTH);
    return 0;
}
