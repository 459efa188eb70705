// Quadrangle detection (section 2.4 of the Quadrangle Detection paper) among clustered lines,
// without trying all N-choose-4 sets: lines are first paired with the lines almost parallel to them
// (rule 1) and far enough apart (rule 4), then each parallel pair is combined with each later pair
// almost perpendicular to it (rule 2). Each combination gives one candidate: its corners are the
// four line intersections, checked against rules 3, 4 and 5 and against support (how much of each
// side its line's segment covers).
//
// Work: N·(N−1)/2 pair tests, then P·(P−1)/2 pair combinations for P parallel pairs. P is
// small for real frames (a board gives 2, clutter a few), but grows as N²/4 in the worst case
// (all lines in two orientations), so P is capped at the workspace's pair capacity: work is
// bounded by N²/2 + C²/2 cheap tests and C²/2 candidate evaluations for capacity C. Pairs past
// the capacity are counted in QuadStats::pairs_dropped and the status is capacity_exceeded.
#pragma once
#include <stdint.h>

#include "base/status.h"
#include "lines/segment.h"
#include "quads/quad_rules.h"

namespace qt {

struct Quad {
    Point16 corners[4];  // anti-clockwise as seen, corner 0 has the smallest x + y (quad_rules.h)
    uint8_t lines[4];    // index into the input lines of the line along side i (corner i -> i + 1),
                         // or kCompletedSide (see detect_quads)
    q16_16 score;        // fraction of the perimeter covered by the four lines' segments, [0, 1];
                         // BoardDetector replaces it by the edge evidence share (quad_refine.h)
};

// Quad::lines of a side that no line found: completed from its neighbours (detect_quads).
constexpr uint8_t kCompletedSide = 255;

// Why candidates were turned down, for tuning the tolerances on real footage.
struct QuadStats {
    uint16_t parallel_pairs = 0;          // pairs passing rule 1 and the rule-4 separation test
    uint16_t pairs_dropped = 0;           // pairs found with the pair capacity full
    uint32_t combinations = 0;            // pair combinations tried
    uint32_t completions = 0;             // (parallel pair, third line) completions tried
    uint32_t rejected_perpendicular = 0;  // rule 2
    uint32_t rejected_shape = 0;          // no four corners, or not convex
    uint32_t rejected_contrast = 0;       // a side's polarity disagrees with QuadParams::contrast
    uint32_t rejected_inside = 0;         // rule 3
    uint32_t rejected_sides = 0;          // rule 4
    uint32_t rejected_aspect = 0;         // rule 5
    uint32_t rejected_support = 0;        // a side covered less than min_side_coverage, or the
                                          // perimeter less than min_score
    uint32_t accepted = 0;                // candidates passing every rule
    uint16_t quads = 0;                   // written to the output (the best `capacity` of them)
    uint16_t rejected_evidence = 0;       // of those, turned down by the edge evidence along their
                                          // sides (board_detector.h, quad_refine.h)
    uint16_t rejected_interior = 0;       // of those, turned down for the edges inside them
                                          // (quad_interior.h)
    uint16_t rejected_across = 0;         // of those, turned down for the lines across them
                                          // (quad_interior.h, count_lines_across)
    uint16_t rejected_junctions = 0;      // of those, turned down for corners where both sides
                                          // run on (quad_refine.h, junction_corners)
};

// One parallel pair: two line indices.
struct LinePair {
    uint8_t a, b;
};

// What detect_quads works out once per line instead of once per candidate: its normal, and
// which lines lie along it (bit j, j < 32: line j has both ends within collinear_distance of
// it, itself included; lines from 32 on, past a QVGA line list, are tested as they come). A
// side's support sums the lines along it, and a busy frame's ~200 candidates would otherwise
// test every line's ends against each of their four sides (about 1 M Cortex-M4 instructions
// on the worst photograph). 12 bytes a line.
struct QuadLine {
    SinCos normal;
    uint32_t collinear;
};

// The memory detect_quads works in and writes to, all the caller's: scratch for pair_capacity
// parallel pairs and for the geometry of every line, room for `capacity` quadrangles, and
// (optionally) for the completed side of each.
struct QuadSearchMemory {
    LinePair* pairs;
    uint16_t pair_capacity;
    QuadLine* geometry;  // n entries
    Quad* out;
    uint16_t capacity;
    Segment* completed = nullptr;  // `capacity` entries, or none: no side is completed
};

// The side from p to q as a line (q16_16 pixels; p != q): its normal, rho and C, no points
// and no polarity (bright_side 0).
Segment line_through(Point16 p, Point16 q);

// Finds quadrangles among lines[0 .. n) (n <= 254) in a width × height frame. Writes the best
// `capacity` distinct candidates (two whose corners all lie within collinear_distance of each other
// are one quadrangle, reported once), highest score first (ties: larger perimeter first, then lower
// line indices), to out[0 .. stats->quads).
//
// With memory.completed and params.complete_hidden_side, a quadrangle may also have one side
// that no line gives, hidden along most of its length (an arm across it) while its corners show:
// for a parallel pair (a, b) and a line c almost perpendicular to both, the side joining the ends
// of a and b farther from c. Its Quad::lines entry is then kCompletedSide and completed[k] holds
// it for out[k] (only its own visible pieces count as its support; the three others need
// theirs). Work: P·N more candidates for P pairs, N lines. Returns bad_size for n > 254 or a zero
// frame size, capacity_exceeded when parallel pairs were dropped (the quads found are still
// valid and written), ok otherwise.
Status detect_quads(const Segment* lines, uint16_t n, uint16_t width, uint16_t height,
                    const QuadParams& params, const QuadSearchMemory& memory, QuadStats* stats);

}  // namespace qt
