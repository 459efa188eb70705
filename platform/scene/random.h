// Uniform and normal deviates in double precision from the project's PCG32, for the synthetic
// scenes and motions (host only). Deterministic for a given seed and stream.
#pragma once
#include <cmath>

#include "base/prng.h"
#include "scene/det_math.h"

namespace qt::scene {

// Uniform in the open interval (0, 1).
inline double uniform01(Pcg32& rng) { return (rng.next() + 0.5) * (1.0 / 4294967296.0); }
// Uniform in (lo, hi).
inline double uniform(Pcg32& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }

// Uniform integer in [lo, hi], lo <= hi.
inline int uniform_int(Pcg32& rng, int lo, int hi) {
    return lo + static_cast<int>(rng.below(static_cast<uint32_t>(hi - lo + 1)));
}

// Standard normal deviates by the polar form of Box-Muller (Marsaglia), in pairs.
class Gaussian {
public:
    explicit Gaussian(Pcg32 rng) : rng_(rng) {}
    double next() {
        if (has_spare_) {
            has_spare_ = false;
            return spare_;
        }
        double u, v, s;
        do {
            u = 2 * uniform01(rng_) - 1;
            v = 2 * uniform01(rng_) - 1;
            s = u * u + v * v;
        } while (s >= 1 || s == 0);
        const double f = std::sqrt(-2 * det_log(s) / s);
        spare_ = v * f;
        has_spare_ = true;
        return u * f;
    }

private:
    Pcg32 rng_;
    double spare_ = 0;
    bool has_spare_ = false;
};

}  // namespace qt::scene
