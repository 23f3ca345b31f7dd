// regmap_table.cpp — see regmap_table.h.
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
#include "host/regmap_table.h"

#include <cstring>

namespace lxt {
namespace regmap {

namespace {
template <typename T>
void assign(T& dst, int64_t v) {
    dst = static_cast<T>(v);
}
void assign(bool& dst, int64_t v) { dst = v != 0; }
}  // namespace

int find(const char* name) {
    for (int i = 0; i < kNumRegs; ++i)
        if (std::strcmp(kRegs[i].name, name) == 0) return i;
    return -1;
}

int64_t get(const axis_settings& s, int i) {
    switch (i) {
        case idx::period: return static_cast<int64_t>(s.period);
        case idx::tbl_period: return static_cast<int64_t>(s.tbl_period);
        case idx::ratio: return static_cast<int64_t>(s.ratio);
        case idx::comp_offset: return static_cast<int64_t>(s.comp_offset);
        case idx::glitch_n: return static_cast<int64_t>(s.glitch_n);
        case idx::sw_debounce: return static_cast<int64_t>(s.sw_debounce);
        case idx::min_spacing: return static_cast<int64_t>(s.min_spacing);
        case idx::pace_m: return static_cast<int64_t>(s.pace_m);
        case idx::backlog_thr: return static_cast<int64_t>(s.backlog_thr);
        case idx::mark_len: return static_cast<int64_t>(s.mark_len);
        case idx::dac_width: return static_cast<int64_t>(s.dac_width);
        case idx::amplitude: return static_cast<int64_t>(s.amplitude);
        case idx::rehome: return s.rehome ? 1 : 0;
        case idx::clear: return s.clear ? 1 : 0;
        case idx::tbl_we: return s.tbl_we ? 1 : 0;
        case idx::tbl_addr: return static_cast<int64_t>(s.tbl_addr);
        case idx::tbl_data: return static_cast<int64_t>(s.tbl_data);
        case idx::map_en: return s.emap.map_en ? 1 : 0;
        case idx::bank_sel: return s.emap.bank_sel ? 1 : 0;
        case idx::map_origin0: return static_cast<int64_t>(s.emap.geom[0].origin);
        case idx::map_k0: return static_cast<int64_t>(s.emap.geom[0].spacing_log2);
        case idx::map_n0: return static_cast<int64_t>(s.emap.geom[0].n_points);
        case idx::map_origin1: return static_cast<int64_t>(s.emap.geom[1].origin);
        case idx::map_k1: return static_cast<int64_t>(s.emap.geom[1].spacing_log2);
        case idx::map_n1: return static_cast<int64_t>(s.emap.geom[1].n_points);
        case idx::map_we: return s.emap.we ? 1 : 0;
        case idx::map_addr: return static_cast<int64_t>(s.emap.addr);
        case idx::map_data: return static_cast<int64_t>(s.emap.data);
        case idx::comp_sync: return s.comp_sync ? 1 : 0;
        case idx::comp_commit: return s.comp_commit ? 1 : 0;
        case idx::pin_cfg: return static_cast<int64_t>(s.pin_cfg);
        default: return 0;
    }
}

bool set(axis_settings& s, int i, int64_t value) {
    if (i < 0 || i >= kNumRegs || !fits(kRegs[i], value)) return false;
    switch (i) {
        case idx::period: assign(s.period, value); return true;
        case idx::tbl_period: assign(s.tbl_period, value); return true;
        case idx::ratio: assign(s.ratio, value); return true;
        case idx::comp_offset: assign(s.comp_offset, value); return true;
        case idx::glitch_n: assign(s.glitch_n, value); return true;
        case idx::sw_debounce: assign(s.sw_debounce, value); return true;
        case idx::min_spacing: assign(s.min_spacing, value); return true;
        case idx::pace_m: assign(s.pace_m, value); return true;
        case idx::backlog_thr: assign(s.backlog_thr, value); return true;
        case idx::mark_len: assign(s.mark_len, value); return true;
        case idx::dac_width: assign(s.dac_width, value); return true;
        case idx::amplitude: assign(s.amplitude, value); return true;
        case idx::rehome: assign(s.rehome, value); return true;
        case idx::clear: assign(s.clear, value); return true;
        case idx::tbl_we: assign(s.tbl_we, value); return true;
        case idx::tbl_addr: assign(s.tbl_addr, value); return true;
        case idx::tbl_data: assign(s.tbl_data, value); return true;
        case idx::map_en: assign(s.emap.map_en, value); return true;
        case idx::bank_sel: assign(s.emap.bank_sel, value); return true;
        case idx::map_origin0: assign(s.emap.geom[0].origin, value); return true;
        case idx::map_k0: assign(s.emap.geom[0].spacing_log2, value); return true;
        case idx::map_n0: assign(s.emap.geom[0].n_points, value); return true;
        case idx::map_origin1: assign(s.emap.geom[1].origin, value); return true;
        case idx::map_k1: assign(s.emap.geom[1].spacing_log2, value); return true;
        case idx::map_n1: assign(s.emap.geom[1].n_points, value); return true;
        case idx::map_we: assign(s.emap.we, value); return true;
        case idx::map_addr: assign(s.emap.addr, value); return true;
        case idx::map_data: assign(s.emap.data, value); return true;
        case idx::comp_sync: assign(s.comp_sync, value); return true;
        case idx::comp_commit: assign(s.comp_commit, value); return true;
        case idx::pin_cfg: assign(s.pin_cfg, value); return true;
        default: return false;
    }
}

}  // namespace regmap
}  // namespace lxt
