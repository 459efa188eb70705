#include "scene/plane_motion.h"

#include "scene/det_math.h"
#include "scene/random.h"

namespace qt::scene {

Point64 apply64(const Homography64& h, double x, double y) {
    const double w = h[6] * x + h[7] * y + h[8];
    return {(h[0] * x + h[1] * y + h[2]) / w, (h[3] * x + h[4] * y + h[5]) / w};
}

Homography64 mul64(const Homography64& a, const Homography64& b) {
    Homography64 m{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) m[3 * r + c] += a[3 * r + k] * b[3 * k + c];
    return m;
}

Homography64 normalised64(Homography64 h) {
    const double s = h[8];
    for (double& v : h) v /= s;
    return h;
}

Homography64 random_inter_frame_motion(Pcg32& rng, double width, double height) {
    const double th = det_radians(uniform(rng, -3, 3)), s = uniform(rng, 0.97, 1.03);
    const double tx = uniform(rng, -10, 10), ty = uniform(rng, -10, 10);
    const double g = uniform(rng, -1e-4, 1e-4), k = uniform(rng, -1e-4, 1e-4);
    double sn, cs;
    det_sincos(th, sn, cs);
    const double cx = width / 2, cy = height / 2;
    const Homography64 to_centre = {1, 0, -cx, 0, 1, -cy, 0, 0, 1};
    const Homography64 perspective = {1, 0, 0, 0, 1, 0, g, k, 1};
    const Homography64 turn = {s * cs, -s * sn, 0, s * sn, s * cs, 0, 0, 0, 1};
    const Homography64 back = {1, 0, cx + tx, 0, 1, cy + ty, 0, 0, 1};
    return normalised64(mul64(back, mul64(turn, mul64(perspective, to_centre))));
}

}  // namespace qt::scene
