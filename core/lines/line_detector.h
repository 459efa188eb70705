// The lines stage of one frame, all memory inside, fixed at compile time: gradient (or words from
// the FPGA) -> edges -> PPHT segments -> clustered lines, ends joined at corners. Camera rows go
// through the gradient and NMS without forming gradient words (edge_stage.h: same edges, less
// work).
//
//   static qt::LineDetectorQvga det;           // ~44 KiB, see ram_bytes()
//   det.begin_frame(320, 240, params);
//   for each camera row: det.push_row(row, 320);        // or push_gradient_row(words, 320)
//   (or, with the FPGA front end: det.push_edge_beats(beats, n, &used) until edge_beats_done())
//   det.finish();                              // runs PPHT and clustering
//   det.lines(), det.line_count(), det.stats()
#pragma once
#include <stdint.h>

#include "base/capacity.h"
#include "base/setting_range.h"
#include "gradient/gradient_stage.h"
#include "lines/edge_beat.h"
#include "lines/edge_stage.h"
#include "lines/hough.h"
#include "lines/line_cluster.h"
#include "lines/smooth_rows.h"

namespace qt {

// The edge map's front end (the Quadrangle Detection paper §2.3, Figure 3: a Canny edge map).
enum class EdgeFrontEnd : uint8_t {
    // Ours (default): central differences of the raw rows, one threshold, NMS.
    threshold_nms,
    // The paper's Canny: Gaussian smoothing of the camera rows (smooth_rows.h, σ ≈ 0.7 px;
    // rows of gradient words from the FPGA are used as they come), NMS, hysteresis between
    // edge_threshold (low) and canny_high (edge_list.h).
    canny,
};
inline const char* edge_front_end_name(EdgeFrontEnd f) {
    return f == EdgeFrontEnd::canny ? "canny" : "threshold_nms";
}

struct LineParams {
    uint16_t edge_threshold = 40;  // L1 gradient magnitude for an edge, grey levels (1..510)
    EdgeFrontEnd front_end = EdgeFrontEnd::threshold_nms;
    uint16_t canny_high = 0;  // canny: the high threshold, grey levels; 0: 2 · edge_threshold
    HoughParams hough;
    ClusterParams cluster;
    CornerParams corners;
};

// LineParams' own units and accepted ranges (base/setting_range.h); the rest are kHoughRanges
// and kClusterRanges.
struct LineRanges {
    SettingRange edge_threshold{"grey levels", 1, 510};
    SettingRange canny_high{"grey levels", 0, 510};
};
inline constexpr LineRanges kLineRanges{};

// The stages of finish(), in order: PPHT; clustering and corner joining; the quadrangle rules
// (board_detector.h). finish(mark) calls mark(stage) as each ends, so a caller can time them.
enum class FinishStage : uint8_t { hough, cluster, quads };

struct LineStats {
    uint32_t edges = 0;             // edge points kept
    uint32_t edges_dropped = 0;     // edge points lost to the edge capacity (thinned or floored)
    uint32_t edges_hysteresis = 0;  // canny: weak edge points not joined to a strong one
    HoughStats hough;
    ClusterStats cluster;
};

// Capacity: a base/capacity.h configuration (max_width, max_height, edge_points, theta_bins,
// rho_step, segments, lines).
template <class Capacity>
class LineDetector {
    static constexpr uint16_t MaxWidth = Capacity::max_width, MaxHeight = Capacity::max_height;
    static constexpr uint16_t EdgeCapacity = Capacity::edge_points;
    static constexpr uint16_t MaxThetaBins = Capacity::theta_bins;
    static constexpr uint32_t HoughBins =
        hough_bins_for(MaxWidth, MaxHeight, Capacity::theta_bins, Capacity::rho_step);
    static constexpr uint16_t MaxSegments = Capacity::segments, MaxLines = Capacity::lines;
    static_assert(MaxSegments <= 255, "clustering handles up to 255 segments");
    static_assert(HoughBins >= 2u * EdgeCapacity, "the accumulator holds hysteresis' stack");

public:
    // Bytes of RAM one detector occupies (all of it static when the object is).
    static constexpr uint32_t ram_bytes() { return sizeof(LineDetector); }
    static constexpr uint16_t max_lines() { return MaxLines; }

    // bad_size (and no frame: rows and finish() get not_in_frame) when a dimension is 0 or
    // above capacity; previous_frame_incomplete when rows of the frame in progress were missing
    // (the new frame has started all the same).
    // window (tracking mode, band_window.h): when active, the frame's edges are sought only in
    // its bands, from camera rows (threshold_nms; canny takes the whole frame: its hysteresis
    // joins edges through pixels outside the bands), gradient rows or edge beats (those outside
    // are passed over); it must stay unchanged until the frame's last row or beat.
    Status begin_frame(uint16_t width, uint16_t height, const LineParams& params,
                       BandWindow* window = nullptr) {
        params_ = params;
        stats_ = LineStats{};
        segment_count_ = line_count_ = 0;
        width_ = height_ = 0;  // until the frame has begun: finish() then says not_in_frame
        window_ = nullptr;
        // Rows missing from the open frame: the edge stage knows, as both paths feed it (the
        // gradient stage is never fed by push_gradient_row, so it cannot tell).
        const bool abandoned = open_ && edge_stage_.in_frame();
        open_ = false;
        if (height > MaxHeight) return Status::bad_size;
        edges_view_ = edges_.view();
        gradient_.kernel.edge_threshold = params.edge_threshold;
        const bool banded =
            window != nullptr && window->active() && params.front_end != EdgeFrontEnd::canny;
        if (banded) window->begin_frame(width, height);
        BandWindow* bands = banded ? window : nullptr;
        window_ = bands;
        gradient_.kernel.bands = bands;
        Status s = gradient_.begin_frame(width, height);
        if (s != Status::ok && s != Status::previous_frame_incomplete) return s;
        const Status e =
            edge_stage_.begin_frame(width, height, params.edge_threshold, edges_view_, bands);
        if (e != Status::ok) return e;
        if (params.front_end == EdgeFrontEnd::canny) smooth_.begin_frame(width, height);
        width_ = width;
        height_ = height;
        open_ = true;
        beats_ = rows_seen_ = false;
        return abandoned ? Status::previous_frame_incomplete : Status::ok;
    }

    // A camera row (grey levels). A refused row (bad_row_length) abandons the frame: later rows
    // and finish() get not_in_frame until the next begin_frame().
    Status push_row(const uint8_t* pixels, uint16_t length) {
        // The edge stage, fed by both paths, leaves the frame with its last row: a camera row
        // after a frame of gradient words is a row after the last one too.
        if (!open_ || !edge_stage_.in_frame() || beats_) return Status::not_in_frame;
        rows_seen_ = true;
        // Directions only where the list can still take the edge: NMS reads a pixel's direction
        // only at or above its threshold, which is at least the list's floor now (the floor only
        // rises), so the rows give the same list with less work once a busy frame fills it.
        const uint16_t list_floor = edges_view_.floor();
        gradient_.kernel.edge_threshold =
            list_floor > params_.edge_threshold ? list_floor : params_.edge_threshold;
        Status edge_status = Status::ok;
        auto edges = [&](uint16_t, const uint16_t* packed, uint16_t n) {
            const Status e = edge_stage_.push_packed_row(packed, n);
            if (e != Status::ok) edge_status = e;
        };
        if (params_.front_end == EdgeFrontEnd::canny) {
            Status g = Status::ok;
            const Status s = smooth_.push_row(pixels, length, [&](const uint8_t* row, uint16_t n) {
                const Status r = gradient_.push_row(row, n, edges);
                if (r != Status::ok) g = r;
            });
            return row_status(s != Status::ok ? s : g != Status::ok ? g : edge_status);
        }
        const Status s = gradient_.push_row(pixels, length, edges);
        return row_status(s != Status::ok ? s : edge_status);
    }

    // A row of gradient words (from the FPGA block), instead of push_row; the same statuses.
    Status push_gradient_row(const gradient_word* words, uint16_t width) {
        if (!open_ || beats_) return Status::not_in_frame;
        rows_seen_ = true;
        return row_status(edge_stage_.push_row(words, width));
    }

    // The frame's edge beats from the FPGA front end (edge_beat.h), instead of rows: the edge
    // list takes its points (those at or above edge_threshold); *used says how many beats were
    // taken, up to and including the frame's trailer, after which edge_beats_done() is true
    // and finish() may run. bad_stream abandons the frame (the FPGA reported it broken off, or
    // the beats do not fit it); not_in_frame after rows, or with no frame begun.
    Status push_edge_beats(const uint8_t* beats, uint32_t count, uint32_t* used) {
        *used = 0;
        if (!open_ || !edge_stage_.in_frame()) return Status::not_in_frame;
        if (!beats_) {
            if (rows_seen_) return Status::not_in_frame;
            beats_ = true;
            feed_.begin_frame(edges_view_, width_, height_, params_.edge_threshold, window_);
        }
        const Status s = feed_.push(beats, count, used);
        if (s != Status::ok) {
            open_ = false;
            return s;
        }
        if (feed_.done()) edge_stage_.close();
        return Status::ok;
    }
    bool edge_beats_done() const { return beats_ && feed_.done(); }

    // After the last row, instead of finish(): closes the frame with its edges and no lines
    // (tracking mode's side fitting measures the sides from the edges). not_in_frame as
    // finish(); capacity_exceeded when edges were dropped.
    Status finish_edges() {
        if (!open_ || edge_stage_.in_frame() || edges_view_.height() != height_ || height_ == 0)
            return Status::not_in_frame;
        open_ = false;
        stats_.edges = edges_view_.size();
        stats_.edges_dropped = edges_view_.dropped();
        return stats_.edges_dropped > 0 ? Status::capacity_exceeded : Status::ok;
    }

    // After the last row: PPHT and clustering. not_in_frame if rows are missing, the frame was
    // abandoned or already finished; capacity_exceeded when edges, segments or clusters were
    // dropped or PPHT ran out of a work budget (walk steps, voters) (the lines found are valid;
    // stats() says what was cut).
    Status finish() {
        return finish([](FinishStage) {});
    }
    // The same, calling mark(stage) as each stage ends (for timing them).
    template <class Mark>
    Status finish(Mark&& mark) {
        if (!open_ || edge_stage_.in_frame() || edges_view_.height() != height_ || height_ == 0)
            return Status::not_in_frame;
        open_ = false;  // once per frame: PPHT consumes the edge list
        if (params_.front_end == EdgeFrontEnd::canny) {
            // Hysteresis before PPHT, its stack in the accumulator PPHT clears when it starts.
            const uint16_t high = params_.canny_high
                                      ? params_.canny_high
                                      : static_cast<uint16_t>(2u * params_.edge_threshold);
            stats_.edges_hysteresis = edges_view_.hysteresis(high, hough_.bins, HoughBins);
        }
        stats_.edges = edges_view_.size();
        stats_.edges_dropped = edges_view_.dropped();
        const Status h = hough_segments(edges_view_, width_, height_, params_.hough, hough_.view(),
                                        segments_, MaxSegments, &segment_count_, &stats_.hough);
        mark(FinishStage::hough);
        if (h != Status::ok) return h;
        const Status c = cluster_segments(segments_, segment_count_, params_.cluster, scratch_,
                                          lines_, MaxLines, &line_count_, &stats_.cluster);
        if (c != Status::ok) return c;
        stats_.cluster.ends_joined = join_corners(lines_, line_count_, params_.corners, corners_);
        mark(FinishStage::cluster);
        const bool cut_short = stats_.edges_dropped > 0 || stats_.hough.segments_dropped > 0 ||
                               stats_.hough.budget_bound() || stats_.cluster.clusters_dropped > 0;
        return cut_short ? Status::capacity_exceeded : Status::ok;
    }

    const Segment* segments() const { return segments_; }
    uint16_t segment_count() const { return segment_count_; }
    const Segment* lines() const { return lines_; }
    uint16_t line_count() const { return line_count_; }
    const LineStats& stats() const { return stats_; }
    // The frame's bands (begin_frame's window when it applies), or null: the whole frame.
    const BandWindow* window() const { return window_; }
    // Keeps the lines for which keep(line) is true, in order (line_count() shrinks).
    template <class Keep>
    void keep_lines(Keep&& keep) {
        uint16_t n = 0;
        for (uint16_t i = 0; i < line_count_; ++i)
            if (keep(lines_[i])) lines_[n++] = lines_[i];
        line_count_ = n;
    }
    // Puts a refined line in place of line i (i < line_count(); others are ignored).
    void replace_line(uint16_t i, const Segment& s) {
        if (i < line_count_) lines_[i] = s;
    }
    // Adds a line found later (a quadrangle's completed side); false when the list is full.
    bool append_line(const Segment& s) {
        if (line_count_ == MaxLines) return false;
        lines_[line_count_++] = s;
        return true;
    }
    const EdgeList& edges() const { return edges_view_; }
    uint16_t width() const { return width_; }  // of the frame begun last, pixels
    uint16_t height() const { return height_; }

    // RAM of the parts, bytes, for the bench's table (bash bench.sh lines-host, docs/lines.md).
    static constexpr uint32_t gradient_bytes() {
        return sizeof(GradientStage<MaxWidth, NmsRowKernel>);
    }
    static constexpr uint32_t smoothing_bytes() { return sizeof(SmoothRows<MaxWidth>); }
    static constexpr uint32_t edge_stage_bytes() { return sizeof(EdgeStage<MaxWidth>); }
    static constexpr uint32_t edge_list_bytes() {
        return sizeof(EdgeListStorage<EdgeCapacity, MaxHeight>);
    }
    static constexpr uint32_t accumulator_bytes() {
        return sizeof(HoughStorage<HoughBins, MaxThetaBins>);
    }
    static constexpr uint32_t line_list_bytes() {
        return sizeof(Segment) * (MaxSegments + MaxLines) + MaxSegments +
               sizeof(CornerCandidate) * 2 * MaxLines;
    }

private:
    // not_in_frame (a row after the last one) leaves the frame as it was; any other refusal
    // abandons it.
    Status row_status(Status s) {
        if (s != Status::ok && s != Status::not_in_frame) open_ = false;
        return s;
    }

    SmoothRows<MaxWidth> smooth_;                     // canny: pixels -> smoothed pixels
    GradientStage<MaxWidth, NmsRowKernel> gradient_;  // pixels -> packed NMS rows, no words
    EdgeStage<MaxWidth> edge_stage_;
    BandWindow* window_ = nullptr;  // this frame's bands, or null
    EdgeBeatFeed feed_;             // the frame's edges from the FPGA's beats (push_edge_beats)
    EdgeListStorage<EdgeCapacity, MaxHeight> edges_;
    EdgeList edges_view_ = edges_.view();
    HoughStorage<HoughBins, MaxThetaBins> hough_;
    Segment segments_[MaxSegments] = {};
    Segment lines_[MaxLines] = {};
    uint8_t scratch_[MaxSegments] = {};
    CornerCandidate corners_[2 * MaxLines] = {};
    LineParams params_;
    LineStats stats_;
    uint16_t width_ = 0, height_ = 0, segment_count_ = 0, line_count_ = 0;
    bool open_ = false;                       // a frame was begun and none of its rows refused
    bool beats_ = false, rows_seen_ = false;  // the frame takes edge beats / has taken rows
};

// QVGA: 320 × 240, 4096 edge points, 2° × 2 px accumulator, 64 segments, 32 lines.
using LineDetectorQvga = LineDetector<Qvga>;
// VGA: 640 × 480, 16384 edge points, 2° × 2 px accumulator, 128 segments, 64 lines.
using LineDetectorVga = LineDetector<Vga>;

}  // namespace qt
