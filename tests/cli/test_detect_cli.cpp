// `quadtrack detect` run in-process: its JSON parsed back and checked against the scene's
// ground truth, and every error path (exit status and its one-line message).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "base/prng.h"
#include "cli/detect_command.h"
#include "io/image_io.h"
#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "scene/board_scene.h"
#include "scene/board_sequence.h"
#include "support/cli_run.h"
#include "support/json_reader.h"
#include "support/temp_dir.h"

using qt::test::Json;
using qt::test::JsonReader;

namespace {

using Run = qt::test::CliRun;

Run detect(const std::vector<std::string>& args) {
    return qt::test::run_cli(qt::cli::run_detect, args);
}

// This process's own directory (each test case runs as its own process under ctest -j).
std::filesystem::path temp_dir() {
    static const qt::test::TempDir dir;
    return dir.dir;
}

std::string write_file(const std::string& name, const std::string& bytes) {
    const std::string path = (temp_dir() / name).string();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f);
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
    return path;
}

std::string board_pgm() {
    const std::string path = (temp_dir() / "board.pgm").string();
    std::string error;
    REQUIRE(
        qt::io::write_pgm(path, qt::scene::render_board(qt::scene::default_board_scene()), error));
    return path;
}

// One error: the status, nothing on stdout, exactly one line on stderr containing `fragment`.
void require_error(const std::vector<std::string>& args, int status, const std::string& fragment) {
    const Run r = detect(args);
    INFO("stderr: " << r.err);
    CHECK(r.status == status);
    CHECK(r.out.empty());
    REQUIRE(!r.err.empty());
    CHECK(r.err.back() == '\n');
    CHECK(r.err.find('\n') == r.err.size() - 1);
    CHECK(r.err.rfind("quadtrack detect: ", 0) == 0);
    CHECK(r.err.find(fragment) != std::string::npos);
}

}  // namespace

TEST_CASE("detect bins a frame larger than the build and reports in the input's pixels",
          "[cli][binning]") {
    // 1283 × 963: by 2 it would be 641 wide, so by 3 (427 × 321, the last 2 columns and 0 rows
    // dropped).
    const qt::scene::BoardSequenceFrame d =
        qt::scene::sized_sequence_frame(qt::scene::kDemoSequence, 0, 1283, 963);
    const std::string path = (temp_dir() / "big_board.pgm").string();
    std::string error;
    REQUIRE(qt::io::write_pgm(path, d.image, error));
    const Run r = detect({path});
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    const Json j = JsonReader::parse(r.out);
    CHECK(j["width"].num == 1283);
    CHECK(j["height"].num == 963);
    CHECK(j["bin"].num == 3);
    // Every line's rho and theta still describe the line through its end points (mapped
    // separately: end points by N·u + (N − 1)/2, rho by N·rho + (N − 1)/2·(cos + sin)).
    REQUIRE(j["lines"].items.size() >= 4);
    for (const Json& l : j["lines"].items) {
        CHECK(l["rho"].num >= 0);
        const double t = l["theta_deg"].num * 3.14159265358979323846 / 180;
        CHECK(std::fabs(l["x1"].num * std::cos(t) + l["y1"].num * std::sin(t) - l["rho"].num) <
              0.03);
        CHECK(std::fabs(l["x2"].num * std::cos(t) + l["y2"].num * std::sin(t) - l["rho"].num) <
              0.03);
    }
    // The corners within a binned pixel (3 px) of the scene's, as the 640 × 480 frame's are
    // within 1 px (below).
    REQUIRE(j["quads"].items.size() >= 1);
    const Json& q = j["quads"][0];
    const int truth_of[4] = {0, 3, 2, 1};  // anti-clockwise as seen from top-left
    for (size_t i = 0; i < 4; ++i) {
        const auto& c = d.scene.corners[truth_of[i]];
        CHECK(std::hypot(q["corners"][i][0].num - c.x / 256.0,
                         q["corners"][i][1].num - c.y / 256.0) < 3.0);
    }
}

TEST_CASE("detect --capacity qvga gives what the QVGA build finds in the same frame",
          "[cli][capacity]") {
    // The reference: the frame pushed straight into a qt::BoardDetectorQvga with default
    // parameters, as the firmware and the C API run it (not through the CLI's runner).
    static qt::BoardDetectorQvga det;
    auto corners_of = [](const Json& q, int i) {
        return std::make_pair(q["corners"][static_cast<size_t>(i)][0].num,
                              q["corners"][static_cast<size_t>(i)][1].num);
    };
    SECTION("a 320 x 240 frame: the same lines and corners as the QVGA detector") {
        // The board of the demo's sequence at half size with 300 straight strokes over it:
        // enough lines to fill the QVGA build's capacities and not the VGA build's.
        qt::scene::BoardSequenceFrame d = qt::scene::board_sequence_frame(3, 2);
        REQUIRE(d.image.width == 320);
        qt::Pcg32 rng(7);
        for (int k = 0; k < 300; ++k) {
            const double x0 = rng.below(320), y0 = rng.below(240), a = rng.below(180) * 0.01745;
            const uint8_t v = rng.below(2) ? 20 : 240;
            const int length = 20 + static_cast<int>(rng.below(80));
            for (int t = 0; t < length; ++t) {
                const int x = static_cast<int>(x0 + t * std::cos(a)),
                          y = static_cast<int>(y0 + t * std::sin(a));
                if (x >= 0 && x < 320 && y >= 0 && y < 240)
                    d.image.pixels[static_cast<size_t>(y * 320 + x)] = v;
            }
        }
        const std::string path = (temp_dir() / "busy_qvga.pgm").string();
        std::string error;
        REQUIRE(qt::io::write_pgm(path, d.image, error));
        qt::BoardParams params;  // detect's display, 1024 x 768, is the default 4:3
        const qt::Status s = qt::io::push_frame(det, d.image, params);
        REQUIRE((s == qt::Status::ok || s == qt::Status::capacity_exceeded));
        const Run r = detect({path, "--capacity", "qvga"});
        INFO("stderr: " << r.err);
        REQUIRE(r.status == 0);
        const Json j = JsonReader::parse(r.out);
        CHECK(j["bin"].num == 1);
        CHECK(j["status"].str == (s == qt::Status::ok ? "ok" : "capacity_exceeded"));
        // "full" names what filled, in this order, and is empty exactly when the status is ok.
        std::string full;
        for (const Json& f : j["full"].items) full += f.str + " ";
        const qt::LineStats& ls = det.lines().stats();
        std::string want;
        if (ls.edges_dropped > 0) want += "edges ";
        if (ls.hough.voters_exhausted) want += "voters ";
        if (ls.hough.budget_exhausted) want += "walk_steps ";
        if (ls.hough.segments_dropped > 0) want += "segments ";
        if (ls.cluster.clusters_dropped > 0) want += "lines ";
        if (det.quad_stats().pairs_dropped > 0) want += "pairs ";
        CHECK(full == want);
        CHECK(full.empty() == (s == qt::Status::ok));
        CHECK(!full.empty());  // the strokes fill the QVGA build's capacities
        REQUIRE(j["lines"].items.size() == det.lines().line_count());
        for (size_t i = 0; i < j["lines"].items.size(); ++i) {
            CHECK(std::fabs(j["lines"][i]["x1"].num - det.lines().lines()[i].x1.raw / 65536.0) <
                  1e-4);
            CHECK(std::fabs(j["lines"][i]["rho"].num - det.lines().lines()[i].rho.raw / 65536.0) <
                  1e-4);
        }
        REQUIRE(j["quads"].items.size() == det.quad_count());
        for (size_t k = 0; k < det.quad_count(); ++k)
            for (int i = 0; i < 4; ++i) {
                const auto c = corners_of(j["quads"][k], i);
                CHECK(std::fabs(c.first - det.quads()[k].corners[i].x.raw / 65536.0) < 1e-4);
                CHECK(std::fabs(c.second - det.quads()[k].corners[i].y.raw / 65536.0) < 1e-4);
            }
        // The VGA build (the default) keeps more of the strokes' lines in the same frame.
        const Run v = detect({path});
        REQUIRE(v.status == 0);
        CHECK(JsonReader::parse(v.out)["lines"].items.size() > j["lines"].items.size());
    }
    SECTION("a 640 x 480 frame is binned by 2 to fit, and reported in the input's pixels") {
        const Run r = detect({board_pgm(), "--capacity", "qvga"});
        INFO("stderr: " << r.err);
        REQUIRE(r.status == 0);
        const Json j = JsonReader::parse(r.out);
        CHECK(j["width"].num == 640);
        CHECK(j["height"].num == 480);
        CHECK(j["bin"].num == 2);
        REQUIRE(j["quads"].items.size() >= 1);
        // The scene's corners (see the next test) within a binned pixel.
        const double truth[4][2] = {{188, 112}, {160, 318}, {430, 352}, {452, 150}};
        for (int i = 0; i < 4; ++i) {
            const auto c = corners_of(j["quads"][0], i);
            CHECK(std::hypot(c.first - truth[i][0], c.second - truth[i][1]) < 2.0);
        }
    }
    SECTION("bad values and frames the QVGA build cannot take") {
        require_error({board_pgm(), "--capacity", "xga"}, 2, "expected vga or qvga, got 'xga'");
        require_error({board_pgm(), "--capacity", "qvga", "--bin", "1"}, 1,
                      "640 x 480 binned by 1 is 640 x 480, not within the QVGA capacity's 320 x "
                      "240");
    }
}

TEST_CASE("detect prints JSON with the board's corners anti-clockwise as seen", "[cli]") {
    const Run r = detect({board_pgm()});
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    REQUIRE(r.err.empty());
    REQUIRE(r.out.back() == '\n');
    REQUIRE(r.out.find('\n') == r.out.size() - 1);  // one line: JSON Lines-ready
    const Json j = JsonReader::parse(r.out);
    CHECK(j["width"].num == 640);
    CHECK(j["height"].num == 480);
    CHECK(j["status"].str == "ok");
    REQUIRE(j["lines"].items.size() >= 4);
    for (const Json& l : j["lines"].items) {
        for (const char* k : {"x1", "y1", "x2", "y2", "rho", "theta_deg"})
            REQUIRE(l[k].type == Json::Type::number);
        CHECK(l["rho"].num >= 0);
        CHECK(l["theta_deg"].num >= 0);
        CHECK(l["theta_deg"].num < 360);
        // rho and theta describe the line through the end points.
        const double t = l["theta_deg"].num * 3.14159265358979323846 / 180;
        CHECK(std::fabs(l["x1"].num * std::cos(t) + l["y1"].num * std::sin(t) - l["rho"].num) <
              0.01);
        CHECK(std::fabs(l["x2"].num * std::cos(t) + l["y2"].num * std::sin(t) - l["rho"].num) <
              0.01);
    }
    REQUIRE(j["quads"].items.size() >= 1);
    const Json& q = j["quads"][0];
    // The scene's corners (platform/scene/board_scene.cpp) in the order top-left, bottom-left,
    // bottom-right, top-right: anti-clockwise as seen, starting at the smallest x + y.
    const double truth[4][2] = {{188, 112}, {160, 318}, {430, 352}, {452, 150}};
    REQUIRE(q["corners"].items.size() == 4);
    for (int i = 0; i < 4; ++i) {
        const Json& c = q["corners"][static_cast<size_t>(i)];
        INFO("corner " << i << ": " << c[0].num << ", " << c[1].num);
        CHECK(std::hypot(c[0].num - truth[i][0], c[1].num - truth[i][1]) < 1.0);
    }
    CHECK(q["score"].num > 0.8);
    CHECK(q["score"].num <= 1.0);
    // The display homography takes the display's corners (1024 × 768 by default) to the quad's.
    const Json& h = q["display_homography"];
    REQUIRE(h.items.size() == 3);
    const double uv[4][2] = {{0, 0}, {0, 768}, {1024, 768}, {1024, 0}};
    for (int i = 0; i < 4; ++i) {
        double p[3];
        for (size_t r2 = 0; r2 < 3; ++r2)
            p[r2] = h[r2][0].num * uv[i][0] + h[r2][1].num * uv[i][1] + h[r2][2].num;
        const Json& c = q["corners"][static_cast<size_t>(i)];
        CHECK(std::hypot(p[0] / p[2] - c[0].num, p[1] / p[2] - c[1].num) < 0.02);
    }
}

TEST_CASE("detect takes options with the papers' names, in both spellings", "[cli]") {
    const std::string img = board_pgm();
    // A 1:1 display with a tight aspect tolerance rejects the 4:3-ish board (rule 5).
    const Run square = detect({img, "--display", "500x500", "--aspect-tolerance=1.05"});
    REQUIRE(square.status == 0);
    CHECK(JsonReader::parse(square.out)["quads"].items.empty());
    // Too high a vote threshold finds no lines at all.
    const Run strict = detect({"--threshold", "255", "--min-line-length=2000", img});
    REQUIRE(strict.status == 0);
    CHECK(JsonReader::parse(strict.out)["lines"].items.empty());
    const Run help = detect({"--help"});
    CHECK(help.status == 0);
    for (const char* name :
         {"--threshold", "--min-line-length", "--max-gap", "--parallel-tolerance",
          "--perpendicular-tolerance", "--min-side", "--max-side", "--display"})
        CHECK(help.out.find(name) != std::string::npos);
}

TEST_CASE("detect: every error is one line on stderr and a non-zero exit", "[cli]") {
    const std::string img = board_pgm();
    require_error({}, 2, "no IMAGE given");
    require_error({img, img}, 2, "one image only");
    require_error({img, "--frobnicate", "3"}, 2, "unknown option '--frobnicate'");
    require_error({img, "--threshold"}, 2, "--threshold needs a value");
    require_error({img, "--threshold", "abc"}, 2, "'abc' is not an integer");
    require_error({img, "--threshold", "0"}, 2, "out of range 1..255");
    require_error({img, "--min-side=1e9"}, 2, "out of range");
    require_error({img, "--display", "640"}, 2, "is not WxH");
    require_error({img, "--rho", "3"}, 2, "3 is not 2 or 4");
    require_error({img, "--min-side", "200", "--max-side", "100"}, 2,
                  "--min-side is above --max-side");
    const std::string missing = (temp_dir() / "no_such_file.pgm").string();
    require_error({missing}, 1, "cannot open");
    require_error({write_file("truncated_header.pgm", "P5\n64 ")}, 1, "truncated_header.pgm");
    require_error({write_file("malformed.pgm", "P5\n64 x48\n255\n")}, 1, "malformed.pgm");
    require_error({write_file("maxval.pgm", "P5\n2 2\n65535\n" + std::string(8, '\0'))}, 1,
                  "unsupported maxval 65535");
    require_error({write_file("raster.pgm", "P5\n4 4\n255\n" + std::string(5, 'a'))}, 1,
                  "truncated");
    require_error({write_file("notimage.txt", "hello world\n")}, 1, "not a PGM");
    // Larger frames are binned to fit (test_streams.cpp), unless --bin says otherwise or no
    // factor fits.
    const std::string big =
        write_file("big.pgm", "P5\n641 480\n255\n" + std::string(641 * 480, '\0'));
    require_error({big, "--bin", "1"}, 1,
                  "641 x 480 binned by 1 is 641 x 480, not within this build's 640 x 480");
    require_error({write_file("wide.pgm", "P5\n10256 16\n255\n" + std::string(10256 * 16, '\0'))},
                  1, "10256 x 16 does not fit this build's 640 x 480 by any bin factor up to 16");
    require_error({big, "--bin", "0"}, 2, "--bin: 0 is out of range 1..16");
    require_error({big, "--bin", "two"}, 2, "'two' is not an integer");
    // Control characters in the user's arguments still give one line (shown as '?').
    require_error({img, "--threshold", "1\n2"}, 2, "'1?2' is not an integer");
    require_error({img, "--frob\nnicate=3"}, 2, "unknown option '--frob?nicate'");
    require_error({img, "two\rlines.pgm"}, 2, "'two?lines.pgm'");
    require_error({img, "--threshold\n"}, 2, "unknown option '--threshold?'");
}
