// tb_vectors — the golden vector files: written by `laserax vectors`, read back, replayed.
//
// * runs the built `laserax vectors` into a temporary folder;
// * reads every CSV back and its hex twin, which must hold the same numbers;
// * replays the laserax_top stimulus (pins + registers) into a fresh hls axis_core and compares
//   every expected column on every row; replays the dds_sincos and pulse_multiplier block files
//   into fresh hls blocks the same way (the files, not the generator, are the reference here);
// * malformed files (truncated row, bad number, wrong header, wrong hex width, bad hex digit,
//   value too wide) are rejected with a message, not a crash.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "hls/axis_core.h"
#include "tb/tb_util.h"
#include "tools/common/dds_table.h"
#include "tools/common/sim.h"
#include "tools/common/vectors.h"

namespace {

int64_t v(const lxt::vec_table& t, const std::vector<int64_t>& row, const char* name) {
    const int i = t.col(name);
    return i < 0 ? INT64_MIN : row[static_cast<size_t>(i)];
}

}  // namespace

int main(int argc, char** argv) {
    tbu::result res("tb_vectors", tbu::seed_from(argc, argv, 1));
    const char* bd = std::getenv("LASERAX_BUILD_DIR");
    const std::string build = bd ? bd : "build";
    const std::string dir = "/tmp/laserax_tb_vectors_" + std::to_string(::getpid());
    const std::string cmd = build + "/laserax vectors --out " + dir + " --calls 20000 > /dev/null";
    if (!res.check(std::system(cmd.c_str()) == 0, "failed: " + cmd)) return res.finish();

    const char* blocks[] = {"input_filter", "quad_decoder", "pulse_multiplier", "output_pacer", "rephase", "dds_sincos",
                            "laserax_top", "pso", "encoder_counter"};
    for (const char* b : blocks) {
        std::string text, hex, err;
        lxt::vec_table t, th;
        res.check(lxt::read_file(dir + "/" + b + ".csv", text, &err), err);
        res.check(lxt::vec_from_csv(text, t, &err), std::string(b) + ".csv: " + err);
        res.check(t.rows.size() == 20000, std::string(b) + ": row count");
        res.check(lxt::read_file(dir + "/" + b + ".hex", hex, &err), err);
        res.check(lxt::vec_from_hex(hex, t, th, &err), std::string(b) + ".hex: " + err);
        res.check(th.rows == t.rows, std::string(b) + ": hex and csv differ");
        res.check(text.find("Command: ") != std::string::npos && hex.find("Command: ") != std::string::npos,
                  std::string(b) + ": no generating command in the header");

        if (std::string(b) == "laserax_top") {
            lx::axis_core core;
            lxt::load_table(core, 256, 32767);
            const char* outs[] = {"sin", "cos", "ref_mark", "qa", "qb", "qz", "cfg_err", "stage", "alarm", "err_cnt",
                                  "raw_count", "comp_pos", "paced_pos", "out_pos", "d"};
            long bad = 0;
            for (size_t r = 0; r < t.rows.size() && bad < 5; ++r) {
                const std::vector<int64_t>& row = t.rows[r];
                lxt::axis_settings s;
                s.period = v(t, row, "period");
                s.ratio = static_cast<uint64_t>(v(t, row, "ratio"));
                s.glitch_n = v(t, row, "glitch_n");
                s.sw_debounce = v(t, row, "sw_debounce");
                s.min_spacing = v(t, row, "min_spacing");
                s.pace_m = v(t, row, "pace_m");
                s.backlog_thr = static_cast<uint64_t>(v(t, row, "backlog_thr"));
                s.mark_len = v(t, row, "mark_len");
                s.dac_width = v(t, row, "dac_width");
                s.amplitude = v(t, row, "amplitude");
                s.tbl_period = v(t, row, "tbl_period");
                s.rehome = v(t, row, "rehome") != 0;
                s.clear = v(t, row, "clear") != 0;
                lx::axis_pins p;
                p.a = v(t, row, "a") != 0;
                p.b = v(t, row, "b") != 0;
                p.sw = v(t, row, "sw") != 0;
                p.lerr = v(t, row, "lerr") != 0;
                const lx::axis_out o = core.step(p, lxt::to_hls(s));
                const int64_t got[] = {o.sin.to_int64(), o.cos.to_int64(), o.ref_mark, o.qa, o.qb, o.qz, o.cfg_err,
                                       o.stage.to_int64(), o.alarm, o.err_cnt.to_int64(), o.raw_count.to_int64(),
                                       o.comp_pos.to_int64(), o.paced_pos.to_int64(), o.out_pos.to_int64(), o.d.to_int64()};
                for (size_t k = 0; k < sizeof(outs) / sizeof(outs[0]); ++k) {
                    if (got[k] != v(t, row, outs[k])) {
                        ++bad;
                        res.check(false, std::string("laserax_top replay row ") + std::to_string(r) + " signal " + outs[k] +
                                             ": expected " + std::to_string(v(t, row, outs[k])) + " got " +
                                             std::to_string(got[k]));
                        break;
                    }
                    res.check(true, "");
                }
            }
            const std::vector<int64_t>& last = t.rows.back();
            res.check(v(t, last, "stage") == 3 || v(t, last, "stage") == 1, "vectors end in an odd stage");
        }
        if (std::string(b) == "dds_sincos") {
            lx::dds_sincos d;
            for (size_t r = 0; r < t.rows.size(); ++r) {
                const std::vector<int64_t>& row = t.rows[r];
                const lx::dds_sincos::out_t o = d.step(v(t, row, "ostep"), v(t, row, "period"), v(t, row, "amplitude"));
                res.expect(o.sin == v(t, row, "sin") && o.cos == v(t, row, "cos"),
                           [&] { return "dds_sincos replay row " + std::to_string(r); });
            }
        }
        if (std::string(b) == "pulse_multiplier") {
            lx::pulse_multiplier m;
            for (size_t r = 0; r < t.rows.size(); ++r) {
                const std::vector<int64_t>& row = t.rows[r];
                const lx::pulse_multiplier::out_t o = m.step(v(t, row, "step"), static_cast<uint64_t>(v(t, row, "ratio")));
                res.expect(o.comp == v(t, row, "comp") && o.delta == v(t, row, "delta"),
                           [&] { return "pulse_multiplier replay row " + std::to_string(r); });
            }
        }
    }

    // malformed input
    std::string text, err;
    lxt::read_file(dir + "/pulse_multiplier.csv", text, &err);
    lxt::vec_table t, layout;
    lxt::vec_from_csv(text, layout, &err);
    const size_t hdr = text.find("step,ratio");
    const size_t row1 = text.find('\n', hdr) + 1;
    const std::string head = text.substr(0, row1);
    const std::string mutations[] = {
        head + "1,34789620252,0\n",                 // missing value
        head + "1,34789620252,0,0,9\n",             // extra value
        head + "x,34789620252,0,0\n",               // not a number
        head + "5,34789620252,0,0\n",               // step 5 does not fit 2 signed bits
        text.substr(0, hdr) + "step,ratioX,comp,delta\n",  // header mismatch
        std::string("1,2,3,4\n"),                   // no header at all
    };
    for (const std::string& m : mutations) {
        err.clear();
        res.check(!lxt::vec_from_csv(m, t, &err) && !err.empty(), "malformed CSV accepted: " + m.substr(m.size() > 40 ? m.size() - 40 : 0));
    }
    const std::string hex_bad[] = {"0001\n", "zz0000000000000000000000000000\n",
                                   std::string(2 + 10 + 10 + 10, 'f') + "\n"};
    for (const std::string& m : hex_bad) {
        err.clear();
        res.check(!lxt::vec_from_hex(m, layout, t, &err) && !err.empty(), "malformed hex accepted: " + m);
    }
    res.check(!lxt::read_file(dir + "/no_such_file.csv", text, &err), "missing file not reported");
    std::system(("rm -rf " + dir).c_str());
    return res.finish();
}
