// Homographies in double precision for generated frame pairs (the tests and the bench of
// core/target/float/homography.h): applying, multiplying, scaling to h9 = 1, and a plausible random
// motion between two frames. Row-major, (x', y', w') = H (x, y, 1); host only.
#pragma once
#include <array>

#include "base/prng.h"

namespace qt::scene {

using Homography64 = std::array<double, 9>;

struct Point64 {
    double x, y;  // px
};

Point64 apply64(const Homography64& h, double x, double y);
Homography64 mul64(const Homography64& a, const Homography64& b);  // a·b: b first
Homography64 normalised64(Homography64 h);                         // scaled to h[8] = 1

// A camera's motion between two frames of width × height px, about the frame's centre:
// rotation within ±3°, scale 0.97–1.03, translation within ±10 px, perspective terms within
// ±1e-4 /px. Normalised to h[8] = 1.
Homography64 random_inter_frame_motion(Pcg32& rng, double width, double height);

}  // namespace qt::scene
