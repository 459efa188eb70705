// Long runs of the two trackers on generated input (what a device sees in days of use): the
// loops and the rules they check, shared by the test command's short soak runs
// (tests/system/test_soak.cpp) and the soak bench (platform/bench/bench_soak.cpp: --frames,
// --seeds), which bench.sh builds with ASan + UBSan so that an overflow or any undefined behaviour
// aborts the run. Host only (heap, double); no images: the trackers' inputs are generated directly.
//
// Quadrangle tracker (core/tracking/quad_tracker.h). A 4:3 board moves and turns smoothly in a 640
// × 480
// frame; each frame its four sides become lines the way the lines stage reports them (ends 10 %
// short of the corners, Gaussian noise on every end, the board's polarity, shuffled), each side
// missed independently with probability miss_rate, and now and then a burst of total loss
// (no line at all). detect_quads() finds the board in the lines (it needs all four sides) and
// QuadTracker::step() gets both, as in the chain. Checked every frame and every burst:
//   - covariance: every constant-velocity filter axis (the closest-point filters of the paper's
//     model, the turn model's angle filter) has Ppp and Pvv within cv_variance_bound() for the
//     track's age; no filter saturates;
//   - a track lost for a side unseen has lived more than max_predicted frames (the counts start
//     with the track);
//   - a burst longer than max_predicted frames: the track is gone (state none) from the burst's
//     (max_predicted + 1)-th frame on, and a new one starts exactly in the first frame after the
//     burst that shows all four sides (the first frame in which detect_quads can see the board):
//     recovery = that frame, by the rule "lost ... when any side has gone unmatched for more than
//     max_predicted frames" and "step() restarts from 1 in the same frame";
//   - any burst: recovered (a track whose four corners are within recovery_tolerance_px of the
//     truth) no later than the first frame showing all four sides at or after both the burst's
//     end and its (max_predicted + 1)-th frame: by then a side predicted beyond its gate has
//     gone unmatched for more than max_predicted frames, so the track was lost and restarts from
//     that frame's detection; otherwise every side is within its gate and is matched, pulled onto
//     its line (within 2 px with this noise), in that frame.
//
// Target tracker (core/target/float/target_tracker.h), driven directly with synthetic homographies
// whose
// truth is exact: a nadir-looking camera (a similarity between ground and image: scale, turn,
// shift) follows a vehicle driving straight at constant speed, so in the tracker's reference
// image the vehicle moves at constant velocity and the fused estimate A·x̂ is exact in exact
// arithmetic once the filter's velocity has settled. Cycles of: init on the vehicle, frames in view
// with exact measurements, then a
// spell without measurements (the camera swings the vehicle out of the image and back) of one
// of four kinds: a drift spell (no longer than max_unseen), an unseen spell (longer), a
// bad-geometry spell (runs of frames whose homography failed or is untrustworthy: flat or
// noise frames), a scale spell (the camera climbs or descends: A scales the area at the
// estimate). Checked every frame against the rule of target_tracker.h's header, computed from
// the inputs alone: lost exactly in the frame the rule names (unseen > max_unseen, more than
// max_bad_geometry untrustworthy homographies in a row while unseen, A's area factor at the
// estimate outside [1/max_scale², max_scale²], which for a similarity is (s_now / s_ref)² with
// s_ref the scale at init or at the last reset the tracker reports) and never before; lost until
// init(); while the
// homographies are trusted, |estimate − truth| <= error_tolerance_px; a measurement offered while
// the track is not lost is accepted (reacquired on the first frame back in view). The error has
// two sources only: the filter's lag while its velocity settles after init (the first update
// leaves r/S = 4/32 of the vehicle's first-frame motion, <= 0.55 px: <= 0.07 px) and float
// rounding in A and the filter, which grows with the spell (about 0.01 px after 380 frames);
// a drift blow-up would be orders of magnitude above the 0.5 px tolerance.
#pragma once
#include <stdint.h>

#include <string>

#include "target/float/target_tracker.h"
#include "tracking/line_tracker.h"

namespace qt::soak {

// ---- constant-velocity filter covariance bound ----------------------------------------------

// Upper bounds of Ppp (px²) and Pvv (px²/frame²) of one axis of a constant-velocity Kalman
// filter (kalman.h: Q = q·[[1/4, 1/2], [1/2, 1]], R = r, P0 = diag(p0_pos, p0_vel)) that is
// predicted every frame and updated at least once every max_gap frames, `age` frames after
// init. The filter's P is the error covariance of the best linear estimator, so it is at most
// the mean square error of any simpler estimator on the same data, worked out here in double:
// before the first update (age <= max_gap − 1 predictions) the initial position carried with
// velocity 0; after it, the straight line through the last two pieces of information (init or
// updates, at most max_gap frames apart) extrapolated up to max_gap − 1 frames. The largest of
// those over every admissible gap and extrapolation is the bound. age < 0: any age.
struct VarianceBound {
    double pos = 0;  // px²
    double vel = 0;  // px²/frame²
};
VarianceBound cv_variance_bound(double q, double r, double p0_pos, double p0_vel, int max_gap,
                                int age);

// ---- quadrangle tracker ---------------------------------------------------------------------

struct QuadSoakConfig {
    uint32_t frames = 100000;
    uint64_t seed = 1;
    LineModel model = LineModel::closest_points;  // the CLI's default: the paper's 3KF
    double miss_rate = 0.3;                       // each side, independently, per frame
    uint32_t gap_min = 100, gap_max = 500;        // frames between bursts of total loss
    uint32_t burst_min = 1, burst_max = 40;       // frames of a burst (no line at all)
    double end_noise_px = 0.3;                    // σ of the noise on each line end, px
    double recovery_tolerance_px = 2.0;  // recovered: every corner within this of the truth
};

struct QuadSoakResult {
    uint32_t frames = 0;
    uint32_t bursts = 0, long_bursts = 0;  // long: more than max_predicted frames
    uint32_t full_frames = 0;              // frames showing all four sides
    uint32_t tracks_started = 0;
    uint32_t lost[5] = {};             // tracks lost, by QuadTrackLost value (index 0 unused)
    uint32_t lost_outside_bursts = 0;  // losses away from bursts and their recovery (not a rule:
                                       //   the tracker's own "price", a side predicted beyond the
                                       //   gate until it is given up; 0 for the paper's model here)
    uint32_t untracked_outside_bursts = 0;  // frames without a track after such a loss
    uint32_t worst_recovery = 0;            // frames from a burst's end to the recovery
    uint32_t worst_wait_full = 0;  // frames from a burst's end to the first frame with all sides
    uint32_t recovered_at_burst_end = 0;  // bursts recovered in their first frame back
    uint32_t recovered_after_whole = 0;   // bursts recovered only after the first frame showing all
        //   four sides after them (allowed up to the rule's frame)
    // Covariances of the checked filter axes (px² and px²/frame²; deg², deg²/frame² for the turn
    // model's angle), largest seen in tracks at least max_predicted + 1 frames old and the bound
    // there, and the same for younger tracks (whose sides may not have been updated yet).
    uint32_t settled_age = 0;  // max_predicted + 1
    double max_pos_variance = 0, pos_variance_bound = 0;
    double max_vel_variance = 0, vel_variance_bound = 0;
    double max_pos_variance_young = 0, pos_variance_bound_young = 0;
    double max_vel_variance_young = 0, vel_variance_bound_young = 0;
    double max_offset_variance =
        0;  // turn model: largest P00 of the offset filter, px² (no bound stated)
    double worst_error_tracking =
        0;                    // px, worst corner error in frames not within a burst's recovery
    uint32_t breaks = 0;      // frames or bursts breaking a checked rule
    std::string first_break;  // the first one, in words (empty if none)
};

QuadSoakResult run_quad_soak(const QuadSoakConfig& config);

// ---- target tracker -------------------------------------------------------------------------

struct TargetSoakConfig {
    uint32_t frames = 6000;
    uint64_t seed = 1;
    uint16_t width = 320, height = 240;
    TargetTrackerParams params;       // defaults: max_unseen 400, max_bad_geometry 15, max_scale 4
    double error_tolerance_px = 0.5;  // |estimate − truth| while the homographies are trusted
};

enum TargetLostRule : uint8_t { rule_unseen = 0, rule_bad_geometry = 1, rule_scale = 2 };

struct TargetSoakResult {
    uint32_t frames = 0;
    uint32_t cycles = 0;
    uint32_t spells[4] = {};  // by kind: drift, unseen, bad geometry, scale
    uint32_t lost_events = 0;
    uint32_t lost_by_rule[3] = {};  // TargetLostRule
    uint32_t lost_on_time = 0;      // lost in exactly the frame the rule names
    uint32_t reacquired = 0;      // returns from a drift spell, reacquired on the first frame back
    uint32_t longest_unseen = 0;  // frames without a measurement before a reacquisition
    double worst_error_px = 0;    // while the homographies were trusted and the track not lost
    double worst_error_outside_px = 0;  // the same, while the target's centre was outside the image
    double farthest_outside_px = 0;     // how far outside the image the target went, px
    uint32_t breaks = 0;                // frames breaking a checked rule
    std::string first_break;
};

TargetSoakResult run_target_soak(const TargetSoakConfig& config);

}  // namespace qt::soak
