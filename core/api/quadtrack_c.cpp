// The C interface (quadtrack_c.h) on qt::BoardDetectorQvga and qt::QuadTracker. The C++
// objects live in the caller's storage (placement new); this file converts parameters and
// results between the C structs and the C++ types, and guards the call order.
#include "api/quadtrack_c.h"

#include <new>
#include <type_traits>
#include <utility>

#include "base/status.h"
#include "quads/board_detector.h"
#include "tracking/quad_tracker.h"
#include "tracking/tracking_mode.h"

namespace {

// A detector and what the C interface adds: its parameters and where the frame stands.
struct DetectorBox {
    qt::BoardDetectorQvga det;
    qt::BoardParams params;
    bool configured = false;  // the last init succeeded
    bool begun = false;       // a frame was begun and has not finished
    bool finished = false;    // the results are those of a finished frame
};

struct TrackerBox {
    qt::QuadTracker tracker;
    qt::TrackingMode mode;
    qt::BandWindow* window = nullptr;  // the next frame's bands (tracking mode), or whole
    bool tracking_mode = false;
    bool configured = false;
};

// The storage constants of the header hold the objects on every target (x86-64, AArch64,
// Cortex-M4); re-initialising constructs over the old object, which needs no destructor.
static_assert(sizeof(DetectorBox) <= QT_DETECTOR_BYTES, "QT_DETECTOR_BYTES too small");
static_assert(alignof(DetectorBox) <= alignof(qt_detector), "qt_detector under-aligned");
static_assert(sizeof(TrackerBox) <= QT_TRACKER_BYTES, "QT_TRACKER_BYTES too small");
static_assert(alignof(TrackerBox) <= alignof(qt_tracker), "qt_tracker under-aligned");
static_assert(std::is_trivially_destructible<DetectorBox>::value,
              "constructed over, never destroyed");
static_assert(std::is_trivially_destructible<TrackerBox>::value,
              "constructed over, never destroyed");

// The header's capacities are the QVGA configuration's.
static_assert(qt::Qvga::max_width == QT_MAX_WIDTH && qt::Qvga::max_height == QT_MAX_HEIGHT,
              "frame size");
static_assert(qt::Qvga::lines == QT_MAX_LINES, "line capacity");
static_assert(qt::BoardDetectorQvga::max_quads() == QT_MAX_QUADS, "quadrangle capacity");

// Numbers shared with the C++ enums.
constexpr bool same(qt::Status s, qt_status c) {
    return static_cast<int>(s) == static_cast<int>(c);
}
static_assert(same(qt::Status::ok, QT_OK) && same(qt::Status::bad_size, QT_BAD_SIZE) &&
                  same(qt::Status::bad_row_length, QT_BAD_ROW_LENGTH) &&
                  same(qt::Status::not_in_frame, QT_NOT_IN_FRAME) &&
                  same(qt::Status::previous_frame_incomplete, QT_PREVIOUS_FRAME_INCOMPLETE) &&
                  same(qt::Status::capacity_exceeded, QT_CAPACITY_EXCEEDED),
              "qt_status mirrors qt::Status");
static_assert(qt::kTrackingModeRanges.half_width.hi <= 255, "band_half_width_px is 8 bits");
static_assert(static_cast<int>(qt::Contrast::bright_board) == QT_CONTRAST_BRIGHT &&
                  static_cast<int>(qt::Contrast::dark_board) == QT_CONTRAST_DARK &&
                  static_cast<int>(qt::Contrast::any) == QT_CONTRAST_ANY,
              "qt_contrast mirrors qt::Contrast");
static_assert(static_cast<int>(qt::LineModel::closest_points) == QT_MODEL_PAPER &&
                  static_cast<int>(qt::LineModel::turn) == QT_MODEL_TURN,
              "qt_model mirrors qt::LineModel");
static_assert(static_cast<int>(qt::TrackState::none) == QT_TRACK_NONE &&
                  static_cast<int>(qt::TrackState::started) == QT_TRACK_STARTED &&
                  static_cast<int>(qt::TrackState::tracking) == QT_TRACK_TRACKING,
              "qt_track_state mirrors qt::TrackState");
static_assert(static_cast<int>(qt::QuadTrackLost::side_unseen) == QT_LOST_SIDE_UNSEEN &&
                  static_cast<int>(qt::QuadTrackLost::shape) == QT_LOST_SHAPE &&
                  static_cast<int>(qt::QuadTrackLost::saturated) == QT_LOST_SATURATED &&
                  static_cast<int>(qt::QuadTrackLost::detection_disagrees) ==
                      QT_LOST_DETECTION_DISAGREES,
              "qt_track_lost mirrors qt::QuadTrackLost");
static_assert(std::is_same<qt_gradient_word, qt::gradient_word>::value, "gradient word");

// A binary angle of at most 180° in whole degrees, rounded half up: a·360 / 2^32.
constexpr uint32_t whole_degrees(qt::angle_t a) {
    return static_cast<uint32_t>((static_cast<uint64_t>(a) * 360u + (1ull << 31)) >> 32);
}
// The config states these defaults in whole degrees and pixels: they must convert exactly.
constexpr qt::QuadTrackerParams kTrackDefaults{};
static_assert(qt::angle_from_deg(static_cast<int32_t>(whole_degrees(kTrackDefaults.gate_angle))) ==
                  kTrackDefaults.gate_angle,
              "default gate angle is not whole degrees");
static_assert(kTrackDefaults.gate_distance.raw % qt::q16_16::one_raw == 0,
              "default gate distance is not whole pixels");

qt_status to_c(qt::Status s) { return static_cast<qt_status>(static_cast<int>(s)); }

bool frame_size_ok(uint16_t width, uint16_t height) {
    return width >= 1 && width <= QT_MAX_WIDTH && height >= 1 && height <= QT_MAX_HEIGHT;
}

DetectorBox& box(qt_detector* d) {
    return *std::launder(reinterpret_cast<DetectorBox*>(d->opaque.bytes));
}
const DetectorBox& box(const qt_detector* d) {
    return *std::launder(reinterpret_cast<const DetectorBox*>(d->opaque.bytes));
}
TrackerBox& box(qt_tracker* t) {
    return *std::launder(reinterpret_cast<TrackerBox*>(t->opaque.bytes));
}

qt_line to_c(const qt::Segment& s) {
    qt_line l{};
    l.x1 = s.x1.raw;
    l.y1 = s.y1.raw;
    l.x2 = s.x2.raw;
    l.y2 = s.y2.raw;
    l.rho = s.rho.raw;
    l.theta = s.theta;
    l.points = s.points;
    l.bright_side = s.bright_side;
    return l;
}

qt_point to_c(qt::Point16 p) { return qt_point{p.x.raw, p.y.raw}; }

}  // namespace

extern "C" {

const char* qt_status_name(qt_status status) {
    switch (status) {
        case QT_NULL_POINTER: return "null pointer";
        case QT_BAD_INDEX: return "index out of range";
        case QT_BAD_CONFIG: return "config value out of range, or object not configured";
        case QT_OK:
        case QT_BAD_SIZE:
        case QT_BAD_ROW_LENGTH:
        case QT_NOT_IN_FRAME:
        case QT_PREVIOUS_FRAME_INCOMPLETE:
        case QT_CAPACITY_EXCEEDED: return qt::status_name(static_cast<qt::Status>(status));
    }
    return "unknown status";
}

void qt_config_default(qt_config* config, uint16_t width, uint16_t height) {
    if (config == nullptr) return;
    const qt::BoardParams board{};
    const qt::QuadTrackerParams track = qt::default_quad_tracker_params(width, height);
    config->edge_threshold = board.lines.edge_threshold;
    config->hough_threshold = board.lines.hough.threshold;
    config->min_line_length = board.lines.hough.min_line_length;
    config->max_line_gap = board.lines.hough.max_line_gap;
    config->contrast = static_cast<uint8_t>(board.quads.contrast);
    config->model = static_cast<uint8_t>(track.lines.model);
    config->filters = track.lines.filters;
    config->max_predicted = track.max_predicted;
    config->gate_angle_deg = static_cast<uint16_t>(whole_degrees(track.gate_angle));
    config->gate_distance_px = static_cast<uint16_t>(track.gate_distance.floor_int());
    const qt::TrackingModeParams mode{};
    config->tracking_mode = QT_TRACKING_MODE_OFF;  // as the command line's default
    config->band_half_width_px = static_cast<uint8_t>(mode.half_width.floor_int());
    config->full_every = mode.full_every;
}

qt_status qt_config_check(const qt_config* c) {
    if (c == nullptr) return QT_NULL_POINTER;
    // The ranges core declares beside each field's parameter struct (base/setting_range.h), in
    // the same units: the command line reads the same ones.
    const bool ok = qt::kLineRanges.edge_threshold.contains(c->edge_threshold) &&
                    qt::kHoughRanges.threshold.contains(c->hough_threshold) &&
                    qt::kHoughRanges.min_line_length.contains(c->min_line_length) &&
                    qt::kHoughRanges.max_line_gap.contains(c->max_line_gap) &&
                    c->contrast <= QT_CONTRAST_ANY && c->model <= QT_MODEL_TURN &&
                    qt::kQuadTrackerRanges.filters.contains(c->filters) &&
                    qt::kQuadTrackerRanges.max_predicted.contains(c->max_predicted) &&
                    qt::kQuadTrackerRanges.gate_angle.contains(c->gate_angle_deg) &&
                    qt::kQuadTrackerRanges.gate_distance.contains(c->gate_distance_px) &&
                    c->tracking_mode <= QT_TRACKING_MODE_ON &&
                    qt::kTrackingModeRanges.half_width.contains(c->band_half_width_px) &&
                    qt::kTrackingModeRanges.full_every.contains(c->full_every);
    return ok ? QT_OK : QT_BAD_CONFIG;
}

qt_status qt_detector_init(qt_detector* detector, const qt_config* config) {
    if (detector == nullptr) return QT_NULL_POINTER;
    DetectorBox& b = *new (detector->opaque.bytes) DetectorBox();
    const qt_status s = qt_config_check(config);
    if (s != QT_OK) return s;
    b.params.lines.edge_threshold = config->edge_threshold;
    b.params.lines.hough.threshold = config->hough_threshold;
    b.params.lines.hough.min_line_length = config->min_line_length;
    b.params.lines.hough.max_line_gap = config->max_line_gap;
    b.params.quads.contrast = static_cast<qt::Contrast>(config->contrast);
    b.configured = true;
    return QT_OK;
}

namespace {
qt_status begin_frame(qt_detector* detector, uint16_t width, uint16_t height,
                      qt::BandWindow* window) {
    DetectorBox& b = box(detector);
    if (!b.configured) return QT_BAD_CONFIG;
    b.finished = false;
    b.begun = false;
    // Checked here as well as in the C++ stages: LineDetector::begin_frame refuses a height
    // above its capacity before resetting its edge list, and its finish() would then run again
    // on the previous frame's edges; with no C++ call on a bad size, the `begun` guard holds.
    if (!frame_size_ok(width, height)) return QT_BAD_SIZE;
    const qt::Status s = b.det.begin_frame(width, height, b.params, window);
    b.begun = s == qt::Status::ok || s == qt::Status::previous_frame_incomplete;
    return to_c(s);
}
}  // namespace

qt_status qt_begin_frame(qt_detector* detector, uint16_t width, uint16_t height) {
    if (detector == nullptr) return QT_NULL_POINTER;
    return begin_frame(detector, width, height, nullptr);
}

qt_status qt_begin_tracked_frame(qt_detector* detector, qt_tracker* tracker, uint16_t width,
                                 uint16_t height) {
    if (detector == nullptr || tracker == nullptr) return QT_NULL_POINTER;
    TrackerBox& t = box(tracker);
    if (!t.configured) return QT_BAD_CONFIG;
    return begin_frame(detector, width, height, t.window);
}

qt_status qt_push_row(qt_detector* detector, const uint8_t* pixels, uint16_t length) {
    if (detector == nullptr || pixels == nullptr) return QT_NULL_POINTER;
    DetectorBox& b = box(detector);
    if (!b.configured) return QT_BAD_CONFIG;
    if (!b.begun) return QT_NOT_IN_FRAME;
    return to_c(b.det.push_row(pixels, length));
}

qt_status qt_push_gradient_row(qt_detector* detector, const qt_gradient_word* words,
                               uint16_t width) {
    if (detector == nullptr || words == nullptr) return QT_NULL_POINTER;
    DetectorBox& b = box(detector);
    if (!b.configured) return QT_BAD_CONFIG;
    if (!b.begun) return QT_NOT_IN_FRAME;
    return to_c(b.det.push_gradient_row(words, width));
}

qt_status qt_finish(qt_detector* detector) {
    if (detector == nullptr) return QT_NULL_POINTER;
    DetectorBox& b = box(detector);
    if (!b.configured) return QT_BAD_CONFIG;
    if (!b.begun) return QT_NOT_IN_FRAME;
    const qt::Status s = b.det.finish();
    // not_in_frame: rows are missing (the frame stays open) or it was abandoned (the next
    // finish says so again). Anything else ends the frame.
    if (s != qt::Status::not_in_frame) b.begun = false;
    b.finished = s == qt::Status::ok || s == qt::Status::capacity_exceeded;
    return to_c(s);
}

uint16_t qt_line_count(const qt_detector* detector) {
    if (detector == nullptr) return 0;
    const DetectorBox& b = box(detector);
    return b.finished ? b.det.lines().line_count() : 0;
}

qt_status qt_get_line(const qt_detector* detector, uint16_t index, qt_line* out) {
    if (detector == nullptr || out == nullptr) return QT_NULL_POINTER;
    if (index >= qt_line_count(detector)) return QT_BAD_INDEX;
    *out = to_c(box(detector).det.lines().lines()[index]);
    return QT_OK;
}

uint16_t qt_quad_count(const qt_detector* detector) {
    if (detector == nullptr) return 0;
    const DetectorBox& b = box(detector);
    return b.finished ? b.det.quad_count() : 0;
}

qt_status qt_get_quad(const qt_detector* detector, uint16_t index, qt_quad* out) {
    if (detector == nullptr || out == nullptr) return QT_NULL_POINTER;
    if (index >= qt_quad_count(detector)) return QT_BAD_INDEX;
    const qt::Quad& q = box(detector).det.quads()[index];
    for (int i = 0; i < 4; ++i) {
        out->corners[i] = to_c(q.corners[i]);
        out->lines[i] = q.lines[i];
    }
    out->score = q.score.raw;
    return QT_OK;
}

qt_status qt_tracker_init(qt_tracker* tracker, const qt_config* config, uint16_t width,
                          uint16_t height) {
    if (tracker == nullptr) return QT_NULL_POINTER;
    TrackerBox& b = *new (tracker->opaque.bytes) TrackerBox();
    const qt_status s = qt_config_check(config);
    if (s != QT_OK) return s;
    if (!frame_size_ok(width, height)) return QT_BAD_SIZE;
    qt::QuadTrackerParams p = qt::default_quad_tracker_params(width, height);
    p.lines.model = static_cast<qt::LineModel>(config->model);
    p.lines.filters = config->filters;
    p.max_predicted = config->max_predicted;
    p.gate_angle = qt::angle_from_deg(static_cast<int32_t>(config->gate_angle_deg));
    p.gate_distance = qt::q16_16::from_int(config->gate_distance_px);
    b.tracker.set_params(p);
    qt::TrackingModeParams mode;
    mode.half_width = qt::q16_16::from_int(config->band_half_width_px);
    mode.full_every = config->full_every;
    b.mode = qt::TrackingMode(mode);
    b.tracking_mode = config->tracking_mode == QT_TRACKING_MODE_ON;
    b.configured = true;
    return QT_OK;
}

qt_status qt_tracker_reset(qt_tracker* tracker) {
    if (tracker == nullptr) return QT_NULL_POINTER;
    TrackerBox& b = box(tracker);
    if (!b.configured) return QT_BAD_CONFIG;
    b.tracker.reset();
    b.mode.reset();
    b.window = nullptr;
    return QT_OK;
}

qt_status qt_track(qt_tracker* tracker, const qt_detector* detector, qt_tracked_quad* out) {
    if (out != nullptr) *out = qt_tracked_quad{};
    if (tracker == nullptr || detector == nullptr || out == nullptr) return QT_NULL_POINTER;
    TrackerBox& t = box(tracker);
    const DetectorBox& d = box(detector);
    if (!t.configured || !d.configured) return QT_BAD_CONFIG;
    if (!d.finished) return QT_NOT_IN_FRAME;
    const auto& lines = d.det.lines();
    const qt::TrackedQuad r =
        t.tracker.step(lines.lines(), lines.line_count(), d.det.quads(), d.det.quad_count());
    out->state = static_cast<uint8_t>(r.state);
    out->detected = r.detected;
    out->lost_reason = static_cast<uint8_t>(t.tracker.stats().lost_reason);
    out->banded = lines.window() != nullptr ? 1 : 0;
    t.window = t.tracking_mode ? t.mode.plan(r) : nullptr;
    out->track_id = r.track_id;
    out->age = r.age;
    for (int i = 0; i < 4; ++i) {
        out->corners[i] = to_c(r.corners[i]);
        out->sides[i] = to_c(r.sides[i]);
    }
    return QT_OK;
}

const char* qt_track_lost_name(uint8_t reason) {
    return qt::quad_track_lost_name(static_cast<qt::QuadTrackLost>(reason));
}

}  // extern "C"
