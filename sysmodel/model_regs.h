// model_regs.h — the host register image (host/regmap.h) and the model register structs: the
// image of an lx::axis_regs or golden::axis_regs and back. System-model / testbench code: the host
// library (host/) knows neither model (its settings type is lxt::axis_settings).
#ifndef LASERAX_SYSMODEL_MODEL_REGS_H
#define LASERAX_SYSMODEL_MODEL_REGS_H

#include <string>

#include "golden/laserax_top.h"
#include "hls/laserax_top.h"
#include "host/regmap.h"
#include "sysmodel/regmap_models.h"

namespace lxt {

reg_image image_from(const lx::axis_regs& r);
// false (and a message naming the register) if a golden member holds a value outside its register.
bool image_from(const golden::axis_regs& r, reg_image* img, std::string* err = nullptr);
lx::axis_regs hls_from(const reg_image& img);
golden::axis_regs golden_from(const reg_image& img);  // registers golden lacks are not carried

}  // namespace lxt

#endif  // LASERAX_SYSMODEL_MODEL_REGS_H
