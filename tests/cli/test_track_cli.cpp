// `quadtrack track` run in-process on a generated sequence: a board moving and turning, with
// dark bars over its top and bottom sides in three middle frames (the Quadrangle Detection paper's
// frames 41–43). Its JSON lines are parsed back and checked against the scene generator's corners,
// and every error path gives its exit status and one line on stderr.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/detect_command.h"
#include "cli/track_command.h"
#include "io/image_io.h"
#include "scene/board_scene.h"
#include "scene/board_sequence.h"
#include "support/barred_board_sequence.h"
#include "support/cli_run.h"
#include "support/json_reader.h"
#include "support/temp_dir.h"

using qt::test::Json;
using qt::test::JsonReader;

namespace {

constexpr int kFrames = qt::test::kBarredFrames, kFirstHidden = qt::test::kFirstBarred,
              kLastHidden = qt::test::kLastBarred;

using Run = qt::test::CliRun;

Run track(const std::vector<std::string>& args) {
    return qt::test::run_cli(qt::cli::run_track, args);
}

std::vector<Json> json_lines(const std::string& text) {
    std::vector<Json> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(JsonReader::parse(line));
    return lines;
}

// A fresh directory per use under this process's own one, so test cases run in parallel (and
// concurrent test runs) do not share files.
std::filesystem::path temp_dir(const std::string& name) {
    static const qt::test::TempDir base;
    const auto dir = base.dir / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void write(const std::filesystem::path& path, const qt::io::GreyImage& img) {
    std::string error;
    REQUIRE(qt::io::write_pgm(path.string(), img, error));
}

// One error: the status, exactly one line on stderr starting "quadtrack track: " and containing
// `fragment`; `json_lines` lines on stdout before it.
void require_error(const std::vector<std::string>& args, int status, const std::string& fragment,
                   size_t json_count = 0) {
    const Run r = track(args);
    INFO("stderr: " << r.err);
    CHECK(r.status == status);
    CHECK(json_lines(r.out).size() == json_count);
    REQUIRE(!r.err.empty());
    CHECK(r.err.back() == '\n');
    CHECK(r.err.find('\n') == r.err.size() - 1);
    CHECK(r.err.rfind("quadtrack track: ", 0) == 0);
    CHECK(r.err.find(fragment) != std::string::npos);
}

}  // namespace

TEST_CASE("track carries the board through frames where its top and bottom sides are hidden",
          "[cli][track]") {
    std::vector<std::array<double, 8>> truth;
    const std::string pattern = qt::test::write_barred_board_sequence(temp_dir("sequence"), truth);
    // Corner i of the JSON (anti-clockwise: TL, BL, BR, TR) is the generator's corner truth_of[i].
    const int truth_of[4] = {0, 3, 2, 1};
    for (const std::vector<std::string>& model :
         {std::vector<std::string>{}, std::vector<std::string>{"--model", "turn"},
          std::vector<std::string>{"--model=paper", "--filters", "2"},
          std::vector<std::string>{"--tracking-mode", "on", "--band-width", "10"}}) {
        std::vector<std::string> args = {pattern};
        args.insert(args.end(), model.begin(), model.end());
        const Run r = track(args);
        std::string shown;
        for (const std::string& a : model) shown += " " + a;
        INFO("options:" << (shown.empty() ? " (defaults)" : shown) << "\nstderr: " << r.err);
        REQUIRE(r.status == 0);
        REQUIRE(r.err.empty());
        const std::vector<Json> frames = json_lines(r.out);
        REQUIRE(frames.size() == kFrames);
        for (int f = 0; f < kFrames; ++f) {
            const Json& j = frames[static_cast<size_t>(f)];
            INFO("frame " << f);
            CHECK(j["frame"].num == f);
            CHECK(j["width"].num == 640);
            CHECK(j["height"].num == 480);
            CHECK(j["status"].str == "ok");
            CHECK(j["state"].str == (f == 0 ? "started" : "tracking"));
            CHECK(j["track_id"].num == 1);
            CHECK(j["lost"].type == Json::Type::null);
            CHECK(j["lines"].items.size() >= 2);
            const Json& q = j["quad"];
            REQUIRE(q.type == Json::Type::object);
            // Side 0 is the left (TL -> BL), 1 the bottom, 2 the right, 3 the top.
            const bool hidden = f >= kFirstHidden && f <= kLastHidden;
            REQUIRE(q["source"].items.size() == 4);
            for (size_t i = 0; i < 4; ++i) {
                const bool top_or_bottom = i == 1 || i == 3;
                CHECK(q["source"][i].str == (hidden && top_or_bottom ? "predicted" : "detected"));
            }
            // The evidence share: the whole perimeter in plain view; with the top and bottom
            // hidden, at most the left and right sides' share of a 4:3 board's perimeter
            // (3 + 3 of 14) and what shows of the others.
            if (hidden)
                CHECK(q["score"].num < 0.5);
            else
                CHECK(q["score"].num > 0.9);
            REQUIRE(q["corners"].items.size() == 4);
            for (size_t i = 0; i < 4; ++i) {
                const Json& c = q["corners"][i];
                const int k = truth_of[i];
                const double e = std::hypot(c[0].num - truth[static_cast<size_t>(f)][2 * k],
                                            c[1].num - truth[static_cast<size_t>(f)][2 * k + 1]);
                INFO("corner " << i << " (" << c[0].num << ", " << c[1].num << "): " << e
                               << " px from the truth");
                CHECK(e < 2.0);
            }
            // The display homography takes the display's corners (1024 × 768) onto the quad's.
            const Json& h = q["display_homography"];
            REQUIRE(h.items.size() == 3);
            const double uv[4][2] = {{0, 0}, {0, 768}, {1024, 768}, {1024, 0}};
            for (size_t i = 0; i < 4; ++i) {
                double p[3];
                for (size_t r2 = 0; r2 < 3; ++r2)
                    p[r2] = h[r2][0].num * uv[i][0] + h[r2][1].num * uv[i][1] + h[r2][2].num;
                CHECK(std::hypot(p[0] / p[2] - q["corners"][i][0].num,
                                 p[1] / p[2] - q["corners"][i][1].num) < 0.02);
            }
        }
    }
}

TEST_CASE("track prints detect's lines for each frame", "[cli][track]") {
    std::vector<std::array<double, 8>> truth;
    const auto dir = temp_dir("lines");
    const std::string pattern = qt::test::write_barred_board_sequence(dir, truth);
    const Run r = track({pattern, "--threshold=20"});
    REQUIRE(r.status == 0);
    const std::vector<Json> frames = json_lines(r.out);
    REQUIRE(frames.size() == kFrames);
    std::FILE* out = std::tmpfile();
    std::FILE* err = std::tmpfile();
    REQUIRE(qt::cli::run_detect({(dir / "f05.pgm").string(), "--threshold=20"}, out, err) == 0);
    const Json detect = JsonReader::parse(qt::test::slurp(out));
    std::fclose(err);
    const Json& a = frames[5]["lines"];
    const Json& b = detect["lines"];
    REQUIRE(a.items.size() == b.items.size());
    for (size_t i = 0; i < a.items.size(); ++i)
        for (const char* k : {"x1", "y1", "x2", "y2", "rho", "theta_deg"})
            CHECK(a[i][k].num == b[i][k].num);
}

TEST_CASE("track: frames without a board report no quad", "[cli][track]") {
    const auto dir = temp_dir("blank");
    for (int f = 0; f < 2; ++f)
        write(dir / ("b" + std::to_string(f) + ".pgm"), qt::io::GreyImage(64, 48, 90));
    const Run r = track({(dir / "b%d.pgm").string()});
    REQUIRE(r.status == 0);
    const std::vector<Json> frames = json_lines(r.out);
    REQUIRE(frames.size() == 2);
    for (const Json& j : frames) {
        CHECK(j["state"].str == "none");
        CHECK(j["track_id"].num == 0);
        CHECK(j["quad"].type == Json::Type::null);
        CHECK(j["lost"].type == Json::Type::null);
        CHECK(j["lines"].items.empty());
    }
}

TEST_CASE("track --help lists the tracker's options, detect does not take them", "[cli][track]") {
    const Run help = track({"--help"});
    CHECK(help.status == 0);
    for (const char* name : {"--model paper|turn", "--filters", "--gate-angle", "--gate-distance",
                             "--max-predicted", "--threshold", "--min-line-length", "--display"})
        CHECK(help.out.find(name) != std::string::npos);
    CHECK(help.out.find("(default paper)") != std::string::npos);
    CHECK(help.out.find("(default 3)") != std::string::npos);
    std::FILE* out = std::tmpfile();
    std::FILE* err = std::tmpfile();
    CHECK(qt::cli::run_detect({"board.pgm", "--model", "turn"}, out, err) == 2);
    CHECK(qt::test::slurp(err).find("unknown option '--model'") != std::string::npos);
    std::fclose(out);
}

TEST_CASE("track: every error is one line on stderr and a non-zero exit", "[cli][track]") {
    const auto dir = temp_dir("errors");
    const std::string frame = (dir / "one.pgm").string();
    write(frame, qt::io::GreyImage(64, 48, 90));
    require_error({}, 2, "no SEQUENCE given");
    require_error({frame, frame}, 2, "one sequence only");
    require_error({frame, "--frobnicate", "3"}, 2, "unknown option '--frobnicate'");
    require_error({frame, "--filters", "4"}, 2, "--filters: 4 is out of range 1..3");
    require_error({frame, "--filters=0"}, 2, "out of range 1..3");
    require_error({frame, "--model", "kalman"}, 2, "'kalman' is not paper or turn");
    require_error({frame, "--gate-angle"}, 2, "--gate-angle needs a value");
    require_error({frame, "--gate-distance", "far"}, 2, "'far' is not a number");
    require_error({frame, "--max-predicted", "256"}, 2, "out of range 0..254, or off");
    require_error({(dir / "no_such_file.pgm").string()}, 1, "cannot open");
    require_error({(dir / "none%03d.pgm").string()}, 1, "none");

    // The frame size changes in the middle: the frames before it are printed, then the error.
    const auto sized = temp_dir("size_change");
    write(sized / "s0.pgm", qt::io::GreyImage(64, 48, 90));
    write(sized / "s1.pgm", qt::io::GreyImage(64, 48, 90));
    write(sized / "s2.pgm", qt::io::GreyImage(80, 48, 90));
    require_error({(sized / "s%d.pgm").string()}, 1,
                  "frame 2 is 80 x 48, the sequence started at 64 x 48", 2);

    // A frame that cannot be read in the middle: the same.
    const auto broken = temp_dir("broken");
    write(broken / "s0.pgm", qt::io::GreyImage(64, 48, 90));
    std::FILE* f = std::fopen((broken / "s1.pgm").string().c_str(), "wb");
    REQUIRE(f);
    std::fputs("P5\n64 48\n255\nshort", f);
    std::fclose(f);
    require_error({(broken / "s%d.pgm").string()}, 1, "s1.pgm", 1);
}
