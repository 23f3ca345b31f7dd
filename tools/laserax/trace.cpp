#include "tools/laserax/trace.h"

#include <cinttypes>

namespace lxt {

namespace {
// VCD signals: identifier, name, width
struct vcd_sig {
    const char* id;
    const char* name;
    int width;
};
const vcd_sig kSigs[] = {
    {"!", "pin_a", 1},       {"\"", "pin_b", 1},        {"#", "switch", 1},        {"$", "laser_err", 1},
    {"%", "raw_count", 32},  {"&", "comp_pos", 38},     {"'", "paced_pos", 38},    {"(", "out_pos", 38},
    {")", "sin", 18},        {"*", "cos", 18},          {"+", "ref_mark", 1},      {",", "qa", 1},
    {"-", "qb", 1},          {".", "stage", 2},         {"/", "alarm", 1},         {"0", "backlog", 40},
};
constexpr int kNumSigs = sizeof(kSigs) / sizeof(kSigs[0]);

void vcd_value(FILE* f, const vcd_sig& s, long long v) {
    if (s.width == 1) {
        std::fprintf(f, "%d%s\n", v ? 1 : 0, s.id);
        return;
    }
    char bits[80];
    const unsigned long long u = static_cast<unsigned long long>(v);
    for (int i = 0; i < s.width; ++i) bits[i] = ((u >> (s.width - 1 - i)) & 1ULL) ? '1' : '0';
    bits[s.width] = '\0';
    std::fprintf(f, "b%s %s\n", bits, s.id);
}
}  // namespace

bool trace_writer::open(const std::string& dir, bool every_clock, int period, const std::string& command, std::string* err) {
    every_ = every_clock;
    period_ = period;
    csv_ = std::fopen((dir + "/trace.csv").c_str(), "w");
    vcd_ = std::fopen((dir + "/trace.vcd").c_str(), "w");
    if (!csv_ || !vcd_) {
        if (err) *err = "cannot write trace files in " + dir;
        close();
        return false;
    }
    std::fprintf(csv_, "# laserax trace. Command: %s\n", command.c_str());
    std::fprintf(csv_, "# period=%d\n", period_);
    std::fprintf(csv_, "# one row per clock at which any column other than true_nm changes%s\n",
                 every_clock ? " (here: every clock)" : "");
    std::fprintf(csv_, "cycle,true_nm,raw_count,comp_pos,paced_pos,out_pos,sin,cos,ref_mark,switch,stage,alarm,backlog,adj,pin_a,pin_b\n");
    std::fprintf(vcd_, "$comment laserax trace. Command: %s $end\n$timescale 10ns $end\n$scope module laserax_top $end\n",
                 command.c_str());
    for (const vcd_sig& s : kSigs) std::fprintf(vcd_, "$var wire %d %s %s $end\n", s.width, s.id, s.name);
    std::fprintf(vcd_, "$upscope $end\n$enddefinitions $end\n");
    return true;
}

void trace_writer::add(const trace_row& r) {
    if (!csv_) return;
    const lx::axis_out& o = r.out;
    const long long v[kNumSigs] = {r.pin_a,
                                   r.pin_b,
                                   r.sw,
                                   r.lerr,
                                   o.raw_count.to_int64(),
                                   o.comp_pos.to_int64(),
                                   o.paced_pos.to_int64(),
                                   o.out_pos.to_int64(),
                                   o.sin.to_int64(),
                                   o.cos.to_int64(),
                                   o.ref_mark,
                                   o.qa,
                                   o.qb,
                                   o.stage.to_int64(),
                                   o.alarm,
                                   o.backlog.to_int64()};
    bool changed = !have_prev_;
    bool header_done = false;
    for (int i = 0; i < kNumSigs; ++i) {
        if (have_prev_ && v[i] == vals_[i]) continue;
        changed = true;
        if (!header_done) {
            std::fprintf(vcd_, "#%lld\n", r.cycle);
            header_done = true;
        }
        vcd_value(vcd_, kSigs[i], v[i]);
        vals_[i] = v[i];
    }
    have_prev_ = true;
    if (changed || every_) {
        // to_int64() is long long under ap_int / ac_int, int64_t (long) under the own types
        const auto i64 = [](const auto& x) { return static_cast<int64_t>(x.to_int64()); };
        std::fprintf(csv_, "%lld,%.3f,%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64 ",%d,%d,%d,%d,%" PRId64 ",%" PRId64 ",%d,%d\n",
                     r.cycle, r.true_nm, i64(o.raw_count), i64(o.comp_pos), i64(o.paced_pos),
                     i64(o.out_pos), i64(o.sin), i64(o.cos), o.ref_mark ? 1 : 0, r.sw ? 1 : 0,
                     o.stage.to_int(), o.alarm ? 1 : 0, i64(o.backlog), i64(o.adj), r.pin_a ? 1 : 0,
                     r.pin_b ? 1 : 0);
        ++rows_;
    }
}

void trace_writer::close() {
    if (csv_) std::fclose(csv_);
    if (vcd_) std::fclose(vcd_);
    csv_ = nullptr;
    vcd_ = nullptr;
}

}  // namespace lxt
