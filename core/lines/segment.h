// A straight line segment found in a frame, in fixed point. Coordinates in pixels with the
// origin at the centre of pixel (0, 0), x to the right, y down.
#pragma once
#include <stdint.h>

#include "base/angle.h"
#include "base/fixed.h"

namespace qt {

struct Segment {
    q16_16 x1, y1, x2, y2;  // end points, pixels
    q16_16 rho;             // distance from the origin to the line, pixels, >= 0
    angle_t theta;          // direction of the normal from the origin to the line, [0°, 360°)
                            // (binary angle; y down, so positive angles turn clockwise on screen)
    q16_16 cx, cy;          // closest point of the line to the origin, C = rho·(cos θ, sin θ)
    uint16_t points;        // edge points the segment was fitted to
    int8_t bright_side;     // contrast polarity: +1 when the brighter side lies in the +normal
                            // direction (away from the origin), -1 towards it, 0 unknown
};

}  // namespace qt
