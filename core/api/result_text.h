// The one text form of the chain's results, shared by the host (golden files written by
// qt_vectors) and the firmware (semihosting output), so the two can be compared byte for byte.
// Numbers are raw fixed-point integers in decimal; fields are space separated; every line ends
// with a newline. A frame is:
//   frame NAME edges E segments S lines L     header: edge points, PPHT segments, lines
//   x1 y1 x2 y2 rho theta cx cy points bright_side     one per line (format_line_text):
//       x1 y1 x2 y2 rho, cx cy  q16_16 pixels (value / 65536)
//       theta                   binary angle (value · 360 / 2^32 degrees)
//       points                  edge points
//       bright_side             +1 / -1 / 0, the contrast polarity (segment.h)
// and, when the frame went through the quadrangle rules and the tracker (the chain vectors):
//   quads Q status STATUS                    quadrangles found; the detector's status_name()
//   quad x0 y0 x1 y1 x2 y2 x3 y3 score l0 l1 l2 l3     one per quadrangle, best first:
//       corners q16_16 px in detect's order, score q16_16 (0..1), l = indices into the lines
//   track STATE ID AGE DETECTED LOST [x0 y0 x1 y1 x2 y2 x3 y3]     the tracker's output:
//       STATE none|started|tracking, ID and AGE decimal, DETECTED the per-side bit mask,
//       LOST the lost reason's name (quad_track_lost_name) or -, corners unless STATE is none
// No printf: the firmware has none.
#pragma once
#include <stddef.h>

#include "base/status.h"
#include "lines/segment.h"
#include "quads/quad_detector.h"
#include "tracking/quad_tracker.h"

namespace qt {

constexpr size_t kLineTextMax = 112;    // longest line/header with its newline and terminating 0
constexpr size_t kResultTextMax = 200;  // longest quads/quad/track line, likewise

// Writes the text of `s` and a terminating 0 into out (at least kLineTextMax bytes); returns
// the length without the 0.
size_t format_line_text(const Segment& s, char* out);

// The header line of a frame (name up to 40 characters) into out (kLineTextMax bytes).
size_t format_frame_header(const char* name, uint32_t edges, uint32_t segments, uint32_t lines,
                           char* out);

// "quads Q status STATUS" into out (kResultTextMax bytes).
size_t format_quads_header(uint16_t quads, Status status, char* out);

// One quadrangle into out (kResultTextMax bytes).
size_t format_quad_text(const Quad& q, char* out);

// The tracker's output for a frame and the reason a track ended in it (QuadTrackStats::
// lost_reason) into out (kResultTextMax bytes).
size_t format_track_text(const TrackedQuad& t, QuadTrackLost lost_reason, char* out);

// A frame's whole text, line by line into sink(const char* text, size_t length): the header,
// the lines, the quadrangles and the track. `det` is a BoardDetector (board_detector.h) after
// finish(), which returned `status`.
template <class Detector, class Sink>
void write_frame_text(const char* name, const Detector& det, Status status,
                      const TrackedQuad& track, QuadTrackLost lost_reason, Sink&& sink) {
    char text[kResultTextMax];
    const auto& lines = det.lines();
    sink(text, format_frame_header(name, lines.stats().edges, lines.segment_count(),
                                   lines.line_count(), text));
    for (uint16_t i = 0; i < lines.line_count(); ++i)
        sink(text, format_line_text(lines.lines()[i], text));
    sink(text, format_quads_header(det.quad_count(), status, text));
    for (uint16_t i = 0; i < det.quad_count(); ++i)
        sink(text, format_quad_text(det.quads()[i], text));
    sink(text, format_track_text(track, lost_reason, text));
}

}  // namespace qt
