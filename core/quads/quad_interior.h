// The inside of a quadrangle: how much of it holds edge points, away from its sides, and how
// many lines run across it.
//
// Why: the board is blank — a white card, at most faint print. The rectangles a photograph
// holds by itself (a box's printed face, a book, a poster, a window with a room behind it)
// pass every rule of the outline, but they carry texture inside. The inside is divided into
// cells of 2 × 2 px, and the cells holding an edge point of the frame's edge list farther than
// a margin from each side (a side's own blurred edge and its refit residual stay out) are
// counted. Cells rather than points: a full edge list keeps every other step of its weaker
// edges (edge_list.h), which leaves such a cell occupied, so the measure does not halve on a
// busy frame.
//
// The share is compared at a common scale. A camera of more rows sees the same texture with a
// smaller share of cells on an edge (edge length grows with the rows, area with their square),
// but not by the rows' ratio: a finer grid also resolves texture a coarser one blurs away. On
// the photo bench (bash bench.sh photos-host, its inside table) the share of the boards and of
// the photographs' own rectangles both fall by about √2 from 240 rows to 480, so the limit is
// stated for a frame 240 rows high and a frame of H rows is held to limit · √(240 / H).
#pragma once
#include <stdint.h>

#include "base/fixed.h"
#include "lines/edge_list.h"
#include "lines/segment.h"
#include "quads/quad_rules.h"

namespace qt {

struct InteriorCount {
    uint32_t cells = 0;    // 2 × 2 px cells (x / 2, y / 2) holding an edge point inside,
                           // farther than the margin from every side
    uint32_t area_px = 0;  // the quadrangle's area, px² (rounded down): area_px / 4 cells
};

// Counts the cells of `edges` strictly inside the convex quadrangle `corners` (either
// orientation) and farther than `margin` px from each of its sides. Work: per row of the
// quadrangle's bounding box, the interval of pixels inside (four bounds carried from the row
// before) and one span lookup over it; 128 B of stack (a row of cells, frames up to 2048 px wide).
InteriorCount count_inside_edges(const EdgeList& edges, const Point16 corners[4], q16_16 margin);

// True when the inside is clear: at most limit_percent % of its cells hold an edge point at
// 240 rows, limit_percent · √(240 / height) % at `height` rows, i.e.
// cells · 400 · √(height) <= limit_percent · area · √240 (the roots as isqrt of the value
// · 2^16). kCheckOff (base/setting_range.h) turns the test off.
bool interior_clear(const InteriorCount& count, uint16_t height, uint8_t limit_percent);

// The lines of `lines` that run across the convex quadrangle `corners` (either orientation):
// over at least `min_inside` px farther than `margin` inside every side, and over at least
// `margin` px farther than `margin` outside a side. A board hides what lies behind it, so the
// lines through its inside stop at its sides (its print) or are an occluder's (an arm: two);
// a quadrangle cut out of a pattern of lines (a checkerboard, tiles, a grid of windows) is
// crossed by the pattern's lines. Work: two clips of each line against the four sides.
uint16_t count_lines_across(const Segment* lines, uint16_t n, const Point16 corners[4],
                            q16_16 margin, q16_16 min_inside);

}  // namespace qt
