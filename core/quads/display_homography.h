// The display homography for the projector use case: the projective map from the display
// rectangle (display pixels, (0, 0) at its top-left corner, width × height) onto a detected
// quadrangle (image pixels), from the four corners alone, in fixed point.
//
//   [x·w]   [a b c] [u]
//   [y·w] = [d e f] [v]      w = g·u + h·v + 1
//   [ w ]   [g h 1] [1]
//
// The square-to-quadrangle solution (Heckbert 1989, "Fundamentals of Texture Mapping",
// §2.2.3) maps the unit square; dividing its first two columns by the display size gives H.
#pragma once
#include <stdint.h>

#include "base/fixed.h"
#include "base/setting_range.h"
#include "quads/quad_rules.h"

namespace qt {

using q12_20 = Fixed<20, int32_t>;  // range ±2048, step ~1e-6

struct DisplayHomography {
    q12_20 a, b, d, e;  // image px per display px
    q16_16 c, f;        // image px: where display (0, 0) lands
    q2_30 g, h;         // 1 / display px
};

// H mapping display (0,0), (W,0), (W,H), (0,H) onto the quadrangle's top-left, top-right,
// bottom-right and bottom-left corners — corners[0], [3], [2], [1] in quad_rules.h's order.
// False (and h untouched) for a display size of 0, corners beyond ±2048 px, or a quadrangle
// so degenerate (three corners nearly collinear) that g or h would leave its format.
bool display_homography(const Point16 corners[4], uint16_t display_width, uint16_t display_height,
                        DisplayHomography& h);

// The display's width and height, display px (base/setting_range.h).
inline constexpr SettingRange kDisplaySizeRange{"display px", 1, 4096};

// Image point of display point (u, v), pixels, |u|, |v| <= 4096. False outside that range or
// when (u, v) maps to infinity (w <= 2^-20, the far side of the horizon line).
bool map_display_point(const DisplayHomography& h, q16_16 u, q16_16 v, Point16& out);

}  // namespace qt
