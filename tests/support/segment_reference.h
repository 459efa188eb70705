// Test-side construction of core Segments from end points in double precision, independent of
// core's fitting code: the normal form (rho >= 0, theta of the normal) worked out directly.
#pragma once
#include <cmath>
#include <cstdint>

#include "lines/segment.h"

namespace qt::ref {

constexpr double kPi = 3.14159265358979323846;

inline q16_16 to_q16(double px) { return q16_16::from_raw(std::llround(px * 65536.0)); }
inline double from_q16(q16_16 v) { return v.raw / 65536.0; }

// Degrees (any value) to a binary angle, 2^32 units per turn.
inline angle_t angle_deg(double deg) {
    double turns = deg / 360.0;
    turns -= std::floor(turns);
    return static_cast<angle_t>(static_cast<uint64_t>(std::llround(turns * 4294967296.0)) &
                                0xFFFFFFFFu);
}

// The segment (x1, y1) -> (x2, y2), pixels, with `points` edge points.
inline Segment segment(double x1, double y1, double x2, double y2, uint16_t points = 100) {
    const double len = std::hypot(x2 - x1, y2 - y1);
    double nx = -(y2 - y1) / len, ny = (x2 - x1) / len;  // unit normal
    double rho = nx * x1 + ny * y1;
    if (rho < 0) {
        rho = -rho;
        nx = -nx;
        ny = -ny;
    }
    Segment s{};
    s.x1 = to_q16(x1);
    s.y1 = to_q16(y1);
    s.x2 = to_q16(x2);
    s.y2 = to_q16(y2);
    s.rho = to_q16(rho);
    s.theta = angle_deg(std::atan2(ny, nx) * 180.0 / kPi);
    s.cx = to_q16(rho * nx);
    s.cy = to_q16(rho * ny);
    s.points = points;
    return s;
}

}  // namespace qt::ref
