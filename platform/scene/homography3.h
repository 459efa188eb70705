// 3×3 homographies in double, row-major (h[8] need not be 1): the truth's plane maps of the
// generated sequences (ground_sequence.h) and what the benches do with them.
#pragma once

namespace qt::scene {

// (u, v) = h·(x, y, 1), dehomogenised.
inline void apply(const double h[9], double x, double y, double& u, double& v) {
    const double w = h[6] * x + h[7] * y + h[8];
    u = (h[0] * x + h[1] * y + h[2]) / w;
    v = (h[3] * x + h[4] * y + h[5]) / w;
}

// r = the adjugate of m: its inverse up to scale, which a homography does not mind.
inline void invert(const double m[9], double r[9]) {
    r[0] = m[4] * m[8] - m[5] * m[7];
    r[1] = m[2] * m[7] - m[1] * m[8];
    r[2] = m[1] * m[5] - m[2] * m[4];
    r[3] = m[5] * m[6] - m[3] * m[8];
    r[4] = m[0] * m[8] - m[2] * m[6];
    r[5] = m[2] * m[3] - m[0] * m[5];
    r[6] = m[3] * m[7] - m[4] * m[6];
    r[7] = m[1] * m[6] - m[0] * m[7];
    r[8] = m[0] * m[4] - m[1] * m[3];
}

// r = a·b (r may not alias a or b).
inline void multiply(const double a[9], const double b[9], double r[9]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

}  // namespace qt::scene
