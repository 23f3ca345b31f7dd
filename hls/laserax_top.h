// laserax_top.h — declaration of the synthesis top (see laserax_top.cpp).
#ifndef LASERAX_HLS_LASERAX_TOP_H
#define LASERAX_HLS_LASERAX_TOP_H

#include "hls/axis_core.h"

void laserax_top(bool a, bool b, bool sw, bool lerr, const lx::axis_regs& regs, lx::axis_out& out);

#endif
