#include "tools/laserax/vectors.h"

#include "tools/laserax/cli_util.h"
#include "tools/laserax/pacing_cli.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "golden/dds_sincos.h"
#include "golden/error_map.h"
#include "golden/input_filter.h"
#include "golden/output_pacer.h"
#include "golden/pulse_multiplier.h"
#include "golden/quad_decoder.h"
#include "golden/rephase.h"
#include "hls/laserax_top.h"
#include "hls/encoder_counter.h"
#include "hls/pso.h"
#include "host/dds_table.h"
#include "sysmodel/sim.h"

namespace lxt {

int vec_table::col(const std::string& name) const {
    for (size_t i = 0; i < cols.size(); ++i)
        if (cols[i].name == name) return static_cast<int>(i);
    return -1;
}

namespace {

int hex_digits(int bits) { return (bits + 3) / 4; }

std::string header_lines(const vec_table& t, const std::string& command, const char* lead) {
    std::ostringstream os;
    os << lead << " laserax golden vectors, block " << t.block << ", " << t.rows.size() << " calls (one row per clock)\n"
       << lead << " GENERATED FILE. Command: " << command << "\n"
       << lead << " expected columns come from golden/ and were checked equal to hls/ when written\n";
    for (const vec_column& c : t.cols)
        os << lead << " field " << c.name << " " << (c.is_input ? "in" : "out") << " " << c.bits << " "
           << (c.is_signed ? "signed" : "unsigned") << "\n";
    return os.str();
}

bool fits(int64_t v, const vec_column& c) {
    if (!c.is_signed && v < 0) return false;
    if (c.bits >= 64) return true;
    if (c.is_signed) {
        const int64_t lim = int64_t(1) << (c.bits - 1);
        return v >= -lim && v < lim;
    }
    return static_cast<uint64_t>(v) < (uint64_t(1) << c.bits);
}

// [-]digits, nothing else, within int64
bool parse_i64(const std::string& s, int64_t& v) {
    size_t i = 0;
    const bool neg = !s.empty() && s[0] == '-';
    if (neg) i = 1;
    if (i >= s.size()) return false;
    uint64_t m = 0;
    for (; i < s.size(); ++i) {
        if (s[i] < '0' || s[i] > '9') return false;
        const uint64_t d = static_cast<uint64_t>(s[i] - '0');
        if (m > (uint64_t(1) << 63) / 10 || m * 10 > (uint64_t(1) << 63) - d) return false;
        m = m * 10 + d;
    }
    if (!neg && m > uint64_t(INT64_MAX)) return false;
    v = neg ? (m == (uint64_t(1) << 63) ? INT64_MIN : -static_cast<int64_t>(m)) : static_cast<int64_t>(m);
    return true;
}

std::vector<std::string> split(const std::string& line, char sep) {
    std::vector<std::string> f;
    std::string cur;
    for (char ch : line) {
        if (ch == sep) {
            f.push_back(cur);
            cur.clear();
        } else {
            cur += ch;  // a CR inside the line stays and makes the value invalid
        }
    }
    f.push_back(cur);
    return f;
}

bool valid_name(const std::string& n) {
    if (n.empty() || !((n[0] >= 'a' && n[0] <= 'z') || n[0] == '_')) return false;
    for (char ch : n)
        if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_')) return false;
    return true;
}

std::string where(const std::string& name, long ln) {
    return (name.empty() ? std::string("<text>") : name) + ":" + std::to_string(ln) + ": ";
}

}  // namespace

std::string vec_to_csv(const vec_table& t, const std::string& command) {
    std::ostringstream os;
    os << header_lines(t, command, "#");
    for (size_t i = 0; i < t.cols.size(); ++i) os << (i ? "," : "") << t.cols[i].name;
    os << "\n";
    for (const std::vector<int64_t>& r : t.rows) {
        for (size_t i = 0; i < r.size(); ++i) os << (i ? "," : "") << r[i];
        os << "\n";
    }
    return os.str();
}

std::string vec_to_hex(const vec_table& t, const std::string& command) {
    std::ostringstream os;
    os << header_lines(t, command, "//");
    os << "// each line: the fields above concatenated in that order, each as two's complement in\n"
       << "// ceil(bits/4) hex digits (most significant field first)\n";
    char buf[32];
    for (const std::vector<int64_t>& r : t.rows) {
        for (size_t i = 0; i < r.size(); ++i) {
            const int bits = t.cols[i].bits;
            const int digits = hex_digits(bits);
            uint64_t u = static_cast<uint64_t>(r[i]);
            if (bits < 64) u &= (uint64_t(1) << bits) - 1;
            if (digits < 4 * 4) u &= (digits >= 16) ? ~uint64_t(0) : ((uint64_t(1) << (4 * digits)) - 1);
            std::snprintf(buf, sizeof buf, "%0*llx", digits, static_cast<unsigned long long>(u));
            os << buf;
        }
        os << "\n";
    }
    return os.str();
}

bool vec_from_csv(const std::string& text, vec_table& t, std::string* err, const std::string& name) {
    t.cols.clear();
    t.rows.clear();
    std::istringstream is(text);
    std::string line;
    long ln = 0;
    bool have_header = false;
    std::vector<vec_column> declared;
    auto fail = [&](const std::string& why) {
        if (err) *err = where(name, ln) + why;
        return false;
    };
    while (std::getline(is, line)) {
        ++ln;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        if (line[0] == '#') {
            std::istringstream ls(line.substr(1));
            std::vector<std::string> w;
            for (std::string x; ls >> x;) w.push_back(x);
            if (w.empty() || w[0] != "field") continue;  // a comment (block, command, ...)
            if (have_header) return fail("a '# field' line after the header row");
            if (w.size() != 5) return fail("malformed field declaration (want: # field NAME in|out BITS signed|unsigned)");
            if (!valid_name(w[1])) return fail("malformed field name '" + w[1] + "'");
            if (w[2] != "in" && w[2] != "out") return fail("field " + w[1] + ": direction '" + w[2] + "' is not in or out");
            int64_t bits = 0;
            if (!parse_i64(w[3], bits) || w[3][0] == '-' || bits < 1 || bits > 64)
                return fail("field " + w[1] + ": width '" + w[3] + "' is not 1..64");
            if (w[4] != "signed" && w[4] != "unsigned")
                return fail("field " + w[1] + ": '" + w[4] + "' is not signed or unsigned");
            for (const vec_column& d : declared)
                if (d.name == w[1]) return fail("duplicate field '" + w[1] + "'");
            vec_column c;
            c.name = w[1];
            c.bits = static_cast<int>(bits);
            c.is_input = w[2] == "in";
            c.is_signed = w[4] == "signed";
            declared.push_back(c);
            continue;
        }
        const std::vector<std::string> f = split(line, ',');
        if (!have_header) {
            if (declared.size() != f.size())
                return fail("header has " + std::to_string(f.size()) + " columns but " + std::to_string(declared.size()) +
                            " fields are declared");
            for (size_t i2 = 0; i2 < f.size(); ++i2)
                if (f[i2] != declared[i2].name)
                    return fail("column '" + f[i2] + "' does not match field '" + declared[i2].name + "'");
            t.cols = declared;
            have_header = true;
            continue;
        }
        if (f.size() != t.cols.size())
            return fail(std::to_string(f.size()) + " values, expected " + std::to_string(t.cols.size()));
        std::vector<int64_t> row(f.size());
        for (size_t i2 = 0; i2 < f.size(); ++i2) {
            if (!parse_i64(f[i2], row[i2])) return fail("column " + t.cols[i2].name + ": not an integer '" + f[i2] + "'");
            if (!fits(row[i2], t.cols[i2]))
                return fail("column " + t.cols[i2].name + ": " + f[i2] + " does not fit " + std::to_string(t.cols[i2].bits) +
                            (t.cols[i2].is_signed ? " signed" : " unsigned") + " bits");
        }
        t.rows.push_back(row);
    }
    if (!have_header) return fail("no header row");
    if (t.rows.empty()) return fail("no data rows");
    return true;
}

bool vec_from_hex(const std::string& text, const vec_table& layout, vec_table& t, std::string* err,
                  const std::string& name) {
    t.cols = layout.cols;
    t.block = layout.block;
    t.rows.clear();
    size_t width = 0;
    for (const vec_column& c : layout.cols) width += static_cast<size_t>(hex_digits(c.bits));
    std::istringstream is(text);
    std::string line;
    long ln = 0;
    while (std::getline(is, line)) {
        ++ln;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line.rfind("//", 0) == 0) continue;
        if (line.size() != width) {
            if (err) *err = where(name, ln) + "" + std::to_string(line.size()) + " hex digits, expected " +
                            std::to_string(width);
            return false;
        }
        std::vector<int64_t> row;
        size_t pos = 0;
        for (const vec_column& c : layout.cols) {
            const int d = hex_digits(c.bits);
            uint64_t u = 0;
            for (int k = 0; k < d; ++k) {
                const char ch = line[pos + static_cast<size_t>(k)];
                int v = -1;
                if (ch >= '0' && ch <= '9') v = ch - '0';
                else if (ch >= 'a' && ch <= 'f') v = ch - 'a' + 10;
                else if (ch >= 'A' && ch <= 'F') v = ch - 'A' + 10;
                if (v < 0) {
                    if (err) *err = where(name, ln) + "not a hex digit '" + std::string(1, ch) + "'";
                    return false;
                }
                u = (u << 4) | static_cast<uint64_t>(v);
            }
            pos += static_cast<size_t>(d);
            if (c.bits < 64 && (u >> c.bits) != 0) {
                if (err) *err = where(name, ln) + "field " + c.name + " wider than " + std::to_string(c.bits) + " bits";
                return false;
            }
            int64_t v = static_cast<int64_t>(u);
            if (c.is_signed && c.bits < 64 && ((u >> (c.bits - 1)) & 1u)) v = static_cast<int64_t>(u - (uint64_t(1) << c.bits));
            row.push_back(v);
        }
        t.rows.push_back(row);
    }
    if (t.rows.empty()) {
        if (err) *err = where(name, ln) + "no data rows";
        return false;
    }
    return true;
}

bool read_file(const std::string& path, std::string& text, std::string* err) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        if (err) *err = "cannot open " + path;
        return false;
    }
    std::ostringstream os;
    os << f.rdbuf();
    text = os.str();
    return true;
}

namespace {

vec_column in(const char* n, int bits, bool s = false) { return vec_column{n, bits, s, true}; }
vec_column out(const char* n, int bits, bool s = false) { return vec_column{n, bits, s, false}; }

}  // namespace

std::vector<vec_column> vec_layout(const std::string& block) {
    using W = lx::axis_widths;
    using EM = lx::error_map_cfg;
    if (block == "input_filter") return {in("pin", 1), in("n", 8), out("f", 1), out("valid", 1), out("glitch", 1)};
    if (block == "quad_decoder")
        return {in("a", 1), in("b", 1), in("lerr", 1), in("glitch_n", 8), in("min_spacing", 16), in("clear", 1),
                out("step", 2, true), out("raw_count", W::W_RAW, true), out("illegal", 1), out("ovs", 1),
                out("err_cnt", 8), out("illegal_st", 1), out("ovs_st", 1), out("lerr_out", 1), out("lerr_alarm", 1),
                out("glitch_st", 1)};
    // preset = 1: the row first loads N = preset_n and R = ratio (pulse_multiplier::preset(), with the
    // row's comp_offset), then steps
    if (block == "pulse_multiplier")
        return {in("step", 2, true), in("ratio", W::W_RATIO), in("comp_offset", W::W_OFFSET, true), in("preset", 1), in("preset_n", W::W_RAW, true),
                out("comp", W::W_POS, true), out("delta", W::W_DELTA, true)};
    if (block == "output_pacer")
        return {in("delta", W::W_DELTA, true), in("pace_m", 16), in("thr", 32), in("clear", 1), in("wide", 1),
                out("pstep", 2, true), out("slot", 1), out("paced", W::W_POS, true), out("backlog", W::W_BACKLOG, true), out("ovs", 1), out("ovs_st", 1)};
    if (block == "rephase")
        return {in("pstep", 2, true), in("slot", 1), in("sw", 1), in("sw_valid", 1), in("rehome", 1), in("unhome", 1),
                in("period", W::W_P), in("mark_len", W::W_P), out("ostep", 2, true), out("out_pos", W::W_POS, true),
                out("mark", 1), out("index", 1), out("stage", 2), out("a", W::W_POS, true), out("d", W::W_PH),
                out("b", W::W_POS, true), out("c", W::W_POS, true), out("z", W::W_POS, true),
                out("adj", W::W_POS, true), out("homed", 1)};
    // tbl_we/tbl_addr/tbl_data: the table write port (written before the step of the same call)
    if (block == "dds_sincos")
        return {in("ostep", 2, true), in("period", W::W_P), in("amplitude", W::W_DAC_MAX), in("tbl_we", 1),
                in("tbl_addr", W::W_TBL_ADDR), in("tbl_data", W::W_TBL), out("sin", W::W_DAC_MAX, true),
                out("cos", W::W_DAC_MAX, true)};
    if (block == "laserax_top")
        return {in("a", 1), in("b", 1), in("sw", 1), in("lerr", 1), in("period", W::W_P), in("ratio", W::W_RATIO),
                in("comp_offset", W::W_OFFSET, true), in("comp_sync", 1), in("comp_commit", 1), in("glitch_n", 8), in("sw_debounce", 16), in("min_spacing", 16), in("pace_m", 16),
                in("backlog_thr", 32), in("mark_len", W::W_P), in("dac_width", W::W_DACW),
                in("amplitude", W::W_DAC_MAX), in("tbl_period", W::W_P), in("rehome", 1), in("clear", 1),
                in("tbl_we", 1), in("tbl_addr", W::W_TBL_ADDR), in("tbl_data", W::W_TBL),
                in("map_en", 1), in("bank_sel", 1), in("map_origin0", W::W_POS, true), in("map_k0", EM::W_K),
                in("map_n0", EM::W_N), in("map_origin1", W::W_POS, true), in("map_k1", EM::W_K),
                in("map_n1", EM::W_N), in("map_we", 1), in("map_addr", EM::W_ADDR), in("map_data", EM::W_CORR, true),
                in("pin_cfg", 4),
                out("sin", W::W_DAC_MAX, true), out("cos", W::W_DAC_MAX, true), out("ref_mark", 1), out("qa", 1),
                out("qb", 1), out("qz", 1), out("q_oe", 1), out("cfg_err", 1), out("stage", 2), out("homed", 1), out("lerr_alarm", 1),
                out("illegal_st", 1), out("err_cnt", 8), out("ovs_edge_st", 1), out("ovs_backlog_st", 1),
                out("glitch_st", 1), out("alarm", 1), out("raw_count", W::W_RAW, true), out("comp_pos", W::W_POS, true),
                out("paced_pos", W::W_POS, true), out("out_pos", W::W_POS, true), out("d", W::W_PH),
                out("step", 2, true), out("delta", W::W_DELTA, true), out("backlog", W::W_BACKLOG, true),
                out("pstep", 2, true), out("ostep", 2, true), out("adj", W::W_POS, true),
                out("a_pos", W::W_POS, true), out("b_pos", W::W_POS, true), out("c_pos", W::W_POS, true),
                out("z_pos", W::W_POS, true), out("rep_mark", 1), out("map_cfg_err", 1), out("corr", EM::W_C, true),
                out("map_delta", EM::W_CDELTA, true)};
    // the map block at its own ports (hls/error_map.h, rtl_ref/error_map.v): position p (the
    // multiplier's comp), homed, the map registers of both banks and the table write port
    if (block == "error_map")
        return {in("p", W::W_POS, true), in("homed", 1), in("map_en", 1), in("bank_sel", 1),
                in("origin0", W::W_POS, true), in("k0", EM::W_K), in("n0", EM::W_N), in("origin1", W::W_POS, true),
                in("k1", EM::W_K), in("n1", EM::W_N), in("we", 1), in("addr", EM::W_ADDR), in("data", EM::W_CORR, true),
                out("corr", EM::W_C, true), out("delta", EM::W_CDELTA, true), out("active", 1), out("in_range", 1),
                out("clamped", 1), out("cfg_err", 1)};
    // the PSO block at its ports (hls/pso.h, rtl_ref/pso.v): every input (pso_in, pso_regs) and
    // every output (pso::out_t)
    if (block == "pso") {
        using PC = lx::pso_cfg;
        return {in("step0", 2, true), in("step1", 2, true), in("step2", 2, true), in("pos0", W::W_POS, true),
                in("pos1", W::W_POS, true), in("pos2", W::W_POS, true), in("ps_inc", PC::W_INC), in("enable", 1),
                in("part_speed", 1), in("axis_mask", PC::N_AXES), in("win_k", PC::W_K), in("fire_dist", PC::W_DIST),
                in("arr_en", 1), in("arr_len", PC::W_LEN), in("arr_wrap", 1), in("arr_we", 1),
                in("arr_addr", PC::W_ADDR), in("arr_data", PC::W_DIST), in("pulse_w", PC::W_PW), in("win_en", 1),
                in("win_src", 2), in("win_low", W::W_POS, true), in("win_high", W::W_POS, true),
                in("min_period", PC::W_GAP), in("clear", 1), out("fire", 1), out("emit", 1), out("pulse", 1),
                out("in_win", 1), out("dist", PC::W_REM, true), out("idx", PC::W_LEN), out("arr_done", 1),
                out("fire_cnt", PC::W_FCNT), out("overlap_cnt", PC::W_OVL), out("overlap", 1), out("overlap_st", 1),
                out("rate_over", 1), out("rate_over_st", 1), out("spacing_err", 1), out("spacing_st", 1),
                out("freq_err", 1), out("freq_st", 1), out("ps_pulse", 1), out("ps_count", W::W_POS, true),
                out("cfg_err", 1)};
    }
    // the encoder counter block at its ports (hls/encoder_counter.h, rtl_ref/encoder_counter.v):
    // every input and every output, channels 0 and 1
    if (block == "encoder_counter") {
        using EC = lx::encoder_counter_cfg;
        return {in("qstep0", 2, true), in("qstep1", 2, true), in("trig", 1), in("pos0", EC::W_POSIN, true),
                in("pos1", EC::W_POSIN, true), in("src0", 2), in("src1", 2), in("sim_inc0", EC::W_INC),
                in("sim_inc1", EC::W_INC), in("sim_down0", 1), in("sim_down1", 1), in("scale0", EC::W_SCALE, true),
                in("scale1", EC::W_SCALE, true), in("rst_req0", 1), in("rst_req1", 1), in("load0", 1), in("load1", 1),
                in("load_val0", EC::W_CNT, true), in("load_val1", EC::W_CNT, true), in("rst_on_trig", 1),
                in("corr_period", EC::W_PER), in("wait_arm", 1), in("wait_ch", 1), in("wait_val", EC::W_CNT, true),
                in("wait_down", 1), out("cnt0", EC::W_CNT, true), out("cnt1", EC::W_CNT, true), out("step0", 2, true),
                out("step1", 2, true), out("rst_done0", 1), out("rst_done1", 1), out("rst_pending0", 1),
                out("rst_pending1", 1), out("corr0", EC::W_CORR, true), out("corr1", EC::W_CORR, true), out("tick", 1),
                out("waiting", 1), out("reached", 1), out("cfg_err", 1)};
    }
    return {};
}

bool vec_check(const vec_table& t, std::string* err) {
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const std::vector<int64_t>& row = t.rows[r];
        if (row.size() != t.cols.size()) {
            if (err) *err = t.block + ": row " + std::to_string(r) + " has " + std::to_string(row.size()) +
                            " values for " + std::to_string(t.cols.size()) + " columns";
            return false;
        }
        for (size_t i = 0; i < row.size(); ++i) {
            if (!fits(row[i], t.cols[i])) {
                if (err) *err = t.block + ": row " + std::to_string(r) + " column " + t.cols[i].name + ": value " +
                                std::to_string(row[i]) + " does not fit";
                return false;
            }
        }
    }
    return true;
}

namespace {

// The map block alone, golden and hls side by side: one call, one row of error_map.{csv,hex}.
struct map_pair {
    golden::error_map g;
    lx::error_map h;

    static lx::error_map_regs hls_regs(const golden::error_map_regs& r) {
        lx::error_map_regs x;
        x.map_en = r.map_en;
        x.bank_sel = r.bank_sel;
        for (int b = 0; b < 2; ++b) {
            x.geom[b].origin = lx::pos_t(r.geom[b].origin);
            x.geom[b].spacing_log2 = lx::error_map_cfg::k_t(r.geom[b].spacing_log2);
            x.geom[b].n_points = lx::error_map_cfg::n_t(r.geom[b].n_points);
        }
        x.we = r.we;
        x.addr = lx::error_map_cfg::addr_t(r.addr);
        x.data = lx::error_map_cfg::word_t(r.data);
        return x;
    }

    // false (and err) if hls and golden differ
    bool step(int64_t p, bool homed, const golden::error_map_regs& r, vec_table& t, std::string* err) {
        const golden::error_map::out o = g.step(p, homed, r);
        const lx::error_map::out_t ho = h.step(lx::pos_t(p), homed, hls_regs(r));
        if (o.corr != ho.corr.to_int64() || o.delta != ho.delta.to_int64() || o.active != ho.active ||
            o.in_range != ho.in_range || o.clamped != ho.clamped || o.cfg_err != ho.cfg_err) {
            if (err) *err = "error_map hls/golden mismatch at call " + std::to_string(t.rows.size());
            return false;
        }
        t.rows.push_back({p, homed, r.map_en, r.bank_sel, r.geom[0].origin, r.geom[0].spacing_log2, r.geom[0].n_points,
                          r.geom[1].origin, r.geom[1].spacing_log2, r.geom[1].n_points, r.we, r.addr, r.data, o.corr,
                          o.delta, o.active, o.in_range, o.clamped, o.cfg_err});
        return true;
    }
};

// The directed tail of error_map.{csv,hex}: kErrorMapTailCalls more calls of the same two map
// instances after the scenario (one stream, row k = call k), for what the scenario's map never
// does (it stays inside one 64-point table of bank 1). Every word read while active is written
// first (the RTL RAM has no power-up contents), and the RTL sees the same inputs.
//   0  bank 0 selected with an invalid geometry while enabled (cfg_err): bank 1 reloaded, 64 words
//      (extremes, exact half-count ties, noise), one per call
//   1  bank 1 (origin 0, k 8, n 64) active: sweep from below the table to beyond it and back,
//      landing on both ends exactly; meanwhile bank 0 (inactive) gets 48 words with extremes
//   2  flip to bank 0 (origin 9001, k 5, n 48) below its table; sweep across it; meanwhile all
//      TBL_DEPTH (1024) words into bank 1 (the inactive bank); extreme positions and origins (39-bit offset)
//   3  invalid geometries of the selected bank while enabled (k 3, 21, 31; n 0, 1, 1025, 2047),
//      each followed by recovery; an invalid one with map_en = 0 (no cfg_err)
//   4  homed and map_en toggles, single-call pulses included
//   5  every spacing k = 4 .. 20 in bank 1 (n = 2, 64 or 1024 by turns): flip to it below the
//      table, travel to both ends exactly and beyond, reverse, flip back
//   6  a flip every 1..5 calls while moving across both tables; then a random walk with random
//      flips and toggles up to the tail length
bool map_tail(map_pair& m, int64_t p, bool homed, golden::error_map_regs r, uint64_t seed, vec_table& t,
              std::string* err) {
    constexpr int32_t kMax = (1 << 23) - 1, kMin = -(1 << 23);
    constexpr int kDepth = golden::error_map::kDepth;
    std::mt19937_64 rng(seed ^ 0x656d61705f7461ULL);
    auto urange = [&rng](int64_t lo, int64_t hi) {
        return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
    };
    const size_t end = t.rows.size() + static_cast<size_t>(kErrorMapTailCalls);
    std::vector<std::pair<int, int32_t>> wq;  // words to write, one per call, into bank !bank_sel
    size_t wq_pos = 0;
    bool ok = true;
    auto call = [&]() {
        if (!ok || t.rows.size() >= end) return;
        golden::error_map_regs c = r;
        c.we = wq_pos < wq.size();
        c.addr = c.we ? wq[wq_pos].first : 0;
        c.data = c.we ? wq[wq_pos].second : 0;
        if (c.we) ++wq_pos;
        ok = m.step(p, homed, c, t, err);
    };
    auto go = [&](int64_t target, int64_t speed) {  // lands on target exactly
        while (ok && p != target && t.rows.size() < end) {
            const int64_t d = target - p;
            p += d > speed ? speed : (d < -speed ? -speed : d);
            call();
        }
    };
    auto dwell = [&](int n) {
        for (int i = 0; i < n; ++i) call();
    };
    auto queue = [&](const std::vector<int32_t>& words) {
        wq.clear();
        wq_pos = 0;
        for (size_t a = 0; a < words.size(); ++a) wq.push_back({static_cast<int>(a), words[a]});
    };

    // 0: reload bank 1 while bank 0 is selected with an invalid geometry (enabled: cfg_err)
    r.map_en = true;
    r.bank_sel = false;
    r.geom[0] = {0, 0, kDepth};
    r.geom[1] = {0, 8, 64};
    std::vector<int32_t> t1(64);
    for (int i = 0; i < 64; ++i)
        t1[static_cast<size_t>(i)] = i < 4 ? ((i & 1) ? kMin : kMax)
                                           : i < 16 ? (2 * (i - 10) + 1) * 128  // exact half counts
                                                    : static_cast<int32_t>(urange(-(1 << 20), 1 << 20));
    queue(t1);
    homed = true;
    for (int i = 0; i < 64; ++i) {
        p += (i & 8) ? 3 : -3;
        call();
    }

    // 1: bank 1 active; both ends exactly, beyond, reversals; bank 0 written meanwhile
    r.bank_sel = true;
    r.geom[0] = {9001, 5, 48};
    std::vector<int32_t> t0(48);
    for (int i = 0; i < 48; ++i)
        t0[static_cast<size_t>(i)] = i % 6 == 0 ? kMax : i % 6 == 3 ? kMin : static_cast<int32_t>(urange(kMin, kMax));
    queue(t0);
    go(-700, 53);
    dwell(3);
    go(0, 50);
    dwell(2);
    go(63 * 256, 37);
    dwell(2);
    go(63 * 256 + 900, 61);
    go(8000, 200);
    for (int j = 0; j < 6; ++j) go(8000 + ((j & 1) ? 1 : -1) * (300 + 17 * j), 3);

    // 2: flip to bank 0 (p below its table); kDepth words into bank 1 meanwhile
    std::vector<int32_t> tb(kDepth);
    {
        int64_t v = urange(kMin / 2, kMax / 2);
        for (size_t a = 0; a < tb.size(); ++a) {
            v += urange(-(1 << 14), 1 << 14);
            v = v < kMin ? kMin : (v > kMax ? kMax : v);
            tb[a] = static_cast<int32_t>(a % 97 == 5 ? kMax : a % 97 == 50 ? kMin : v);
        }
        tb[0] = kMin;
        tb[kDepth - 1] = kMax;
    }
    queue(tb);
    r.bank_sel = false;
    dwell(2);
    go(9001, 7);
    go(9001 + 47 * 32, 3);
    go(9001 + 47 * 32 + 200, 5);
    go(9400, 11);
    const int64_t pmax = (int64_t(1) << 37) - 1, pmin = -(int64_t(1) << 37);
    p = pmin;
    dwell(2);
    p = pmax;
    dwell(2);
    r.geom[0].origin = pmax;
    p = pmin;
    dwell(2);
    r.geom[0].origin = pmin;
    p = pmax;
    dwell(2);
    r.geom[0].origin = 9001;
    p = 9500;
    dwell(2);

    // 3: invalid geometries of the selected bank while enabled, each followed by recovery
    const golden::error_map_geom g0 = r.geom[0];
    const int bad_k[] = {3, 21, 31}, bad_n[] = {0, 1, kDepth + 1, 2 * kDepth - 1};
    for (int k : bad_k) {
        r.geom[0].spacing_log2 = k;
        go(p + 20, 3);
        r.geom[0] = g0;
        go(p - 17, 3);
    }
    for (int n : bad_n) {
        r.geom[0].n_points = n;
        go(p + 20, 3);
        r.geom[0] = g0;
        go(p - 17, 3);
    }
    r.map_en = false;
    r.geom[0].spacing_log2 = 3;
    dwell(6);
    r.geom[0] = g0;
    dwell(3);
    r.map_en = true;

    // 4: homed and map_en toggles while moving
    const int pulse[] = {5, 1, 3, 1, 2};
    for (int w : pulse) {
        homed = false;
        go(p + 3 * w, 3);
        homed = true;
        go(p + 7, 1);
        r.map_en = false;
        go(p - 2 * w, 2);
        r.map_en = true;
        go(p - 5, 1);
    }
    homed = false;
    r.map_en = false;
    dwell(2);
    homed = true;
    r.map_en = true;
    dwell(2);

    // 5: every spacing in bank 1 (written above: drain the queue first)
    while (ok && wq_pos < wq.size() && t.rows.size() < end) {
        p += urange(-9, 9);
        p = p < 8500 ? 8500 : (p > 10700 ? 10700 : p);
        call();
    }
    for (int k = 4; k <= 20; ++k) {
        const int n = k % 3 == 0 ? 2 : (k % 3 == 1 ? kDepth : 64);
        const int64_t span = int64_t(n - 1) << k;
        const int64_t speed = 1 + span / 40;
        r.geom[1] = {p + 100 + k, k, n};
        const int64_t o = r.geom[1].origin;
        r.bank_sel = true;
        dwell(1);
        go(o, speed);
        go(o + span, speed);
        go(o + span + (int64_t(1) << k) + 33, speed);
        go(o + span / 3 + 5, speed);
        r.bank_sel = false;
        dwell(2);
    }

    // 6: rapid flips between the two tables, then a random walk to the tail length
    r.geom[1] = {-3000, 6, kDepth};
    p = 8000;
    long long next_flip = 0;
    while (ok && p < 11000 && t.rows.size() < end) {
        if (next_flip-- <= 0) {
            r.bank_sel = !r.bank_sel;
            next_flip = urange(0, 4);
        }
        p += 9;
        call();
    }
    while (ok && t.rows.size() < end) {
        if (rng() % 200 == 0) r.bank_sel = !r.bank_sel;
        if (rng() % 300 == 0) homed = !homed;
        if (rng() % 300 == 0) r.map_en = !r.map_en;
        p += urange(-40, 40);
        p = p < 7000 ? 7000 : (p > 12000 ? 12000 : p);
        call();
    }
    return ok;
}

}  // namespace

bool build_vectors(uint64_t seed, long long calls, std::vector<vec_table>& tables, std::string* err) {
    std::mt19937_64 rng(seed);
    axis_settings s;
    s.glitch_n = 2;
    s.sw_debounce = 8;
    s.pace_m = 3;
    s.backlog_thr = 40;
    s.min_spacing = 3;
    dual_axis ax(s);

    // column layouts shared with rtl_stress_vectors (vec_layout); the DDS table port and the
    // multiplier preset are not exercised here (golden/ has neither): they stay 0
    vec_table top{"laserax_top", vec_layout("laserax_top"), {}};
    vec_table flt{"input_filter", vec_layout("input_filter"), {}};
    vec_table dec{"quad_decoder", vec_layout("quad_decoder"), {}};
    vec_table mul{"pulse_multiplier", vec_layout("pulse_multiplier"), {}};
    vec_table pac{"output_pacer", vec_layout("output_pacer"), {}};
    vec_table rep{"rephase", vec_layout("rephase"), {}};
    vec_table dds{"dds_sincos", vec_layout("dds_sincos"), {}};
    vec_table emp{"error_map", vec_layout("error_map"), {}};

    // standalone blocks, golden and hls, fed with the chain's inter-block signals
    golden::input_filter g_flt, g_swf;
    lx::input_filter<8> h_flt;
    golden::quad_decoder g_dec;
    lx::quad_decoder h_dec;
    golden::pulse_multiplier g_mul;
    lx::pulse_multiplier h_mul;
    golden::output_pacer g_pac;
    lx::output_pacer h_pac;
    golden::rephase g_rep;
    lx::rephase h_rep;
    golden::dds_sincos g_dds;
    lx::dds_sincos h_dds;
    map_pair emap;
    g_flt.reset();
    g_swf.reset();
    g_dec.reset();
    g_mul.reset();
    g_pac.reset();
    g_rep.reset();
    g_dds.reset();
    {
        const std::vector<uint32_t> tbl = dds_table(256, 32767);
        for (size_t k = 0; k < tbl.size(); ++k) h_dds.load(static_cast<unsigned>(k), tbl[k]);
    }
    int prev_step = 0, prev_pstep = 0, prev_ostep = 0, prev_stage = 0;
    bool prev_slot = false;
    int64_t prev_delta = 0;
    bool prev_lerr = false;
    int64_t prev_comp = 0;
    bool prev_homed = false;
    golden::input_filter::out prev_sw{false, false, false};

    int64_t n = 0;
    int dir = 1;
    long long wait = 0, spacing = 5;
    int glitch_left = 0, lerr_left = 0;
    const int kMapPoints = 64;
    int map_words = 0;
    uint64_t mul_ratio = golden::default_ratio();
    int64_t mul_offset = 0;
    for (long long t = 0; t < calls; ++t) {
        axis_settings ns = ax.settings();
        ns.rehome = false;
        ns.clear = false;
        ns.comp_commit = false;
        const long long phase = t * 8 / calls;  // eight acts: homing, reversals, faults, re-homing
        // compensation updates while moving: from calls/4 on with comp_sync = 1, so the offset's
        // low word written alone (calls/3 - 12) has no effect until the commit with the full value
        // (calls/3); the ratio update at calls/2 is committed in its own call; from 7/8 on
        // comp_sync = 0 again and an offset write acts at once
        const int64_t off1 = -(int64_t(37) << 32) - 123456789;
        if (t == calls / 4) ns.comp_sync = true;
        if (t == calls / 3 - 12)
            ns.comp_offset = static_cast<int64_t>((static_cast<uint64_t>(ns.comp_offset) & ~uint64_t(0xFFFFFFFF)) |
                                                  (static_cast<uint64_t>(off1) & 0xFFFFFFFFu));  // low word only
        if (t == calls / 3) {
            ns.comp_offset = off1;
            ns.comp_commit = true;
        }
        if (t == calls / 2) {
            ns.ratio = s.ratio + 4000000;
            ns.comp_commit = true;
        }
        if (t == calls * 7 / 8 - 100) ns.comp_sync = false;
        if (t == calls * 7 / 8) ns.comp_offset = int64_t(5) << 31;
        if (t == calls * 5 / 8) ns.rehome = true;
        // the digital pins (DESIGN 4.7, pin_cfg): qz as the window B..C from 11/16 to 3/4; the A/B
        // encoding rotated by 2 counts (the index state at A = B = 1) from inside the safe state
        // at 3/4 on (a rotation while running would be a two-line step at the pins); q_oe held
        // high through the alarms from 13/16 on (hiz_alarm = 0)
        if (t == calls * 11 / 16) ns.pin_cfg = 8 | 1;
        if (t == calls * 3 / 4) ns.pin_cfg = 8;
        if (t == calls * 3 / 4 + 10) ns.pin_cfg = 8 | (2 << 1);
        if (t == calls * 13 / 16) ns.pin_cfg = 2 << 1;
        if (t % 5000 == 4999) ns.clear = true;
        if (t == calls * 3 / 4) ns.tbl_period = 264;               // invalid configuration ...
        if (t == calls * 3 / 4 + 50) ns.tbl_period = ns.period;    // ... and back
        // error map: once homed, a 64-point table (spacing 2^8 counts from comp 0) is written into
        // bank 1 through the map port, one word per call, while the axis moves; then bank 1 is
        // selected and enabled; it is disabled again for the last eighth. (More map cases: the
        // laserax_top stress set and tb_chain_error_map.)
        if (ax.gold().homed && map_words < kMapPoints) {
            ns.emap.we = true;
            ns.emap.addr = map_words;
            ns.emap.data = ((map_words * 7919) % 2001) - 1000;  // +-3.9 counts, Q15.8
            if (++map_words == kMapPoints) {
                ns.emap.geom[1].origin = 0;
                ns.emap.geom[1].spacing_log2 = 8;
                ns.emap.geom[1].n_points = kMapPoints;
            }
        } else if (map_words == kMapPoints && !ns.emap.map_en && t < calls * 7 / 8) {
            ns.emap.bank_sel = true;
            ns.emap.map_en = true;
        }
        if (t == calls * 7 / 8) ns.emap.map_en = false;
        ax.set(ns);
        if (wait-- <= 0) {
            n += dir;
            wait = spacing;
        }
        if (phase == 0 || phase == 1) dir = 1;
        if (phase == 2) dir = -1;
        if (phase >= 3) dir = (t / 3000) % 2 ? 1 : -1;
        if (rng() % 4000 == 0) n += 2;  // illegal transition
        if (glitch_left == 0 && rng() % 500 == 0) glitch_left = 1 + static_cast<int>(rng() % 3);
        if (lerr_left == 0 && phase == 4 && rng() % 3000 == 0) lerr_left = 20;
        spacing = (phase == 5) ? 1 : 5;  // overspeed burst
        lx::axis_pins p;
        quad_pins(n, p.a, p.b);
        if (glitch_left > 0) {
            p.a = !p.a;
            --glitch_left;
        }
        p.lerr = lerr_left > 0;
        if (lerr_left > 0) --lerr_left;
        p.sw = n >= 300;
        const std::string m = ax.step(p);
        if (!m.empty()) {
            if (err) *err = "laserax_top call " + std::to_string(t) + ": " + m;
            return false;
        }
        const lx::axis_out& h = ax.hls();
        const golden::axis_out& g = ax.gold();
        const golden::axis_regs gr = to_golden(ns);
        top.rows.push_back({p.a, p.b, p.sw, p.lerr, gr.period, static_cast<int64_t>(gr.ratio), gr.comp_offset, gr.comp_sync,
                            gr.comp_commit, gr.glitch_n,
                            gr.sw_debounce, gr.min_spacing, gr.pace_m, static_cast<int64_t>(gr.backlog_thr), gr.mark_len,
                            gr.dac_width, gr.amplitude, gr.tbl_period, gr.rehome, gr.clear, 0, 0, 0,
                            gr.emap.map_en, gr.emap.bank_sel, gr.emap.geom[0].origin, gr.emap.geom[0].spacing_log2,
                            gr.emap.geom[0].n_points, gr.emap.geom[1].origin, gr.emap.geom[1].spacing_log2,
                            gr.emap.geom[1].n_points, gr.emap.we, gr.emap.addr, gr.emap.data, gr.pin_cfg,
                            g.sin, g.cos, g.ref_mark,
                            g.qa, g.qb, g.qz, g.q_oe, g.cfg_err, g.stage, g.homed, g.lerr_alarm, g.illegal_st, g.err_cnt,
                            g.ovs_edge_st, g.ovs_backlog_st, g.glitch_st, g.alarm, g.raw_count, g.comp_pos, g.paced_pos, g.out_pos,
                            g.d, g.step, g.delta, g.backlog, g.pstep, g.ostep, g.adj, g.a_pos, g.b_pos, g.c_pos,
                            g.z_pos, g.rep_mark, g.map_cfg_err, g.corr, g.map_delta});
        (void)h;

        // block level
        const golden::input_filter::out fo = g_flt.step(p.a, gr.glitch_n);
        const lx::input_filter<8>::out_t hfo = h_flt.step(p.a, gr.glitch_n);
        const golden::quad_decoder::out dq = g_dec.step(p.a, p.b, p.lerr, gr.glitch_n, gr.min_spacing, gr.clear);
        const lx::quad_decoder::out_t hdq = h_dec.step(p.a, p.b, p.lerr, gr.glitch_n, gr.min_spacing, gr.clear);
        // the multiplier's ports carry the ratio / offset in force (comp_sync / comp_commit, DESIGN 4.7)
        if (!gr.comp_sync || gr.comp_commit) {
            mul_ratio = gr.ratio;
            mul_offset = gr.comp_offset;
        }
        const golden::pulse_multiplier::out mo = g_mul.step(prev_step, mul_ratio, mul_offset);
        const lx::pulse_multiplier::out_t hmo = h_mul.step(prev_step, mul_ratio, mul_offset);
        // the pacer's wide: the rephase stage of the previous call (DESIGN 4.7)
        const bool wide = prev_stage == 2;
        const golden::output_pacer::out po = g_pac.step(prev_delta, gr.pace_m, gr.backlog_thr, gr.clear, wide);
        const lx::output_pacer::out_t hpo = h_pac.step(prev_delta, 0, gr.pace_m, gr.backlog_thr, gr.clear, wide);
        const golden::rephase::out ro =
            g_rep.step(prev_pstep, prev_slot, prev_sw.f, prev_sw.valid, gr.rehome, prev_lerr, gr.period, gr.mark_len);
        const lx::rephase::out_t hro =
            h_rep.step(prev_pstep, prev_slot, prev_sw.f, prev_sw.valid, gr.rehome, prev_lerr, gr.period, gr.mark_len);
        const golden::dds_sincos::out so = g_dds.step(prev_ostep, gr.period, gr.amplitude);
        const lx::dds_sincos::out_t hso = h_dds.step(prev_ostep, gr.period, gr.amplitude);
        const golden::input_filter::out swo = g_swf.step(p.sw, gr.sw_debounce);

        const bool same = fo.f == hfo.f && fo.valid == hfo.valid && fo.glitch == hfo.glitch &&
                          dq.glitch_st == hdq.glitch_st && dq.step == hdq.step.to_int() &&
                          dq.raw_count == hdq.raw_count.to_int64() && dq.illegal == hdq.illegal && dq.ovs == hdq.ovs &&
                          dq.err_cnt == hdq.err_cnt.to_int() && dq.illegal_st == hdq.illegal_st &&
                          dq.ovs_st == hdq.ovs_st && dq.lerr == hdq.lerr && dq.lerr_alarm == hdq.lerr_alarm &&
                          mo.comp == hmo.comp.to_int64() && mo.delta == hmo.delta.to_int64() &&
                          po.pstep == hpo.pstep.to_int() && po.slot == hpo.slot && po.paced == hpo.paced.to_int64() &&
                          po.backlog == hpo.backlog.to_int64() && po.ovs == hpo.ovs && po.ovs_st == hpo.ovs_st &&
                          ro.ostep == hro.ostep.to_int() && ro.out_pos == hro.out_pos.to_int64() && ro.mark == hro.mark && ro.index == hro.index &&
                          ro.stage == hro.stage.to_int() && ro.a == hro.a.to_int64() && ro.d == hro.d.to_int64() &&
                          ro.b == hro.b.to_int64() && ro.c == hro.c.to_int64() && ro.z == hro.z.to_int64() &&
                          ro.adj == hro.adj.to_int64() && ro.homed == hro.homed && so.sin == hso.sin.to_int64() &&
                          so.cos == hso.cos.to_int64();
        if (!same) {
            if (err) *err = "block-level hls/golden mismatch at call " + std::to_string(t);
            return false;
        }
        flt.rows.push_back({p.a, gr.glitch_n, fo.f, fo.valid, fo.glitch});
        dec.rows.push_back({p.a, p.b, p.lerr, gr.glitch_n, gr.min_spacing, gr.clear, dq.step, dq.raw_count, dq.illegal,
                            dq.ovs, dq.err_cnt, dq.illegal_st, dq.ovs_st, dq.lerr, dq.lerr_alarm, dq.glitch_st});
        mul.rows.push_back({prev_step, static_cast<int64_t>(mul_ratio), mul_offset, 0, 0, mo.comp, mo.delta});
        pac.rows.push_back({prev_delta, gr.pace_m, static_cast<int64_t>(gr.backlog_thr), gr.clear, wide, po.pstep,
                            po.slot, po.paced, po.backlog, po.ovs, po.ovs_st});
        rep.rows.push_back({prev_pstep, prev_slot, prev_sw.f, prev_sw.valid, gr.rehome, prev_lerr, gr.period, gr.mark_len, ro.ostep,
                            ro.out_pos, ro.mark, ro.index, ro.stage, ro.a, ro.d, ro.b, ro.c, ro.z, ro.adj, ro.homed});
        dds.rows.push_back({prev_ostep, gr.period, gr.amplitude, 0, 0, 0, so.sin, so.cos});
        // the map reads the multiplier's comp and the rephase homed of the previous call (the
        // registered outputs, as hls/laserax_top.h) with the map registers of this call
        if (!emap.step(prev_comp, prev_homed, gr.emap, emp, err)) return false;
        prev_step = dq.step;
        prev_delta = mo.delta;
        prev_pstep = po.pstep;
        prev_slot = po.slot;
        prev_stage = ro.stage;
        prev_ostep = ro.ostep;
        prev_lerr = dq.lerr;
        prev_sw = swo;
        prev_comp = mo.comp;
        prev_homed = ro.homed;
    }
    // error_map.{csv,hex} only: the same map instances continue with a directed tail
    if (!map_tail(emap, prev_comp, prev_homed, to_golden(ax.settings()).emap, seed, emp, err)) return false;
    tables = {flt, dec, mul, pac, rep, dds, emp, top};
    return true;
}

int cmd_vectors(const std::vector<std::string>& args, size_t first, const std::string& command) {
    std::string dir = "out/vectors";
    uint64_t seed = 1;
    long long calls = 40000;
    controller_opts ctl;
    cli c("laserax vectors", args, first,
          std::string("usage: laserax vectors [--out DIR] [--seed N] [--calls N] [controller options]\n"
                      "  --out DIR    output folder, non-empty (default out/vectors)\n"
                      "  --seed N     random seed, 0..2^64-1 (default 1)\n"
                      "  --calls N    calls of the random part of each file, 100..100000000 (default 40000)\n"
                      "controller options (the vectors' pace_m is fixed by the scenario: the smallest value in\n"
                      "their pace_m columns is checked):\n") +
              kControllerUsage);
    while (c.next()) {
        if (c.is("--out")) c.get_text(&dir);
        else if (c.is("--seed")) c.get_u64(0, UINT64_MAX, &seed);
        else if (c.is("--calls")) c.get_int(100, 100000000, &calls);
        else if (parse_controller_option(c, &ctl)) continue;
        else c.unknown();
    }
    if (c.failed()) return c.status();
    if (ctl.have_mhz != ctl.have_filter)  // before the scenario runs
        return check_controller_pacing("laserax vectors", ctl, 0, 100.0, "", "");
    std::vector<vec_table> tables;
    std::string err;
    if (!build_vectors(seed, calls, tables, &err) || !build_motion_vectors(seed, calls, tables, &err)) {
        std::fprintf(stderr, "laserax vectors: %s\n", err.c_str());
        return 1;
    }
    if (ctl.have_mhz) {  // the pace_m the vectors use: the smallest in any pace_m column
        long long pace_m = -1;
        for (const vec_table& t : tables) {
            const int col = t.col("pace_m");
            if (col < 0) continue;
            for (const std::vector<int64_t>& row : t.rows)
                if (pace_m < 0 || row[static_cast<size_t>(col)] < pace_m) pace_m = row[static_cast<size_t>(col)];
        }
        if (pace_m >= 0) {
            const int rc = check_controller_pacing("laserax vectors", ctl, pace_m, kClockHz / 1e6,
                                                   "the vectors' pace_m " + std::to_string(pace_m),
                                                   "the vectors' pace_m is fixed; --force-pace writes them anyway");
            if (rc != 0) return rc;
        }
    }
    if (!make_dirs(dir, "laserax vectors")) return 1;
    for (const vec_table& t : tables) {
        if (!vec_check(t, &err)) {
            std::fprintf(stderr, "laserax vectors: %s\n", err.c_str());
            return 1;
        }
    }
    for (const vec_table& t : tables) {
        for (int kind = 0; kind < 2; ++kind) {
            const std::string path = dir + "/" + t.block + (kind ? ".hex" : ".csv");
            std::ofstream f(path);
            f << (kind ? vec_to_hex(t, command) : vec_to_csv(t, command));
            if (!f) {
                std::fprintf(stderr, "laserax vectors: cannot write %s\n", path.c_str());
                return 1;
            }
        }
        std::printf("  %-18s %8zu calls, %2zu fields -> %s/%s.{csv,hex}\n", t.block.c_str(), t.rows.size(), t.cols.size(),
                    dir.c_str(), t.block.c_str());
    }
    {
        const std::string path = dir + "/dds_table_p256.hex";
        std::ofstream f(path);
        f << dds_table_hex(256, 32767, lx::axis_widths::TBL_DEPTH, command);
    }
    return 0;
}

}  // namespace lxt
