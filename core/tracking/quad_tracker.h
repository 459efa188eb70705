// The quadrangle tracker: the Quadrangle Detection paper §2 "Real-time Quadrangle Tracking" and
// Experiment 3. Four line trackers (line_tracker.h), one per side, carry a board found by
// detect_quads() from frame to frame; a side the lines stage misses in a frame (the paper's frames
// 41–43, where the top and bottom sides are not extracted) is predicted, and the quadrangle is
// still rebuilt from the four lines.
//
// Each frame (step()):
//   1. No track: the best detected quadrangle, if any, starts one (every side "detected").
//   2. Track: each side's tracker predicts; each side takes the detected line that passes the
//      gate — orientation within gate_angle of the predicted side (modulo 180°), both ends
//      within gate_distance px of the predicted line, the same contrast polarity when both
//      are known, and overlapping the predicted side's extent. When each side of this frame's
//      best detected quadrangle passes the gate of one tracked side (in the same cyclic order),
//      those four lines are taken: they were refitted to the edge evidence between the
//      detection's corners, where the longest gated line can be a background edge clustered
//      onto a side. Otherwise each side takes the longest gated line; a line serves one side
//      at most. Matched sides are updated ("detected"), the others keep their prediction
//      ("predicted"). The corners are the crossings of consecutive sides.
//   2b. Taking a lost side back. A predicted side can drift beyond the gate from the line the
//      detector sees (the paper's constant-velocity model on a board turning 2.5°/frame: 12 px
//      after three hidden frames of the demo), and would then stay predicted until the track
//      is lost. When at least one side matched and one did not, the unmatched sides take their
//      lines from this frame's best detected quadrangle (the filters are updated, as by a
//      match: not restarted; the track id stays) if all of these hold:
//        - every matched side's counterpart in the detection (both wind anti-clockwise, so the
//          correspondence is a cyclic shift) passes that side's gate: the detection is the
//          tracked board, not another one;
//        - each of the detection's four sides is within take_back_length (1/16) of that side's
//          length when the track last matched all four: the board's shape, which a line
//          standing in for a hidden side (an occluder's edge across the board) changes;
//        - both ends of each line taken lie within take_back_sigmas (3) standard deviations of
//          the side's prediction (LineTracker::innovation_variance): a side is only taken as
//          far as its own filters say it may have drifted.
//      QuadTrackStats::taken_back says which sides were taken.
//   3. The track is LOST, and step() restarts from 1 in the same frame, when any side has gone
//      unmatched for more than max_predicted frames in a row, when the four sides no longer
//      make a convex quadrangle whose sides are within QuadParams' side lengths, when a
//      filter saturated, or when no side matched while this frame's best detected quadrangle
//      has a corner more than gate_distance from the tracked one (the board moved faster than
//      the gate). A stated rule rather than a confidence: it bounds how long the output can be
//      pure extrapolation, max_predicted frames. With some sides matched a disagreeing
//      detection is not trusted as a whole: it is too often the matched sides plus an
//      occluder's edges (rule 2b says when one of its sides is taken all the same).
//
// Output corners follow detect's contract: anti-clockwise as seen, corner 0 with the smallest
// x + y, side i from corner i to corner i + 1; the per-side flags follow the same order.
#pragma once
#include <stdint.h>

#include "base/setting_range.h"
#include "lines/segment.h"
#include "quads/quad_detector.h"
#include "quads/quad_rules.h"
#include "tracking/line_tracker.h"

namespace qt {

struct QuadTrackerParams {
    LineTrackerParams lines;  // per side; default_line_tracker_params(width, height)
    // Gate: largest angle between a detected line and the predicted side, degrees.
    angle_t gate_angle = angle_from_deg(8);
    // Gate: largest distance of a detected line's end points from the predicted side, px.
    // 12 px holds a board moving ~10 px/frame on the frame after the track starts, when the
    // filters do not know its velocity yet.
    q16_16 gate_distance = q16_16::from_int(12);
    // A side may be predicted this many frames in a row before the track is dropped.
    uint8_t max_predicted = 15;
    // Taking a lost side back (see the top of the file): on or off, and the largest relative
    // difference between a side of the detection and the same side when the track last matched
    // all four, fraction of the latter. 1/16: a hand-held board's sides change length by a % or
    // two a frame as it tilts or nears, while an occluder whose edge stands in for a side (the
    // demo's bars reach 24 px into a board 200 px tall) shortens the sides next to it by more.
    // The taken line must also lie within take_back_sigmas standard deviations of the side's
    // prediction (LineTracker::innovation_variance at each of its ends): a side is only taken
    // back as far as its filters say it may have drifted. Range 1..8.
    bool take_back = true;
    q16_16 take_back_length = q16_16::from_ratio(1, 16);
    uint8_t take_back_sigmas = 3;
    // Shape limits of the rebuilt quadrangle (side lengths; the other rules are detection's).
    QuadParams shape;
};

// The units and accepted ranges of QuadTrackerParams' gates and of LineTrackerParams::filters
// (base/setting_range.h); max_predicted at kCheckOff: a track is never dropped for it.
struct QuadTrackerRanges {
    SettingRange gate_angle{"degrees", 0, 90};
    SettingRange gate_distance{"px", 0, 1000};
    SettingRange max_predicted{"frames", 0, 254, 0, true};
    SettingRange filters{"", 1, 3};
};
inline constexpr QuadTrackerRanges kQuadTrackerRanges{};

// QuadTrackerParams for a width × height frame with default_line_tracker_params().
QuadTrackerParams default_quad_tracker_params(uint16_t width, uint16_t height);

enum class TrackState : uint8_t {
    none,      // no quadrangle this frame
    started,   // a new track from this frame's detection
    tracking,  // carried by the trackers (see TrackedQuad::detected for which sides were seen)
};

// "none", "started" or "tracking": the name the JSON and the result text use.
const char* track_state_name(TrackState state);

struct TrackedQuad {
    TrackState state = TrackState::none;
    Point16 corners[4] = {};  // px, detect's order (see the top of the file)
    Segment sides[4] = {};    // side i's line (corner i -> i + 1): measured or predicted
    uint8_t detected = 0;     // bit i: side i was matched to a detected line this frame
    uint32_t track_id = 0;    // 1, 2, ...: a new id every time a track starts
    uint32_t age = 0;         // frames since the track started (0 on the start frame)
};

// Why a track ended (the C API's qt_track_lost has the same values).
enum class QuadTrackLost : uint8_t {
    none = 0,                 // no track ended this frame
    side_unseen = 1,          // a side predicted for more than max_predicted frames
    shape = 2,                // no convex quadrangle with sides in range
    saturated = 3,            // a filter saturated
    detection_disagrees = 4,  // no side matched, and the detection is elsewhere
};

// What the last step() did, for tuning and for the JSON.
struct QuadTrackStats {
    QuadTrackLost lost_reason = QuadTrackLost::none;  // of the track that ended this frame
    uint8_t taken_back = 0;  // bit i: side i (detect's order) was taken back this frame
};

// The JSON name of a reason ("side_unseen", "shape", "saturated", "detection_disagrees"), or
// nullptr for none and unknown values.
const char* quad_track_lost_name(QuadTrackLost reason);

class QuadTracker {
public:
    // QuadTrackerParams{} has no frame size, so its filter origins all sit at (0, 0): pass
    // default_quad_tracker_params(width, height) here or to set_params() before the first step.
    explicit QuadTracker(const QuadTrackerParams& params = QuadTrackerParams{}) : params_(params) {}
    void set_params(const QuadTrackerParams& params) {
        params_ = params;
        reset();
    }
    void reset();

    // One frame: lines[0 .. n) from the lines stage and quads[0 .. quad_count) from
    // detect_quads() on those lines (best first; Quad::lines index into `lines`).
    TrackedQuad step(const Segment* lines, uint16_t n, const Quad* quads, uint16_t quad_count);

    const QuadTrackStats& stats() const { return stats_; }
    bool tracking() const { return active_; }
    // Side i's line tracker, in the order of the quadrangle the track started from (read-only,
    // for checking the filters' covariances).
    const LineTracker& side(int i) const { return sides_[i]; }

private:
    TrackedQuad start(const Segment* lines, const Quad& quad);
    bool agrees(const TrackedQuad& tracked, const Quad& detected) const;
    // The association gate: `s` may be the side whose prediction is `predicted`.
    bool gated(const Segment& s, const Segment& predicted) const;
    // Both ends of `s` within take_back_sigmas standard deviations of side `side`'s prediction.
    bool within_reach(int side, const Segment& predicted, const Segment& s) const;
    // The cyclic shift that makes `quad`'s side i + shift pass the gate of the track's side i
    // (and overlap it) for every i, or -1.
    int whole_match(const Segment* lines, uint16_t n, const Quad& quad, const Segment predicted[4],
                    const Point16 corners[4]) const;
    // Takes the unmatched sides back from `quad` when it agrees with the matched ones
    // (`detected` bits, tracker order); marks the lines it takes in `used`. Returns the bits of
    // the sides taken.
    uint8_t take_back(const Segment* lines, uint16_t n, const Quad& quad,
                      const Segment predicted[4], uint8_t detected, uint32_t used[8]);

    QuadTrackerParams params_;
    LineTracker sides_[4];
    uint8_t missed_[4] = {0, 0, 0, 0};  // frames in a row each side went unmatched
    q16_16 whole_lengths_[4] = {};      // side lengths when all four were last matched, px
    bool active_ = false;
    uint32_t track_id_ = 0;
    uint32_t age_ = 0;
    QuadTrackStats stats_;
};

}  // namespace qt
