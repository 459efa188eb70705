// The target tracker's whole frame, streamed row by row (the Filtering and Geometry paper Fig. 3
// with Table I): camera rows → gradient words (gradient_stage.h, or the FPGA block's) → Harris
// corners with their patches (harris.h) → NCC matches to the previous frame's corners → RANSAC
// homography → target tracker (target_tracker.h), whose measurement is the template found by NCC
// (template_search.h) in a region of the frame captured as its rows went by.
//
// No frame buffer: the region captured is where the tracker expects the target under constant
// camera motion (TargetTracker::expected()), widened by capture_margin_px for the difference
// between that guess and the frame's measured homography; the search window, known only once
// the homography is, is clipped to it. RAM is the members below (sizeof(TargetPipelineQvga)
// is printed by bash bench.sh target-host, docs/target.md). No heap, no exceptions.
#pragma once
#include <stdint.h>

#include <type_traits>

#include "base/capacity.h"
#include "base/floor_div.h"
#include "base/status.h"
#include "gradient/gradient_stage.h"
#include "target/float/frame_homography.h"
#include "target/float/target_tracker.h"
#include "target/float/template_pose.h"
#include "target/harris.h"
#include "target/morph_detect.h"
#include "target/template_search.h"

namespace qt {

// The measurement: how the target is found in the search region (Table III step 2).
enum class TargetDetector : uint8_t {
    ncc_template,   // ours (default): the NCC template of frame 0 (template_search.h)
    morphological,  // the paper's: top-hat and clustering (morph_detect.h), polarity, element
                    // and area learnt from the box of frame 0
};
const char* target_detector_name(TargetDetector d);

// The pipeline's corners: HarrisParams' defaults, sought in a band of 12 rows about the middle
// of each cell row (40 rows at QVGA). Against every row (band_rows 0): the Cortex-M4F rows
// stage 6.6 M → 2.6 M instructions a frame; on the generated sequences the target's error while
// visible 0.87 px both, at the end of the spell out of view 4.6 → 4.8 px (medians over 15
// seeds); on the real footage 58.3 → 57.8 % within 10 px (docs/target.md).
constexpr HarrisParams target_harris_params() {
    HarrisParams h;
    h.band_rows = 12;
    return h;
}

struct TargetPipelineParams {
    HarrisParams harris = target_harris_params();
    FrameHomographyParams geometry;
    TargetTrackerParams tracker;
    uint16_t capture_margin_px = 8;  // region kept beyond the expected search window, px
    // template_blend 1: the template is cut again at the match when a measurement is accepted
    // with an NCC below this (Q15; 0.85 = 27853): it follows the target's slow change of look
    // without being re-cut every frame, which would let the sub-pixel errors of successive cuts
    // add up to a drift. 0: never. template_only refreshes at every match, as the paper's
    // template tracker does (its Fig. 8).
    int32_t refresh_score_q15 = 27853;
    // 1: the template is replaced by the cut at a match whose NCC fell below refresh_score_q15.
    // N > 1 (default 8): every accepted match moves it 1/N of the way to the cut there (pixels,
    // and at step 1 the centre offset; blend_toward): a running mean of the target's look over
    // about N frames, which one partly occluded cut cannot take over (a walker's legs, an
    // occluder's edge): on the real footage 51.9 → 57.8 % within 10 px, wrong claims 17 → 8
    // of 65 (docs/target.md).
    // template_only replaces at every match (the paper's Fig. 8).
    uint8_t template_blend = 8;
    // The template is searched as the ground's motion since its cut shows it (template_pose.h):
    // warped by that motion's Jacobian at its centre, and blended in that pose. Without it the
    // running mean lags a target whose look the camera turned (the generated sequences lost two
    // vehicles of 15 after the flare). false: the template as cut.
    bool template_follows_ground = true;
    // The template search's lattice (search_template's step): 1 scores every placement of the
    // window; s > 1 every s-th along each axis, then the placements beside the three best: about
    // 1/s² of the work. 2 (default): the search's Cortex-M4F cost a frame 1.4 M → 0.5 M
    // instructions median, 2.7 M → 0.8 M worst; the generated sequences' figures the same, the
    // real footage's 58.4 → 57.8 % within 10 px (docs/target.md).
    uint8_t template_search_step = 2;
    // The motion prior (search_template's prior): the template search takes prior·(d / r)² off
    // the NCC of a placement d px from the prediction in a window of half-side r (Q15), and
    // keeps the best of what is left; the match is still judged by its own NCC (min_score,
    // D_nds). A look-alike at the window's edge must then out-score the target by 0.2 to be
    // taken for it. 0: the best NCC anywhere in the window (the paper). On the real footage
    // (docs/target.md) within 10 px 52.6 → 57.8 %, wrong claims 17 → 8 of 65.
    int16_t motion_prior_q15 = 6554;
    // Whole-frame re-detection (the NCC template): after redetect_after frames without an
    // accepted match (lost ones too), every other frame is kept whole at a coarse step (the
    // smallest multiple of the track's step that fits the frame into the captured region) and
    // the template, averaged to that step (shrink_template), is searched over all of it; the
    // best placement, when its NCC reaches redetect_score_q15 (Q15), sends the next frame's
    // search there (TargetTracker::look_at), and a match there of the same NCC restarts the
    // track. The frames between search the prediction as before. A target that left the
    // window (a flick faster than the window, a long occlusion, a cut) is found again
    // wherever it is: on the real footage the coin 18.3 → 47.2 % within 10 px, the walkers
    // unchanged (docs/target.md). Both stages ask more than min_score: the motion model no
    // longer vouches for the place. None for a target whose coarse template would have fewer
    // than kMinRedetectSide pixels a side. 0: off.
    uint16_t redetect_after = 15;
    int16_t redetect_score_q15 = 27853;  // 0.85
    TargetDetector detector = TargetDetector::ncc_template;
    // The frame homography leaves out the previous frame's corners whose patch reaches the
    // target's box (around the last estimate, grown by kTargetBoxSlackPx): the target moves on
    // the ground, so its corners, within the inlier threshold of the ground's motion when it
    // moves slowly, pulled every frame's homography towards its motion, and the accumulated
    // homography drifted with it. false: every corner (the paper).
    bool ground_corners_only = true;
    uint8_t morph_min_contrast = 12;  // morphological: a detection's top-hat, grey levels
};

// TargetPipelineParams' ranges (base/setting_range.h).
struct TargetPipelineRanges {
    SettingRange template_blend{"", 1, 64};
    SettingRange template_search_step{"placements", 1, 8};
    SettingRange motion_prior_q15{"Q15", 0, 32767};
    SettingRange redetect_after{"frames", 0, 65535};
    SettingRange redetect_score{"", 0, 1};  // NCC (redetect_score_q15: Q15)
};
inline constexpr TargetPipelineRanges kTargetPipelineRanges{};

inline const char* target_detector_name(TargetDetector d) {
    return d == TargetDetector::morphological ? "morphological" : "ncc_template";
}

// What one frame gave.
struct TargetFrame {
    bool started = false;      // this frame started the track (set_target)
    bool tracking = false;     // a track exists (started now or before)
    TargetEstimate estimate;   // the tracker's output (meaningful when tracking)
    uint16_t features = 0;     // Harris corners of this frame
    FrameHomography geometry;  // previous → this frame (status too_few_pairs on the first frame)
    SearchWindow window;       // where the template was searched
    TemplateHit hit;           // the best match there
    bool redetection = false;  // kept whole and searched for re-detection (hit: its best)
};

// The steps of TargetPipeline::finish(), in the order it ends them, for a caller that times them
// (the firmware's budgets). match and homography end only when there is a previous frame of the
// same size; predict, search, update and refresh only while tracking (not on the start frame).
enum class TargetStage : uint8_t {
    harris,      // corner selection (the per-row Harris response is done by push_row)
    match,       // NCC matches to the previous frame's corners, sub-pixel displacements
    homography,  // RANSAC and the refit
    predict,     // the filter's prediction and search window
    search,      // the template search (NCC) in the window, or a re-detection's in the frame
    update,      // the filter's update with the match
    refresh,     // the template cut again at the match, when it is
};

// Capacity: a base/capacity.h configuration (max_width, features, patch_radius, max_template,
// max_region).
template <class Capacity>
class TargetPipeline {
    static constexpr uint16_t MaxWidth = Capacity::max_width, MaxFeatures = Capacity::features;
    static constexpr int PatchRadius = Capacity::patch_radius;
    static constexpr uint8_t MaxTemplate = Capacity::max_template;
    static constexpr uint16_t MaxRegion = Capacity::max_region;
    static constexpr uint16_t MorphRegion = Capacity::morph_region;
    static constexpr uint16_t kMaxStep = RegionCapture<MaxRegion, MaxRegion>::kMaxStep;
    // The re-detection's template, pixels a side at least (fewer match anything).
    static constexpr uint8_t kMinRedetectSide = 4;
    using Morph =
        typename std::conditional<(MorphRegion > 0), MorphDetector<MorphRegion, MorphRegion>,
                                  MorphDetectorLeftOut>::type;

public:
    using Features = FeatureSet<PatchRadius, MaxFeatures>;

    // The parameters of the frame begun last.
    const TargetPipelineParams& params() const { return params_; }

    // Starts (or restarts) tracking at the next frame begun on the box of w × h pixels with
    // top-left (x, y), px; the target's centre is the box's centre. Called while a frame is
    // open, that frame goes on as before (its rows are not being kept for the box).
    // A box of up to MaxTemplate px a side is the template pixel for pixel; a larger one is seen
    // at a coarser step s (2..kMaxStep): the frame's s × s blocks, averaged, as pixels
    // (RegionCapture), s the smallest that brings the box within MaxTemplate blocks a side, the
    // blocks' grid placed on the box's top-left (and, in later frames, on the template's
    // expected top-left). The search, the template's refresh and the morphological detector
    // then work on blocks; the estimate, the window and the hit stay in frame pixels. bad_size
    // when w or h is 0 or above max_box_side(); the box is checked against the frame at
    // finish().
    Status set_target(int32_t x, int32_t y, uint16_t w, uint16_t h) {
        if (w == 0 || h == 0 || w > max_box_side() || h > max_box_side()) return Status::bad_size;
        const uint16_t side = w > h ? w : h;
        const uint16_t step = static_cast<uint16_t>((side + MaxTemplate - 1) / MaxTemplate);
        roi_x_ = x;
        roi_y_ = y;
        roi_w_ = w;
        roi_h_ = h;
        roi_step_ = step;
        pending_target_ = true;
        target_captured_ = false;
        return Status::ok;
    }
    // The largest box side set_target() takes, px: MaxTemplate blocks of kMaxStep px.
    static constexpr uint32_t max_box_side() { return uint32_t{MaxTemplate} * kMaxStep; }

    // bad_size (and no frame: rows and finish() get not_in_frame) when a dimension is 0 or
    // above capacity; previous_frame_incomplete when rows of the frame in progress were missing
    // (the new frame has started all the same). A refused or torn frame leaves no trace: the
    // next complete frame is matched to the last complete one and the track is as it was.
    // not_in_build (and no frame) when params ask for the morphological detector and the
    // capacity leaves it out (morph_region 0).
    Status begin_frame(uint16_t width, uint16_t height, const TargetPipelineParams& params) {
        const bool abandoned = open_ && y_ < height_;
        open_ = false;
        if (MorphRegion == 0 && params.detector == TargetDetector::morphological)
            return Status::not_in_build;
        params_ = params;
        gradient_.kernel.harris = &harris_;  // set each frame: a copied pipeline reads its own
        Status s = gradient_.begin_frame(width, height);
        if (s != Status::ok && s != Status::previous_frame_incomplete) return s;
        const Status h = harris_.begin_frame(width, height, params_.harris);
        if (h != Status::ok && h != Status::previous_frame_incomplete) return h;
        width_ = width;
        height_ = height;
        y_ = 0;
        open_ = true;
        target_captured_ = pending_target_;
        redetect_step_ = 0;
        if (pending_target_) {
            // The box's blocks and a margin around them (the morphological detector's opening
            // needs the target's surroundings).
            step_ = roi_step_;
            ox_ = static_cast<uint16_t>(floor_mod(roi_x_, step_));
            oy_ = static_cast<uint16_t>(floor_mod(roi_y_, step_));
            constexpr int64_t m = MaxTemplate / 2 + 2;
            capture_.begin(box_block(roi_x_, ox_) - m, box_block(roi_y_, oy_) - m,
                           box_blocks(roi_w_) + 2 * m, box_blocks(roi_h_) + 2 * m, width, height,
                           step_, ox_, oy_);
        } else if (tracking_ && (redetect_step_ = redetect_step()) > 0) {
            // The whole frame in coarse blocks (as much of it as the region holds).
            ox_ = oy_ = 0;
            capture_.begin(0, 0, MaxRegion, MaxRegion, width, height, redetect_step_);
        } else if (tracking_) {
            const SearchWindow e = tracker_.expected();
            const int32_t radius = static_cast<int32_t>(params_.tracker.max_radius_px >
                                                                params_.tracker.template_radius_px
                                                            ? params_.tracker.max_radius_px
                                                            : params_.tracker.template_radius_px);
            // In blocks (px at step 1): the radius and margin rounded up, half a template; the
            // grid on the template's expected top-left.
            ox_ = grid_origin(e.x, offset_x_q8_, template_.w);
            oy_ = grid_origin(e.y, offset_y_q8_, template_.h);
            expected_x_ = e.x;
            expected_y_ = e.y;
            const int64_t half = (int64_t{radius} + params_.capture_margin_px + step_ - 1) / step_ +
                                 MaxTemplate / 2 + 1;
            capture_.begin(floor_div(clamped_px(e.x) - ox_, step_) - half,
                           floor_div(clamped_px(e.y) - oy_, step_) - half, 2 * half + 1,
                           2 * half + 1, width, height, step_, ox_, oy_);
        } else {
            capture_.begin(0, 0, 0, 0, width, height);
        }
        return abandoned ? Status::previous_frame_incomplete : Status::ok;
    }

    Status push_row(const uint8_t* pixels, uint16_t length) {
        if (!open_ || !gradient_.in_frame()) return Status::not_in_frame;
        // A row of the wrong length: the Harris detector refuses it and abandons its frame, and
        // so does the pipeline (later rows and finish() get not_in_frame).
        Status s = harris_.push_pixel_row(pixels, length);
        if (s != Status::ok) {
            open_ = false;
            return s;
        }
        Status hs = Status::ok;
        s = gradient_.push_row(pixels, length,
                               [&](uint16_t y, const gradient_word* words, uint16_t w) {
                                   const Status r = harris_.push_gradient_row(y, words, w);
                                   if (r != Status::ok) hs = r;
                               });
        capture_.push_row(y_, pixels);
        ++y_;
        return s != Status::ok ? s : hs;
    }

    // After the last row: corners, homography, tracking.
    Status finish(TargetFrame& out) {
        return finish(out, [](TargetStage) {});
    }
    // The same, calling mark(stage) as each step of TargetStage ends.
    template <class Mark>
    Status finish(TargetFrame& out, Mark&& mark) {
        out = TargetFrame{};
        if (!open_ || y_ != height_ || width_ == 0) return Status::not_in_frame;
        const Status hs = harris_.finish();
        if (hs != Status::ok && hs != Status::capacity_exceeded) return hs;
        mark(TargetStage::harris);
        const Features& cur = harris_.features();
        out.features = cur.count;
        const FrameGeometry g = frame_geometry(cur, out, mark);
        if (pending_target_ && target_captured_) {
            pending_target_ = false;
            if (!start_target(out)) {
                keep_features(cur);
                return Status::bad_size;  // the box is not wholly inside the frame
            }
        } else if (tracking_) {
            track(g, out, mark);
        }
        out.tracking = tracking_;
        keep_features(cur);
        return hs;
    }

    const TargetTracker& tracker() const { return tracker_; }

private:
    // Table I: the homography from the previous frame's corners to this frame's (none when the
    // previous frame had another size: its corners cannot be matched).
    template <class Mark>
    FrameGeometry frame_geometry(const Features& cur, TargetFrame& out, Mark& mark) {
        FrameGeometry g;
        if (!have_previous_ || prev_.width != width_ || prev_.height != height_) return g;
        FrameHomographyParams gc = params_.geometry;
        // Corners move with the camera: look for each where the last homography sends it.
        float ex, ey;
        const float cx = 0.5f * static_cast<float>(width_), cy = 0.5f * static_cast<float>(height_);
        if (tracking_ && apply_homography(last_h_, cx, cy, ex, ey)) {
            gc.match.offset_x = clamp16(ex - cx);
            gc.match.offset_y = clamp16(ey - cy);
        }
        const bool exclude = params_.ground_corners_only && tracking_ && target_box_.valid;
        auto ground = [&](const Feature<PatchRadius>& f) {
            return !exclude || !target_box_.reaches(f.px, f.py, PatchRadius);
        };
        out.geometry =
            homography_between(prev_, cur, gc, scratch_, ground, [&] { mark(TargetStage::match); });
        mark(TargetStage::homography);
        g.valid = out.geometry.ransac.status == HomographyStatus::ok;
        // Unmeasured: too few pairs, with fewer ground corners in the previous frame (or corners
        // in this one) than a homography needs inliers (a bare scene). Corners enough that found
        // no pairs (a cut, noise, a flare) are evidence against the motion model instead. Counted
        // only when the pairs were too few.
        if (out.geometry.ransac.status == HomographyStatus::too_few_pairs) {
            uint16_t corners = 0;
            for (uint16_t i = 0; i < prev_.count && corners < cur.count; ++i)
                if (ground(prev_.items[i])) ++corners;
            g.unmeasured = corners < gc.ransac.min_inliers;
        }
        g.h = out.geometry.ransac.h;
        g.reprojection_px = out.geometry.ransac.reprojection_px;
        g.d_rep = out.geometry.ransac.d_rep;
        g.d_rep_capped_px = out.geometry.ransac.d_rep_capped_px;
        if (g.valid) last_h_ = g.h;
        return g;
    }

    // The frame set_target() named: its template cut, the filter started at the box's centre.
    // False, and no track, when the box is not wholly inside the frame.
    bool start_target(TargetFrame& out) {
        const PixelRegion& r = capture_.region();
        const int32_t bx = static_cast<int32_t>(box_block(roi_x_, ox_)),
                      by = static_cast<int32_t>(box_block(roi_y_, oy_));
        const uint8_t bw = static_cast<uint8_t>(box_blocks(roi_w_)),
                      bh = static_cast<uint8_t>(box_blocks(roi_h_));
        if (!box_in_frame() || !cut_template(r, bx, by, bw, bh, template_)) {
            tracking_ = false;
            return false;
        }
        const float x = static_cast<float>(roi_x_) + 0.5f * static_cast<float>(roi_w_ - 1);
        const float y = static_cast<float>(roi_y_) + 0.5f * static_cast<float>(roi_h_ - 1);
        tracker_.init(x, y, width_, height_, params_.tracker);
        unmatched_ = 0;
        look_pending_ = false;
        pose_.reset(x, y);
        last_h_ = Homography{};
        learn_morphology(r, bx, by, bw, bh);
        // The box's centre less the template's (its blocks' centre), 1/256 px: 0 at step 1.
        offset_x_q8_ = static_cast<int32_t>(int64_t{roi_x_} * 256 + (roi_w_ - 1) * 128 -
                                            to_frame_q8(int64_t{bx} * 256 + (bw - 1) * 128, ox_));
        offset_y_q8_ = static_cast<int32_t>(int64_t{roi_y_} * 256 + (roi_h_ - 1) * 128 -
                                            to_frame_q8(int64_t{by} * 256 + (bh - 1) * 128, oy_));
        tracking_ = true;
        out.started = true;
        out.estimate.state = tracker_.state();
        out.estimate.x = x;
        out.estimate.y = y;
        remember_box(x, y);
        return true;
    }

    // A tracked frame: predict (Table II), search the window, update, and re-cut the template
    // when its match has weakened.
    template <class Mark>
    void track(const FrameGeometry& g, TargetFrame& out, Mark& mark) {
        const bool was_lost = tracker_.state() == TargetState::lost;
        out.window = tracker_.predict(g);
        if (!was_lost) pose_.follow(tracker_.camera_motion());
        posed_ok_ = false;
        // A template can only match a target it wholly covers: while the prediction puts the
        // template across the image border (the target leaving or coming back), the best
        // placement inside is something else, so nothing is searched.
        // A re-detection frame is kept whole and coarse: the window is not searched in it.
        if (!template_inside(out.window.x, out.window.y) || redetect_step_ > 0)
            out.window.radius = 0;
        mark(TargetStage::predict);
        const TargetMeasurement m = out.window.radius > 0 ? measure(out) : TargetMeasurement{};
        out.redetection = redetect_step_ > 0;
        look_pending_ = out.redetection && redetect(out);
        mark(TargetStage::search);
        out.estimate = tracker_.update(m);
        remember_box(out.estimate.x, out.estimate.y);
        mark(TargetStage::update);
        const bool accepted = out.estimate.state == TargetState::measured ||
                              out.estimate.state == TargetState::reacquired;
        unmatched_ = accepted ? 0 : unmatched_ < UINT16_MAX ? unmatched_ + 1 : unmatched_;
        const bool every = params_.tracker.method == TargetMethod::template_only;
        const bool blend = params_.template_blend > 1 && !every;
        if (accepted && params_.detector == TargetDetector::ncc_template &&
            (every || blend || out.hit.score_q15 < params_.refresh_score_q15) &&
            grid_was_aligned(m))
            refresh_template(out.hit.x_q8 + offset_x_q8_, out.hit.y_q8 + offset_y_q8_,
                             blend ? params_.template_blend : 1);
        mark(TargetStage::refresh);
    }

    // This frame's re-detection step (frame px per block of the whole frame kept), or 0 for
    // none: off, a method that never measures (homography_only), too soon, the other frame of
    // the pair, a look to follow, or no step that fits the frame and leaves the template
    // kMinRedetectSide pixels a side.
    uint16_t redetect_step() const {
        const uint16_t after = params_.redetect_after;
        if (after == 0 || params_.detector != TargetDetector::ncc_template ||
            params_.tracker.method == TargetMethod::homography_only || look_pending_ ||
            unmatched_ < after || (unmatched_ - after) % 2 != 0)
            return 0;
        for (uint32_t s = step_; s <= kMaxStep; s += step_) {
            if ((width_ + s - 1) / s > MaxRegion || (height_ + s - 1) / s > MaxRegion) continue;
            const uint32_t f = s / step_;
            return template_.w / f >= kMinRedetectSide && template_.h / f >= kMinRedetectSide
                       ? static_cast<uint16_t>(s)
                       : 0;
        }
        return 0;
    }
    // A re-detection frame's search: the template averaged over f × f of its pixels (f: the
    // re-detection step over the track's) searched over the whole region. True, and the
    // tracker told to look there next frame, when the best placement's NCC reaches
    // redetect_score_q15; out.hit is that placement (frame px).
    bool redetect(TargetFrame& out) {
        TargetTemplate<MaxTemplate> coarse;
        shrink_template(template_, static_cast<uint16_t>(redetect_step_ / step_), coarse);
        const PixelRegion& r = capture_.region();
        const uint16_t half = static_cast<uint16_t>((r.w > r.h ? r.w : r.h) / 2 + 1);
        out.hit = search_template(coarse, r, r.x0 + r.w / 2, r.y0 + r.h / 2, half,
                                  params_.template_search_step);
        out.hit.x_q8 = static_cast<int32_t>(block_to_frame_q8(out.hit.x_q8, redetect_step_, 0));
        out.hit.y_q8 = static_cast<int32_t>(block_to_frame_q8(out.hit.y_q8, redetect_step_, 0));
        if (!out.hit.found || out.hit.score_q15 < params_.redetect_score_q15) return false;
        // The window: the coarse block's uncertainty and a frame's motion.
        const float radius = static_cast<float>(redetect_step_) + params_.tracker.min_radius_px;
        tracker_.look_at(
            static_cast<float>(out.hit.x_q8 + offset_x_q8_) * (1.0f / 256.0f),
            static_cast<float>(out.hit.y_q8 + offset_y_q8_) * (1.0f / 256.0f),
            radius < params_.tracker.max_radius_px ? radius : params_.tracker.max_radius_px,
            static_cast<float>(params_.redetect_score_q15) * (1.0f / 32768.0f));
        return true;
    }

    // The measurement in out.window (radius > 0) by the configured detector; out.hit in frame
    // pixels.
    TargetMeasurement measure(TargetFrame& out) {
        TargetMeasurement m;
        m.searched = true;
        // The window in blocks (pixels at step 1): centre and radius.
        const int32_t wx = to_blocks(out.window.x, ox_), wy = to_blocks(out.window.y, oy_);
        const uint16_t wr = static_cast<uint16_t>(
            (out.window.radius + static_cast<float>(step_ - 1)) / static_cast<float>(step_));
        if (params_.detector == TargetDetector::morphological) {
            const MorphDetection d =
                morph_detector_.detect(capture_.region(), wx, wy, wr, polarity_, morph_);
            out.hit.found = d.found;
            out.hit.x_q8 = static_cast<int32_t>(to_frame_q8(d.x_q8, ox_));
            out.hit.y_q8 = static_cast<int32_t>(to_frame_q8(d.y_q8, oy_));
            out.hit.score_q15 = d.found ? 32767 : 0;
            out.hit.positions = d.clusters;
            m.found = d.found;
            m.x = static_cast<float>(out.hit.x_q8) * (1.0f / 256.0f);
            m.y = static_cast<float>(out.hit.y_q8) * (1.0f / 256.0f);
            m.score = d.found ? 1.0f : 0.0f;
            return m;
        }
        // The template in this frame's pose; its centre offset (under half a pixel, or block)
        // is left as cut.
        float j[4];
        posed_ok_ = params_.template_follows_ground && pose_.jacobian(j) &&
                    !warp_negligible(j, template_.w, template_.h) &&
                    warp_template(template_.pixels, template_.w, template_.h, j, posed_.pixels);
        posed_.w = template_.w;
        posed_.h = template_.h;
        out.hit = search_template(posed_ok_ ? posed_ : template_, capture_.region(), wx, wy, wr,
                                  params_.template_search_step, params_.motion_prior_q15);
        out.hit.x_q8 = static_cast<int32_t>(to_frame_q8(out.hit.x_q8, ox_));
        out.hit.y_q8 = static_cast<int32_t>(to_frame_q8(out.hit.y_q8, oy_));
        if (out.hit.found) {
            m.found = true;
            m.x = static_cast<float>(out.hit.x_q8 + offset_x_q8_) * (1.0f / 256.0f);
            m.y = static_cast<float>(out.hit.y_q8 + offset_y_q8_) * (1.0f / 256.0f);
            m.score = static_cast<float>(out.hit.score_q15) * (1.0f / 32768.0f);
        }
        return m;
    }

    // Whether the template, placed for a target centred at (x, y) px, lies wholly inside the
    // image: its first and last pixels (blocks of step_ px at step > 1) within the frame.
    bool template_inside(float x, float y) const {
        const float left = template_first_px(x, offset_x_q8_, template_.w);
        const float top = template_first_px(y, offset_y_q8_, template_.h);
        return left >= 0 && top >= 0 &&
               left + static_cast<float>(template_.w * step_ - 1) <=
                   static_cast<float>(width_ - 1) &&
               top + static_cast<float>(template_.h * step_ - 1) <= static_cast<float>(height_ - 1);
    }
    // A position in px as an integer for the capture window, truncated toward zero; beyond
    // ±1e9 px (and NaN, as -1e9) the window misses every frame alike, so it is held there
    // rather than converted out of range.
    static int64_t clamped_px(float v) {
        constexpr float far_px = 1.0e9f;
        if (v > far_px) return static_cast<int64_t>(far_px);
        if (v > -far_px) return static_cast<int64_t>(v);
        return -static_cast<int64_t>(far_px);
    }
    // A match offset, px, held to ±32 000; NaN (no offset known) is 0, never converted.
    static int16_t clamp16(float v) {
        if (v != v) return 0;
        return static_cast<int16_t>(v < -32000.0f ? -32000.0f : v > 32000.0f ? 32000.0f : v);
    }
    // A window centre, px, rounded and held to ±1e6 (NaN: -1e6, outside every frame).
    static int32_t round_px(float v) {
        const float c = !(v >= -1.0e6f) ? -1.0e6f : v > 1.0e6f ? 1.0e6f : v;
        return static_cast<int32_t>(c < 0 ? c - 0.5f : c + 0.5f);
    }
    // Cuts the template again centred as near as whole pixels allow on the target centre
    // (x_q8, y_q8) (1/256 px) and keeps the remainder as the centre's offset from the template's
    // centre. Nothing changes when the template would leave the captured region.
    // (In blocks at a step above 1: the centre nearest in blocks, the offset in frame px.)
    void refresh_template(int32_t x_q8, int32_t y_q8, uint8_t blend) {
        const int32_t w = template_.w, h = template_.h;
        const int32_t bx_q8 = static_cast<int32_t>(from_frame_q8(x_q8, ox_)),
                      by_q8 = static_cast<int32_t>(from_frame_q8(y_q8, oy_));
        // Top-left so that the template centre tl + (w − 1)/2 is nearest the target centre.
        const int32_t left = static_cast<int32_t>(floor_div(bx_q8 - (w - 1) * 128 + 128, 256));
        const int32_t top = static_cast<int32_t>(floor_div(by_q8 - (h - 1) * 128 + 128, 256));
        TargetTemplate<MaxTemplate> cut;
        if (!cut_template(capture_.region(), left, top, template_.w, template_.h, cut)) return;
        const int32_t cut_x_q8 =
            static_cast<int32_t>(x_q8 - to_frame_q8(int64_t{left} * 256 + (w - 1) * 128, ox_));
        const int32_t cut_y_q8 =
            static_cast<int32_t>(y_q8 - to_frame_q8(int64_t{top} * 256 + (h - 1) * 128, oy_));
        // The template as searched this frame (in the current pose) moves toward the cut; its
        // pose is then this frame's.
        const uint8_t* from = posed_ok_ ? posed_.pixels : template_.pixels;
        for (int32_t i = 0; i < w * h; ++i)
            template_.pixels[i] = static_cast<uint8_t>(blend_toward(from[i], cut.pixels[i], blend));
        // The target's offset from the template's centre follows the cut's, except in blocks
        // under a running mean. There the cut is placed by the estimate, which carries the
        // match's sub-pixel bias, and the block grid is placed by it too: blended into the
        // offset, the bias came back every frame, and a still target drifted without bound
        // (3 px in 100 frames at 5 px a block). The offset set_target() gave is kept instead:
        // the mean of the cuts holds the target where the first cut did. (At step 1 the cut's
        // whole-pixel placement bounds the offset to ±0.5 px.)
        if (blend <= 1 || step_ == 1) {
            offset_x_q8_ = blend_toward(offset_x_q8_, cut_x_q8, blend);
            offset_y_q8_ = blend_toward(offset_y_q8_, cut_y_q8, blend);
        }
        pose_.reset(static_cast<float>(x_q8) * (1.0f / 256.0f),
                    static_cast<float>(y_q8) * (1.0f / 256.0f));
    }
    // At a step above 1, whether the target was found within a quarter block of where the grid
    // was placed for it: only then do its blocks hold the template's pixels, so that a template
    // cut from them carries no part-block misplacement into the track (always true at step 1).
    bool grid_was_aligned(const TargetMeasurement& m) const {
        if (step_ == 1) return true;
        const float quarter = 0.25f * static_cast<float>(step_);
        const float dx = m.x - expected_x_, dy = m.y - expected_y_;
        return dx <= quarter && dx >= -quarter && dy <= quarter && dy >= -quarter;
    }
    // Blocks of step_ px across a box side of n px (the grid starts on the box's edge).
    int64_t box_blocks(int64_t n) const { return (n + step_ - 1) / step_; }
    // The block of the grid from origin o whose first pixel is frame pixel a.
    int64_t box_block(int64_t a, int64_t o) const { return floor_div(a - o, step_); }
    // The template's first pixel along one axis, px, for a target centred at `centre` px: the
    // centre less the target's offset from the template's centre (1/256 px) less half the
    // template (`blocks` a side, step_ px each).
    float template_first_px(float centre, int32_t offset_q8, int32_t blocks) const {
        const float s = static_cast<float>(step_);
        return centre - static_cast<float>(offset_q8) * (1.0f / 256.0f) -
               0.5f * s * static_cast<float>(blocks - 1) - 0.5f * (s - 1.0f);
    }
    // The grid origin, [0, step), that puts a block edge at the template's expected first
    // pixel. 0 at step 1.
    uint16_t grid_origin(float centre, int32_t offset_q8, int32_t blocks) const {
        const float left = template_first_px(centre, offset_q8, blocks);
        const int64_t a = clamped_px(left < 0 ? left - 0.5f : left + 0.5f);
        return static_cast<uint16_t>(floor_mod(a, step_));
    }
    // A block coordinate (1/256 block) of the grid of step s from origin o as frame px (1/256
    // px): block X's centre is frame pixel o + s·X + (s − 1)/2. The identity at step 1.
    static int64_t block_to_frame_q8(int64_t b_q8, uint16_t s, uint16_t o) {
        return b_q8 * s + (s - 1) * 128 + int64_t{o} * 256;
    }
    // The same on this frame's grid (step_).
    int64_t to_frame_q8(int64_t b_q8, uint16_t o) const {
        return block_to_frame_q8(b_q8, step_, o);
    }
    // The inverse, rounded down to 1/256 block.
    int64_t from_frame_q8(int64_t f_q8, uint16_t o) const {
        return floor_div(f_q8 - (step_ - 1) * 128 - int64_t{o} * 256, step_);
    }
    // A window centre, px, as the nearest block (round_px(v) itself at step 1).
    int32_t to_blocks(float v, uint16_t o) const {
        const float s = static_cast<float>(step_);
        return round_px((v - static_cast<float>(o) - 0.5f * (s - 1.0f)) / s);
    }
    // The box of set_target() lies wholly inside the frame begun.
    bool box_in_frame() const {
        return roi_x_ >= 0 && roi_y_ >= 0 && int64_t{roi_x_} + roi_w_ <= width_ &&
               int64_t{roi_y_} + roi_h_ <= height_;
    }
    // The morphological detector's settings from the box of frame 0: an element two pixels
    // wider than the box (odd), the polarity in which a cluster is found nearest the box's
    // centre, and areas within 1/4..4× of that cluster's.
    // (The box in blocks: bx, by, bw, bh; pixels at step 1.)
    void learn_morphology(const PixelRegion& r, int32_t bx, int32_t by, int32_t bw, int32_t bh) {
        const int32_t side = bw > bh ? bw : bh;
        morph_ = MorphParams{};
        morph_.element = static_cast<uint8_t>((side + 2) | 1);
        morph_.min_contrast = params_.morph_min_contrast;
        morph_.min_area = 1;
        morph_.max_area = 65535;
        const int32_t cx = bx + (bw - 1) / 2, cy = by + (bh - 1) / 2;
        const uint16_t rad = static_cast<uint16_t>(side / 2);
        const MorphDetection b = morph_detector_.detect(r, cx, cy, rad, Polarity::bright, morph_);
        const MorphDetection d = morph_detector_.detect(r, cx, cy, rad, Polarity::dark, morph_);
        auto dist = [&](const MorphDetection& k) {
            const int64_t dx = k.x_q8 - int64_t{cx} * 256, dy = k.y_q8 - int64_t{cy} * 256;
            return dx * dx + dy * dy;
        };
        const bool dark = d.found && (!b.found || dist(d) < dist(b));
        polarity_ = dark ? Polarity::dark : Polarity::bright;
        const uint16_t area = dark ? d.area : b.found ? b.area : 16;
        morph_.min_area = static_cast<uint16_t>(area / 4 > 1 ? area / 4 : 1);
        morph_.max_area = static_cast<uint16_t>(area > 16383 ? 65535 : area * 4);
    }
    // The target's box in this frame, for the next frame's homography: the template's extent
    // (blocks of step_ px) centred on the estimate; none once the track is lost.
    void remember_box(float x, float y) {
        target_box_.valid = tracking_ && tracker_.state() != TargetState::lost;
        const float half_w = 0.5f * static_cast<float>(template_.w * step_),
                    half_h = 0.5f * static_cast<float>(template_.h * step_);
        target_box_.x0 = x - half_w - kTargetBoxSlackPx;
        target_box_.x1 = x + half_w + kTargetBoxSlackPx;
        target_box_.y0 = y - half_h - kTargetBoxSlackPx;
        target_box_.y1 = y + half_h + kTargetBoxSlackPx;
    }

    // This frame's corners become the next frame's previous ones (a copy: the detector's set
    // is overwritten by the next frame, and one copy costs less RAM than a second detector set).
    void keep_features(const Features& cur) {
        prev_.width = cur.width;
        prev_.height = cur.height;
        prev_.count = cur.count;
        for (uint16_t i = 0; i < cur.count; ++i) prev_.items[i] = cur.items[i];
        have_previous_ = true;
    }

    TargetPipelineParams params_;
    // XyWordRowKernel in the rows Harris reads only (its bands): the others are not computed.
    struct HarrisRowsKernel : XyWordRowKernel {
        const HarrisDetector<MaxWidth, MaxFeatures, PatchRadius>* harris = nullptr;
        void operator()(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                        uint16_t width, uint16_t y, gradient_word* out) const {
            if (harris->needs_gradient_row(y))
                XyWordRowKernel::operator()(above, center, below, width, y, out);
        }
    };
    GradientStage<MaxWidth, HarrisRowsKernel> gradient_;
    HarrisDetector<MaxWidth, MaxFeatures, PatchRadius> harris_;
    Features prev_;  // the previous frame's corners
    FrameHomographyScratch<PatchRadius, MaxFeatures> scratch_;
    RegionCapture<MaxRegion, MaxRegion> capture_;
    TargetTemplate<MaxTemplate> template_;
    // The template warped into this frame's pose (valid when posed_ok_), and that pose.
    TargetTemplate<MaxTemplate> posed_;
    bool posed_ok_ = false;
    TemplatePose pose_;
    TargetTracker tracker_;
    Morph morph_detector_;
    MorphParams morph_;
    Polarity polarity_ = Polarity::bright;
    Homography last_h_;
    // The estimate's error and the target's motion in a frame are a few px: the box grows by
    // this much each side, px.
    static constexpr float kTargetBoxSlackPx = 2.0f;
    struct TargetBox {
        bool valid = false;
        float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // px, the previous frame's image
        // Whether the patch of radius r px centred on pixel (x, y) overlaps the box.
        bool reaches(int16_t x, int16_t y, int r) const {
            const float fx = static_cast<float>(x), fy = static_cast<float>(y),
                        fr = static_cast<float>(r);
            return fx + fr >= x0 && fx - fr <= x1 && fy + fr >= y0 && fy - fr <= y1;
        }
    };
    TargetBox target_box_;  // ground_corners_only: the target in the previous frame
    uint16_t width_ = 0, height_ = 0, y_ = 0;
    bool have_previous_ = false;
    bool open_ = false;  // a frame was begun and none of its rows refused
    bool tracking_ = false;
    uint16_t unmatched_ = 0;      // tracked frames since the last accepted match
    uint16_t redetect_step_ = 0;  // this frame is kept whole at this step to re-detect (0: not)
    bool look_pending_ = false;   // the last frame's re-detection told the tracker where to look
    bool pending_target_ = false;
    bool target_captured_ = false;  // this frame's rows are kept around the pending box
    int32_t offset_x_q8_ = 0, offset_y_q8_ = 0;  // target centre − template centre, 1/256 px
    int32_t roi_x_ = 0, roi_y_ = 0;              // set_target()'s box, px
    uint16_t roi_w_ = 0, roi_h_ = 0;
    uint16_t roi_step_ = 1;     // its step, from the frame it starts on
    uint16_t step_ = 1;         // the track's step: frame px per block of the captured region
    uint16_t ox_ = 0, oy_ = 0;  // this frame's block grid origin, px in [0, step_)
    float expected_x_ = 0, expected_y_ = 0;  // the target centre the grid was placed for, px
};

// QVGA: 320-pixel rows, 96 corners, 9×9 patches, templates up to 16×16, a captured region of
// up to 84×84 px (the default 24 px search radius + 8 px margin + half a template, each side).
using TargetPipelineQvga = TargetPipeline<Qvga>;
// VGA for the CLI.
using TargetPipelineVga = TargetPipeline<Vga>;

}  // namespace qt
