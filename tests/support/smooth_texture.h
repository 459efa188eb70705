// A smooth grey-level texture in double precision, for tests that need sub-pixel truth: three
// sinusoids of 0.2–0.5 rad/px in different directions about 128, so within [18, 238]; its second
// derivatives are at most max |f_xx| + max |f_yy| = 27.1 grey levels a px².
#pragma once
#include <cmath>

namespace qt::test {

inline double smooth_texture(double x, double y) {
    return 128 + 50 * std::sin(0.45 * x + 0.15 * y + 0.4) +
           40 * std::sin(-0.2 * x + 0.5 * y + 1.3) + 20 * std::sin(0.3 * x + 0.35 * y + 2.2);
}

}  // namespace qt::test
