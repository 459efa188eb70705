#include "scene/det_math.h"

#include <cmath>

namespace qt::scene {

namespace {
constexpr double kLn2 = 0.69314718055994530942;
}  // namespace

double det_exp(double x) {
    const double n = std::floor(x / kLn2 + 0.5);
    const double r = x - n * kLn2;  // |r| <= 0.35
    double sum = 1, term = 1;
    for (int k = 1; k <= 20; ++k) {
        term *= r / k;
        sum += term;
    }
    return std::ldexp(sum, static_cast<int>(n));
}

double det_log(double x) {
    int e = 0;
    double m = std::frexp(x, &e);  // x = m·2^e, m in [0.5, 1), exact
    if (m < 0.70710678118654752) {
        m *= 2;
        --e;
    }
    const double t = (m - 1) / (m + 1), t2 = t * t;  // |t| < 0.172: log m = 2 atanh t
    double s = 0;
    for (int k = 25; k >= 1; k -= 2) s = s * t2 + 1.0 / k;
    return 2 * t * s + e * kLn2;
}

void det_sincos(double x, double& s, double& c) {
    const double r = x - 2 * kPi * std::floor(x / (2 * kPi) + 0.5);  // [-pi, pi]
    const double r2 = r * r;
    double ts = r, tc = 1;
    s = r;
    c = 1;
    for (int k = 1; k <= 16; ++k) {
        ts *= -r2 / ((2 * k) * (2 * k + 1));
        tc *= -r2 / ((2 * k - 1) * (2 * k));
        s += ts;
        c += tc;
    }
}

}  // namespace qt::scene
