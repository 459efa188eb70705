// Side refinement of a detected quadrangle: each side refitted by total least squares to the
// edge points that lie along it between its corners, with the side's contrast polarity, and
// the corners moved to the refitted sides' crossings.
//
// Why: the quadrangle rules pick four clustered lines, and on a real background a side's best
// line can be a short segment of it bent by the background's edges (a line 3 px off at one end
// moves the far corner by several pixels), or stop short where the background takes over.
// The quadrangle itself says where each side runs: from corner to corner. Refitting there,
// with every edge point of the side (not only those of one PPHT segment), is what gives
// sub-pixel corners on cluttered frames.
//
// Per side, twice: the points within `band` px of the current line (first pass: the side
// between its corners; second: the first fit, with `fine_band`), whose gradient direction is
// within ±2 bins (±45°) of the side's own (dark to bright across it, from the line's
// polarity), skipping `end_margin` px at each corner where the two sides' gradients mix. A
// side with points on fewer than `min_share_percent` % of its steps (an occluded side) keeps
// its line. Work: (2·band + 1) edge-list lookups per pixel of perimeter, twice.
#pragma once
#include <stdint.h>

#include "base/setting_range.h"
#include "lines/edge_list.h"
#include "lines/segment.h"
#include "quads/quad_detector.h"

namespace qt {

struct RefineParams {
    // First pass: half width of the search, px. 0: no refinement — each side stays the line
    // the rules chose, its evidence gathered within fine_band of it (the paper's quadrangle).
    q16_16 band = q16_16::from_ratio(5, 2);
    q16_16 fine_band = q16_16::from_int(1);   // second pass, px
    q16_16 end_margin = q16_16::from_int(3);  // skipped at each corner along the side, px
    uint8_t min_share_percent = 25;  // steps of the side that must hold a point to refit, %
    // A candidate whose corners all lie within this of a quadrangle already kept is that
    // quadrangle again (the same board from other lines): not refined a second time, px.
    q16_16 duplicate_distance = q16_16::from_int(6);
    // Verification: a quadrangle is kept when each side shows next to both its corners and has
    // edge evidence on at least min_side_evidence_percent of its steps (a completed side, see
    // detect_quads: min_hidden_side_evidence_percent), and the four together on
    // min_evidence_percent. Each at kCheckOff: that check is not made (the side's, with its
    // corners; all three off keeps every candidate, scored by its evidence all the same).
    uint8_t min_side_evidence_percent = 30;
    uint8_t min_hidden_side_evidence_percent = 20;
    uint8_t min_evidence_percent = 60;
    // The inside (quad_interior.h): a kept quadrangle has at most this share of the 2 × 2 px
    // cells inside it holding an edge point farther than inside_margin from its sides, % at
    // 240 rows (scaled by √(240 / rows)). kCheckOff: not tested (a board showing projected or
    // printed content with strong edges).
    uint8_t max_inside_edge_cells_percent = 16;
    q16_16 inside_margin = q16_16::from_int(4);  // px
    // A kept quadrangle is crossed by at most this many lines of the line list, each inside it
    // over at least half its shortest side (quad_interior.h, count_lines_across); kCheckOff: not
    // tested (a board seen through a grid, a window's bars).
    uint8_t max_lines_across = 2;
    // A kept quadrangle has at most this many corners where both its sides run on
    // (junction_corners); kCheckOff: not tested.
    uint8_t max_junction_corners = 1;
};

// RefineParams' units and accepted ranges (base/setting_range.h); the limits marked can_be_off
// switch their check off at kCheckOff.
struct RefineRanges {
    SettingRange band{"px", 0, 8};
    SettingRange fine_band{"px", 5, 80, 1};  // 0.5..8
    SettingRange min_side_evidence_percent{"%", 0, 100, 0, true};
    SettingRange min_hidden_side_evidence_percent{"%", 0, 100, 0, true};
    SettingRange min_evidence_percent{"%", 0, 100, 0, true};
    SettingRange max_inside_edge_cells_percent{"%", 0, 100, 0, true};
    SettingRange inside_margin{"px", 0, 16};
    SettingRange max_lines_across{"lines", 0, 254, 0, true};
    SettingRange max_junction_corners{"corners", 0, 3, 0, true};
};
inline constexpr RefineRanges kRefineRanges{};

// The edge evidence of a quadrangle's sides: per side, the steps along it (pixels of its major
// axis between the end margins) and those holding an edge point of the side's polarity within
// fine_band of the refitted line (of the given line when it was not refitted; a step between
// two such steps counts too, as a full edge list thins weak edges to every other step), and whether
// some step within the first and within the last quarter of them held one (bit 0, bit 1: the
// side shows next to both its corners).
struct SideEvidence {
    uint16_t steps[4];
    uint16_t held[4];
    uint8_t ends[4];
};

// Refines `quad` (detect_quads() order; side i on *lines[i]) in place and writes each side's line
// to sides[i]: refitted (its extent the old line's end points projected onto it) or, when too few
// points were found, the old line. Corners are re-put in detect's order (smallest x + y first;
// quad.lines, sides and evidence rotate with them). Returns the mask of sides refitted (bit i: side
// i), 0 when nothing changed — then also when the refitted sides no longer make a convex
// quadrangle, in which case quad and sides are those given.
uint8_t refine_quad(const EdgeList& edges, const Segment* const lines[4],
                    const RefineParams& params, Quad& quad, Segment sides[4],
                    SideEvidence* evidence = nullptr);

// refine_quad, then verify_evidence (completed: the sides quad.lines marks kCompletedSide), as
// BoardDetector keeps a candidate: true when it passes, with quad and sides refined and *score
// its share of steps with evidence. A side whose evidence already fails ends
// the work there, false: the sides after it are not walked (on a busy frame most candidates
// fail, and each side costs two walks); quad is then left as given and sides unwritten.
bool refine_verified(const EdgeList& edges, const Segment* const lines[4],
                     const RefineParams& params, Quad& quad, Segment sides[4], q16_16* score);

// The share of the steps with evidence over the four sides, q16_16 in [0, 1]; false when a
// side or the whole falls below the verification limits of `params` that are not kCheckOff.
// completed: bit i when side i was completed rather than found.
bool verify_evidence(const SideEvidence& e, uint8_t completed, const RefineParams& params,
                     q16_16* share);

// The corners of a quadrangle where both sides' lines run on past it: each side's line has
// edge points of either polarity (within fine_band) on at least half the steps of a stretch
// beyond the corner (past end_margin, a quarter of the side long and at least 6 px). A board's
// corner ends both its sides; a checkerboard's square has a crossing at each corner.
uint8_t junction_corners(const EdgeList& edges, const Point16 corners[4],
                         const RefineParams& params);

}  // namespace qt
