// Total-least-squares line fits in fixed point, shared by PPHT (fit to edge points) and
// clustering (refit of merged segments).
#pragma once
#include <stdint.h>

#include "base/angle.h"
#include "base/fixed.h"
#include "lines/segment.h"

namespace qt {

// Weighted raw moments of points given in 1/32 pixel relative to an anchor. Bounds: with
// |coordinate| <= 2^16 (2048 px) and total weight <= 2^15, every sum stays below 2^63.
struct Moments {
    int64_t n = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;

    void add(int32_t x, int32_t y, int32_t w = 1) {
        n += w;
        sx += static_cast<int64_t>(w) * x;
        sy += static_cast<int64_t>(w) * y;
        sxx += static_cast<int64_t>(w) * x * x;
        syy += static_cast<int64_t>(w) * y * y;
        sxy += static_cast<int64_t>(w) * x * y;
    }
    // The spread of w points spaced evenly along a segment of extent (dx, dy) about its middle:
    // w·(dx, dy)(dx, dy)ᵀ / 12, the second moment of a uniform distribution on the segment.
    void add_spread(int32_t dx, int32_t dy, int32_t w) {
        sxx += static_cast<int64_t>(w) * dx * dx / 12;
        syy += static_cast<int64_t>(w) * dy * dy / 12;
        sxy += static_cast<int64_t>(w) * dx * dy / 12;
    }
};

// A line through a point with a unit direction.
struct FittedLine {
    q16_16 mx, my;  // centroid of the fitted points, pixels
    q2_30 dx, dy;   // unit direction along the line (dx >= 0, or dx == 0 and dy > 0)
};

// Fit to moments whose coordinates are 1/32 pixel relative to (anchor_x32, anchor_y32), also
// in 1/32 pixel. The direction is the principal axis, ½·atan2(2·Sxy, Sxx − Syy), which
// minimises the sum of squared perpendicular distances. Returns false when n == 0.
bool fit_line(const Moments& m, int32_t anchor_x32, int32_t anchor_y32, FittedLine& out);

// Signed position of point (px, py) along the line from its centroid, pixels.
q16_16 along(const FittedLine& line, q16_16 px, q16_16 py);

// The segment of `line` between positions t1 <= t2 along it, with rho, theta and C relative
// to the image origin.
Segment make_segment(const FittedLine& line, q16_16 t1, q16_16 t2, uint16_t points);

}  // namespace qt
