// regmap_vectors.cpp — vector files for the register map in RTL: the AXI4-Lite slave
// rtl_ref/laserax_regs.v alone and the IP top rtl_ref/laserax_axil.v (slave + chain). Expected
// values come from the C++ host helper (lxt::reg_image, host/regmap.h) and the bit-true
// chain (hls/laserax_top.h), never from the Verilog.
//
//   laserax_regs.hex  one row per clock: the AXI4-Lite inputs, the expected AXI outputs and every
//                     register port o_<name>. Reset values read back at every word of the map
//                     (reserved words, 0x00..0x0F and addresses past the map included); for every
//                     register random values in each word (bits above the width set too), the
//                     extremes, negative values of the signed registers, partial WSTRB writes; then
//                     random traffic: writes and reads in parallel, AW before W, W before AW, both
//                     together, late BREADY/RREADY, unaligned addresses, writes to reserved and
//                     unmapped words, junk on the address/data lines while VALID is 0.
//   laserax_axil.hex  one row per clock: pins a, b, sw, lerr, the AXI4-Lite inputs, the expected AXI
//                     outputs and every laserax_top output (the laserax_top columns of
//                     lxt::vec_layout). The host programs the chain only through the bus: settings,
//                     the compensation sequence of lxt::compensation_writes (comp_sync, ratio and
//                     comp_offset words, comp_commit pulse) for new air / material conditions, two
//                     error-map loads by lxt::program_map (geometry, words through the map write
//                     port, bank flip, map_en), DDS table loads by lxt::program_dds (tbl_period = 0,
//                     the quarter-wave words through the table write port, period, mark_len,
//                     dac_width, amplitude, tbl_period = P: one safe-state window each) switching
//                     the period 256 <-> 640 counts or only the amplitude (and dac_width), a stray
//                     table word written while the chain runs and restored later, clear and rehome
//                     pulses, reads; meanwhile the pins move the axis through homing (with the
//                     period in force) and back and forth.
//
// The slave's timing is the one documented in docs/REGISTERS.md ("RTL slave") and modelled by
// axil_slave below: AWREADY = no address held and no response pending, WREADY likewise; a write
// takes effect at the edge at which the later of its AW and W handshakes completes (BVALID rises
// at that edge); ARREADY = !RVALID, RDATA registered at the AR handshake from the registers before
// that edge. The register contents are a reg_image: a write merges the WSTRB bytes into the
// word's current value and goes through reg_image::write_word; reads and the o_<name> columns come
// from reg_image::get. For the chain, the call of edge t runs laserax_top::step() with the registers
// of the image before the writes of edge t (hls_from(image)): a write completing at edge t acts
// in call t+1, the latency of the register stage in laserax_axil.
//
// Usage: regmap_vectors --out DIR [--seed N] [--calls N]   writes DIR/laserax_regs.hex and
//        DIR/laserax_axil.hex (--calls: rows of laserax_axil, default 50000 as in scripts/rtl_sim.sh;
//        with much fewer, e.g. 15000, there is no room for two period changes and a homing with
//        each period after them, and the program fails saying so)

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include "hls/laserax_top.h"
#include "rtl_ref/tb/vecgen.h"
#include "host/dds_table.h"
#include "host/regmap.h"
#include "sysmodel/model_regs.h"
#include "tools/laserax/vectors.h"

namespace {

namespace rm = lxt::regmap;
using lxt::vec_column;
using lxt::vec_table;
using vecgen::rng_t;

constexpr int kAddrW = 12;  // ADDR_W of the slave in the testbenches
constexpr uint32_t kAddrMask = (1u << kAddrW) - 1;

int64_t i64(bool b) { return b ? 1 : 0; }


// ---- the bus ---------------------------------------------------------------------------------

struct axil_in {
    uint32_t awaddr = 0;
    bool awvalid = false;
    uint32_t wdata = 0;
    unsigned wstrb = 0;
    bool wvalid = false;
    bool bready = false;
    uint32_t araddr = 0;
    bool arvalid = false;
    bool rready = false;
};

// The register word at a byte offset: register index and word number, or -1.
struct word_ref {
    int reg = -1;
    int word = 0;
};
word_ref word_at(uint32_t offset) {
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const rm::reg_info& r = rm::kRegs[i];
        if (offset >= r.offset && offset < r.offset + 4u * static_cast<uint32_t>(r.words()))
            return {i, static_cast<int>((offset - r.offset) / 4)};
    }
    return {};
}

// The AXI4-Lite slave of rtl_ref/laserax_regs.v as documented (docs/REGISTERS.md, "RTL slave").
class axil_slave {
public:
    lxt::reg_image img;  // the registers

    bool awready() const { return !aw_full_ && !bvalid_; }
    bool wready() const { return !w_full_ && !bvalid_; }
    bool bvalid() const { return bvalid_; }
    bool arready() const { return !rvalid_; }
    bool rvalid() const { return rvalid_; }
    uint32_t rdata() const { return rdata_; }

    // The word a read of this byte address returns: the register's bits (0 above its width), 0
    // for reserved and unmapped words; address bits [1:0] are ignored.
    uint32_t read_word(uint32_t addr) const {
        const word_ref w = word_at(addr & ~3u);
        if (w.reg < 0) return 0;
        const uint64_t bits = rm::to_bits(rm::kRegs[w.reg], img.get(w.reg));
        return static_cast<uint32_t>(bits >> (32 * w.word));
    }

    // One rising edge with the master's signals `in` (set up before the edge). Returns true if a
    // write took effect at this edge (the registers after the edge hold it).
    bool edge(const axil_in& in) {
        const bool aw_hs = in.awvalid && awready();
        const bool w_hs = in.wvalid && wready();
        const bool ar_hs = in.arvalid && arready();
        const bool fire = (aw_full_ || aw_hs) && (w_full_ || w_hs);
        const uint32_t rd = read_word(in.araddr);  // the registers before the edge
        if (fire) {
            const uint32_t addr = aw_full_ ? aw_addr_ : in.awaddr;
            const uint32_t data = w_full_ ? w_data_ : in.wdata;
            const unsigned strb = w_full_ ? w_strb_ : in.wstrb;
            uint32_t mask = 0;
            for (int b = 0; b < 4; ++b)
                if (strb & (1u << b)) mask |= 0xFFu << (8 * b);
            const uint32_t off = addr & ~3u;
            if (word_at(off).reg >= 0) img.write_word(off, (read_word(off) & ~mask) | (data & mask));
        }
        if (aw_hs) aw_addr_ = in.awaddr;
        if (w_hs) {
            w_data_ = in.wdata;
            w_strb_ = in.wstrb;
        }
        aw_full_ = (aw_full_ || aw_hs) && !fire;
        w_full_ = (w_full_ || w_hs) && !fire;
        bvalid_ = fire || (bvalid_ && !in.bready);
        if (ar_hs) rdata_ = rd;
        rvalid_ = ar_hs || (rvalid_ && !in.rready);
        return fire;
    }

private:
    bool aw_full_ = false, w_full_ = false, bvalid_ = false, rvalid_ = false;
    uint32_t aw_addr_ = 0, w_data_ = 0, rdata_ = 0;
    unsigned w_strb_ = 0;
};

// One bus transaction of the master. Delays are clocks from the start of the transaction: AW/AR
// valid from aw_delay, W valid from w_delay (writes), BREADY/RREADY from resp_delay.
struct txn {
    uint32_t addr = 0;
    uint32_t data = 0;
    unsigned strb = 0xF;
    int aw_delay = 0, w_delay = 0, resp_delay = 0;
};

// AXI4-Lite master: a write queue and a read queue, each one transaction at a time, both in
// parallel. VALID stays up until its handshake; while VALID is 0 the address and data lines carry
// junk (the slave must ignore them).
class axil_master {
public:
    std::deque<txn> writes, reads;
    long long n_writes = 0, n_reads = 0;

    bool idle() const { return writes.empty() && reads.empty() && !w_busy_ && !r_busy_; }
    bool write_idle() const { return writes.empty() && !w_busy_; }

    axil_in drive(long long k, rng_t& r) {
        if (!w_busy_ && !writes.empty()) {
            w_ = writes.front();
            writes.pop_front();
            w_busy_ = true;
            aw_done_ = w_done_ = false;
            w_start_ = k;
        }
        if (!r_busy_ && !reads.empty()) {
            r_ = reads.front();
            reads.pop_front();
            r_busy_ = true;
            ar_done_ = false;
            r_start_ = k;
        }
        axil_in in;
        in.awaddr = static_cast<uint32_t>(r.u()) & kAddrMask;
        in.wdata = static_cast<uint32_t>(r.u());
        in.wstrb = static_cast<unsigned>(r.u() & 0xF);
        in.araddr = static_cast<uint32_t>(r.u()) & kAddrMask;
        if (w_busy_) {
            in.awvalid = !aw_done_ && k >= w_start_ + w_.aw_delay;
            in.wvalid = !w_done_ && k >= w_start_ + w_.w_delay;
            in.bready = k >= w_start_ + w_.resp_delay;
            if (in.awvalid) in.awaddr = w_.addr;
            if (in.wvalid) {
                in.wdata = w_.data;
                in.wstrb = w_.strb;
            }
        } else {
            in.bready = r.chance(2);  // no response is pending: any level
        }
        if (r_busy_) {
            in.arvalid = !ar_done_ && k >= r_start_ + r_.aw_delay;
            in.rready = k >= r_start_ + r_.resp_delay;
            if (in.arvalid) in.araddr = r_.addr;
        } else {
            in.rready = r.chance(2);
        }
        return in;
    }

    // After the edge: the handshakes of `in` against the slave's outputs before the edge.
    void observe(const axil_in& in, bool awready, bool wready, bool bvalid, bool arready, bool rvalid) {
        if (w_busy_) {
            aw_done_ = aw_done_ || (in.awvalid && awready);
            w_done_ = w_done_ || (in.wvalid && wready);
            if (bvalid && in.bready) {
                w_busy_ = false;
                ++n_writes;
            }
        }
        if (r_busy_) {
            ar_done_ = ar_done_ || (in.arvalid && arready);
            if (rvalid && in.rready && ar_done_) {
                r_busy_ = false;
                ++n_reads;
            }
        }
    }

private:
    txn w_, r_;
    bool w_busy_ = false, r_busy_ = false, aw_done_ = false, w_done_ = false, ar_done_ = false;
    long long w_start_ = 0, r_start_ = 0;
};

// A transaction with random handshake timing: AW and W together (half the time), AW first or W
// first; responses accepted at once or a few clocks late.
txn random_timing(rng_t& r, uint32_t addr, uint32_t data, unsigned strb) {
    txn t;
    t.addr = addr;
    t.data = data;
    t.strb = strb;
    if (!r.chance(2)) {
        if (r.chance(2)) t.w_delay = static_cast<int>(r.range(1, 4));
        else t.aw_delay = static_cast<int>(r.range(1, 4));
    }
    t.resp_delay = r.chance(3) ? static_cast<int>(r.range(0, 6)) : 0;
    return t;
}

// ---- column layouts ----------------------------------------------------------------------------

vec_column col(const char* name, int bits, bool is_input, bool is_signed = false) {
    vec_column c;
    c.name = name;
    c.bits = bits;
    c.is_input = is_input;
    c.is_signed = is_signed;
    return c;
}

std::vector<vec_column> axil_columns() {
    return {col("awaddr", kAddrW, true), col("awvalid", 1, true), col("wdata", 32, true), col("wstrb", 4, true),
            col("wvalid", 1, true),      col("bready", 1, true),  col("araddr", kAddrW, true), col("arvalid", 1, true),
            col("rready", 1, true),      col("awready", 1, false), col("wready", 1, false), col("bvalid", 1, false),
            col("bresp", 2, false),      col("arready", 1, false), col("rvalid", 1, false), col("rdata", 32, false),
            col("rresp", 2, false)};
}

void put_axil(std::vector<int64_t>& row, const axil_in& in, const axil_slave& s) {
    row.insert(row.end(), {static_cast<int64_t>(in.awaddr), i64(in.awvalid), static_cast<int64_t>(in.wdata),
                           static_cast<int64_t>(in.wstrb), i64(in.wvalid), i64(in.bready),
                           static_cast<int64_t>(in.araddr), i64(in.arvalid), i64(in.rready), i64(s.awready()),
                           i64(s.wready()), i64(s.bvalid()), 0, i64(s.arready()), i64(s.rvalid()),
                           static_cast<int64_t>(s.rdata()), 0});
}

// One clock of the slave alone: the master drives, the slave takes the edge; one row with the AXI
// columns and every register port after the edge.
void regs_clock(axil_master& m, axil_slave& s, rng_t& r, vec_table& t) {
    const axil_in in = m.drive(static_cast<long long>(t.rows.size()), r);
    const bool awr = s.awready(), wr = s.wready(), bv = s.bvalid(), arr = s.arready(), rv = s.rvalid();
    s.edge(in);
    m.observe(in, awr, wr, bv, arr, rv);
    std::vector<int64_t> row;
    put_axil(row, in, s);
    for (int i = 0; i < rm::kNumRegs; ++i) row.push_back(s.img.get(i));
    t.rows.push_back(row);
}

// Clocks until the master has finished every queued transaction (false after `limit` clocks).
bool drain(axil_master& m, axil_slave& s, rng_t& r, vec_table& t, long long limit = 100000) {
    for (long long n = 0; !m.idle(); ++n) {
        if (n > limit) return false;
        regs_clock(m, s, r, t);
    }
    return true;
}

// A random value of register i: anywhere in its width, often an extreme.
int64_t random_value(rng_t& r, int i) {
    const rm::reg_info& ri = rm::kRegs[i];
    switch (r.range(0, 5)) {
        case 0: return rm::width_min(ri);
        case 1: return rm::width_max(ri);
        case 2: return ri.is_signed ? -1 : 0;
        default: return rm::from_bits(ri, r.u());
    }
}

// ---- laserax_regs: the slave alone -----------------------------------------------------------

bool regs_set(rng_t& r, vec_table& t, std::string* err) {
    t.block = "laserax_regs";
    t.cols = axil_columns();
    for (int i = 0; i < rm::kNumRegs; ++i)
        t.cols.push_back(col(rm::kRegs[i].name, rm::kRegs[i].width, false, rm::kRegs[i].is_signed));

    axil_slave s;
    axil_master m;
    const uint32_t end = rm::kEndOffset;
    auto read = [&](uint32_t addr, int delay, int resp) {
        txn x;
        x.addr = addr & kAddrMask;
        x.aw_delay = delay;
        x.resp_delay = resp;
        m.reads.push_back(x);
    };
    auto write = [&](const txn& x) { m.writes.push_back(x); };
    auto read_all = [&]() {  // every word of the map and a little past it
        for (uint32_t a = 0; a < end + 16; a += 4) read(a, 0, 0);
    };

    bool ok = true;
    // 1. reset values: every word, and far addresses
    read_all();
    for (uint32_t a : {0x7FCu, 0x800u, 0xFFCu, end + 0x100u, 0x200u + rm::kRegs[0].offset})
        read(a, static_cast<int>(r.range(0, 2)), static_cast<int>(r.range(0, 3)));
    ok = ok && drain(m, s, r, t);
    // 2. per register: full-word writes of random values (junk above the width), then random
    //    WSTRB, each read back after the writes; -1, -2 and the most negative value of signed ones
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const rm::reg_info& ri = rm::kRegs[i];
        std::vector<int64_t> values;
        for (int round = 0; round < 4; ++round) values.push_back(random_value(r, i));
        if (ri.is_signed) values.insert(values.end(), {int64_t(-1), rm::width_min(ri), int64_t(-2)});
        for (size_t round = 0; round < values.size(); ++round) {
            const uint64_t bits = rm::to_bits(ri, values[round]);
            for (int w = 0; w < ri.words(); ++w) {
                uint32_t data = static_cast<uint32_t>(bits >> (32 * w));
                const int top = ri.width - 32 * w;  // bits of the register in this word
                if (top < 32 && r.chance(2)) data |= static_cast<uint32_t>(r.u()) << top;  // junk above the width
                const unsigned strb = round == 2 || round == 3 ? static_cast<unsigned>(r.range(0, 15)) : 0xFu;
                write(random_timing(r, ri.offset + 4u * static_cast<uint32_t>(w), data, strb));
            }
            ok = ok && drain(m, s, r, t);
            for (int w = 0; w <= ri.words(); ++w)  // the words and the reserved word after them
                read(ri.offset + 4u * static_cast<uint32_t>(w), 0, static_cast<int>(r.range(0, 2)));
            ok = ok && drain(m, s, r, t);
        }
    }
    // 3. reserved and unmapped words: writes change nothing, reads return 0
    for (uint32_t a = 0; a < end + 16; a += 4) {
        if (word_at(a).reg >= 0) continue;
        write(random_timing(r, a, static_cast<uint32_t>(r.u()), 0xF));
        ok = ok && drain(m, s, r, t);
        read(a, 0, 0);
    }
    ok = ok && drain(m, s, r, t);
    // 4. random traffic, writes and reads in parallel (both channels busy in the same clocks)
    for (int n = 0; n < 1500; ++n) {
        uint32_t addr;
        const int kind = static_cast<int>(r.range(0, 9));
        if (kind < 7) {  // a register word
            const int i = static_cast<int>(r.range(0, rm::kNumRegs - 1));
            addr = rm::kRegs[i].offset + 4u * static_cast<uint32_t>(r.range(0, rm::kRegs[i].words() - 1));
            if (r.chance(10)) addr |= static_cast<uint32_t>(r.range(1, 3));  // unaligned: bits [1:0] ignored
        } else if (kind == 7) {
            addr = static_cast<uint32_t>(r.range(0, (end + 64) / 4)) * 4;  // anywhere near the map
        } else {
            addr = static_cast<uint32_t>(r.u()) & kAddrMask;  // anywhere
        }
        const unsigned strb = r.chance(2) ? 0xFu : static_cast<unsigned>(r.range(0, 15));
        write(random_timing(r, addr, static_cast<uint32_t>(r.u()), strb));
        const txn rd = random_timing(r, r.chance(2) ? addr : static_cast<uint32_t>(r.range(0, (end + 16) / 4)) * 4, 0, 0);
        read(rd.addr, rd.aw_delay, rd.resp_delay);
    }
    ok = ok && drain(m, s, r, t);
    // 5. every word read back once more, then a few idle clocks
    read_all();
    ok = ok && drain(m, s, r, t);
    for (int n = 0; n < 4; ++n) regs_clock(m, s, r, t);
    if (!ok) {
        *err = "laserax_regs: the master did not finish (slave model stuck?)";
        return false;
    }
    std::printf("  laserax_regs: %lld writes, %lld reads\n", m.n_writes, m.n_reads);
    return true;
}

// ---- laserax_axil: slave + chain -------------------------------------------------------------

bool axil_set(rng_t& r, long long calls, vec_table& t, std::string* err) {
    t.block = "laserax_axil";
    t.cols = {col("a", 1, true), col("b", 1, true), col("sw", 1, true), col("lerr", 1, true)};
    for (const vec_column& c : axil_columns()) t.cols.push_back(c);
    for (const vec_column& c : lxt::vec_layout("laserax_top"))
        if (!c.is_input) t.cols.push_back(c);

    axil_slave s;
    axil_master m;
    lx::laserax_top core;  // power-up state, table for P = 256 (the RTL's INIT_FILE)
    lxt::reg_image host;  // what the host has programmed (its own copy of the map)

    auto queue = [&](const std::vector<lxt::reg_write>& seq) {
        for (const lxt::reg_write& w : seq) m.writes.push_back(random_timing(r, w.offset, w.value, 0xF));
    };
    auto set_regs = [&](std::initializer_list<std::pair<int, int64_t>> vals) {
        std::vector<int> idx;
        for (const auto& v : vals) {
            host.set(v.first, v.second);
            idx.push_back(v.first);
        }
        queue(lxt::writes_for(host, idx));
    };
    auto pulse = [&](int i) {
        host.set(i, 1);
        queue(host.writes(i));
        host.set(i, 0);
        queue(host.writes(i));
    };
    // new air / material conditions -> ratio and comp_offset, framed by comp_sync / comp_commit
    auto compensate = [&](double p_pa, double t_air, double alpha, double t_mat, double origin_um) {
        lxt::comp_inputs ci;
        ci.pressure_pa = p_pa;
        ci.air_temp_c = t_air;
        ci.alpha_ppm_per_c = alpha;
        ci.material_temp_c = t_mat;
        ci.origin_um = origin_um;
        std::string e;
        if (!lxt::apply_compensation(ci, &host, nullptr, &e)) {
            *err = "laserax_axil: apply_compensation: " + e;
            return false;
        }
        queue(lxt::compensation_writes(host));
        host.set(rm::idx::comp_sync, 1);  // the sequence sets it (and pulses comp_commit)
        return true;
    };
    auto load_map = [&](int64_t origin, int k, int points, double amp) {
        lxt::map_table mt;
        mt.origin = origin;
        mt.spacing_log2 = k;
        for (int i = 0; i < points; ++i)
            mt.corr.push_back(static_cast<double>(r.range(-1000, 1000)) / 1000.0 * amp);
        lxt::map_load ld;
        std::string e;
        if (!lxt::program_map(mt, true, &host, &ld, &e)) {
            *err = "laserax_axil: program_map: " + e;
            return false;
        }
        queue(ld.seq);
        return true;
    };
    // A new quarter-wave table for (period, amplitude) and the switch to it (lxt::program_dds, one
    // safe-state window): the writes back to back as a driver issues them, one in 8 with random
    // timing. After a load with a period change the host waits for the axis to home with the new
    // period (the sweeps take it through the switch) before its next step, at most until call
    // await_until; once the writes are through, the model's table RAM is checked (check_table).
    int n_tbl_loads = 0, n_period_changes = 0, n_stray = 0;
    bool await_home = false, check_table = false;
    long long await_until = 0;
    auto load_dds = [&](int period, int amp, int mark_len, int dac_width) {
        lxt::dds_setting ds;
        ds.period = period;
        ds.amplitude = amp;
        ds.mark_len = mark_len;
        ds.dac_width = dac_width;
        const bool change = host.get(rm::idx::period) != period;
        lxt::dds_load ld;
        std::string e;
        if (!lxt::program_dds(ds, &host, &ld, &e)) {
            *err = "laserax_axil: program_dds: " + e;
            return false;
        }
        for (const lxt::reg_write& w : ld.seq) {
            txn x;
            if (r.chance(8)) x = random_timing(r, w.offset, w.value, 0xF);
            x.addr = w.offset;
            x.data = w.value;
            m.writes.push_back(x);
        }
        await_home = change;
        await_until = static_cast<long long>(t.rows.size()) + 16000;
        check_table = true;
        ++n_tbl_loads;
        n_period_changes += change ? 1 : 0;
        return true;
    };
    // one table word through the port (tbl_addr, tbl_data, tbl_we = 1, tbl_we = 0)
    auto table_word = [&](int64_t addr, int64_t data) {
        host.set(rm::idx::tbl_addr, addr);
        host.set(rm::idx::tbl_data, data);
        host.set(rm::idx::tbl_we, 1);
        queue(lxt::writes_for(host, {rm::idx::tbl_addr, rm::idx::tbl_data, rm::idx::tbl_we}));
        host.set(rm::idx::tbl_we, 0);
        queue(host.writes(rm::idx::tbl_we));
    };
    int64_t stray_addr = -1;  // a table word overwritten while running, restored at the next host step

    // settings first (the chain runs from reset with the CSV reset values meanwhile)
    set_regs({{rm::idx::glitch_n, 1}, {rm::idx::sw_debounce, 3}, {rm::idx::pace_m, 2}, {rm::idx::backlog_thr, 200},
              {rm::idx::min_spacing, 2}});

    // motion on the pins (raw laser counts n), switch closes at n >= sw_pos
    int64_t n = 0;
    int dir = 1;
    long long wait = 0, spacing = 40, seg_left = 0;
    // the travel: sw_pos - 80 .. sw_pos + reach raw counts, reach enough to home and pass Z
    // (A + P + P/4) with the period in force (~8.1 output counts per raw count)
    const int64_t sw_pos = 60;
    int64_t reach = 80;
    int glitch_left = 0;
    long long next_event = 300;
    int event = 0;
    long long homed = 0, corr = 0, cfg_err = 0;  // calls, for the summary line
    bool was_homed = false;  // o.homed of the previous call
    int last_stage = 1;      // o.stage of the previous call
    long long homings_256 = 0, homings_640 = 0;  // homings after the first table load, by period
    for (long long k = 0; k < calls; ++k) {
        // --- host programme: one step whenever the write queue has drained ---
        if (check_table && m.write_idle()) {
            // the sequence did what it claims: the model's table RAM holds lxt::dds_table's words
            // (the RTL's is compared through sin/cos on every clock)
            check_table = false;
            const int p = static_cast<int>(s.img.get(rm::idx::period));
            const std::vector<uint32_t> words = lxt::dds_table(p, static_cast<int>(s.img.get(rm::idx::amplitude)));
            for (int j = 0; j < p / 4; ++j) {
                if (core.dds().read(static_cast<unsigned>(j)) != words[static_cast<size_t>(j)]) {
                    *err = "laserax_axil: after the table load for P = " + std::to_string(p) + " word " +
                           std::to_string(j) + " of the table RAM is not lxt::dds_table's";
                    return false;
                }
            }
        }
        if (await_home && m.write_idle() && (was_homed || k >= await_until)) {
            await_home = false;
            next_event = k + r.range(200, 1500);
        }
        if (!await_home && k >= next_event && k < calls - 4000 && m.write_idle()) {
            bool ok = true;
            if (stray_addr >= 0) {  // put back the word of the table in force
                const std::vector<uint32_t> words = lxt::dds_table(
                    static_cast<int>(host.get(rm::idx::period)), static_cast<int>(host.get(rm::idx::amplitude)));
                table_word(stray_addr, words[static_cast<size_t>(stray_addr)]);
                stray_addr = -1;
            }
            // one cycle of 14 steps; the DDS table steps are spread over it (each load un-homes the
            // axis, and the host waits for the homing with the new period)
            switch (event++ % 14) {
                case 0: ok = compensate(100000.0 + static_cast<double>(r.range(-3000, 3000)), 20.0 + static_cast<double>(r.range(-30, 30)) / 10.0,
                                        11.5, 20.0 + static_cast<double>(r.range(-50, 50)) / 10.0,
                                        static_cast<double>(r.range(-20, 40))); break;
                case 1: ok = load_map(-512 + r.range(-100, 100), 7, 20, 30.0); break;
                case 2:
                case 10: {  // table load + period change 256 <-> 640 (mark_len anywhere in P/4 .. P)
                    const int p = host.get(rm::idx::period) == 256 ? 640 : 256;
                    ok = load_dds(p, r.chance(2) ? 32767 : static_cast<int>(r.range(2000, 32767)),
                                  static_cast<int>(r.range(p / 4, p)), 0);
                    break;
                }
                case 3: pulse(rm::idx::clear); break;
                case 4:  // a stray table word while the chain runs (tbl_period == period, against
                         // DESIGN 4.6): written, and that call is in the safe state (cfg_err), so
                         // the chain restarts unhomed; put back at the next host step
                    stray_addr = r.range(0, host.get(rm::idx::period) / 4 - 1);
                    table_word(stray_addr, static_cast<int64_t>(r.u() & 0x1FFFF));
                    ++n_stray;
                    break;
                case 5: ok = compensate(101325.0 + static_cast<double>(r.range(-5000, 5000)), 21.0, 0.0, 20.0, 0.0); break;
                case 6: set_regs({{rm::idx::map_en, r.chance(3) ? 0 : 1}}); break;
                case 7: {  // new amplitude, same period: a wide one (dac_width widened) or a narrow
                           // one with a dac_width chosen here
                    const int p = static_cast<int>(host.get(rm::idx::period));
                    if (r.chance(2)) ok = load_dds(p, static_cast<int>(r.range(40000, 131071)), 0, 0);
                    else ok = load_dds(p, static_cast<int>(r.range(100, 2047)), 0, static_cast<int>(r.range(12, 16)));
                    break;
                }
                case 8:  // read back a few registers
                    for (int j = 0; j < 4; ++j) {
                        txn x = random_timing(r, rm::kRegs[r.range(0, rm::kNumRegs - 1)].offset, 0, 0);
                        m.reads.push_back(x);
                    }
                    break;
                case 9:  // a few clocks of an invalid pace_m (safe state, cfg_err), then a valid one
                    set_regs({{rm::idx::pace_m, 1}});
                    set_regs({{rm::idx::pace_m, r.range(2, 3)}, {rm::idx::backlog_thr, r.range(100, 400)}});
                    break;
                case 11: ok = load_map(-600 + r.range(-100, 100), 6, 40, 60.0); break;
                case 12: pulse(rm::idx::rehome); break;
                default: ok = compensate(99000.0, 19.5, 23.0, 21.0 + static_cast<double>(r.range(0, 20)) / 10.0,
                                         static_cast<double>(r.range(0, 60))); break;
            }
            if (!ok) return false;
            next_event = k + r.range(200, 1500);
        }

        // --- pins ---
        // sweeps between the two ends of the travel, through the switch: new speed (or a stop)
        // now and then, a reversal in mid-travel now and then; neither while the host waits for
        // the homing after a period change (a homing move: end to end through the switch, quick)
        if (seg_left-- <= 0 || (await_home && spacing > 12)) {
            seg_left = r.range(300, 3000);
            const bool stop = r.chance(12), reverse = r.chance(10);
            spacing = await_home ? r.range(6, 12) : stop ? 1000000 : r.range(6, 30);
            if (reverse && !await_home) dir = -dir;
            if (wait > spacing) wait = spacing;
        }
        reach = std::max<int64_t>(80, host.get(rm::idx::period) * 5 / 32 + 20);
        if (n > sw_pos + reach) dir = -1;
        if (n < sw_pos - 80) dir = 1;
        // (inside the referencing window, stage 2, the homing move slows to at most 8 output counts
        // per 55 calls: the pacer's rate there is one count per 2 * pace_m calls, DESIGN 4.4)
        const long long step_calls = (await_home && last_stage == 2) ? std::max<long long>(spacing, 55) : spacing;
        if (wait-- <= 0) {
            n += dir;
            wait = step_calls;
        }
        bool a = false, b = false;
        {
            const int i = static_cast<int>(((n % 4) + 4) % 4);
            a = i == 1 || i == 2;
            b = i == 2 || i == 3;
        }
        if (glitch_left == 0 && r.chance(3000)) glitch_left = 1;
        if (glitch_left > 0) {
            a = !a;
            --glitch_left;
        }
        lx::axis_pins p;
        p.a = a;
        p.b = b;
        p.sw = n >= sw_pos;
        p.lerr = false;

        // --- one clock: the chain steps with the registers before this edge's write ---
        const axil_in in = m.drive(k, r);
        const lx::axis_out o = core.step(p, lxt::hls_from(s.img));
        const bool awr = s.awready(), wr = s.wready(), bv = s.bvalid(), arr = s.arready(), rv = s.rvalid();
        s.edge(in);
        m.observe(in, awr, wr, bv, arr, rv);

        std::vector<int64_t> row = {i64(p.a), i64(p.b), i64(p.sw), i64(p.lerr)};
        put_axil(row, in, s);
        row.insert(row.end(),
                   {o.sin.to_int64(), o.cos.to_int64(), i64(o.ref_mark), i64(o.qa), i64(o.qb), i64(o.qz), i64(o.q_oe),
                    i64(o.cfg_err), static_cast<int64_t>(o.stage.to_uint64()), i64(o.homed), i64(o.lerr_alarm),
                    i64(o.illegal_st), static_cast<int64_t>(o.err_cnt.to_uint64()), i64(o.ovs_edge_st),
                    i64(o.ovs_backlog_st), i64(o.glitch_st), i64(o.alarm), o.raw_count.to_int64(),
                    o.comp_pos.to_int64(), o.paced_pos.to_int64(), o.out_pos.to_int64(),
                    static_cast<int64_t>(o.d.to_uint64()), o.step.to_int64(), o.delta.to_int64(), o.backlog.to_int64(),
                    o.pstep.to_int64(), o.ostep.to_int64(), o.adj.to_int64(), o.a_pos.to_int64(), o.b_pos.to_int64(),
                    o.c_pos.to_int64(), o.z_pos.to_int64(), i64(o.rep_mark), i64(o.map_cfg_err), o.corr.to_int64(),
                    o.map_delta.to_int64()});
        t.rows.push_back(row);
        homed += o.homed ? 1 : 0;
        if (o.homed && !was_homed && n_tbl_loads > 0) {  // a homing after a table load, by period
            if (s.img.get(rm::idx::period) == 256) ++homings_256;
            else ++homings_640;  // the only other period of the scenario
        }
        was_homed = o.homed;
        last_stage = static_cast<int>(o.stage.to_uint64());
        corr += o.corr != 0 ? 1 : 0;
        cfg_err += o.cfg_err ? 1 : 0;
    }
    // the bus delivered what the host helper meant: the slave's registers equal the host's image
    if (!m.write_idle()) {
        *err = "laserax_axil: writes still queued at the end (raise --calls)";
        return false;
    }
    for (int i = 0; i < rm::kNumRegs; ++i) {
        if (s.img.get(i) != host.get(i)) {
            *err = std::string("laserax_axil: register ") + rm::kRegs[i].name + " differs from the host image at the end";
            return false;
        }
    }
    // the scenario covers what it claims: table loads with a period change both ways, and after
    // them a homing with each period
    if (n_period_changes < 2 || homings_256 == 0 || homings_640 == 0) {
        *err = "laserax_axil: " + std::to_string(n_period_changes) + " period changes, homings after a table load "
               "with P = 256: " + std::to_string(homings_256) + ", with P = 640: " + std::to_string(homings_640) +
               " (want >= 2 and >= 1 each: raise --calls)";
        return false;
    }
    std::printf("  laserax_axil: %lld writes, %lld reads, %d host steps (DDS table loads %d, %d of them with a "
                "period change; stray table words %d); homings after a load with P = 256: %lld, with P = 640: "
                "%lld; calls homed %lld, with a map correction %lld, cfg_err %lld\n",
                m.n_writes, m.n_reads, event, n_tbl_loads, n_period_changes, n_stray, homings_256, homings_640,
                homed, corr, cfg_err);
    return true;
}


}  // namespace

int main(int argc, char** argv) {
    return vecgen::run(argc, argv, "regmap_vectors", 5, 50000, "lxt::reg_image and hls/",
                       [](rng_t& r, long long calls, std::vector<vec_table>* tables, std::string* err) {
                           tables->resize(2);
                           return regs_set(r, (*tables)[0], err) && axil_set(r, calls, (*tables)[1], err);
                       });
}
