// tb_vectors — the golden vector files: written by `laserax vectors`, read back, replayed.
//
// * runs the built `laserax vectors` into a temporary folder;
// * reads every CSV back and its hex twin, which must hold the same numbers;
// * replays the laserax_top stimulus (pins, registers, table and error-map write ports) into a
//   fresh hls laserax_top and compares every output column on every row; replays the dds_sincos
//   (table port included), pulse_multiplier (preset included) and error_map (its directed tail
//   included) block files into fresh hls blocks the same way (the files, not the generator, are
//   the reference here). The laserax_top replay runs a second hls core that takes the row's
//   registers through its write port on every row (laserax_top::write_regs + tick: the register
//   reload and check in every call) beside the first one's step(), which writes only a block that
//   differs from the presented one (the in-force shortcut, issue 13): all 36 outputs must agree
//   on every row. Columns are found by
//   name: a replay fails if the file has an input column it does not apply or an output column it
//   cannot compare, so a new column cannot go unchecked;
// * malformed files (truncated row, bad number, wrong header, wrong hex width, bad hex digit,
//   and the strict-reader cases of issue 12: field direction / width / signedness words, a field
//   line after the header, a CR inside a number, duplicate names, a negative unsigned (64-bit)
//   value, a leading +, no data rows, an empty hex file; each with FILE:LINE: reason),
//   value too wide) are rejected with a message, not a crash.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "hls/laserax_top.h"
#include "tb/tb_util.h"
#include "host/dds_table.h"
#include "sysmodel/sim.h"
#include "tools/laserax/vectors.h"

namespace {

// Input columns of one table read by name; remembers what was read, so that a replay can insist
// on having applied every input column of the file.
class inputs {
public:
    explicit inputs(const lxt::vec_table& t) : t_(t), used_(t.cols.size(), false) {}
    void row(const std::vector<int64_t>& r) { row_ = &r; }
    int64_t operator()(const char* name) {
        const int i = t_.col(name);  // inputs come first: quad_decoder has an input and an output lerr
        if (i < 0 || !t_.cols[static_cast<size_t>(i)].is_input) {
            missing_ = name;
            return 0;
        }
        used_[static_cast<size_t>(i)] = true;
        return (*row_)[static_cast<size_t>(i)];
    }
    // every input column applied, and no column asked for that the file does not have
    void report(tbu::result& res) const {
        res.check(missing_.empty(), t_.block + " replay: the file has no input column " + missing_);
        for (size_t i = 0; i < t_.cols.size(); ++i)
            res.check(!t_.cols[i].is_input || used_[i], t_.block + " replay: input column " + t_.cols[i].name +
                                                            " is not applied by the replay");
    }

private:
    const lxt::vec_table& t_;
    std::vector<bool> used_;
    std::string missing_;
    const std::vector<int64_t>* row_ = nullptr;
};

struct named {
    const char* name;
    int64_t value;
};

// Compares every output column of row r with the replayed value of that name; an output column
// without a replayed value is a failure. Returns false on the first difference of the row.
bool check_outputs(tbu::result& res, const lxt::vec_table& t, size_t r, const std::vector<named>& got) {
    const std::vector<int64_t>& row = t.rows[r];
    for (size_t i = 0; i < t.cols.size(); ++i) {
        const lxt::vec_column& c = t.cols[i];
        if (c.is_input) continue;
        const named* g = nullptr;
        for (const named& n : got)
            if (c.name == n.name) g = &n;
        if (!res.expect(g != nullptr, [&] { return t.block + " replay: no replayed value for output column " + c.name; }))
            return false;
        if (!res.expect(g->value == row[i], [&] {
                return t.block + " replay row " + std::to_string(r) + " signal " + c.name + ": expected " +
                       std::to_string(row[i]) + " got " + std::to_string(g->value);
            }))
            return false;
    }
    return true;
}

// the 37 outputs of a laserax_top call by name (the output columns of laserax_top.csv)
std::vector<named> top_outputs(const lx::axis_out& x) {
    return {
        {"sin", x.sin.to_int64()}, {"cos", x.cos.to_int64()}, {"ref_mark", x.ref_mark}, {"qa", x.qa},
        {"qb", x.qb}, {"qz", x.qz}, {"q_oe", x.q_oe}, {"cfg_err", x.cfg_err}, {"stage", x.stage.to_int64()}, {"homed", x.homed},
        {"lerr_alarm", x.lerr_alarm}, {"illegal_st", x.illegal_st}, {"err_cnt", x.err_cnt.to_int64()},
        {"ovs_edge_st", x.ovs_edge_st}, {"ovs_backlog_st", x.ovs_backlog_st}, {"glitch_st", x.glitch_st},
        {"alarm", x.alarm}, {"raw_count", x.raw_count.to_int64()}, {"comp_pos", x.comp_pos.to_int64()},
        {"paced_pos", x.paced_pos.to_int64()}, {"out_pos", x.out_pos.to_int64()}, {"d", x.d.to_int64()},
        {"step", x.step.to_int64()}, {"delta", x.delta.to_int64()}, {"backlog", x.backlog.to_int64()},
        {"pstep", x.pstep.to_int64()}, {"ostep", x.ostep.to_int64()}, {"adj", x.adj.to_int64()},
        {"a_pos", x.a_pos.to_int64()}, {"b_pos", x.b_pos.to_int64()}, {"c_pos", x.c_pos.to_int64()},
        {"z_pos", x.z_pos.to_int64()}, {"rep_mark", x.rep_mark}, {"map_cfg_err", x.map_cfg_err},
        {"corr", x.corr.to_int64()}, {"map_delta", x.map_delta.to_int64()}};
}

void replay_top(tbu::result& res, const lxt::vec_table& t) {
    lx::laserax_top core;
    lxt::load_table(core, 256, 32767);
    lx::laserax_top reload;  // written on every row (no shortcut of an unchanged block)
    lxt::load_table(reload, 256, 32767);
    inputs in(t);
    long bad = 0;
    long reload_bad = 0;
    for (size_t r = 0; r < t.rows.size() && bad < 5; ++r) {
        in.row(t.rows[r]);
        lxt::axis_settings s;
        s.period = in("period");
        s.ratio = static_cast<uint64_t>(in("ratio"));
        s.comp_offset = in("comp_offset");
        s.comp_sync = in("comp_sync") != 0;
        s.comp_commit = in("comp_commit") != 0;
        s.glitch_n = in("glitch_n");
        s.sw_debounce = in("sw_debounce");
        s.min_spacing = in("min_spacing");
        s.pace_m = in("pace_m");
        s.backlog_thr = static_cast<uint64_t>(in("backlog_thr"));
        s.mark_len = in("mark_len");
        s.dac_width = in("dac_width");
        s.amplitude = in("amplitude");
        s.tbl_period = in("tbl_period");
        s.rehome = in("rehome") != 0;
        s.clear = in("clear") != 0;
        s.pin_cfg = in("pin_cfg");
        s.emap.map_en = in("map_en") != 0;
        s.emap.bank_sel = in("bank_sel") != 0;
        s.emap.geom[0].origin = in("map_origin0");
        s.emap.geom[0].spacing_log2 = static_cast<int>(in("map_k0"));
        s.emap.geom[0].n_points = static_cast<int>(in("map_n0"));
        s.emap.geom[1].origin = in("map_origin1");
        s.emap.geom[1].spacing_log2 = static_cast<int>(in("map_k1"));
        s.emap.geom[1].n_points = static_cast<int>(in("map_n1"));
        s.emap.we = in("map_we") != 0;
        s.emap.addr = static_cast<int>(in("map_addr"));
        s.emap.data = static_cast<int32_t>(in("map_data"));
        lx::axis_regs regs = lxt::to_hls(s);
        regs.tbl_we = in("tbl_we") != 0;  // the table port is not a golden register
        regs.tbl_addr = static_cast<unsigned>(in("tbl_addr"));
        regs.tbl_data = static_cast<unsigned>(in("tbl_data"));
        lx::axis_pins p;
        p.a = in("a") != 0;
        p.b = in("b") != 0;
        p.sw = in("sw") != 0;
        p.lerr = in("lerr") != 0;
        const lx::axis_out o = core.step(p, regs);
        reload.write_regs(regs);
        const lx::axis_out& ro = reload.tick(p);
        const std::vector<named> got = top_outputs(o);
        if (!check_outputs(res, t, r, got)) ++bad;
        const std::vector<named> rgot = top_outputs(ro);
        for (size_t i = 0; i < got.size() && reload_bad < 5; ++i)
            if (!res.expect(rgot[i].value == got[i].value, [&] {
                    return "laserax_top row " + std::to_string(r) + ": " + got[i].name + " " + std::to_string(got[i].value) +
                           " with step(), " + std::to_string(rgot[i].value) + " with a register write every call";
                }))
                ++reload_bad;
    }
    in.report(res);
#ifndef __SYNTHESIS__  // (the RAM flags: C simulation only)
    res.check(core.ram_violations() == 0 && reload.ram_violations() == 0,
              "laserax_top: RAM port violations " + std::to_string(core.ram_violations() | reload.ram_violations()));
#endif
    const std::vector<int64_t>& last = t.rows.back();
    const int stage = t.col("stage");
    res.check(stage >= 0 && (last[static_cast<size_t>(stage)] == 3 || last[static_cast<size_t>(stage)] == 1),
              "vectors end in an odd stage");
}

void replay_dds(tbu::result& res, const lxt::vec_table& t) {
    lx::dds_sincos d;  // power-up table: P = 256, amp = 32767
    inputs in(t);
    long bad = 0;
    for (size_t r = 0; r < t.rows.size() && bad < 5; ++r) {
        in.row(t.rows[r]);
        const bool we = in("tbl_we") != 0;
        const unsigned addr = static_cast<unsigned>(in("tbl_addr"));
        const uint32_t data = static_cast<uint32_t>(in("tbl_data"));
        if (we) d.write(addr, data);  // before the step of the same call, as laserax_top::step()
        const lx::dds_sincos::out_t o = d.step(lx::step_t(in("ostep")), static_cast<unsigned>(in("period")),
                                               static_cast<unsigned>(in("amplitude")));
        if (!check_outputs(res, t, r, {{"sin", o.sin.to_int64()}, {"cos", o.cos.to_int64()}})) ++bad;
    }
    in.report(res);
#ifndef __SYNTHESIS__  // (the RAM flags: C simulation only)
    res.check(d.ram_violations() == 0, "dds_sincos: RAM port violations " + std::to_string(d.ram_violations()));
#endif
}

void replay_multiplier(tbu::result& res, const lxt::vec_table& t) {
    lx::pulse_multiplier m;
    inputs in(t);
    long bad = 0;
    for (size_t r = 0; r < t.rows.size() && bad < 5; ++r) {
        in.row(t.rows[r]);
        const uint64_t ratio = static_cast<uint64_t>(in("ratio"));
        const int64_t preset_n = in("preset_n");
        const lx::offset_t off = in("comp_offset");
        if (in("preset") != 0) m.preset(lx::raw_t(preset_n), lx::ratio_t(ratio), off);
        const lx::pulse_multiplier::out_t o = m.step(lx::step_t(in("step")), lx::ratio_t(ratio), off);
        if (!check_outputs(res, t, r, {{"comp", o.comp.to_int64()}, {"delta", o.delta.to_int64()}})) ++bad;
    }
    in.report(res);
}

void replay_error_map(tbu::result& res, const lxt::vec_table& t) {
    lx::error_map m;
    inputs in(t);
    long bad = 0;
    for (size_t r = 0; r < t.rows.size() && bad < 5; ++r) {
        in.row(t.rows[r]);
        lx::error_map_regs regs;
        regs.map_en = in("map_en") != 0;
        regs.bank_sel = in("bank_sel") != 0;
        regs.geom[0].origin = in("origin0");
        regs.geom[0].spacing_log2 = static_cast<unsigned>(in("k0"));
        regs.geom[0].n_points = static_cast<unsigned>(in("n0"));
        regs.geom[1].origin = in("origin1");
        regs.geom[1].spacing_log2 = static_cast<unsigned>(in("k1"));
        regs.geom[1].n_points = static_cast<unsigned>(in("n1"));
        regs.we = in("we") != 0;
        regs.addr = static_cast<unsigned>(in("addr"));
        regs.data = in("data");
        const lx::error_map::out_t o = m.step(lx::pos_t(in("p")), in("homed") != 0, regs);
        if (!check_outputs(res, t, r,
                           {{"corr", o.corr.to_int64()}, {"delta", o.delta.to_int64()}, {"active", o.active},
                            {"in_range", o.in_range}, {"clamped", o.clamped}, {"cfg_err", o.cfg_err}}))
            ++bad;
    }
    in.report(res);
#ifndef __SYNTHESIS__  // (the RAM flags: C simulation only)
    res.check(m.ram_violations() == 0, "error_map: RAM port violations " + std::to_string(m.ram_violations()));
#endif
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
                            "error_map", "laserax_top", "pso", "encoder_counter"};
    for (const char* b : blocks) {
        std::string text, hex, err;
        lxt::vec_table t, th;
        res.check(lxt::read_file(dir + "/" + b + ".csv", text, &err), err);
        res.check(lxt::vec_from_csv(text, t, &err), std::string(b) + ".csv: " + err);
        t.block = b;  // (the CSV reader does not set it; the replay messages name it)
        // (error_map: the scenario's calls, then its directed tail)
        const size_t want = 20000 + (std::string(b) == "error_map" ? static_cast<size_t>(lxt::kErrorMapTailCalls) : 0);
        res.check(t.rows.size() == want, std::string(b) + ": row count");
        res.check(lxt::read_file(dir + "/" + b + ".hex", hex, &err), err);
        res.check(lxt::vec_from_hex(hex, t, th, &err), std::string(b) + ".hex: " + err);
        res.check(th.rows == t.rows, std::string(b) + ": hex and csv differ");
        res.check(text.find("Command: ") != std::string::npos && hex.find("Command: ") != std::string::npos,
                  std::string(b) + ": no generating command in the header");

        if (std::string(b) == "laserax_top") replay_top(res, t);
        if (std::string(b) == "dds_sincos") replay_dds(res, t);
        if (std::string(b) == "pulse_multiplier") replay_multiplier(res, t);
        if (std::string(b) == "error_map") replay_error_map(res, t);
    }

    // malformed input
    std::string text, err;
    lxt::read_file(dir + "/pulse_multiplier.csv", text, &err);
    lxt::vec_table t, layout;
    lxt::vec_from_csv(text, layout, &err);
    const size_t hdr = text.find("step,ratio");
    const size_t row1 = text.find('\n', hdr) + 1;
    const std::string head = text.substr(0, row1);
    const size_t ncol = layout.cols.size();
    // a data row: first value, then ratio, then zeros, `values` values in all
    auto row_with = [](const std::string& first, size_t values) {
        std::string r = first + ",34789620252";
        for (size_t k = 2; k < values; ++k) r += ",0";
        return r + "\n";
    };
    std::string bad_header = text.substr(hdr, row1 - hdr);
    bad_header.replace(bad_header.find("ratio"), 5, "ratioX");
    err.clear();
    res.check(lxt::vec_from_csv(head + row_with("1", ncol), t, &err) && t.rows.size() == 1,
              "well-formed CSV row rejected (the malformed cases below would prove nothing): " + err);
    const std::string mutations[] = {
        head + row_with("1", ncol - 1),        // missing value
        head + row_with("1", ncol + 1),        // extra value
        head + row_with("x", ncol),            // not a number
        head + row_with("5", ncol),            // step 5 does not fit 2 signed bits
        text.substr(0, hdr) + bad_header,      // header mismatch
        std::string("1,2,3,4,5,6\n"),          // no header at all
    };
    for (const std::string& m : mutations) {
        err.clear();
        res.check(!lxt::vec_from_csv(m, t, &err) && !err.empty(), "malformed CSV accepted: " + m.substr(m.size() > 40 ? m.size() - 40 : 0));
    }
    size_t width = 0;  // hex digits per line
    for (const lxt::vec_column& c : layout.cols) width += static_cast<size_t>((c.bits + 3) / 4);
    err.clear();
    res.check(lxt::vec_from_hex(std::string(width, '0') + "\n", layout, t, &err) && t.rows.size() == 1,
              "well-formed hex line rejected: " + err);
    const std::string hex_bad[] = {
        "0001\n",                                        // wrong line length
        std::string(width + 1, '0') + "\n",              // one digit too many
        "zz" + std::string(width - 2, '0') + "\n",       // not a hex digit
        "f" + std::string(width - 1, '0') + "\n",        // step 15 wider than 2 bits
    };
    for (const std::string& m : hex_bad) {
        err.clear();
        res.check(!lxt::vec_from_hex(m, layout, t, &err) && !err.empty(), "malformed hex accepted: " + m);
    }
    // strict reader (issue 12): each case rejected with "FILE:LINE: reason"
    {
        const std::string ok = "# field a in 4 signed\n# field u out 64 unsigned\na,u\n-3,7\n";
        err.clear();
        res.check(lxt::vec_from_csv(ok, t, &err, "ok.csv") && t.rows.size() == 1 && t.rows[0][0] == -3,
                  "well-formed small CSV rejected: " + err);
        struct bad_case {
            std::string text, file_line, reason;
        };
        const bad_case cases[] = {
            {"# field a inout 4 signed\na\n1\n", "b.csv:1: ", "direction 'inout' is not in or out"},
            {"# field a in 4x signed\na\n1\n", "b.csv:1: ", "width '4x' is not 1..64"},
            {"# field a in 0 signed\na\n1\n", "b.csv:1: ", "width '0' is not 1..64"},
            {"# field a in 65 signed\na\n1\n", "b.csv:1: ", "width '65' is not 1..64"},
            {"# field a in -4 signed\na\n1\n", "b.csv:1: ", "width '-4' is not 1..64"},
            {"# field a in 4 sign\na\n1\n", "b.csv:1: ", "'sign' is not signed or unsigned"},
            {"# field a in 4 signed extra\na\n1\n", "b.csv:1: ", "malformed field declaration"},
            {"# field a in 4 signed\na\n# field b in 4 signed\n1\n", "b.csv:3: ", "a '# field' line after the header"},
            {"# field a in 4 signed\na\n1\r2\n", "b.csv:3: ", "not an integer '1\r2'"},
            {"# field a in 4 signed\n# field a in 4 signed\na,a\n1,1\n", "b.csv:2: ", "duplicate field 'a'"},
            {"# field u in 64 unsigned\nu\n-1\n", "b.csv:3: ", "-1 does not fit 64 unsigned bits"},
            {"# field u in 8 unsigned\nu\n-1\n", "b.csv:3: ", "-1 does not fit 8 unsigned bits"},
            {"# field a in 4 signed\na\n+1\n", "b.csv:3: ", "not an integer '+1'"},
            {"# field a in 4 signed\na\n 1\n", "b.csv:3: ", "not an integer ' 1'"},
            {"# field a in 64 signed\na\n9223372036854775808\n", "b.csv:3: ", "not an integer"},
            {"# field a in 4 signed\na\n", "b.csv:2: ", "no data rows"},
            {"# field A in 4 signed\nA\n1\n", "b.csv:1: ", "malformed field name 'A'"},
        };
        for (const bad_case& c : cases) {
            err.clear();
            const bool okr = lxt::vec_from_csv(c.text, t, &err, "b.csv");
            res.check(!okr && err.find(c.file_line) == 0 && err.find(c.reason) != std::string::npos,
                      "strict CSV reader: want '" + c.file_line + "..." + c.reason + "', got '" + err + "' (accepted: " +
                          (okr ? "yes" : "no") + ")");
        }
        const std::string hex_empty[] = {"", "// a comment only\n", "\n\n"};
        for (const std::string& m : hex_empty) {
            err.clear();
            res.check(!lxt::vec_from_hex(m, layout, t, &err, "e.hex") && err.find("e.hex:") == 0 &&
                          err.find("no data rows") != std::string::npos,
                      "empty hex file accepted or wrong message: '" + err + "'");
        }
        err.clear();
        res.check(!lxt::vec_from_hex("zz" + std::string(width - 2, '0') + "\n", layout, t, &err, "z.hex") &&
                      err.find("z.hex:1: not a hex digit") == 0,
                  "hex message names file and line: '" + err + "'");
    }
    res.check(!lxt::read_file(dir + "/no_such_file.csv", text, &err), "missing file not reported");
    std::system(("rm -rf " + dir).c_str());
    return res.finish();
}
