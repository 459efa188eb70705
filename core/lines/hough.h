// Fixed-point progressive probabilistic Hough transform (PPHT; Matas, Galambos, Kittler 2000)
// over an edge list: points are visited in a seeded pseudo-random order; each votes; when a
// bin reaches the vote threshold its line is followed through the edge points in both
// directions (tolerating gaps up to max_line_gap), refitted by total least squares as it
// goes, and if the run is at least min_line_length long its points are removed from the
// accumulator and the segment is reported.
//
// Accumulator: theta_bins normal angles over 180° (θ_i = i·180°/theta_bins) by rho bins of
// rho_step pixels about the frame centre, 8-bit saturating counters. A point votes only for
// the θ within ±vote_window_deg of its gradient direction (the line's normal is the gradient
// direction), which cuts the votes per point from theta_bins to about
// theta_bins·2·window/180 and keeps clutter of other orientations out of each bin.
//
// A bin at the threshold is followed only when it stands out in its θ row (min_peak_percent): a
// line puts its votes in a bin or two, a textured patch spreads them over its width, and most
// walks from such bins find no segment yet cost as much as those that do.
//
// Work per frame is bounded by two budgets (HoughParams): the points that vote (max_voters)
// and the steps of line following (max_walk_steps); the votes withdrawn are at most those cast.
#pragma once
#include <stdint.h>

#include "base/isqrt.h"
#include "base/setting_range.h"
#include "base/status.h"
#include "lines/edge_list.h"
#include "lines/segment.h"

namespace qt {

struct HoughParams {
    uint16_t theta_bins = 90;       // accumulator angle bins over 180° (2° each at 90)
    uint16_t rho_step = 2;          // accumulator distance bin, pixels: 1, 2 or 4
    uint16_t threshold = 12;        // votes a bin needs before its line is followed (1..255)
    uint16_t min_line_length = 20;  // shortest segment reported, pixels
    uint16_t max_line_gap = 4;      // longest run of missing edge pixels inside a segment, pixels
    uint16_t vote_window_deg = 24;  // ± degrees around the gradient direction; 90 or more: all θ
    uint16_t corridor = 1;          // pixels either side of the line searched while following it
    uint32_t max_walk_steps = 200000;  // bound on line-following work per frame (steps)
    // Bound on voting per frame: edge points that vote, at most; 0: half the edge list's
    // capacity (2048 with qt::Qvga, 8192 with qt::Vga). Points past it in the visiting order do
    // not vote or seed a line, but walks still follow and consume them, and the quadrangle
    // evidence still reads them: a long line has voted past the threshold well before its
    // share of the list has (at half the capacity the photo bench's detection moves by at most
    // 0.2 point: docs/lines.md).
    uint16_t max_voters = 0;
    // A bin that reached the threshold is followed only when its count is at least this
    // percentage of its flank's on one side at least (the larger count 2 and 3 bins that way in
    // its θ row, kPeakFlank: lines 2·rho_step..4·rho_step px beside it); else it waits for more
    // votes. A lone line, or either edge of a bar, has a low flank; a textured patch, whose
    // votes spread over its width, has none. 0: every bin at the threshold is followed (the
    // reference PPHT).
    uint16_t min_peak_percent = 300;
    uint64_t seed = 1;  // visiting order
};

// HoughParams' units and accepted ranges (base/setting_range.h). rho_step: 2 or 4 in the range
// (the VGA build's accumulator has no room for 1); theta_bins at most the build's capacity.
struct HoughRanges {
    SettingRange theta_bins{"bins", 2, 90};
    SettingRange rho_step{"px", 2, 4};
    SettingRange threshold{"votes", 1, 255};
    SettingRange min_line_length{"px", 2, 2048};
    SettingRange max_line_gap{"px", 0, 255};
    SettingRange vote_window_deg{"degrees", 1, 90};
    SettingRange corridor{"px", 0, 4};
    SettingRange max_walk_steps{"steps", 1, 100000000};
    SettingRange max_voters{"points", 0, 65535};
    SettingRange min_peak_percent{"%", 0, 1000};
    SettingRange seed{"", 0, 2147483647};
};
inline constexpr HoughRanges kHoughRanges{};

// The flank min_peak_percent compares a bin with: the bins this far and one farther along ρ.
constexpr uint32_t kPeakFlank = 2;

struct HoughStats {
    uint32_t points_visited = 0;    // edge points that voted
    uint32_t votes = 0;             // accumulator increments
    uint32_t saturated_votes = 0;   // increments lost to a bin at 255
    uint32_t lines_followed = 0;    // bins that reached the threshold and stood out
    uint32_t flat_bins = 0;         // votes that left a bin at the threshold that did not stand
                                    // out (min_peak_percent): not followed then
    uint32_t walk_steps = 0;        // pixels stepped while following lines
    uint16_t segments = 0;          // segments reported
    uint16_t segments_dropped = 0;  // segments found with the output full: the shortest of
                                    // those found and the new one is dropped
    bool budget_exhausted = false;  // stopped at max_walk_steps: not every point was visited
    bool voters_exhausted = false;  // stopped at max_voters: fresh points were left unvisited
    // Either budget bound: the frame's lines may miss some a full run would find.
    bool budget_bound() const { return budget_exhausted || voters_exhausted; }
};

// Working memory of PPHT, as a view (see HoughStorage for the owning type).
struct HoughWorkspace {
    uint8_t* bins;  // theta_bins × rho bins counters
    uint32_t bin_capacity;
    uint32_t* cos_sin_q14;  // per θ bin: cos in the low 16 bits, sin in the high, signed,
                            // 1.0 = 2^14 (one load, and one SMLAD on a Cortex-M4, per vote)
    uint16_t theta_capacity;
    uint16_t* table_bins;  // theta_bins the tables hold (0: not filled): a frame with the same
                           // theta_bins as the last one reuses them (90 CORDIC runs saved)
};

// Rho bins on each side of the frame centre: ceil(R / rho_step), R = floor(distance from the
// centre to a corner) + 1 pixels.
constexpr uint32_t hough_rho_half_bins(uint32_t width, uint32_t height, uint32_t rho_step) {
    const uint32_t hx = (width + 1) / 2, hy = (height + 1) / 2;
    return (isqrt32(hx * hx + hy * hy) + 1u + rho_step - 1u) / rho_step;
}

// Accumulator bins a frame needs: theta_bins × (2 · half + 1). Compile-time capacities
// (line_detector.h) and the run-time check use this one formula.
constexpr uint32_t hough_bins_for(uint32_t width, uint32_t height, uint32_t theta_bins,
                                  uint32_t rho_step) {
    return theta_bins * (2 * hough_rho_half_bins(width, height, rho_step) + 1);
}

// Runs PPHT over `edges` of a width × height frame. Segments go to out[0 .. *count). Returns
// bad_size for a bad frame or parameters that need more bins than the workspace holds
// (nothing is written then); ok otherwise — capacity and budget limits are in `stats`.
// Marks the edge points' states (voted, consumed) as it goes, and keeps its list of the points
// a walk found in the edge list's spare words (the points' strengths are gone after it).
Status hough_segments(EdgeList& edges, uint16_t width, uint16_t height, const HoughParams& params,
                      const HoughWorkspace& ws, Segment* out, uint16_t out_capacity,
                      uint16_t* count, HoughStats* stats);

// Owning storage: BinCapacity bytes of counters + 4·MaxThetaBins + 2 bytes of tables.
template <uint32_t BinCapacity, uint16_t MaxThetaBins>
struct HoughStorage {
    uint8_t bins[BinCapacity] = {};
    uint32_t cos_sin_q14[MaxThetaBins] = {};
    uint16_t table_bins = 0;
    HoughWorkspace view() {
        return HoughWorkspace{bins, BinCapacity, cos_sin_q14, MaxThetaBins, &table_bins};
    }
};

}  // namespace qt
