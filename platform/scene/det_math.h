// Elementary functions from IEEE basic operations only (+, −, ×, ÷, floor, frexp/ldexp), for
// the scene generators: libm's exp/log/sin/cos may differ in the last ulp between libraries,
// which could flip a rounded grey level, so a (scene, seed) pair would not give the same bytes
// on every platform. Compile with -ffp-contract=off (quadtrack_scene does).
#pragma once

namespace qt::scene {

constexpr double kPi = 3.14159265358979323846;

double det_exp(double x);                         // accurate to ~1e-15 relative for |x| < 700
double det_log(double x);                         // x > 0
void det_sincos(double x, double& s, double& c);  // x in radians, |x| < 1e6
inline double det_radians(double deg) { return deg * kPi / 180.0; }

}  // namespace qt::scene
