// The one text form of a detected line, shared by the host (golden files written by
// qt_vectors) and the firmware (semihosting output), so the two can be compared byte for byte.
// Fields, space separated, raw fixed-point integers in decimal:
//   x1 y1 x2 y2 rho   q16_16 pixels (value / 65536)
//   theta             binary angle (value · 360 / 2^32 degrees)
//   cx cy             q16_16 pixels
//   points            edge points
//   bright_side       +1 / -1 / 0, the contrast polarity (segment.h)
// and a newline. A frame's lines follow its header line
//   frame NAME edges E segments S lines L
// No printf: the firmware has none.
#pragma once
#include <stddef.h>

#include "segment.h"

namespace qt {

constexpr size_t kLineTextMax = 112;  // longest line with its newline and terminating 0

// Writes the text of `s` and a terminating 0 into out (at least kLineTextMax bytes); returns
// the length without the 0.
size_t format_line_text(const Segment& s, char* out);

// The header line of a frame (name up to 40 characters) into out (kLineTextMax bytes).
size_t format_frame_header(const char* name, uint32_t edges, uint32_t segments, uint32_t lines,
                           char* out);

}  // namespace qt
