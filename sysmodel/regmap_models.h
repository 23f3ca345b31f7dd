// regmap_models.h — the register map (host/regmap_table.h) applied to the model register
// structs: accessors that read or write one register of lx::axis_regs or golden::axis_regs by
// index, and the conversions between them and the host settings struct lxt::axis_settings.
// System-model / testbench code: it joins host/, hls/ and golden/, which never include each other.
//
// GENERATED FILE - do not edit. Source: regmap/laserax_regs.csv. Command: /usr/bin/python3 scripts/gen_regmap.py
#ifndef LASERAX_SYSMODEL_REGMAP_MODELS_H
#define LASERAX_SYSMODEL_REGMAP_MODELS_H

#include <cstdint>

#include "golden/laserax_top.h"
#include "hls/laserax_top.h"
#include "host/regmap_table.h"

namespace lxt {
namespace regmap {

// lx::axis_regs: every register.
int64_t get(const lx::axis_regs& r, int i);
bool set(lx::axis_regs& r, int i, int64_t value);  // false (r unchanged) if value does not fit
// golden::axis_regs: false for registers golden has no member for (golden_member == "").
// get() returns the member as it is (it may lie outside the register's width).
bool get(const golden::axis_regs& r, int i, int64_t* value);
bool set(golden::axis_regs& r, int i, int64_t value);

}  // namespace regmap

// The hls register struct for a golden one (registers golden lacks keep their reset values) or for
// the host settings; member values are truncated to the register widths, as a register write would.
lx::axis_regs to_hls(const golden::axis_regs& s);
lx::axis_regs to_hls(const axis_settings& s);
// The golden register struct for the host settings (members golden lacks are dropped) and back
// (registers golden lacks keep their reset values); members are copied as they are.
golden::axis_regs to_golden(const axis_settings& s);
axis_settings settings_from(const golden::axis_regs& g);

}  // namespace lxt

#endif  // LASERAX_SYSMODEL_REGMAP_MODELS_H
