// Tracking mode (tracking/tracking_mode.h): the plan's rules worked by hand, and on the photo
// bench's moving board in front of three real photographs (opencv-doc) the tracked corners of
// frames processed in bands against those of the same frames processed whole.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "quads/board_detector.h"
#include "scene/photo_board_scene.h"
#include "tracking/quad_tracker.h"
#include "tracking/tracking_mode.h"

using namespace qt;

namespace {

// A tracked square (x0, 50) .. (x0 + 100, 150) with every side matched.
TrackedQuad square_at(int x0, uint32_t id = 1) {
    TrackedQuad t;
    t.state = TrackState::tracking;
    t.detected = 0xF;
    t.track_id = id;
    const int xs[4] = {x0, x0, x0 + 100, x0 + 100}, ys[4] = {50, 150, 150, 50};
    for (int i = 0; i < 4; ++i) t.corners[i] = {q16_16::from_int(xs[i]), q16_16::from_int(ys[i])};
    return t;
}

// The window's columns in row 100 (the left and right sides' bands).
std::vector<int> row_100(BandWindow* w) {
    ColumnSpan s[BandWindow::kMaxSpans];
    const uint8_t n = w->spans(100, 100, 0, 320, s);
    std::vector<int> out;
    for (uint8_t i = 0; i < n; ++i) {
        out.push_back(s[i].begin);
        out.push_back(s[i].end);
    }
    return out;
}

const std::vector<io::NamedImage>& photos() {
    static std::vector<io::NamedImage> loaded;
    static std::string error;
    if (loaded.empty() && error.empty()) io::read_image_folder(QT_PHOTO_DIR, loaded, error);
    INFO(error);
    REQUIRE(std::string(QT_PHOTOS_MISSING).empty());
    REQUIRE(!loaded.empty());
    return loaded;
}

BoardDetectorQvga g_det;

}  // namespace

TEST_CASE("TrackingMode plans bands ahead of a held board, the whole frame otherwise",
          "[tracking_mode]") {
    TrackingMode mode;  // 8 px either side, 4 px beyond the corners, every 16th frame whole
    // The first frame of a track: bands where the board is (no motion known yet).
    BandWindow* w = mode.plan(square_at(60));
    REQUIRE(w != nullptr);
    CHECK(row_100(w) == std::vector<int>{52, 69, 152, 169});  // 60 ± 8 and 160 ± 8
    // Moved 4 px right: the next bands 4 px further on.
    w = mode.plan(square_at(64));
    REQUIRE(w != nullptr);
    CHECK(row_100(w) == std::vector<int>{60, 77, 160, 177});  // 68 ± 8 and 168 ± 8
    // A side predicted rather than seen: the whole frame.
    TrackedQuad hidden = square_at(68);
    hidden.detected = 0xB;
    CHECK(mode.plan(hidden) == nullptr);
    // A new track (another id): bands where it is, without the old one's motion.
    w = mode.plan(square_at(100, 2));
    REQUIRE(w != nullptr);
    CHECK(row_100(w) == std::vector<int>{92, 109, 192, 209});
    // No track: the whole frame.
    CHECK(mode.plan(TrackedQuad{}) == nullptr);
    // Every 16th frame whole: 15 banded frames in a row at most.
    mode.reset();
    int banded_run = 0, longest = 0;
    for (int k = 0; k < 40; ++k) {
        const bool banded = mode.plan(square_at(60)) != nullptr;
        banded_run = banded ? banded_run + 1 : 0;
        longest = banded_run > longest ? banded_run : longest;
    }
    CHECK(longest == 15);
    // Switched off: always the whole frame.
    TrackingModeParams off;
    off.enabled = false;
    TrackingMode none(off);
    CHECK(none.plan(square_at(60)) == nullptr);
}

TEST_CASE("Tracking mode keeps the full frames' corners on real-photograph sequences",
          "[tracking_mode][slow]") {
    constexpr int kFrames = 60;
    const QuadTrackerParams tracker_params = default_quad_tracker_params(320, 240);
    int banded_total = 0, frames_total = 0;
    for (int n = 0; n < 3; ++n) {
        const io::NamedImage& photo = photos()[photos().size() * static_cast<size_t>(n) / 3];
        INFO(photo.name);
        scene::PhotoSequenceOptions o;
        o.width = 320;
        o.height = 240;
        QuadTracker whole(tracker_params), banded(tracker_params);
        TrackingMode mode;
        BandWindow* window = nullptr;
        double sq_apart = 0, sq_whole = 0, sq_banded = 0;
        int both = 0, states_differ = 0;
        for (int k = 0; k < kFrames; ++k) {
            const scene::PhotoBoardScene s = scene::make_photo_sequence_frame(o, photo.image, k);
            TrackedQuad t[2];
            for (int pass = 0; pass < 2; ++pass) {
                BandWindow* w = pass == 1 ? window : nullptr;
                REQUIRE(g_det.begin_frame(320, 240, BoardParams{}, w) == Status::ok);
                for (int y = 0; y < 240; ++y)
                    REQUIRE(g_det.push_row(&s.image.pixels[static_cast<size_t>(y) * 320], 320) ==
                            Status::ok);
                const Status st = g_det.finish();
                REQUIRE((st == Status::ok || st == Status::capacity_exceeded));
                QuadTracker& tracker = pass == 0 ? whole : banded;
                t[pass] = tracker.step(g_det.lines().lines(), g_det.lines().line_count(),
                                       g_det.quads(), g_det.quad_count());
            }
            banded_total += window != nullptr;
            ++frames_total;
            window = mode.plan(t[1]);
            states_differ += (t[0].state == TrackState::none) != (t[1].state == TrackState::none);
            if (t[0].state == TrackState::none || t[1].state == TrackState::none) continue;
            ++both;
            for (int i = 0; i < 4; ++i) {
                const double wx = t[0].corners[i].x.raw / 65536.0,
                             wy = t[0].corners[i].y.raw / 65536.0;
                const double bx = t[1].corners[i].x.raw / 65536.0,
                             by = t[1].corners[i].y.raw / 65536.0;
                sq_apart += (wx - bx) * (wx - bx) + (wy - by) * (wy - by);
                // s.corners: the display's top-left, bottom-left, bottom-right, top-right, the
                // tracker's order for a board turned less than 45 degrees.
                sq_whole += (wx - s.corners[i].x) * (wx - s.corners[i].x) +
                            (wy - s.corners[i].y) * (wy - s.corners[i].y);
                sq_banded += (bx - s.corners[i].x) * (bx - s.corners[i].x) +
                             (by - s.corners[i].y) * (by - s.corners[i].y);
            }
        }
        const double apart = std::sqrt(sq_apart / (4.0 * both));
        const double rms_whole = std::sqrt(sq_whole / (4.0 * both)),
                     rms_banded = std::sqrt(sq_banded / (4.0 * both));
        INFO("frames tracked by both " << both << ", RMS apart " << apart << " px, against the "
                                       << "truth " << rms_whole << " (whole) and " << rms_banded
                                       << " (bands) px");
        CHECK(states_differ == 0);
        CHECK(both >= kFrames - 1);
        CHECK(apart <= 0.1);
        CHECK(rms_banded <= rms_whole + 0.1);
    }
    // Most frames of a held board run in bands (every 16th whole, and the first).
    CHECK(banded_total * 10 >= frames_total * 8);
}
