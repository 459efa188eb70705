// The geometry of quadrangle candidates and the five rules of section 2.4 of the Quadrangle
// Detection paper, each a separate function so that each can be tested on hand-worked cases. Fixed
// point only.
//
// Conventions: pixels with the origin at the centre of pixel (0, 0), x right, y down.
// A quadrangle's corners run ANTI-CLOCKWISE AS SEEN IN THE IMAGE, starting with the corner of
// smallest x + y. For a board turned by less than 45° that is: top-left, bottom-left,
// bottom-right, top-right, so side 0 is the left side, 1 the bottom, 2 the right, 3 the top.
// In y-down coordinates this order has a negative shoelace sum Σ (x_i·y_{i+1} − x_{i+1}·y_i).
#pragma once
#include <stdint.h>

#include "base/angle.h"
#include "base/fixed.h"
#include "base/setting_range.h"
#include "lines/segment.h"

namespace qt {

struct Point16 {
    q16_16 x, y;  // pixels
};

// Which side of the board's outline is brighter (the board is a white surface in the paper).
enum class Contrast : uint8_t {
    bright_board,  // every side has the brighter side inside (the default)
    dark_board,    // every side has the darker side inside
    any,           // polarity not checked
};

// Tolerances of the five rules, every one with its unit. The defaults admit a board tilted up
// to 40° out of the image plane and turned up to 30° in it (docs/quadrangles.md).
struct QuadParams {
    // Rule 1: opposite sides almost parallel — largest angle between them, degrees.
    angle_t parallel_tolerance = angle_from_deg(34);
    // Rule 2: adjacent sides almost perpendicular — largest deviation from 90°, degrees.
    angle_t perpendicular_tolerance = angle_from_deg(35);
    // Rule 3: corners inside the image — at least this far inside the frame's outer pixel
    // edges (the frame spans [-0.5, width - 0.5] × [-0.5, height - 0.5]), pixels.
    q16_16 corner_margin = q16_16::from_int(0);
    // Rule 4: every side (corner to corner) between these lengths, pixels; a shortest side of
    // 0 stands for a tenth of the frame height (detect_quads).
    q16_16 min_side_length = q16_16::from_int(0);
    q16_16 max_side_length = q16_16::from_int(2048);
    // Rule 5: the display area's aspect, width / height, and the largest factor by which the
    // measured ratio (mean of top and bottom sides) / (mean of left and right sides) may
    // differ from it, either way. Perspective alone moves the ratio by up to 1/cos(tilt).
    q16_16 display_aspect = q16_16::from_ratio(4, 3);
    q16_16 aspect_tolerance = q16_16::from_ratio(9, 5);
    // ... and the larger factor allowed when the quadrangle shows the perspective that a tilt
    // strong enough for it brings: a pair of opposite sides converging by at least
    // perspective_convergence. Why: a 1:1 or 16:9 board tilted up to 35° can read beyond 1.8
    // off the 4:3 display, and its sides then converge (tests/quads/test_quad_rules.cpp samples
    // the photo bench's poses; the bench prints its boards' factors and convergence), whereas a
    // band cut out of a board by two bars across it, whose edges are parallel, gets no such
    // allowance. Below aspect_tolerance it is not used.
    q16_16 tilted_aspect_tolerance = q16_16::from_ratio(11, 5);
    angle_t perspective_convergence = angle_from_deg(4);
    // Support: each side must be covered by segments over at least this fraction of its length
    // (a quadrangle from four lines whose segments lie elsewhere is not a board). Every line
    // with both ends within collinear_distance pixels of the side's line counts, so a side cut
    // in two by an occluder keeps both pieces.
    q16_16 min_side_coverage = q16_16::from_ratio(1, 5);
    q16_16 collinear_distance = q16_16::from_int(2);
    // ... and the four together at least this fraction of the perimeter (the score), [0, 1].
    q16_16 min_score = q16_16::from_ratio(1, 2);
    // Beyond the paper: the sides' contrast polarity must agree with the board being brighter
    // (or darker) than its surroundings. Quadrangles made of sides of different objects rarely
    // pass this, which is what keeps false detections on cluttered frames down.
    Contrast contrast = Contrast::bright_board;
    // Beyond the paper: a side hidden along most of its length is completed from the two
    // sides next to it (detect_quads), then must show edge evidence of its own (quad_refine.h).
    bool complete_hidden_side = true;
};

// QuadParams' units and accepted ranges (base/setting_range.h); aspects and coverages are
// factors and fractions, without a unit.
struct QuadRanges {
    SettingRange parallel_tolerance{"degrees", 0, 45};
    SettingRange perpendicular_tolerance{"degrees", 0, 60};
    SettingRange corner_margin{"px", 0, 1000};
    SettingRange min_side_length{"px", 0, 2048};
    SettingRange max_side_length{"px", 1, 2048};
    SettingRange aspect_tolerance{"", 1, 10};
    SettingRange tilted_aspect_tolerance{"", 1, 10};
    SettingRange perspective_convergence{"degrees", 0, 90};
    SettingRange min_side_coverage{"", 0, 1};
    SettingRange collinear_distance{"px", 0, 100};
    SettingRange min_score{"", 0, 1};
};
inline constexpr QuadRanges kQuadRanges{};

// The parameters with the frame-size defaults filled in for a frame `height` px tall: a
// min_side_length of 0 becomes a tenth of the height (at least 1 px).
QuadParams sized_quad_params(const QuadParams& p, uint16_t height);

// Orientation of the line through a segment's normal angle, modulo 180°.
angle_t line_orientation(const Segment& s);

// Rule 1: the lines' orientations differ by at most parallel_tolerance (modulo 180°).
bool rule_parallel(angle_t theta_a, angle_t theta_b, const QuadParams& p);
// Rule 2: the lines' orientations differ from 90° by at most perpendicular_tolerance.
bool rule_perpendicular(angle_t theta_a, angle_t theta_b, const QuadParams& p);
// Rule 3: every corner lies inside the frame, corner_margin pixels in from its outer edges.
bool rule_corners_inside(const Point16 corners[4], uint16_t width, uint16_t height,
                         const QuadParams& p);
// Rule 4: every side length in [min_side_length, max_side_length].
bool rule_side_lengths(const q16_16 sides[4], const QuadParams& p);
// Rule 5: with sides in the corner order above (0 left, 1 bottom, 2 right, 3 top), the ratio
// (s1 + s3) / (s0 + s2) lies within [display_aspect / tol, display_aspect · tol], tol the
// larger of aspect_tolerance and tilted_aspect_tolerance when `convergence` (the larger
// orientation difference of the two pairs of opposite sides, opposite_convergence) is at least
// perspective_convergence, aspect_tolerance otherwise.
bool rule_aspect(const q16_16 sides[4], angle_t convergence, const QuadParams& p);
// The larger orientation difference of the quadrangle's opposite sides (lines[0] with
// lines[2], lines[1] with lines[3]), [0, 90°].
angle_t opposite_convergence(const Segment* const lines[4]);

// Contrast: with corners in any order and side i on line sides[i] (normal sin_cos(theta) in
// normals[i]), each line's bright_side puts the quadrangle's interior (its corners' mean) on
// the side p.contrast asks for. Lines of unknown polarity (bright_side 0) pass.
bool rule_contrast(const Point16 corners[4], const Segment* const sides[4], const SinCos normals[4],
                   const QuadParams& p);

// Signed distance of the point (x, y) (q16_16 raw, |x|, |y| <= 16384 px) from `line`, whose
// normal `normal` = sin_cos(line.theta) the caller computes once: n·p − rho, pixels, q16_16
// raw, positive on the +normal side. Inline: the support of each candidate side asks it of
// every line's ends.
inline int64_t signed_distance(const Segment& line, SinCos normal, int64_t x, int64_t y) {
    // Each product below 2^30 · 2^30: the sum fits easily.
    return shr_round_half_away(x * normal.cos.raw + y * normal.sin.raw, 30) - line.rho.raw;
}

// Where two lines (rho, theta of their normals) cross, pixels. False when they are closer to
// parallel than ~0.06° (|sin| < 2^-10) or the crossing lies beyond ±16384 px.
bool intersect_lines(const Segment& a, const Segment& b, Point16& out);
// The same with the normals sin_cos(a.theta) and sin_cos(b.theta) already computed (a CORDIC
// costs some 300 instructions on a Cortex-M4; detect_quads() computes each line's once).
bool intersect_lines(const Segment& a, SinCos na, const Segment& b, SinCos nb, Point16& out);

// Length of the segment from a to b, pixels, rounded down to 2^-16 px.
q16_16 distance(Point16 a, Point16 b);
// Its square in 2^-32 px² units, below 2^63 (distance() is its integer square root): to
// compare lengths without the root.
uint64_t distance2(Point16 a, Point16 b);

// Twice the signed area, Σ (x_i·y_{i+1} − x_{i+1}·y_i), in px² (q16_16 squared = 2^-32 px²
// units); negative for anti-clockwise as seen in the image.
int64_t shoelace2(const Point16 corners[4]);

// True when the four corners form a strictly convex quadrangle (either winding).
bool is_convex(const Point16 corners[4]);

// Length of segment s's overlap with the side a -> b, measured along the side, pixels in
// [0, |ab|]: s's end points are projected onto the side and the interval clipped to it.
q16_16 side_overlap(Point16 a, Point16 b, const Segment& s);

}  // namespace qt
