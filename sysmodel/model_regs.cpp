// model_regs.cpp — see model_regs.h.
#include "sysmodel/model_regs.h"

namespace lxt {

namespace rm = regmap;

// The host library sizes the error-map banks from the register map; the core holds that many.
static_assert(kMapDepth == lx::error_map_cfg::TBL_DEPTH, "map_n0 max differs from the core's table depth");

reg_image image_from(const lx::axis_regs& r) {
    reg_image img;
    for (int i = 0; i < rm::kNumRegs; ++i) img.set(i, rm::get(r, i));  // always fits: same widths
    return img;
}

bool image_from(const golden::axis_regs& r, reg_image* img, std::string* err) {
    reg_image out;
    for (int i = 0; i < rm::kNumRegs; ++i) {
        int64_t v = 0;
        if (!rm::get(r, i, &v)) continue;  // golden has no such register
        if (!out.set(i, v)) {
            if (err)
                *err = std::string("golden::axis_regs::") + rm::kRegs[i].golden_member + " = " +
                       std::to_string(static_cast<long long>(v)) + " does not fit register " + rm::kRegs[i].name + " (" +
                       range_text(rm::kRegs[i]) + ")";
            return false;
        }
    }
    *img = out;
    return true;
}

lx::axis_regs hls_from(const reg_image& img) {
    lx::axis_regs r;
    for (int i = 0; i < rm::kNumRegs; ++i) rm::set(r, i, img.get(i));
    return r;
}

golden::axis_regs golden_from(const reg_image& img) {
    golden::axis_regs r;
    for (int i = 0; i < rm::kNumRegs; ++i) rm::set(r, i, img.get(i));  // false for registers golden lacks
    return r;
}

}  // namespace lxt
