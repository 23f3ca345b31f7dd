// regmap.cpp — see regmap.h.
#include "host/regmap.h"

#include <cmath>
#include <cstdio>

#include "host/thermal.h"
#include "host/dds_table.h"

namespace lxt {

namespace rm = regmap;

namespace {

constexpr size_t kWords = (rm::kEndOffset - rm::kFirstOffset) / 4;
constexpr double kCountsPerUm = 1000.0 / kOutputCountNmComp;  // 12.8

size_t word_index(uint32_t offset) { return (offset - rm::kFirstOffset) / 4; }

std::string word_name(const rm::reg_info& r, int w) {
    if (r.words() == 1) return r.name;
    const int lo = 32 * w;
    const int hi = (r.width < lo + 32 ? r.width : lo + 32) - 1;
    return std::string(r.name) + "[" + std::to_string(hi) + ":" + std::to_string(lo) + "]";
}

void set_err(std::string* err, const std::string& m) {
    if (err) *err = m;
}

}  // namespace

std::string range_text(const rm::reg_info& r) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%d bits %s: %lld .. %lld", r.width, r.is_signed ? "signed" : "unsigned",
                  static_cast<long long>(rm::width_min(r)), static_cast<long long>(rm::width_max(r)));
    return buf;
}

// ---- reg_image -------------------------------------------------------------------------------

reg_image::reg_image() : w_(kWords, 0u) {
    for (int i = 0; i < rm::kNumRegs; ++i) set(i, rm::kRegs[i].reset);
}

bool reg_image::set(int i, int64_t value) {
    if (i < 0 || i >= rm::kNumRegs || !rm::fits(rm::kRegs[i], value)) return false;
    const rm::reg_info& r = rm::kRegs[i];
    const uint64_t bits = rm::to_bits(r, value);
    for (int w = 0; w < r.words(); ++w)
        w_[word_index(r.offset) + static_cast<size_t>(w)] = static_cast<uint32_t>(bits >> (32 * w));
    return true;
}

int64_t reg_image::get(int i) const {
    if (i < 0 || i >= rm::kNumRegs) return 0;
    const rm::reg_info& r = rm::kRegs[i];
    uint64_t bits = 0;
    for (int w = 0; w < r.words(); ++w)
        bits |= static_cast<uint64_t>(w_[word_index(r.offset) + static_cast<size_t>(w)]) << (32 * w);
    return rm::from_bits(r, bits);  // masks the bits above the width
}

bool reg_image::write(const std::string& name, int64_t value, std::string* err) {
    const int i = rm::find(name.c_str());
    if (i < 0) {
        set_err(err, "unknown register '" + name + "' (see docs/REGISTERS.md)");
        return false;
    }
    if (!set(i, value)) {
        set_err(err, "value " + std::to_string(static_cast<long long>(value)) + " does not fit register " + name +
                         " (" + range_text(rm::kRegs[i]) + ")");
        return false;
    }
    return true;
}

bool reg_image::read(const std::string& name, int64_t* value, std::string* err) const {
    const int i = rm::find(name.c_str());
    if (i < 0) {
        set_err(err, "unknown register '" + name + "' (see docs/REGISTERS.md)");
        return false;
    }
    *value = get(i);
    return true;
}

bool reg_image::write_word(uint32_t offset, uint32_t value, std::string* err) {
    if (offset % 4 != 0 || offset < rm::kFirstOffset || offset >= rm::kEndOffset) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "offset 0x%X is not a word of the register map (0x%X .. 0x%X)", offset,
                      rm::kFirstOffset, rm::kEndOffset - 4);
        set_err(err, buf);
        return false;
    }
    w_[word_index(offset)] = value;
    return true;
}

uint32_t reg_image::word(uint32_t offset) const {
    if (offset % 4 != 0 || offset < rm::kFirstOffset || offset >= rm::kEndOffset) return 0;
    return w_[word_index(offset)];
}

std::vector<reg_write> reg_image::writes(int i) const {
    std::vector<reg_write> out;
    if (i < 0 || i >= rm::kNumRegs) return out;
    const rm::reg_info& r = rm::kRegs[i];
    const uint64_t bits = rm::to_bits(r, get(i));
    for (int w = 0; w < r.words(); ++w) {
        reg_write x;
        x.offset = r.offset + 4u * static_cast<uint32_t>(w);
        x.name = word_name(r, w);
        x.value = static_cast<uint32_t>(bits >> (32 * w));
        out.push_back(x);
    }
    return out;
}

std::vector<reg_write> writes_for(const reg_image& img, const std::vector<int>& regs) {
    std::vector<reg_write> out;
    for (int i : regs) {
        const std::vector<reg_write> w = img.writes(i);
        out.insert(out.end(), w.begin(), w.end());
    }
    return out;
}

std::string format_writes(const std::vector<reg_write>& w) {
    std::string s;
    char buf[128];
    for (const reg_write& x : w) {
        std::snprintf(buf, sizeof buf, "0x%04X %s 0x%08X\n", x.offset, x.name.c_str(), x.value);
        s += buf;
    }
    return s;
}

// ---- image <-> settings ----------------------------------------------------------------------

bool image_from(const axis_settings& s, reg_image* img, std::string* err) {
    reg_image out;
    for (int i = 0; i < rm::kNumRegs; ++i) {
        const int64_t v = rm::get(s, i);
        if (!out.set(i, v)) {
            set_err(err, std::string("axis_settings::") + rm::kRegs[i].hls_member + " = " +
                             std::to_string(static_cast<long long>(v)) + " does not fit register " + rm::kRegs[i].name +
                             " (" + range_text(rm::kRegs[i]) + ")");
            return false;
        }
    }
    *img = out;
    return true;
}

axis_settings settings_from(const reg_image& img) {
    axis_settings s;
    for (int i = 0; i < rm::kNumRegs; ++i) rm::set(s, i, img.get(i));  // always fits: the image holds register values
    return s;
}

bool init_registers(const reg_image& img, const bus_write_fn& write, std::string* err) {
    return init_registers(settings_from(img), write, err);
}

// ---- compensation ----------------------------------------------------------------------------

bool apply_compensation(const comp_inputs& in, reg_image* img, comp_outputs* out, std::string* err) {
    const comp_outputs c = compute_compensation(in);
    if (out) *out = c;
    if (!c.ok) {
        set_err(err, c.error);
        return false;
    }
    // both fit by construction (ratio_from_scale, comp_offset_from_scaling check the widths)
    if (!img->set(rm::idx::ratio, static_cast<int64_t>(c.ratio)) || !img->set(rm::idx::comp_offset, c.comp_offset)) {
        set_err(err, "ratio or comp_offset does not fit its register");
        return false;
    }
    return true;
}

std::vector<reg_write> compensation_writes(const reg_image& img) {
    // comp_sync = 1, the words of ratio and comp_offset, then a comp_commit pulse: the core takes
    // the new pair in one clock (DESIGN 4.7) and never sees a half-written register
    reg_image w = img;
    w.set(rm::idx::comp_sync, 1);
    std::vector<reg_write> out = writes_for(w, {rm::idx::comp_sync, rm::idx::ratio, rm::idx::comp_offset});
    w.set(rm::idx::comp_commit, 1);
    const std::vector<reg_write> on = w.writes(rm::idx::comp_commit);
    w.set(rm::idx::comp_commit, 0);
    const std::vector<reg_write> off = w.writes(rm::idx::comp_commit);
    out.insert(out.end(), on.begin(), on.end());
    out.insert(out.end(), off.begin(), off.end());
    return out;
}

comp_readback compensation_from_image(const reg_image& img, const comp_knowns& k) {
    comp_readback b;
    const uint64_t ratio = static_cast<uint64_t>(img.get(rm::idx::ratio));
    const int64_t comp_offset = img.get(rm::idx::comp_offset);
    if (ratio == 0) {
        b.error = "ratio register is 0 (invalid configuration)";
        return b;
    }
    const ratio_readback rb = scale_from_ratio(ratio, k.wavelength_nm);
    b.scale = rb.scale;
    b.register_ppm = rb.ppm_vs_vacuum;

    // the expansion factor exactly as compute_compensation quantises it (origin does not enter g)
    lxt::thermal_params tp;
    const lxt::thermal_status ts = lxt::make_thermal(k.alpha_ppm_per_c, k.material_temp_c, 0, &tp);
    if (!ts.ok) {
        b.error = ts.error;
        return b;
    }
    b.expansion = lxt::gradient(tp);
    b.n = air_index_from_ratio(ratio, k.wavelength_nm, b.expansion);

    // pressure: n(p) is strictly increasing in p; bisection over the equation's range
    const lxt::air_limits lim =
        k.equation == lxt::air_equation::edlen ? lxt::edlen_limits() : lxt::ciddor_limits();
    lxt::air_input ai;
    ai.wavelength_nm = k.wavelength_nm;
    ai.temp_c = k.air_temp_c;
    ai.rh_percent = k.rh_percent;
    ai.co2_ppm = k.co2_ppm;
    auto n_at = [&](double p, bool* ok) {
        ai.pressure_pa = p;
        const lxt::air_index_result r = lxt::air_index(k.equation, ai);
        *ok = r.ok;
        if (!r.ok) b.error = r.error;
        return r.n;
    };
    bool ok_lo = false, ok_hi = false;
    double lo = lim.p_min_pa, hi = lim.p_max_pa;
    double n_lo = n_at(lo, &ok_lo);
    // humid air at the lowest pressures may be invalid (vapour pressure above the total): start
    // at the first valid pressure, 100 Pa steps
    while (!ok_lo && lo + 100.0 <= hi) {
        lo += 100.0;
        n_lo = n_at(lo, &ok_lo);
    }
    const double n_hi = n_at(hi, &ok_hi);
    if (!ok_lo || !ok_hi) return b;  // the knowns are outside the equation's range (message set)
    b.error.clear();
    if (!(b.n >= n_lo && b.n <= n_hi)) {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "ratio %llu implies n = %.10f, outside n = %.10f .. %.10f of the %s equation at %g .. %g Pa "
                      "for these conditions (pressure out of range)",
                      static_cast<unsigned long long>(ratio), b.n, n_lo, n_hi, lxt::air_equation_name(k.equation),
                      lo, hi);
        b.error = buf;
        return b;
    }
    for (int it = 0; it < 200 && hi - lo > 1e-7; ++it) {
        const double mid = 0.5 * (lo + hi);
        bool ok = false;
        const double n_mid = n_at(mid, &ok);
        if (!ok) return b;
        if (n_mid < b.n)
            lo = mid;
        else
            hi = mid;
    }
    b.pressure_pa = 0.5 * (lo + hi);

    const lxt::encoder_scaling es = lxt::to_encoder_scaling(tp);
    b.origin_known = es.k169_e7 != 0;
    if (b.origin_known) {
        b.origin_counts = origin_from_comp_offset(comp_offset, es.k169_e7);
        b.origin_um = b.origin_counts / kCountsPerUm;
    } else if (comp_offset != 0) {
        b.error = "comp_offset is not 0 but the knowns give no expansion (alpha (20 - T) = 0)";
        return b;
    }
    b.ok = true;
    return b;
}

// ---- error map -------------------------------------------------------------------------------

bool map_word_from_counts(double counts, int32_t* word, std::string* err) {
    if (!std::isfinite(counts)) {
        set_err(err, "error-map correction is not a finite number");
        return false;
    }
    const double x = counts * 256.0;                                       // exact scaling by a power of two
    const double r = x < 0 ? -std::floor(-x + 0.5) : std::floor(x + 0.5);  // round half away from zero
    const double lim = static_cast<double>(1 << 23);
    if (r < -lim || r > lim - 1.0) {
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "error-map correction %.6g counts is outside the Q15.8 table word (-32768 .. 32767.996 counts)",
                      counts);
        set_err(err, buf);
        return false;
    }
    *word = static_cast<int32_t>(r);
    return true;
}

double map_counts_from_word(int32_t word) { return static_cast<double>(word) / 256.0; }

namespace {
struct bank_regs {
    int origin, k, n;
};
bank_regs bank_of(int b) {
    return b == 0 ? bank_regs{rm::idx::map_origin0, rm::idx::map_k0, rm::idx::map_n0}
                  : bank_regs{rm::idx::map_origin1, rm::idx::map_k1, rm::idx::map_n1};
}
}  // namespace

bool program_map(const map_table& t, bool activate, reg_image* img, map_load* out, std::string* err) {
    const rm::reg_info& kr = rm::kRegs[rm::idx::map_k0];
    const rm::reg_info& nr = rm::kRegs[rm::idx::map_n0];
    const int64_t npts = static_cast<int64_t>(t.corr.size());
    if (!rm::legal(kr, t.spacing_log2)) {
        set_err(err, "error-map spacing 2^" + std::to_string(t.spacing_log2) + " counts: k must be " +
                         std::to_string(kr.min) + " .. " + std::to_string(kr.max));
        return false;
    }
    if (!rm::legal(nr, npts)) {
        set_err(err, "error map with " + std::to_string(npts) + " points: must be " + std::to_string(nr.min) + " .. " +
                         std::to_string(nr.max));
        return false;
    }
    if (!rm::fits(rm::kRegs[rm::idx::map_origin0], t.origin)) {
        set_err(err, "error-map origin " + std::to_string(static_cast<long long>(t.origin)) +
                         " counts does not fit map_origin (" + range_text(rm::kRegs[rm::idx::map_origin0]) + ")");
        return false;
    }
    map_load ld;
    ld.words.reserve(t.corr.size());
    for (size_t i = 0; i < t.corr.size(); ++i) {
        const double c = t.units == map_units::um ? t.corr[i] * kCountsPerUm : t.corr[i];
        int32_t w = 0;
        std::string e;
        if (!map_word_from_counts(c, &w, &e)) {
            set_err(err, "point " + std::to_string(i) + ": " + e);
            return false;
        }
        ld.words.push_back(w);
    }
    reg_image m = *img;
    ld.bank = m.get(rm::idx::bank_sel) != 0 ? 0 : 1;
    const bank_regs br = bank_of(ld.bank);
    m.set(br.origin, t.origin);
    m.set(br.k, t.spacing_log2);
    m.set(br.n, npts);
    ld.seq = writes_for(m, {br.origin, br.k, br.n});
    for (size_t i = 0; i < ld.words.size(); ++i) {
        m.set(rm::idx::map_addr, static_cast<int64_t>(i));
        m.set(rm::idx::map_data, ld.words[i]);
        m.set(rm::idx::map_we, 1);
        const std::vector<reg_write> w1 = writes_for(m, {rm::idx::map_addr, rm::idx::map_data, rm::idx::map_we});
        ld.seq.insert(ld.seq.end(), w1.begin(), w1.end());
        m.set(rm::idx::map_we, 0);
        const std::vector<reg_write> w0 = m.writes(rm::idx::map_we);
        ld.seq.insert(ld.seq.end(), w0.begin(), w0.end());
    }
    if (activate) {
        m.set(rm::idx::bank_sel, ld.bank);
        m.set(rm::idx::map_en, 1);
        const std::vector<reg_write> w = writes_for(m, {rm::idx::bank_sel, rm::idx::map_en});
        ld.seq.insert(ld.seq.end(), w.begin(), w.end());
    }
    *img = m;
    if (out) *out = ld;
    return true;
}

bool replay(const std::vector<reg_write>& seq, reg_image* img, map_ram* ram, std::string* err) {
    for (const reg_write& x : seq) {
        if (!img->write_word(x.offset, x.value, err)) return false;
        if (ram && img->get(rm::idx::map_we) != 0) {
            const int bank = img->get(rm::idx::bank_sel) != 0 ? 0 : 1;
            const size_t addr = static_cast<size_t>(img->get(rm::idx::map_addr));
            if (addr < ram->bank[bank].size())
                ram->bank[bank][addr] = static_cast<int32_t>(img->get(rm::idx::map_data));
        }
    }
    return true;
}

bool map_from_image(const reg_image& img, int bank, const std::vector<int32_t>& words, map_units units, map_table* out,
                    std::string* err) {
    if (bank != 0 && bank != 1) {
        set_err(err, "error-map bank must be 0 or 1");
        return false;
    }
    const bank_regs br = bank_of(bank);
    map_table t;
    t.origin = img.get(br.origin);
    t.spacing_log2 = static_cast<int>(img.get(br.k));
    const int64_t npts = img.get(br.n);
    t.units = units;
    if (!rm::legal(rm::kRegs[br.k], t.spacing_log2) || !rm::legal(rm::kRegs[br.n], npts)) {
        set_err(err, "bank " + std::to_string(bank) + " geometry is invalid (k = " + std::to_string(t.spacing_log2) +
                         ", n = " + std::to_string(static_cast<long long>(npts)) + "): map_cfg_err");
        return false;
    }
    if (static_cast<int64_t>(words.size()) < npts) {
        set_err(err, "bank " + std::to_string(bank) + " has " + std::to_string(static_cast<long long>(npts)) +
                         " points but " + std::to_string(words.size()) + " words were given");
        return false;
    }
    for (int64_t i = 0; i < npts; ++i) {
        const double c = map_counts_from_word(words[static_cast<size_t>(i)]);
        t.corr.push_back(units == map_units::um ? c / kCountsPerUm : c);
    }
    *out = t;
    return true;
}

// ---- DDS quarter-wave table ------------------------------------------------------------------

bool program_dds(const dds_setting& s, reg_image* img, dds_load* out, std::string* err) {
    const rm::reg_info& pr = rm::kRegs[rm::idx::period];
    const rm::reg_info& mr = rm::kRegs[rm::idx::mark_len];
    const rm::reg_info& wr = rm::kRegs[rm::idx::dac_width];
    const rm::reg_info& ar = rm::kRegs[rm::idx::amplitude];
    if (!rm::legal(pr, s.period)) {
        set_err(err, "DDS period " + std::to_string(s.period) + ": must be " + std::to_string(pr.min) + " .. " +
                         std::to_string(pr.max) + " in steps of " + std::to_string(pr.step));
        return false;
    }
    if (!rm::legal(ar, s.amplitude)) {
        set_err(err, "DDS amplitude " + std::to_string(s.amplitude) + ": must be " + std::to_string(ar.min) + " .. " +
                         std::to_string(ar.max));
        return false;
    }
    const int mark_len = s.mark_len == 0 ? s.period / 4 : s.mark_len;
    if (!rm::legal(mr, mark_len) || mark_len < s.period / 4 || mark_len > s.period) {
        set_err(err, "mark_len " + std::to_string(mark_len) + " for period " + std::to_string(s.period) +
                         ": must be P/4 .. P (" + std::to_string(s.period / 4) + " .. " + std::to_string(s.period) +
                         ")");
        return false;
    }
    const auto amp_max = [](int64_t w) { return (int64_t(1) << (w - 1)) - 1; };
    int64_t width = s.dac_width;
    if (width == 0) {  // keep the image's width if the amplitude fits it, else widen just enough
        width = img->get(rm::idx::dac_width);
        if (!rm::legal(wr, width) || s.amplitude > amp_max(width)) {
            width = wr.min;
            while (width < wr.max && s.amplitude > amp_max(width)) ++width;
        }
    }
    if (!rm::legal(wr, width) || s.amplitude > amp_max(width)) {
        set_err(err, "dac_width " + std::to_string(static_cast<long long>(width)) + " for amplitude " +
                         std::to_string(s.amplitude) + ": must be " + std::to_string(wr.min) + " .. " +
                         std::to_string(wr.max) + " with amplitude <= 2^(dac_width-1) - 1");
        return false;
    }
    dds_load ld;
    std::string e;
    ld.words = dds_table(s.period, s.amplitude, &e);  // the ranges above are dds_table's
    if (ld.words.size() != static_cast<size_t>(s.period / 4)) {
        set_err(err, "dds_table: " + e);
        return false;
    }
    reg_image m = *img;
    // 1. the table is being rewritten: tbl_period = 0 matches no period (safe state from here)
    m.set(rm::idx::tbl_period, 0);
    ld.seq = m.writes(rm::idx::tbl_period);
    // 2. the words through the port
    for (size_t k = 0; k < ld.words.size(); ++k) {
        m.set(rm::idx::tbl_addr, static_cast<int64_t>(k));
        m.set(rm::idx::tbl_data, ld.words[k]);
        m.set(rm::idx::tbl_we, 1);
        const std::vector<reg_write> w1 = writes_for(m, {rm::idx::tbl_addr, rm::idx::tbl_data, rm::idx::tbl_we});
        ld.seq.insert(ld.seq.end(), w1.begin(), w1.end());
        m.set(rm::idx::tbl_we, 0);
        const std::vector<reg_write> w0 = m.writes(rm::idx::tbl_we);
        ld.seq.insert(ld.seq.end(), w0.begin(), w0.end());
    }
    // 3. the period-dependent registers, 4. tbl_period = P: valid again
    m.set(rm::idx::period, s.period);
    m.set(rm::idx::mark_len, mark_len);
    m.set(rm::idx::dac_width, width);
    m.set(rm::idx::amplitude, s.amplitude);
    m.set(rm::idx::tbl_period, s.period);
    const std::vector<reg_write> w = writes_for(
        m, {rm::idx::period, rm::idx::mark_len, rm::idx::dac_width, rm::idx::amplitude, rm::idx::tbl_period});
    ld.seq.insert(ld.seq.end(), w.begin(), w.end());
    *img = m;
    if (out) *out = ld;
    return true;
}

}  // namespace lxt
