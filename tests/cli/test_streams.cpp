// Every command that reads an image or a sequence, fed through a pipe to its standard input
// ("-") as `ffmpeg ... -f yuv4mpegpipe - | quadtrack track -` would: a live stream whose frames
// are written only after the line of the one before is out; a stream cut inside a frame; PGM
// images one after another; and the board sequence at camera sizes larger than the build
// (768 × 576, 1280 × 720, 1920 × 1080), binned to fit, tracked with corner errors (input pixels)
// within the bin factor times the 640 × 480 sequence's. The frames are the project's own board
// sequence (platform/scene/board_sequence.h) written as Y4M.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/detect_command.h"
#include "cli/homography_command.h"
#include "cli/target_command.h"
#include "cli/track_command.h"
#include "io/image_io.h"
#include "scene/board_sequence.h"
#include "support/json_reader.h"
#include "support/pipe_run.h"
#include "support/temp_dir.h"

using qt::test::Json;
using qt::test::JsonReader;
using qt::test::PipeRun;

namespace {

// What a Y4M writer sends: the header, then each frame's bytes.
struct Y4m {
    std::string header;
    std::vector<std::string> frames;
    std::vector<qt::scene::BoardScene> truth;
};

std::string write_with(const std::function<bool(std::FILE*, std::string&)>& body) {
    std::FILE* f = std::tmpfile();
    REQUIRE(f);
    std::string error;
    const bool ok = body(f, error);
    INFO(error);
    REQUIRE(ok);
    std::rewind(f);
    std::string s;
    char buf[65536];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    std::fclose(f);
    return s;
}

Y4m board_y4m(int width, int height, int frames, bool mono = true,
              const qt::scene::BoardMotionSpec& spec = qt::scene::kDemoSequence) {
    Y4m y;
    y.header = write_with([&](std::FILE* f, std::string& e) {
        return qt::io::write_y4m_header(f, "test", width, height, mono, e);
    });
    for (int k = 0; k < frames; ++k) {
        const qt::scene::BoardSequenceFrame d =
            qt::scene::sized_sequence_frame(spec, k, width, height);
        y.frames.push_back(write_with([&](std::FILE* f, std::string& e) {
            return qt::io::write_y4m_frame(f, "test", d.image, mono, e);
        }));
        y.truth.push_back(d.scene);
    }
    return y;
}

std::vector<Json> json_lines(const std::string& text) {
    std::vector<Json> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(JsonReader::parse(line));
    return lines;
}

// Exactly one line on stderr, starting with `prefix` and containing `fragment`.
void check_one_error_line(const std::string& err, const std::string& prefix,
                          const std::string& fragment) {
    INFO("stderr: " << err);
    REQUIRE(!err.empty());
    CHECK(err.find('\n') == err.size() - 1);
    CHECK(err.rfind(prefix, 0) == 0);
    CHECK(err.find(fragment) != std::string::npos);
}

// The worst distance of a JSON quad's corners from the truth's, in the best rotation of their
// order (anti-clockwise as seen in the JSON, the generator's clockwise), px.
double worst_corner_error(const Json& quad, const qt::scene::BoardScene& truth) {
    double best = 1e30;
    for (int r = 0; r < 4; ++r) {
        double worst = 0;
        for (size_t i = 0; i < 4; ++i) {
            const auto& c = truth.corners[(r + 4 - static_cast<int>(i)) % 4];
            worst = std::max(worst, std::hypot(quad["corners"][i][0].num - c.x / 256.0,
                                               quad["corners"][i][1].num - c.y / 256.0));
        }
        best = std::min(best, worst);
    }
    return best;
}

// Processing a frame takes milliseconds here, seconds under a sanitizer or an emulator.
constexpr double kLineTimeout = 120;

}  // namespace

TEST_CASE("track -: a live stream gets each frame's line before the next frame is written",
          "[cli][stream]") {
    const Y4m y = board_y4m(640, 480, 4);
    PipeRun run(qt::cli::run_track, {"-"});
    REQUIRE(run.write(y.header));
    for (size_t k = 0; k < y.frames.size(); ++k) {
        REQUIRE(run.write(y.frames[k]));
        // The writer holds the next frame back until this one's line is out: a command that
        // read ahead or held its output would never answer.
        INFO("frame " << k);
        REQUIRE(run.wait_for_lines(k + 1, kLineTimeout));
        CHECK(run.count_lines() == k + 1);
    }
    CHECK(run.finish() == 0);
    CHECK(run.err.empty());
    const std::vector<Json> lines = json_lines(run.out);
    REQUIRE(lines.size() == y.frames.size());
    for (size_t k = 0; k < lines.size(); ++k) {
        CHECK(lines[k]["frame"].num == static_cast<double>(k));
        CHECK(lines[k]["bin"].num == 1);
        REQUIRE(lines[k]["quad"].type == Json::Type::object);
        CHECK(worst_corner_error(lines[k]["quad"], y.truth[k]) < 1.0);
    }
}

TEST_CASE("track -: a stream cut inside a frame gives the whole frames' lines and one error line",
          "[cli][stream]") {
    const Y4m y = board_y4m(640, 480, 3);
    PipeRun run(qt::cli::run_track, {"-"});
    REQUIRE(run.write(y.header + y.frames[0] + y.frames[1] + y.frames[2].substr(0, 100000)));
    CHECK(run.finish() == 1);
    CHECK(json_lines(run.out).size() == 2);
    // 100000 bytes of frame 2: its 6-byte FRAME line and 99994 of its 307200 pixels.
    check_one_error_line(run.err, "quadtrack track: standard input: Y4M frame 2: ",
                         "truncated frame data: expected 307200 bytes, got 99994");

    // Cut inside the header: nothing but the error.
    PipeRun header(qt::cli::run_track, {"-"});
    REQUIRE(header.write("YUV4MPEG2 W640 H4"));
    CHECK(header.finish() == 1);
    CHECK(header.out.empty());
    check_one_error_line(header.err, "quadtrack track: standard input: ", "truncated Y4M header");

    // Nothing at all.
    PipeRun empty(qt::cli::run_track, {"-"});
    CHECK(empty.finish() == 1);
    check_one_error_line(empty.err, "quadtrack track: standard input: ", "not a PGM");
}

TEST_CASE("track -: PGM images one after another, and one cut short", "[cli][stream]") {
    std::string pgms;
    std::vector<qt::scene::BoardScene> truth;
    for (int k = 0; k < 3; ++k) {
        const qt::scene::BoardSequenceFrame d = qt::scene::board_sequence_frame(k);
        pgms += "P5\n640 480\n255\n" + std::string(d.image.pixels.begin(), d.image.pixels.end());
        truth.push_back(d.scene);
    }
    PipeRun run(qt::cli::run_track, {"-", "--model", "turn"});
    REQUIRE(run.write(pgms));
    CHECK(run.finish() == 0);
    CHECK(run.err.empty());
    const std::vector<Json> lines = json_lines(run.out);
    REQUIRE(lines.size() == 3);
    for (size_t k = 0; k < 3; ++k) CHECK(worst_corner_error(lines[k]["quad"], truth[k]) < 1.0);

    PipeRun cut(qt::cli::run_track, {"-"});
    REQUIRE(cut.write(pgms.substr(0, pgms.size() - 1000)));
    CHECK(cut.finish() == 1);
    CHECK(json_lines(cut.out).size() == 2);
    check_one_error_line(cut.err, "quadtrack track: standard input: image 2: ",
                         "truncated pixel data: expected 307200 bytes, got 306200");
}

TEST_CASE("detect -, target -, homography A -: standard input", "[cli][stream]") {
    const Y4m y = board_y4m(640, 480, 2);
    SECTION("detect reads the first frame") {
        PipeRun run(qt::cli::run_detect, {"-"});
        // The rest of the stream is never read: whether the writer gets it all in is not the
        // point, the command's answer is.
        run.write(y.header + y.frames[0] + y.frames[1]);
        CHECK(run.finish() == 0);
        CHECK(run.err.empty());
        const Json j = JsonReader::parse(run.out);
        CHECK(j["width"].num == 640);
        CHECK(j["bin"].num == 1);
        REQUIRE(j["quads"].items.size() >= 1);
        CHECK(worst_corner_error(j["quads"][0], y.truth[0]) < 1.0);
    }
    SECTION("target reads every frame") {
        PipeRun run(qt::cli::run_target, {"-", "--roi", "300,220,16,16"});
        REQUIRE(run.write(y.header + y.frames[0] + y.frames[1]));
        CHECK(run.finish() == 0);
        CHECK(run.err.empty());
        const std::vector<Json> lines = json_lines(run.out);
        REQUIRE(lines.size() == 2);
        CHECK(lines[0]["bin"].num == 1);
    }
    SECTION("homography A - reads B from standard input") {
        const qt::test::TempDir dir;
        const std::string a = (dir.dir / "a.y4m").string();
        std::FILE* f = std::fopen(a.c_str(), "wb");
        REQUIRE(f);
        std::fwrite(y.header.data(), 1, y.header.size(), f);
        std::fwrite(y.frames[0].data(), 1, y.frames[0].size(), f);
        std::fclose(f);
        PipeRun run(qt::cli::run_homography, {a, "-"});
        REQUIRE(run.write(y.header + y.frames[1]));
        CHECK(run.finish() == 0);
        CHECK(run.err.empty());
        const Json j = JsonReader::parse(run.out);
        CHECK(j["bin"][0].num == 1);
        CHECK(j["bin"][1].num == 1);

        PipeRun both(qt::cli::run_homography, {"-", "-"});
        CHECK(both.finish() == 2);
        check_one_error_line(both.err, "quadtrack homography: ", "standard input");
    }
}

TEST_CASE("track -: camera sizes binned to fit, corner errors within the bin factor times VGA's",
          "[cli][stream][binning][slow]") {
    // The demo's board sequence (its bars over the top and bottom sides in frames 5-7) scaled to
    // each camera frame; its worst and mean corner errors over the sequence, input pixels.
    struct Run {
        double worst = 0, mean = 0;
    };
    auto track = [](const Y4m& y, int width, int height, int bin, const std::string& model) {
        PipeRun run(qt::cli::run_track, {"-", "--model", model});
        std::string all = y.header;
        for (const std::string& f : y.frames) all += f;
        REQUIRE(run.write(all));
        INFO(width << " x " << height << ": " << run.err);
        REQUIRE(run.finish() == 0);
        const std::vector<Json> lines = json_lines(run.out);
        REQUIRE(lines.size() == y.frames.size());
        Run r;
        for (size_t k = 0; k < lines.size(); ++k) {
            const Json& j = lines[k];
            CHECK(j["width"].num == width);
            CHECK(j["height"].num == height);
            CHECK(j["bin"].num == bin);
            CHECK(j["track_id"].num == 1);
            REQUIRE(j["quad"].type == Json::Type::object);
            const double e = worst_corner_error(j["quad"], y.truth[k]);
            r.worst = std::max(r.worst, e);
            r.mean += e / static_cast<double>(lines.size());
        }
        return r;
    };
    struct Camera {
        int width, height;
        bool mono;
        int bin;
    };
    // 1280 × 720 as 4:2:0 (its chroma planes read and dropped), the others grey. Each sequence is
    // drawn once and tracked with both models.
    const Camera vga_camera{640, 480, true, 1};
    const Camera cameras[] = {{768, 576, true, 2}, {1280, 720, false, 2}, {1920, 1080, true, 3}};
    auto draw = [](const Camera& c) {
        return board_y4m(c.width, c.height, qt::scene::kBoardSequenceFrames, c.mono);
    };
    const Y4m vga_y4m = draw(vga_camera);
    std::vector<Y4m> camera_y4m;
    for (const Camera& c : cameras) camera_y4m.push_back(draw(c));
    // Each line model against its own 640 × 480 run: the turn model's small errors make the bound
    // tight enough to show an offset of (N − 1)/2 px in the mapping back.
    for (const char* model : {"paper", "turn"}) {
        const Run vga = track(vga_y4m, 640, 480, 1, model);
        for (size_t i = 0; i < camera_y4m.size(); ++i) {
            const Camera& c = cameras[i];
            const Run r = track(camera_y4m[i], c.width, c.height, c.bin, model);
            INFO(model << ", " << c.width << " x " << c.height << " by " << c.bin << ": worst "
                       << r.worst << " px, mean " << r.mean << " px; 640 x 480: worst " << vga.worst
                       << " px, mean " << vga.mean << " px");
            CHECK(r.worst <= c.bin * vga.worst);
            CHECK(r.mean <= c.bin * vga.mean);
        }
    }
}
