// The target tracker (the Filtering and Geometry paper §III, Fig. 3, Tables II and III): a Kalman
// filter (target_kalman.h) fused with the frame-to-frame homographies of the ground, accumulated
// while the target is not measured and reset when it is found again.
//
// Coordinates. The filter lives in the image of a reference frame m; the accumulated homography
// A = Π H(i−1→i) for i = m+1..n (equation (11)) maps that image into the current frame n. A
// measurement z of frame n enters the filter as A⁻¹ z (equation (10)); the position reported in
// frame n is A x̂. Camera motion is therefore carried by A and the filter models only the
// target's own motion over the ground. While the target is perturbed (occluded, a bad match)
// or out of view, nothing is measured: the filter predicts and A keeps accumulating, so the
// reported position follows the ground and the target's last estimated velocity, also outside
// the image. Table III's reset: when a measurement is accepted with D_nds <= reset_nds and
// det S <= reset_det_s, the filter is carried into frame n (TargetKalman::change_frame(A)) and
// A becomes the identity (m = n); the drift accumulated in A is cleared.
//
// Gates (Table II): a measurement is used only when D_nds (equation (6)) <= gate_nds and the
// frame's homography is trustworthy: estimated, with its reprojection error D_rep (equation
// (7) over every matched pair it is judged on, not only RANSAC's inliers, which are within
// inlier_px by construction) below the gate: RepGate::paper compares the paper's sum with
// th_rep_px2; RepGate::capped (default) its capped RMS with gate_rep_px. A frame whose
// homography failed or is untrustworthy is carried by the last good one (constant camera
// motion) and counted. A frame with too few corners to measure the motion at all
// (FrameGeometry::unmeasured: a table, a wall, the sky) is no evidence either way: it is carried
// the same, not counted, and its measurement is used — the paper's gate would lose every target
// on a textureless background (docs/target.md, Real footage).
//
// States, per frame: measured (a measurement accepted), reacquired (the first accepted after
// frames without one), predicted (none accepted; the target's estimated position is inside
// the image), out_of_view (none accepted; outside the image), lost (until init(), or the lost
// search below: no measurement for more than max_unseen frames, or more than max_bad_geometry
// consecutive frames without a trustworthy homography while unseen, or A no longer a plausible
// camera motion: it sends the estimate to infinity, or scales the area around it by a factor
// outside [1/max_scale², max_scale²] — then A's position is not worth reporting — or the
// estimate more than max_outside frame widths (heights) outside the image: a coasting estimate
// that far out is no longer a place to look for the target. A lost target reports the last
// estimate it reported before it was lost.
//
// An unconfirmed exit is lost too (fused, reference formulation): the estimate leaves the
// image after more than max_unconfirmed_exit frames searched in vain while the camera's motion
// keeps the last measured position inside it — it left by its own predicted motion alone, and
// nothing confirms that the target did (a walker who stopped behind a sign). Such a target
// reports its last measured position, carried by the camera. With lost_search_px > 0 it is
// searched for there in a window that grows by lost_search_px a frame up to max_radius_px, and
// a match (NCC at least min_score) restarts the filter on it, reported as reacquired; off by
// default: on the real footage it re-acquires look-alikes as often as the walker
// (docs/target.md, Real footage).
//
// The comparison methods of the paper's §IV are modes of the same tracker (TargetMethod).
// Float only, never double; no heap.
#pragma once
#include <stdint.h>

#include "base/setting_range.h"
#include "target/float/homography.h"
#include "target/float/target_kalman.h"

namespace qt {

enum class TargetState : uint8_t { measured, reacquired, predicted, out_of_view, lost };
const char* target_state_name(TargetState s);

enum class TargetMethod : uint8_t {
    fused,            // the paper's proposed method (this file's header)
    filter_only,      // Kalman filter in image coordinates, gated measurements, no homography
    homography_only,  // the initial position carried by the accumulated homography, never measured
    template_only,    // the best template match near the last position, no filter, no gate
};
const char* target_method_name(TargetMethod m);

// Which reprojection error gates the frame's homography (Table II's D_rep <= th_rep).
enum class RepGate : uint8_t {
    capped,  // RMS over all matched pairs of equation (7)'s terms, each capped (homography.h)
    paper,   // equation (7) as written: D_rep = Σ over all matched pairs, px², <= th_rep_px2
};
const char* rep_gate_name(RepGate g);

// Where the filter lives (§III-B).
enum class TargetFormulation : uint8_t {
    // Ours (default): the filter lives in the image of the reference frame m, measurements
    // enter as A⁻¹ z, the estimate is A x̂ (this file's header). Every accepted measurement
    // re-anchors the filter, so the error of A never builds up while the target is seen.
    reference,
    // The paper's reading of Tables II and III: the filter lives in the current image (carried
    // into each new frame by the frame's homography, then Φ), measurements enter as they are;
    // while the target is perturbed its position is the reference point x_m of the last reset
    // frame m carried by the accumulated homography, x_n = A x_m (equation (11)), which holds
    // no motion of the target's own. Without the reset m stays 0, A accumulates from frame 0,
    // and so does its error (Fig. 12).
    paper,
};
const char* target_formulation_name(TargetFormulation f);

// The search region's shape and size (Table III step 2, §III-B).
enum class SearchRegionShape : uint8_t {
    // Ours (default): a square of candidate centres around the prediction, half side
    // gate_sigmas·σ of the larger axis of S in the current image, clamped to
    // [min_radius_px, max_radius_px].
    square,
    // The paper's: four corners x̂ ± gate_sigmas·σ (per axis, from S) in the filter's image
    // mapped by the accumulated homography; the search covers their bounding box (up to the
    // captured region, max_radius_px). While the target is perturbed the region is not
    // recomputed but carried by A ("wait for the region transformed by the homography to come
    // into the FOV"); the first accepted measurement re-initialises it from the state.
    paper,
};
const char* search_region_name(SearchRegionShape r);

struct TargetTrackerParams {
    TargetMethod method = TargetMethod::fused;
    bool reset = true;  // Table III's reset (false: A accumulates from frame 0, Fig. 12)
    TargetFormulation formulation = TargetFormulation::reference;
    SearchRegionShape region = SearchRegionShape::square;
    TargetKalmanParams kalman;
    float min_score = 0.7f;  // a template match counts as found when its NCC >= this
    float gate_nds = 9.21f;  // D_nds gate: χ²(2 dof) at 99 %
    RepGate rep_gate = RepGate::capped;
    // capped: homography trustworthy when d_rep_capped_px <= this, px. With the cap at
    // (2·inlier_px)² = 16 px², 2 px refuses an H that fails to explain about a quarter of the
    // pairs; the benches' frames reach 1.4 px (12 % of NCC mismatches).
    float gate_rep_px = 2.0f;
    // paper: ... when D_rep (the sum over the pairs) <= this, px². The paper gives no value;
    // the benches' frames reach 1 360 px² (55 pairs a frame, a few mismatches of up to 24 px).
    float th_rep_px2 = 1500.0f;
    float reset_nds = 5.99f;      // reset when D_nds <= this (χ²(2) at 95 %) ...
    float reset_det_s = 2500.0f;  // ... and det S <= this, px⁴ (σ ≈ 7 px per axis; with the
                                  // paper's Q, S never falls below q_pos + r ≈ 24 px² per axis)
    float gate_sigmas = 3.0f;     // search radius = gate_sigmas · √(largest variance of S), px,
    float min_radius_px = 4.0f;   //   clamped to [min_radius_px, max_radius_px]
    float max_radius_px = 24.0f;
    float template_radius_px = 16.0f;  // template_only: fixed search radius around the last match
    uint16_t max_unseen = 400;         // lost after this many frames without a measurement
    uint16_t max_bad_geometry =
        15;                  // lost after this many untrustworthy homographies in a row, unseen
    float max_scale = 4.0f;  // lost when A scales the area at the estimate beyond max_scale²
    // Lost when the estimate, unseen, is more than this many frame widths left or right of the
    // image (heights above or below): frames; 0 loses it as soon as it leaves the image.
    float max_outside = 1.0f;
    // The unconfirmed-exit rule above: frames searched in vain before the exit; kCheckOff: off.
    uint8_t max_unconfirmed_exit = 3;
    // A target lost by that rule is searched for around its last measured position in a window
    // growing by this many px a frame; 0: not searched for (lost stays lost until init()).
    float lost_search_px = 0.0f;
    // Coasting out of view (fused, reference formulation): when the estimate leaves the image,
    // it follows the track fitted by least squares to the accepted measurements of the last
    // coast_fit_frames frames (at least 8 of them, in the reference image), frames;
    // 0..kMaxCoastFitFrames. The filter's velocity follows the last few measurements' errors
    // (the paper's Q lets it), and out of view they grow with every frame; a fit to many
    // measurements hardly moves with them. 0: the filter's velocity (the paper).
    uint16_t coast_fit_frames = 63;
    // The track's shape. A target at constant velocity on the ground plane, seen in the
    // reference image (a perspective view of that plane), moves on a straight line but not at
    // constant speed: x(t) = (a + b·t) / (1 + c·t) per axis with one c for both (the point's
    // depth changes linearly with t). true: that track (5 numbers); false: a straight line at
    // constant speed (c = 0), which under perspective misses the spell's end by px.
    bool coast_projective = true;
};

// TargetTrackerParams' units and accepted ranges (base/setting_range.h).
struct TargetTrackerRanges {
    SettingRange min_score{"", -1, 1};            // NCC
    SettingRange gate_nds{"", 1, 100000000, 2};   // 0.01..1e6
    SettingRange gate_rep_px{"px", 1, 10000, 2};  // 0.01..100
    SettingRange th_rep_px2{"px^2", 0, 1000000000};
    SettingRange reset_nds{"", 0, 1000000};
    SettingRange reset_det_s{"px^4", 0, 1000000000000};
    SettingRange max_radius_px{"px", 1, 48};
    SettingRange max_unseen{"frames", 1, 65535};
    SettingRange max_outside{"frame sizes", 0, 100};
    SettingRange coast_fit_frames{"frames", 0, 63};
    SettingRange max_unconfirmed_exit{"frames", 0, 254, 0, true};
    SettingRange lost_search_px{"px per frame", 0, 48};
};
inline constexpr TargetTrackerRanges kTargetTrackerRanges{};

// The frame's camera motion: the homography from the previous frame's image into this one.
struct FrameGeometry {
    bool valid = false;         // false: the estimate failed this frame
    Homography h;               // previous → current image
    float reprojection_px = 0;  // equation (7) as RMS over the inliers, px (diagnostic only)
    float d_rep = 0;            // equation (7) over all matched pairs, the paper's sum, px²
    float d_rep_capped_px = 0;  // its capped RMS, px (RansacResult::d_rep_capped_px)
    // Too few corners in either frame to measure the camera's motion (a scene without texture:
    // a table, a wall, the sky): no evidence either way, so TargetTracker::predict assumes the
    // last trusted motion and the measurement is still used (see the top of this file).
    bool unmeasured = false;
};

// Table II's D_rep condition on the frame's homography (valid aside): true when trusted.
bool geometry_trusted(const FrameGeometry& g, const TargetTrackerParams& params);

// Where the caller should look for the target in the current frame.
struct SearchWindow {
    float x = 0, y = 0;  // centre, px (may lie outside the image)
    float radius = 0;    // half side of the square of candidate centres, px; 0: do not search
    // SearchRegionShape::paper: the four mapped corners (current image, px) whose bounding box
    // the radius covers; unset (corners = false) for the square.
    bool corners = false;
    float cx[4] = {0, 0, 0, 0}, cy[4] = {0, 0, 0, 0};
};

// The best template match in the window, from the caller's template search.
struct TargetMeasurement {
    bool searched = false;  // a window was searched this frame (found or not)
    bool found = false;
    float x = 0, y = 0;  // matched target centre, px
    float score = 0;     // NCC, -1..1
};

struct TargetEstimate {
    TargetState state = TargetState::lost;
    float x = 0,
          y = 0;      // target centre in the current image, px (outside the image when out of view)
    float nds = 0;    // D_nds of the measurement considered (0 when none)
    float det_s = 0;  // det S of the prediction, px⁴
    bool reset = false;   // the accumulation was reset this frame
    uint16_t unseen = 0;  // frames since the last accepted measurement
};

class TargetTracker {
public:
    // Starts on the target's centre (x, y) in an image of width × height px.
    void init(float x, float y, uint16_t width, uint16_t height, const TargetTrackerParams& params);
    // First half of a frame: carries the estimate into the current image with the frame's
    // geometry and predicts. Returns where to search (radius 0: nothing to search, e.g. lost
    // or homography_only).
    SearchWindow predict(const FrameGeometry& geometry);
    // Where predict() would look if this frame's homography equalled the last trustworthy one
    // (constant camera motion): for capturing the search region while the frame's rows stream
    // by, before its homography is known. Changes nothing.
    SearchWindow expected() const;
    // Second half: the search result (found == false when nothing matched well enough).
    TargetEstimate update(const TargetMeasurement& m);
    // After update(): the target's look was found at (x, y) px of this frame's image by a
    // search that did not follow the prediction (the pipeline's whole-frame search). The next
    // predict() returns the window of half-side `radius` px there, carried by the next frame's
    // camera motion, instead of the prediction's; a match in it with an NCC of at least
    // min_score restarts the filter on it, reported as reacquired, and anything less leaves the
    // track as if nothing had been found (the filter is not updated: the window was not the
    // prediction's). The D_nds gate does not apply: the prediction is what failed. Works
    // while lost too.
    void look_at(float x, float y, float radius, float min_score);

    // The most frames the coasting line is fitted over (the measurements kept).
    static constexpr uint16_t kMaxCoastFitFrames =
        static_cast<uint16_t>(kTargetTrackerRanges.coast_fit_frames.hi);

    TargetState state() const { return state_; }
    const TargetTrackerParams& params() const { return params_; }
    const Homography& accumulated() const { return acc_; }
    // The camera's motion previous → current image the last predict() carried A by (fused and
    // homography_only: the frame's trusted homography, or the last one); identity otherwise.
    const Homography& camera_motion() const { return last_h_; }

private:
    bool in_image(float x, float y) const;
    bool within_reach(float x, float y) const;
    bool accumulation_plausible() const;
    bool paper_formulation() const;
    void position(float& x, float& y) const;  // A x̂, current image

    SearchWindow window_from_state();  // the window for the current prediction
    SearchWindow paper_region(bool refresh);

    TargetTrackerParams params_;
    TargetKalman kf_;
    // TargetFormulation::paper: the reference point x_m of the last reset frame, image m.
    float ref_x_ = 0, ref_y_ = 0;
    // SearchRegionShape::paper: the region's corners in the image A maps from, px.
    float roi_x_[4] = {0, 0, 0, 0}, roi_y_[4] = {0, 0, 0, 0};
    Homography acc_;     // reference image → current image
    Homography last_h_;  // the last trustworthy frame homography
    uint16_t width_ = 0, height_ = 0;
    TargetState state_ = TargetState::lost;
    bool geometry_ok_ = false;
    bool geometry_assumed_ = false;  // this frame's motion unmeasured: the last trusted one
    uint16_t unseen_ = 0;
    uint16_t bad_geometry_ = 0;
    float last_x_ = 0, last_y_ = 0;  // template_only: the last match
    float held_x_ = 0, held_y_ = 0;  // the last estimate reported while not lost
    float meas_x_ = 0, meas_y_ = 0;  // the last accepted measurement, reference image
    uint16_t unconfirmed_ = 0;       // frames searched in vain since then
    // Lost by an unconfirmed exit at (lost_x_, lost_y_), current image: searched for there.
    bool lost_by_exit_ = false;
    float lost_x_ = 0, lost_y_ = 0;
    uint16_t lost_frames_ = 0;  // frames lost so, for the search window's growth
    // look_at(): where (previous image, px) and how wide (px) the next window is, and the NCC
    // a match there needs; looked_: this frame's window is it.
    bool looking_ = false, looked_ = false;
    float look_x_ = 0, look_y_ = 0, look_radius_ = 0, look_score_ = 0;
    // Whether the estimate (x, y), unseen, leaves the image unconfirmed; (mx, my) the last
    // measured position carried into this image.
    bool unconfirmed_exit(float x, float y, float& mx, float& my) const;
    bool searching_lost() const;
    SearchWindow predict_from_state(const FrameGeometry& g);  // predict() without look_at()
    void restart_on(float x, float y);
    // The accepted measurements of the last frames, in the reference image (A⁻¹ z, carried by
    // A at each reset), oldest first from history_start_ (a ring), with their frame.
    static constexpr uint16_t kHistory = kMaxCoastFitFrames + 1;
    static constexpr uint16_t kMinCoastSamples = 8;
    struct Sample {
        float x, y;
        uint32_t frame;
    };
    Sample history_[kHistory] = {};
    uint16_t history_start_ = 0, history_count_ = 0;
    uint32_t frame_ = 0;  // frames predicted since init
    void remember(float x, float y);
    void carry_history(const Homography& h);
    // Fits the coasting track and puts the filter on it; false (filter unchanged) with too few
    // samples.
    bool coast_from_history();
    // Puts the filter on the coasting track at frame (position and velocity); false (filter
    // unchanged) past kMinCoastDepth.
    bool coast_at(uint32_t frame);
    // The coasting track in the reference image: x = x_mean + (ax + bx·u) / (1 + c·u) px (y
    // alike), u = frames since the fit's frame − t_mean.
    struct CoastTrack {
        uint32_t frame = 0;  // the frame it was fitted in
        float t_mean = 0;    // the samples' mean time, frames from `frame` (≤ 0)
        float x_mean = 0, y_mean = 0, ax = 0, bx = 0, ay = 0, by = 0, c = 0;
    };
    static constexpr float kMinCoastDepth = 0.25f;  // 1 + c·u below this: the track ends
    CoastTrack coast_;
    bool coasting_ = false;  // out of view since the fit, no measurement accepted yet
};

}  // namespace qt
