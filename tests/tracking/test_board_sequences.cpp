// The quadrangle tracker on rendered board sequences, through the whole detection chain
// (platform/demo/demo_sequence.h): the demo's sequence (bars over the top and bottom sides in
// frames 5-7 while the board turns 2.5°/frame) and a side hidden while the board turns faster
// (scene::kTurningSequence: a bar over the bottom side in frames 6-9, 3°/frame). Corner errors
// against the scene generator's corners.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "demo/demo_sequence.h"
#include "scene/board_sequence.h"

using namespace qt;

namespace {

std::vector<cli::BoardTrackFrame> run(const scene::BoardMotionSpec& spec, LineModel model) {
    std::vector<cli::BoardTrackFrame> frames;
    std::string error;
    const bool ok = cli::track_board_sequence(
        spec, 640, 480, cli::demo_tracker_params(model, 640, 480), frames, error);
    INFO(error);
    REQUIRE(ok);
    REQUIRE(frames.size() == static_cast<size_t>(spec.frames));
    return frames;
}

// Every frame: one track, a quadrangle, nothing taken back while the bars are up. From
// first_whole + delay on: worst corner error <= bound, and every side detected unless hidden.
void check_run(const std::vector<cli::BoardTrackFrame>& frames, int first_whole, int delay,
               double bound) {
    for (size_t f = 0; f < frames.size(); ++f) {
        const cli::BoardTrackFrame& k = frames[f];
        INFO("frame " << f << ": worst corner error " << k.worst_error_px << " px, sides "
                      << int{k.quad.detected} << ", taken back " << int{k.taken_back});
        REQUIRE(k.quad.state != TrackState::none);
        CHECK(k.quad.track_id == 1);
        CHECK(k.lost == QuadTrackLost::none);
        if (k.hidden) CHECK(k.taken_back == 0);
        if (static_cast<int>(f) >= first_whole + delay) {
            if (!k.hidden) CHECK(k.quad.detected == 0xF);
            CHECK(k.worst_error_px <= bound);
        }
    }
}

}  // namespace

TEST_CASE("board sequences: the demo's, sized to 640 x 480, is the demo's frame for frame",
          "[board_sequence]") {
    for (int f = 0; f < scene::kBoardSequenceFrames; ++f) {
        const scene::BoardSequenceFrame a = scene::board_sequence_frame(f);
        const scene::BoardSequenceFrame b =
            scene::sized_sequence_frame(scene::kDemoSequence, f, 640, 480);
        INFO("frame " << f);
        CHECK(a.image.pixels == b.image.pixels);
        CHECK(a.hidden == b.hidden);
        for (int i = 0; i < 4; ++i) {
            CHECK(a.scene.corners[i].x == b.scene.corners[i].x);
            CHECK(a.scene.corners[i].y == b.scene.corners[i].y);
        }
    }
}

TEST_CASE(
    "board sequences: after the bars the demo's board is tracked within 1 px, the paper's "
    "model taking its lost side back",
    "[board_sequence][take_back]") {
    // Frame 8 is the first with a whole detection after the bars (frames 5-7).
    const int first_whole = scene::kLastHiddenFrame + 1;
    SECTION("quadtrack track's default model: within 1 px from the first whole frame on") {
        const LineModel model = cli::TrackOptions().model;
        check_run(run(scene::kDemoSequence, model), first_whole, 0, 1.0);
    }
    SECTION("the paper's 3KF: the bottom side taken back within one frame, then within 1 px") {
        const std::vector<cli::BoardTrackFrame> frames =
            run(scene::kDemoSequence, LineModel::closest_points);
        check_run(frames, first_whole, 1, 1.0);
        // It had drifted beyond the gate: taken back, not matched.
        CHECK((frames[first_whole].taken_back | frames[first_whole + 1].taken_back) != 0);
    }
    SECTION("the turn model: within 1 px throughout") {
        check_run(run(scene::kDemoSequence, LineModel::turn), 0, 0, 1.0);
    }
}

TEST_CASE("board sequences: a side hidden while the board turns is taken back",
          "[board_sequence][take_back]") {
    const int first_whole = scene::kTurningSequence.last_hidden + 1;
    SECTION("the paper's 3KF: taken back in the first whole frame, then within 1 px") {
        const std::vector<cli::BoardTrackFrame> frames =
            run(scene::kTurningSequence, LineModel::closest_points);
        check_run(frames, first_whole, 0, 1.0);
        CHECK(frames[first_whole].taken_back != 0);
    }
    SECTION("the turn model: within 1 px throughout") {
        check_run(run(scene::kTurningSequence, LineModel::turn), 0, 0, 1.0);
    }
}
