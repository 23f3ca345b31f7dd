// laserax_axil_call.h — host-side (testbench) helper: calls the synthesis top laserax_axil(),
// whose arguments are one scalar per register, with the registers of an lx::axis_regs. Header-only
// and built on hls/ and the standard library only, so it compiles in the Vitis C simulation too.
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
#ifndef LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H
#define LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H

#include "hls/laserax_axil.h"

namespace lxt {

inline void laserax_axil_regs(bool a, bool b, bool sw, bool lerr, const lx::axis_regs& r, lx::axis_out& out) {
    laserax_axil(a, b, sw, lerr,
                r.period,
                r.tbl_period,
                r.ratio,
                r.comp_offset,
                r.glitch_n,
                r.sw_debounce,
                r.min_spacing,
                r.pace_m,
                r.backlog_thr,
                r.mark_len,
                r.dac_width,
                r.amplitude,
                r.rehome,
                r.clear,
                r.tbl_we,
                r.tbl_addr,
                r.tbl_data,
                r.emap.map_en,
                r.emap.bank_sel,
                r.emap.geom[0].origin,
                r.emap.geom[0].spacing_log2,
                r.emap.geom[0].n_points,
                r.emap.geom[1].origin,
                r.emap.geom[1].spacing_log2,
                r.emap.geom[1].n_points,
                r.emap.we,
                r.emap.addr,
                r.emap.data,
                r.comp_sync,
                r.comp_commit,
                out);
}

}  // namespace lxt

#endif  // LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H
