// regmap_models.cpp — see regmap_models.h.
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
#include "sysmodel/regmap_models.h"

namespace lxt {

namespace {
template <typename T>
void assign(T& dst, int64_t v) {
    dst = static_cast<T>(v);
}
void assign(bool& dst, int64_t v) { dst = v != 0; }
template <typename D, typename S>
void convert(D& dst, const S& src) {
    dst = static_cast<D>(src);
}
}  // namespace

namespace regmap {

int64_t get(const lx::axis_regs& r, int i) {
    switch (i) {
        case idx::period: return static_cast<int64_t>(r.period.to_uint64());
        case idx::tbl_period: return static_cast<int64_t>(r.tbl_period.to_uint64());
        case idx::ratio: return static_cast<int64_t>(r.ratio.to_uint64());
        case idx::comp_offset: return r.comp_offset.to_int64();
        case idx::glitch_n: return static_cast<int64_t>(r.glitch_n.to_uint64());
        case idx::sw_debounce: return static_cast<int64_t>(r.sw_debounce.to_uint64());
        case idx::min_spacing: return static_cast<int64_t>(r.min_spacing.to_uint64());
        case idx::pace_m: return static_cast<int64_t>(r.pace_m.to_uint64());
        case idx::backlog_thr: return static_cast<int64_t>(r.backlog_thr.to_uint64());
        case idx::mark_len: return static_cast<int64_t>(r.mark_len.to_uint64());
        case idx::dac_width: return static_cast<int64_t>(r.dac_width.to_uint64());
        case idx::amplitude: return static_cast<int64_t>(r.amplitude.to_uint64());
        case idx::rehome: return r.rehome ? 1 : 0;
        case idx::clear: return r.clear ? 1 : 0;
        case idx::tbl_we: return r.tbl_we ? 1 : 0;
        case idx::tbl_addr: return static_cast<int64_t>(r.tbl_addr.to_uint64());
        case idx::tbl_data: return static_cast<int64_t>(r.tbl_data.to_uint64());
        case idx::map_en: return r.emap.map_en ? 1 : 0;
        case idx::bank_sel: return r.emap.bank_sel ? 1 : 0;
        case idx::map_origin0: return r.emap.geom[0].origin.to_int64();
        case idx::map_k0: return static_cast<int64_t>(r.emap.geom[0].spacing_log2.to_uint64());
        case idx::map_n0: return static_cast<int64_t>(r.emap.geom[0].n_points.to_uint64());
        case idx::map_origin1: return r.emap.geom[1].origin.to_int64();
        case idx::map_k1: return static_cast<int64_t>(r.emap.geom[1].spacing_log2.to_uint64());
        case idx::map_n1: return static_cast<int64_t>(r.emap.geom[1].n_points.to_uint64());
        case idx::map_we: return r.emap.we ? 1 : 0;
        case idx::map_addr: return static_cast<int64_t>(r.emap.addr.to_uint64());
        case idx::map_data: return r.emap.data.to_int64();
        case idx::comp_sync: return r.comp_sync ? 1 : 0;
        case idx::comp_commit: return r.comp_commit ? 1 : 0;
        case idx::pin_cfg: return static_cast<int64_t>(r.pin_cfg.to_uint64());
        default: return 0;
    }
}

bool set(lx::axis_regs& r, int i, int64_t value) {
    if (i < 0 || i >= kNumRegs || !fits(kRegs[i], value)) return false;
    switch (i) {
        case idx::period: r.period = lx::uint<13>(value); return true;
        case idx::tbl_period: r.tbl_period = lx::uint<13>(value); return true;
        case idx::ratio: r.ratio = lx::uint<37>(value); return true;
        case idx::comp_offset: r.comp_offset = lx::sint<64>(value); return true;
        case idx::glitch_n: r.glitch_n = lx::uint<8>(value); return true;
        case idx::sw_debounce: r.sw_debounce = lx::uint<16>(value); return true;
        case idx::min_spacing: r.min_spacing = lx::uint<16>(value); return true;
        case idx::pace_m: r.pace_m = lx::uint<16>(value); return true;
        case idx::backlog_thr: r.backlog_thr = lx::uint<32>(value); return true;
        case idx::mark_len: r.mark_len = lx::uint<13>(value); return true;
        case idx::dac_width: r.dac_width = lx::uint<5>(value); return true;
        case idx::amplitude: r.amplitude = lx::uint<18>(value); return true;
        case idx::rehome: r.rehome = value != 0; return true;
        case idx::clear: r.clear = value != 0; return true;
        case idx::tbl_we: r.tbl_we = value != 0; return true;
        case idx::tbl_addr: r.tbl_addr = lx::uint<10>(value); return true;
        case idx::tbl_data: r.tbl_data = lx::uint<17>(value); return true;
        case idx::map_en: r.emap.map_en = value != 0; return true;
        case idx::bank_sel: r.emap.bank_sel = value != 0; return true;
        case idx::map_origin0: r.emap.geom[0].origin = lx::sint<38>(value); return true;
        case idx::map_k0: r.emap.geom[0].spacing_log2 = lx::uint<5>(value); return true;
        case idx::map_n0: r.emap.geom[0].n_points = lx::uint<11>(value); return true;
        case idx::map_origin1: r.emap.geom[1].origin = lx::sint<38>(value); return true;
        case idx::map_k1: r.emap.geom[1].spacing_log2 = lx::uint<5>(value); return true;
        case idx::map_n1: r.emap.geom[1].n_points = lx::uint<11>(value); return true;
        case idx::map_we: r.emap.we = value != 0; return true;
        case idx::map_addr: r.emap.addr = lx::uint<10>(value); return true;
        case idx::map_data: r.emap.data = lx::sint<24>(value); return true;
        case idx::comp_sync: r.comp_sync = value != 0; return true;
        case idx::comp_commit: r.comp_commit = value != 0; return true;
        case idx::pin_cfg: r.pin_cfg = lx::uint<4>(value); return true;
        default: return false;
    }
}

bool get(const golden::axis_regs& r, int i, int64_t* value) {
    switch (i) {
        case idx::period: *value = static_cast<int64_t>(r.period); return true;
        case idx::tbl_period: *value = static_cast<int64_t>(r.tbl_period); return true;
        case idx::ratio: *value = static_cast<int64_t>(r.ratio); return true;
        case idx::comp_offset: *value = static_cast<int64_t>(r.comp_offset); return true;
        case idx::glitch_n: *value = static_cast<int64_t>(r.glitch_n); return true;
        case idx::sw_debounce: *value = static_cast<int64_t>(r.sw_debounce); return true;
        case idx::min_spacing: *value = static_cast<int64_t>(r.min_spacing); return true;
        case idx::pace_m: *value = static_cast<int64_t>(r.pace_m); return true;
        case idx::backlog_thr: *value = static_cast<int64_t>(r.backlog_thr); return true;
        case idx::mark_len: *value = static_cast<int64_t>(r.mark_len); return true;
        case idx::dac_width: *value = static_cast<int64_t>(r.dac_width); return true;
        case idx::amplitude: *value = static_cast<int64_t>(r.amplitude); return true;
        case idx::rehome: *value = static_cast<int64_t>(r.rehome); return true;
        case idx::clear: *value = static_cast<int64_t>(r.clear); return true;
        case idx::tbl_we: *value = static_cast<int64_t>(r.tbl_we); return true;
        case idx::map_en: *value = static_cast<int64_t>(r.emap.map_en); return true;
        case idx::bank_sel: *value = static_cast<int64_t>(r.emap.bank_sel); return true;
        case idx::map_origin0: *value = static_cast<int64_t>(r.emap.geom[0].origin); return true;
        case idx::map_k0: *value = static_cast<int64_t>(r.emap.geom[0].spacing_log2); return true;
        case idx::map_n0: *value = static_cast<int64_t>(r.emap.geom[0].n_points); return true;
        case idx::map_origin1: *value = static_cast<int64_t>(r.emap.geom[1].origin); return true;
        case idx::map_k1: *value = static_cast<int64_t>(r.emap.geom[1].spacing_log2); return true;
        case idx::map_n1: *value = static_cast<int64_t>(r.emap.geom[1].n_points); return true;
        case idx::map_we: *value = static_cast<int64_t>(r.emap.we); return true;
        case idx::map_addr: *value = static_cast<int64_t>(r.emap.addr); return true;
        case idx::map_data: *value = static_cast<int64_t>(r.emap.data); return true;
        case idx::comp_sync: *value = static_cast<int64_t>(r.comp_sync); return true;
        case idx::comp_commit: *value = static_cast<int64_t>(r.comp_commit); return true;
        case idx::pin_cfg: *value = static_cast<int64_t>(r.pin_cfg); return true;
        default: return false;
    }
}

bool set(golden::axis_regs& r, int i, int64_t value) {
    if (i < 0 || i >= kNumRegs || !fits(kRegs[i], value)) return false;
    switch (i) {
        case idx::period: assign(r.period, value); return true;
        case idx::tbl_period: assign(r.tbl_period, value); return true;
        case idx::ratio: assign(r.ratio, value); return true;
        case idx::comp_offset: assign(r.comp_offset, value); return true;
        case idx::glitch_n: assign(r.glitch_n, value); return true;
        case idx::sw_debounce: assign(r.sw_debounce, value); return true;
        case idx::min_spacing: assign(r.min_spacing, value); return true;
        case idx::pace_m: assign(r.pace_m, value); return true;
        case idx::backlog_thr: assign(r.backlog_thr, value); return true;
        case idx::mark_len: assign(r.mark_len, value); return true;
        case idx::dac_width: assign(r.dac_width, value); return true;
        case idx::amplitude: assign(r.amplitude, value); return true;
        case idx::rehome: assign(r.rehome, value); return true;
        case idx::clear: assign(r.clear, value); return true;
        case idx::tbl_we: assign(r.tbl_we, value); return true;
        case idx::map_en: assign(r.emap.map_en, value); return true;
        case idx::bank_sel: assign(r.emap.bank_sel, value); return true;
        case idx::map_origin0: assign(r.emap.geom[0].origin, value); return true;
        case idx::map_k0: assign(r.emap.geom[0].spacing_log2, value); return true;
        case idx::map_n0: assign(r.emap.geom[0].n_points, value); return true;
        case idx::map_origin1: assign(r.emap.geom[1].origin, value); return true;
        case idx::map_k1: assign(r.emap.geom[1].spacing_log2, value); return true;
        case idx::map_n1: assign(r.emap.geom[1].n_points, value); return true;
        case idx::map_we: assign(r.emap.we, value); return true;
        case idx::map_addr: assign(r.emap.addr, value); return true;
        case idx::map_data: assign(r.emap.data, value); return true;
        case idx::comp_sync: assign(r.comp_sync, value); return true;
        case idx::comp_commit: assign(r.comp_commit, value); return true;
        case idx::pin_cfg: assign(r.pin_cfg, value); return true;
        default: return false;
    }
}

}  // namespace regmap

lx::axis_regs to_hls(const golden::axis_regs& s) {
    lx::axis_regs r;
    r.period = s.period;
    r.tbl_period = s.tbl_period;
    r.ratio = s.ratio;
    r.comp_offset = s.comp_offset;
    r.glitch_n = s.glitch_n;
    r.sw_debounce = s.sw_debounce;
    r.min_spacing = s.min_spacing;
    r.pace_m = s.pace_m;
    r.backlog_thr = s.backlog_thr;
    r.mark_len = s.mark_len;
    r.dac_width = s.dac_width;
    r.amplitude = s.amplitude;
    r.rehome = s.rehome;
    r.clear = s.clear;
    r.tbl_we = s.tbl_we;
    r.emap.map_en = s.emap.map_en;
    r.emap.bank_sel = s.emap.bank_sel;
    r.emap.geom[0].origin = s.emap.geom[0].origin;
    r.emap.geom[0].spacing_log2 = s.emap.geom[0].spacing_log2;
    r.emap.geom[0].n_points = s.emap.geom[0].n_points;
    r.emap.geom[1].origin = s.emap.geom[1].origin;
    r.emap.geom[1].spacing_log2 = s.emap.geom[1].spacing_log2;
    r.emap.geom[1].n_points = s.emap.geom[1].n_points;
    r.emap.we = s.emap.we;
    r.emap.addr = s.emap.addr;
    r.emap.data = s.emap.data;
    r.comp_sync = s.comp_sync;
    r.comp_commit = s.comp_commit;
    r.pin_cfg = s.pin_cfg;
    return r;
}

lx::axis_regs to_hls(const axis_settings& s) {
    lx::axis_regs r;
    r.period = lx::uint<13>(s.period);
    r.tbl_period = lx::uint<13>(s.tbl_period);
    r.ratio = lx::uint<37>(s.ratio);
    r.comp_offset = lx::sint<64>(s.comp_offset);
    r.glitch_n = lx::uint<8>(s.glitch_n);
    r.sw_debounce = lx::uint<16>(s.sw_debounce);
    r.min_spacing = lx::uint<16>(s.min_spacing);
    r.pace_m = lx::uint<16>(s.pace_m);
    r.backlog_thr = lx::uint<32>(s.backlog_thr);
    r.mark_len = lx::uint<13>(s.mark_len);
    r.dac_width = lx::uint<5>(s.dac_width);
    r.amplitude = lx::uint<18>(s.amplitude);
    r.rehome = s.rehome;
    r.clear = s.clear;
    r.tbl_we = s.tbl_we;
    r.tbl_addr = lx::uint<10>(s.tbl_addr);
    r.tbl_data = lx::uint<17>(s.tbl_data);
    r.emap.map_en = s.emap.map_en;
    r.emap.bank_sel = s.emap.bank_sel;
    r.emap.geom[0].origin = lx::sint<38>(s.emap.geom[0].origin);
    r.emap.geom[0].spacing_log2 = lx::uint<5>(s.emap.geom[0].spacing_log2);
    r.emap.geom[0].n_points = lx::uint<11>(s.emap.geom[0].n_points);
    r.emap.geom[1].origin = lx::sint<38>(s.emap.geom[1].origin);
    r.emap.geom[1].spacing_log2 = lx::uint<5>(s.emap.geom[1].spacing_log2);
    r.emap.geom[1].n_points = lx::uint<11>(s.emap.geom[1].n_points);
    r.emap.we = s.emap.we;
    r.emap.addr = lx::uint<10>(s.emap.addr);
    r.emap.data = lx::sint<24>(s.emap.data);
    r.comp_sync = s.comp_sync;
    r.comp_commit = s.comp_commit;
    r.pin_cfg = lx::uint<4>(s.pin_cfg);
    return r;
}

golden::axis_regs to_golden(const axis_settings& s) {
    golden::axis_regs g;
    convert(g.period, s.period);
    convert(g.tbl_period, s.tbl_period);
    convert(g.ratio, s.ratio);
    convert(g.comp_offset, s.comp_offset);
    convert(g.glitch_n, s.glitch_n);
    convert(g.sw_debounce, s.sw_debounce);
    convert(g.min_spacing, s.min_spacing);
    convert(g.pace_m, s.pace_m);
    convert(g.backlog_thr, s.backlog_thr);
    convert(g.mark_len, s.mark_len);
    convert(g.dac_width, s.dac_width);
    convert(g.amplitude, s.amplitude);
    convert(g.rehome, s.rehome);
    convert(g.clear, s.clear);
    convert(g.tbl_we, s.tbl_we);
    convert(g.emap.map_en, s.emap.map_en);
    convert(g.emap.bank_sel, s.emap.bank_sel);
    convert(g.emap.geom[0].origin, s.emap.geom[0].origin);
    convert(g.emap.geom[0].spacing_log2, s.emap.geom[0].spacing_log2);
    convert(g.emap.geom[0].n_points, s.emap.geom[0].n_points);
    convert(g.emap.geom[1].origin, s.emap.geom[1].origin);
    convert(g.emap.geom[1].spacing_log2, s.emap.geom[1].spacing_log2);
    convert(g.emap.geom[1].n_points, s.emap.geom[1].n_points);
    convert(g.emap.we, s.emap.we);
    convert(g.emap.addr, s.emap.addr);
    convert(g.emap.data, s.emap.data);
    convert(g.comp_sync, s.comp_sync);
    convert(g.comp_commit, s.comp_commit);
    convert(g.pin_cfg, s.pin_cfg);
    return g;
}

axis_settings settings_from(const golden::axis_regs& g) {
    axis_settings s;
    convert(s.period, g.period);
    convert(s.tbl_period, g.tbl_period);
    convert(s.ratio, g.ratio);
    convert(s.comp_offset, g.comp_offset);
    convert(s.glitch_n, g.glitch_n);
    convert(s.sw_debounce, g.sw_debounce);
    convert(s.min_spacing, g.min_spacing);
    convert(s.pace_m, g.pace_m);
    convert(s.backlog_thr, g.backlog_thr);
    convert(s.mark_len, g.mark_len);
    convert(s.dac_width, g.dac_width);
    convert(s.amplitude, g.amplitude);
    convert(s.rehome, g.rehome);
    convert(s.clear, g.clear);
    convert(s.tbl_we, g.tbl_we);
    convert(s.emap.map_en, g.emap.map_en);
    convert(s.emap.bank_sel, g.emap.bank_sel);
    convert(s.emap.geom[0].origin, g.emap.geom[0].origin);
    convert(s.emap.geom[0].spacing_log2, g.emap.geom[0].spacing_log2);
    convert(s.emap.geom[0].n_points, g.emap.geom[0].n_points);
    convert(s.emap.geom[1].origin, g.emap.geom[1].origin);
    convert(s.emap.geom[1].spacing_log2, g.emap.geom[1].spacing_log2);
    convert(s.emap.geom[1].n_points, g.emap.geom[1].n_points);
    convert(s.emap.we, g.emap.we);
    convert(s.emap.addr, g.emap.addr);
    convert(s.emap.data, g.emap.data);
    convert(s.comp_sync, g.comp_sync);
    convert(s.comp_commit, g.comp_commit);
    convert(s.pin_cfg, g.pin_cfg);
    return s;
}

}  // namespace lxt
