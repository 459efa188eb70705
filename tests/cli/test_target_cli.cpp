// `quadtrack homography` and `quadtrack target` run in-process on frames of the generated
// airborne sequence written as PGM files. Their JSON is parsed back and checked against the
// generator's truth (the ground plane's homography between frames, the target's position), and
// every error path gives its exit status and one line on stderr.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/homography_command.h"
#include "cli/target_command.h"
#include "demo/target_runner.h"
#include "io/image_io.h"
#include "scene/ground_sequence.h"
#include "support/cli_run.h"
#include "support/json_reader.h"
#include "support/temp_dir.h"

using qt::test::Json;
using qt::test::JsonReader;

namespace {

qt::test::CliRun homography(const std::vector<std::string>& args) {
    return qt::test::run_cli(qt::cli::run_homography, args);
}
qt::test::CliRun target(const std::vector<std::string>& args) {
    return qt::test::run_cli(qt::cli::run_target, args);
}

const qt::test::TempDir& temp() {
    static const qt::test::TempDir dir;
    return dir;
}

// One line of stderr, nothing on stdout.
void check_error(const qt::test::CliRun& r, int status, const std::string& needle) {
    CHECK(r.status == status);
    CHECK(r.out.empty());
    CHECK(r.err.find(needle) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

}  // namespace

TEST_CASE("quadtrack homography: two frames of the airborne sequence give the ground's homography",
          "[target][cli]") {
    const qt::scene::GroundSequence seq(qt::scene::short_ground_sequence());
    const std::string a = temp().pgm("h_a.pgm", seq.render(20)),
                      b = temp().pgm("h_b.pgm", seq.render(21));
    const auto r = homography({a, b});
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const Json j = JsonReader::parse(r.out);
    CHECK(j["status"].str == "ok");
    CHECK(j["inliers"].num >= 20);
    CHECK(j["matches"].num >= j["inliers"].num);
    CHECK(j["features"].items.size() == 2);
    // The four frame corners through the printed H and through the truth.
    const qt::scene::GroundTruth truth21 = seq.truth(21);
    const double* t = truth21.h_from_previous;
    double worst = 0;
    for (double x : {-0.5, 319.5})
        for (double y : {-0.5, 239.5}) {
            auto map = [&](auto m, double& u, double& v) {
                const double w = m(2, 0) * x + m(2, 1) * y + m(2, 2);
                u = (m(0, 0) * x + m(0, 1) * y + m(0, 2)) / w;
                v = (m(1, 0) * x + m(1, 1) * y + m(1, 2)) / w;
            };
            double u, v, tu, tv;
            map([&](int i,
                    int k) { return j["H"][static_cast<size_t>(i)][static_cast<size_t>(k)].num; },
                u, v);
            map([&](int i, int k) { return t[3 * i + k]; }, tu, tv);
            worst = std::max(worst, std::hypot(u - tu, v - tv));
        }
    INFO("worst corner error " << worst << " px");
    CHECK(worst < 0.5);
}

TEST_CASE("quadtrack homography: errors and a pair with nothing to match", "[target][cli]") {
    const std::string flat = temp().pgm("flat.pgm", qt::io::GreyImage(64, 48, 90));
    const auto none = homography({flat, flat});
    REQUIRE(none.status == 0);  // a result, not an error: H is null and status says why
    const Json j = JsonReader::parse(none.out);
    CHECK(j["H"].type == Json::Type::null);
    CHECK(j["status"].str == "too_few_pairs");
    CHECK(j["reprojection_px"].type == Json::Type::null);  // no H, no fit: not a perfect 0
    CHECK(j["features"][0].num == 0);

    check_error(homography({flat}), 2, "expected two images A B, got 1 argument");
    check_error(homography({flat, flat, "--inlier-px", "0"}), 2, "--inlier-px: 0 is out of range");
    check_error(homography({flat, flat, "--roi", "1,1,5,5"}), 2, "unknown option '--roi'");
    check_error(homography({flat, temp().path("missing.pgm")}), 1, "missing.pgm");
    const std::string big = temp().pgm("big.pgm", qt::io::GreyImage(641, 10, 0));
    check_error(homography({flat, big, "--bin", "1"}), 1,
                "641 x 10 binned by 1 is 641 x 10, not within this build's 640 x 480");
    const auto help = homography({"--help"});
    CHECK(help.status == 0);
    CHECK(help.out.find("--inlier-px PX") != std::string::npos);
}

TEST_CASE("quadtrack target: the sequence's target tracked through the flare and out of view",
          "[target][cli][slow]") {
    const qt::scene::GroundSequenceConfig cfg = qt::scene::short_ground_sequence();
    const qt::scene::GroundSequence seq(cfg);
    for (int k = 0; k < seq.frames(); ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "t%03d.pgm", k);
        temp().pgm(name, seq.render(k));
    }
    const qt::cli::TargetBox box = qt::cli::start_box(seq.truth(0));
    const std::string roi = std::to_string(box.x) + "," + std::to_string(box.y) + "," +
                            std::to_string(box.side) + "," + std::to_string(box.side);
    const auto r = target({temp().path("t%03d.pgm"), "--roi", roi});
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    std::istringstream lines(r.out);
    std::string line;
    int k = 0;
    double worst_in = 0, worst_out = 0;
    while (std::getline(lines, line)) {
        const Json j = JsonReader::parse(line);
        REQUIRE(j["frame"].num == k);
        const qt::scene::GroundTruth t = seq.truth(k);
        const double e = std::hypot(j["x"].num - t.target_x, j["y"].num - t.target_y);
        const std::string state = j["state"].str;
        if (!t.in_view) {
            worst_out = std::max(worst_out, e);
            CHECK((state == "out_of_view" || state == "predicted"));
        } else if (!t.occluded) {
            worst_in = std::max(worst_in, e);
        }
        CHECK(state != "lost");
        ++k;
    }
    CHECK(k == seq.frames());
    INFO("worst error in view " << worst_in << " px, out of view " << worst_out << " px");
    CHECK(worst_in < 2.0);
    CHECK(worst_out < 5.0);
}

TEST_CASE("quadtrack target: command-line and input errors", "[target][cli]") {
    const std::string f = temp().pgm("e000.pgm", qt::io::GreyImage(64, 48, 90));
    temp().pgm("e001.pgm", qt::io::GreyImage(64, 40, 90));
    check_error(target({f}), 2, "--roi X,Y,W,H is required");
    check_error(target({f, "--roi", "1,2,3"}), 2, "is not x,y,w,h");
    check_error(target({f, "--roi", "1,2,400,3"}), 2,
                "boxes are at most 384 x 384 px once binned, this one is 400 x 3 binned by 1");
    check_error(target({f, "--roi", "1,2,7000,3"}), 2, "size");
    // A box over 24 px (30 x 20: blocks of 2 px) inside the frame runs.
    CHECK(target({f, "--roi", "1,2,30,20"}).status == 0);
    check_error(target({f, "--roi", "1,2,5,5", "--method", "magic"}), 2, "'magic' is not fused");
    check_error(target({f, "--roi", "1,2,5,5", "--reset", "maybe"}), 2, "is not on or off");
    check_error(target({f, "--roi", "1,2,5,5", "--coast-track", "curve"}), 2,
                "'curve' is not perspective or line");
    check_error(target({f, "--roi", "1,2,5,5", "--frame-corners", "some"}), 2,
                "'some' is not ground or all");
    CHECK(target({f, "--roi", "1,2,30,20", "--coast-track", "line", "--frame-corners", "all"})
              .status == 0);
    check_error(target({f, "--roi", "60,2,10,10"}), 2, "is not wholly inside the 64 x 48 frame 0");
    // The second frame has another size: the first line is written, then one error line.
    const auto r = target({temp().path("e%03d.pgm"), "--roi", "10,10,9,9"});
    CHECK(r.status == 1);
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 1);
    CHECK(r.err.find("frame 1 is 64 x 40, the sequence started at 64 x 48") != std::string::npos);
    const auto help = target({"--help"});
    CHECK(help.status == 0);
    CHECK(help.out.find("--q-pos PX2") != std::string::npos);
}
