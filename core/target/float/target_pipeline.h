// The target tracker's whole frame, streamed row by row (filtering-geometry.txt Fig. 3 with
// Table I): camera rows → gradient words (gradient_stage.h, or the FPGA block's) → Harris
// corners with their patches (harris.h) → NCC matches to the previous frame's corners →
// RANSAC homography → target tracker (target_tracker.h), whose measurement is the template
// found by NCC (template_search.h) in a region of the frame captured as its rows went by.
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
#include "base/status.h"
#include "gradient/gradient_stage.h"
#include "target/float/frame_homography.h"
#include "target/float/target_tracker.h"
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

struct TargetPipelineParams {
    HarrisParams harris;
    FrameHomographyParams geometry;
    TargetTrackerParams tracker;
    uint16_t capture_margin_px = 8;  // region kept beyond the expected search window, px
    // The template is cut again at the match when a measurement is accepted with an NCC
    // below this (Q15; 0.85 = 27853): it follows the target's slow change of look (scale,
    // rotation, the ground moving behind it) without being re-cut every frame, which would
    // let the sub-pixel errors of successive cuts add up to a drift. 0: never. template_only
    // refreshes at every match, as the paper's template tracker does (its Fig. 8).
    int32_t refresh_score_q15 = 27853;
    TargetDetector detector = TargetDetector::ncc_template;
    uint8_t morph_min_contrast = 12;  // morphological: a detection's top-hat, grey levels
};

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
};

// The steps of TargetPipeline::finish(), in the order it ends them, for a caller that times them
// (the firmware's budgets). match and homography end only when there is a previous frame of the
// same size; predict, search, update and refresh only while tracking (not on the start frame).
enum class TargetStage : uint8_t {
    harris,      // corner selection (the per-row Harris response is done by push_row)
    match,       // NCC matches to the previous frame's corners, sub-pixel displacements
    homography,  // RANSAC and the refit
    predict,     // the filter's prediction and search window
    search,      // the template search (NCC) in the window
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
    using Morph =
        typename std::conditional<(MorphRegion > 0), MorphDetector<MorphRegion, MorphRegion>,
                                  MorphDetectorLeftOut>::type;

public:
    using Features = FeatureSet<PatchRadius, MaxFeatures>;

    // The parameters of the frame begun last.
    const TargetPipelineParams& params() const { return params_; }

    // Starts (or restarts) tracking at the next frame begun: the template is that frame's w × h
    // pixels with top-left (x, y), px; the target's centre is the box's centre. Called while a
    // frame is open, that frame goes on as before (its rows are not being kept for the box).
    // bad_size when w or h is 0 or above MaxTemplate (the box is checked against the frame at
    // finish()).
    Status set_target(int32_t x, int32_t y, uint8_t w, uint8_t h) {
        if (w == 0 || h == 0 || w > MaxTemplate || h > MaxTemplate) return Status::bad_size;
        roi_x_ = x;
        roi_y_ = y;
        roi_w_ = w;
        roi_h_ = h;
        pending_target_ = true;
        target_captured_ = false;
        return Status::ok;
    }

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
        Status s = gradient_.begin_frame(width, height);
        if (s != Status::ok && s != Status::previous_frame_incomplete) return s;
        const Status h = harris_.begin_frame(width, height, params_.harris);
        if (h != Status::ok && h != Status::previous_frame_incomplete) return h;
        width_ = width;
        height_ = height;
        y_ = 0;
        open_ = true;
        target_captured_ = pending_target_;
        if (pending_target_) {
            // The box and a margin around it (the morphological detector's opening needs the
            // target's surroundings).
            constexpr int64_t m = MaxTemplate / 2 + 2;
            capture_.begin(roi_x_ - m, roi_y_ - m, roi_w_ + 2 * m, roi_h_ + 2 * m, width, height);
        } else if (tracking_) {
            const SearchWindow e = tracker_.expected();
            const int32_t half = static_cast<int32_t>(params_.tracker.max_radius_px >
                                                              params_.tracker.template_radius_px
                                                          ? params_.tracker.max_radius_px
                                                          : params_.tracker.template_radius_px) +
                                 params_.capture_margin_px + MaxTemplate / 2 + 1;
            capture_.begin(clamped_px(e.x) - half, clamped_px(e.y) - half, 2 * half + 1,
                           2 * half + 1, width, height);
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
        FrameGeometry g;
        // Another size than the previous frame's: its corners cannot be matched; the track goes
        // on without a homography this frame.
        if (have_previous_ && prev_.width == width_ && prev_.height == height_) {
            FrameHomographyParams gc = params_.geometry;
            // Corners move with the camera: look for each where the last homography sends it.
            float ex, ey;
            const float cx = 0.5f * static_cast<float>(width_),
                        cy = 0.5f * static_cast<float>(height_);
            if (tracking_ && apply_homography(last_h_, cx, cy, ex, ey)) {
                gc.match.offset_x = clamp16(ex - cx);
                gc.match.offset_y = clamp16(ey - cy);
            }
            out.geometry =
                homography_between(prev_, cur, gc, scratch_, [&] { mark(TargetStage::match); });
            mark(TargetStage::homography);
            g.valid = out.geometry.ransac.status == HomographyStatus::ok;
            g.h = out.geometry.ransac.h;
            g.reprojection_px = out.geometry.ransac.reprojection_px;
            g.d_rep = out.geometry.ransac.d_rep;
            g.d_rep_capped_px = out.geometry.ransac.d_rep_capped_px;
            if (g.valid) last_h_ = g.h;
        }
        if (pending_target_ && target_captured_) {
            pending_target_ = false;
            const PixelRegion& r = capture_.region();
            if (!cut_template(r, roi_x_, roi_y_, roi_w_, roi_h_, template_)) {
                tracking_ = false;
                keep_features(cur);
                return Status::bad_size;  // the box is not wholly inside the frame
            }
            tracker_.init(static_cast<float>(roi_x_) + 0.5f * static_cast<float>(roi_w_ - 1),
                          static_cast<float>(roi_y_) + 0.5f * static_cast<float>(roi_h_ - 1),
                          width_, height_, params_.tracker);
            last_h_ = Homography{};
            learn_morphology(r);
            // The box's centre is the template's: no offset.
            offset_x_q8_ = 0;
            offset_y_q8_ = 0;
            tracking_ = true;
            out.started = true;
            out.estimate.state = tracker_.state();
            out.estimate.x = static_cast<float>(roi_x_) + 0.5f * static_cast<float>(roi_w_ - 1);
            out.estimate.y = static_cast<float>(roi_y_) + 0.5f * static_cast<float>(roi_h_ - 1);
        } else if (tracking_) {
            out.window = tracker_.predict(g);
            mark(TargetStage::predict);
            TargetMeasurement m;
            if (out.window.radius > 0 && params_.detector == TargetDetector::morphological) {
                const MorphDetection d = morph_detector_.detect(
                    capture_.region(), round_px(out.window.x), round_px(out.window.y),
                    static_cast<uint16_t>(out.window.radius), polarity_, morph_);
                out.hit.found = d.found;
                out.hit.x_q8 = d.x_q8;
                out.hit.y_q8 = d.y_q8;
                out.hit.score_q15 = d.found ? 32767 : 0;
                out.hit.positions = d.clusters;
                m.found = d.found;
                m.x = static_cast<float>(d.x_q8) * (1.0f / 256.0f);
                m.y = static_cast<float>(d.y_q8) * (1.0f / 256.0f);
                m.score = d.found ? 1.0f : 0.0f;
            } else if (out.window.radius > 0) {
                const float rad = out.window.radius;
                out.hit = search_template(template_, capture_.region(), round_px(out.window.x),
                                          round_px(out.window.y), static_cast<uint16_t>(rad));
                if (out.hit.found) {
                    m.found = true;
                    m.x = static_cast<float>(out.hit.x_q8 + offset_x_q8_) * (1.0f / 256.0f);
                    m.y = static_cast<float>(out.hit.y_q8 + offset_y_q8_) * (1.0f / 256.0f);
                    m.score = static_cast<float>(out.hit.score_q15) * (1.0f / 32768.0f);
                }
            }
            mark(TargetStage::search);
            out.estimate = tracker_.update(m);
            mark(TargetStage::update);
            const bool accepted = out.estimate.state == TargetState::measured ||
                                  out.estimate.state == TargetState::reacquired;
            const bool every = params_.tracker.method == TargetMethod::template_only;
            if (accepted && params_.detector == TargetDetector::ncc_template &&
                (every || out.hit.score_q15 < params_.refresh_score_q15))
                refresh_template(out.hit.x_q8 + offset_x_q8_, out.hit.y_q8 + offset_y_q8_);
            mark(TargetStage::refresh);
        }
        out.tracking = tracking_;
        keep_features(cur);
        return hs;
    }

    const TargetTracker& tracker() const { return tracker_; }

private:
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
    void refresh_template(int32_t x_q8, int32_t y_q8) {
        const int32_t w = template_.w, h = template_.h;
        // Top-left so that the template centre tl + (w − 1)/2 is nearest the target centre.
        const int32_t left = floor_div256(x_q8 - (w - 1) * 128 + 128);
        const int32_t top = floor_div256(y_q8 - (h - 1) * 128 + 128);
        if (!cut_template(capture_.region(), left, top, template_.w, template_.h, template_))
            return;
        offset_x_q8_ = x_q8 - (left * 256 + (w - 1) * 128);
        offset_y_q8_ = y_q8 - (top * 256 + (h - 1) * 128);
    }
    // The morphological detector's settings from the box of frame 0: an element two pixels
    // wider than the box (odd), the polarity in which a cluster is found nearest the box's
    // centre, and areas within 1/4..4× of that cluster's.
    void learn_morphology(const PixelRegion& r) {
        const int32_t side = roi_w_ > roi_h_ ? roi_w_ : roi_h_;
        morph_ = MorphParams{};
        morph_.element = static_cast<uint8_t>((side + 2) | 1);
        morph_.min_contrast = params_.morph_min_contrast;
        morph_.min_area = 1;
        morph_.max_area = 65535;
        const int32_t cx = roi_x_ + (roi_w_ - 1) / 2, cy = roi_y_ + (roi_h_ - 1) / 2;
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
    static int32_t floor_div256(int32_t v) { return v >= 0 ? v / 256 : -((255 - v) / 256); }
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
    GradientStage<MaxWidth, XyWordRowKernel> gradient_;  // gx, gy only: all Harris reads
    HarrisDetector<MaxWidth, MaxFeatures, PatchRadius> harris_;
    Features prev_;  // the previous frame's corners
    FrameHomographyScratch<PatchRadius, MaxFeatures> scratch_;
    RegionCapture<MaxRegion, MaxRegion> capture_;
    TargetTemplate<MaxTemplate> template_;
    TargetTracker tracker_;
    Morph morph_detector_;
    MorphParams morph_;
    Polarity polarity_ = Polarity::bright;
    Homography last_h_;
    uint16_t width_ = 0, height_ = 0, y_ = 0;
    bool have_previous_ = false;
    bool open_ = false;  // a frame was begun and none of its rows refused
    bool tracking_ = false;
    bool pending_target_ = false;
    bool target_captured_ = false;  // this frame's rows are kept around the pending box
    int32_t offset_x_q8_ = 0, offset_y_q8_ = 0;  // target centre − template centre, 1/256 px
    int32_t roi_x_ = 0, roi_y_ = 0;
    uint8_t roi_w_ = 0, roi_h_ = 0;
};

// QVGA: 320-pixel rows, 96 corners, 9×9 patches, templates up to 16×16, a captured region of
// up to 84×84 px (the default 24 px search radius + 8 px margin + half a template, each side).
using TargetPipelineQvga = TargetPipeline<Qvga>;
// VGA for the CLI.
using TargetPipelineVga = TargetPipeline<Vga>;

}  // namespace qt
