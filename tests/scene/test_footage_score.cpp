// The real-footage bench's scoring (platform/bench/footage_score.h) on a run worked by hand:
// every count follows from the frames below, not from the code.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "bench/footage_score.h"
#include "support/temp_dir.h"

using qt::bench::Score;
using qt::bench::Step;

namespace {

// The truth of a walker in a 384 × 288 video from its marks (one a line, after the header).
qt::scene::FootageTruth truth_of(const std::string& marks) {
    qt::test::TempDir d;
    const std::string path = (d.dir / "w.txt").string();
    std::ofstream(path) << "target w\nvideo v.avi 384x288\nstart 0 94 80 13 41\n" << marks;
    qt::scene::FootageTruth t;
    std::string error;
    REQUIRE(qt::scene::read_footage_truth(path, t, error));
    return t;
}

}  // namespace

TEST_CASE("footage score: within, switches, claims while out, an occlusion and its re-acquisition",
          "[footage]") {
    // The walker at (100 + f, 100) in frames 0..15, hidden in 6..8 (marks 6 and 8 occluded,
    // so 7 too; 9 lies between 8 and the visible 10: visible), out of the frame from 16.
    const qt::scene::FootageTruth t = truth_of(
        "0 100 100 13 41 visible\n5 105 100 13 41 visible\n"
        "6 106 100 13 41 occluded\n8 108 100 13 41 occluded\n"
        "10 110 100 13 41 visible\n15 115 100 13 41 visible\n"
        "16 - - - - out\n18 - - - - out\n");
    // The run, frame by frame: claims, and the estimate's offset in x from the walker.
    struct F {
        bool tracking, claims;
        double dx;
    };
    const F frames[] = {
        {true, true, 0},  // 0: the start, not scored
        {true, true, 0},  // 1..4: measured on the walker
        {true, true, 0},   {true, true, 0}, {true, true, 0},
        {true, false, 15},  // 5: predicted, 15 px off: not within, not a claim
        {true, true, 25},   // 6: hidden, a claim 25 px off: a switch, during the occlusion
        {true, true, 25},   // 7: the same run of wrong claims
        {true, false, 5},   // 8: hidden, predicted 5 px off: within
        {true, true, 3},    // 9: visible again, a claim 3 px off: re-acquired at once
        {true, true, 0},   {true, true, 0}, {true, true, 0},  // 10..12
        {true, true, 30},   // 13: a second switch, away from any occlusion
        {false, false, 0},  // 14: no position at all: not within
        {true, true, 0},    // 15
        {true, true, 0},    // 16: out of the frame, claimed
        {true, false, 0},   // 17: out, not claimed
        {true, true, 0},    // 18: out, claimed
    };
    std::vector<Step> run;
    for (int f = 0; f < 19; ++f) {
        Step s;
        s.tracking = frames[f].tracking;
        s.claims = frames[f].claims;
        s.x = 100 + f + frames[f].dx;
        s.y = 100;
        s.ms = f;
        run.push_back(s);
    }
    const Score s = qt::bench::score(run, t, 10);
    CHECK(s.frames == 15);     // 1..15
    CHECK(s.within == 10);     // 1-4, 8, 9, 10-12, 15
    CHECK(s.switches == 2);    // 6-7, 13
    CHECK(s.claims_out == 2);  // 16, 18
    CHECK(s.occlusions == 1);
    CHECK(s.wrong_after == 1);  // the claims of 6-7
    CHECK(s.reacquired == 1);
    REQUIRE(s.reacquire_frames.size() == 1);
    CHECK(s.reacquire_frames[0] == 0);  // claimed on 9, the first visible frame
    REQUIRE(s.errors.size() == 15);
    CHECK(std::isinf(s.errors[13]));  // frame 14
    CHECK(s.times.size() == 18);      // every scored frame, out ones included
    CHECK(s.kept == 0);
    CHECK(s.runs == 1);
    // Two runs add up; the median of the errors is the 15th smallest of 30: 8 zeros a run.
    Score both;
    both.add(s);
    both.add(s);
    CHECK(both.frames == 30);
    CHECK(both.switches == 4);
    CHECK(both.runs == 2);
    CHECK(qt::bench::median(both.errors) == 0);
    CHECK(qt::bench::median({1, 2, 3, 10}) == 2.5);
    CHECK(std::isnan(qt::bench::median({})));
}

TEST_CASE("footage score: positions more than a frame width or height outside the image",
          "[footage]") {
    // A 384 × 288 frame; the walker in it in frames 0..3, out from 4. Outside by more than a
    // frame width: x < -384 or x > 767 (the last pixel, 383, plus 384); by a height: y < -288
    // or y > 575.
    const qt::scene::FootageTruth t = truth_of(
        "0 100 100 13 41 visible\n3 103 100 13 41 visible\n4 - - - - out\n6 - - - - out\n");
    struct F {
        bool tracking;
        double x, y;
    };
    const F frames[] = {
        {true, 100, 100},   // 0: the start, not scored
        {true, -384, 100},  // 1: one frame width outside exactly: not counted
        {true, -385, 100},  // 2: more than a width: counted
        {true, 100, 576},   // 3: more than a height below: counted
        {true, 900, 100},   // 4: far, but the walker is out of the frame
        {false, 900, 100},  // 5: no position given
        {true, 767, -288},  // 6: on both limits: not counted (and the walker is out)
    };
    std::vector<Step> run;
    for (const F& f : frames) {
        Step s;
        s.tracking = f.tracking;
        s.x = f.x;
        s.y = f.y;
        run.push_back(s);
    }
    const Score s = qt::bench::score(run, t, 10);
    CHECK(s.frames == 3);
    CHECK(s.far_outside == 2);
}
