// golden/input_filter.cpp — see input_filter.h (DESIGN.md 4.1, golden definition).
#include "golden/input_filter.h"

namespace golden {

void input_filter::reset() { *this = input_filter{}; }

}  // namespace golden
