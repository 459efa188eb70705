// Tracking mode: while the quadrangle tracker holds the board, the next frame is processed only
// in bands around its predicted sides (lines/band_window.h); a frame costs what the board's
// outline costs, not what the room holds.
//
// plan() runs after each frame's QuadTracker::step and says what the next frame is: bands, or
// the whole frame. Bands when the tracker matched all four sides of the board this frame and
// fewer than full_every − 1 frames in a row were banded; the whole frame otherwise (no track, a
// side predicted rather than seen, and every full_every-th frame, where the detector may find
// another board or a side the bands missed). The bands follow the corners' motion: each corner
// of this frame moved on by its motion since the last frame when both frames tracked the same
// board (the same track id), and half_width px either side of each side, reach px beyond its
// corners. Inside the bands the edges are the full frame's; outside them nothing is computed,
// so a quadrangle found there has no inside edges and no lines across (its checks pass).
#pragma once
#include <stdint.h>

#include "base/fixed.h"
#include "base/setting_range.h"
#include "lines/band_window.h"
#include "tracking/quad_tracker.h"

namespace qt {

struct TrackingModeParams {
    bool enabled = true;
    // Half width of a band, px: the tracker's gate (12 px) and what a corner's motion may
    // change from one frame to the next.
    q16_16 half_width = q16_16::from_int(8);
    q16_16 reach = q16_16::from_int(4);  // beyond each corner along the side, px
    uint16_t full_every = 16;            // frames: every full_every-th frame is whole
    // The lines a banded frame keeps: those within this angle of a band's side (the tracker's
    // gate is 8°); the others cross a band and are background edges it cuts short.
    angle_t line_angle = angle_from_deg(10);
    // Each side measured by a fit to the edge points of its band (refine_quad from the
    // predicted side) instead of PPHT and the quadrangle search, which a banded frame then
    // skips.
    bool fit_sides = true;
};

// TrackingModeParams' units and accepted ranges (base/setting_range.h).
struct TrackingModeRanges {
    SettingRange half_width{"px", 2, 64};
    SettingRange reach{"px", 0, 64};
    SettingRange full_every{"frames", 2, 65535};
    SettingRange line_angle{"degrees", 1, 45};
};
inline constexpr TrackingModeRanges kTrackingModeRanges{};

struct TrackingModeStats {
    uint32_t banded = 0;  // frames planned as bands
    uint32_t whole = 0;   // frames planned whole
};

class TrackingMode {
public:
    explicit TrackingMode(const TrackingModeParams& params = TrackingModeParams{})
        : params_(params) {}

    // The window of the next frame from this frame's tracked board: the bands, or null for the
    // whole frame. The window stays valid until the next plan() or reset().
    BandWindow* plan(const TrackedQuad& tracked);
    // Forget the board: the next frame is whole.
    void reset();
    const TrackingModeStats& stats() const { return stats_; }
    const TrackingModeParams& params() const { return params_; }

private:
    TrackingModeParams params_;
    TrackingModeStats stats_;
    BandWindow window_;
    Point16 last_[4] = {};
    uint32_t last_id_ = 0;  // track id of last_ (0: none)
    uint16_t banded_run_ = 0;
};

}  // namespace qt
