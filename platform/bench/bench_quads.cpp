// Host benchmark of board detection on generated scenes with ground-truth corners
// (platform/scene/board_bench_scene.h): QVGA boards under perspective (tilt <= 40°, rotation <=
// 30°, scale 15–80 %) over textured, cluttered, unevenly lit backgrounds with noise and blur, in
// three sets — unoccluded, one side partly occluded, no board — and, when OpenCV was found at
// configure time, the squares.cpp recipe on the same frames beside ours.
//
// A board counts as detected when the best quadrangle's corners, in the order returned
// (anti-clockwise as seen, top-left first), are each within kHitPx of the truth. Corner RMSE
// is over the detected boards' corners. A false detection is any quadrangle on a board-free
// frame, or a best quadrangle on a board frame that is not the board. Everything printed is
// deterministic except the times (medians over the frames, one run).
// Run by `bash bench.sh quads-host`; `--scenes N` sets the scenes per set (default 500),
// `--list-failures` names every scene that was missed or falsely detected, with its seed.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "scene/board_bench_scene.h"

#ifdef QT_HAVE_OPENCV
#include "bench/opencv_squares.h"
#endif

namespace {

namespace sc = qt::scene;
using Clock = std::chrono::steady_clock;
using Corners = std::array<sc::Point2, 4>;

constexpr double kHitPx = 3.0;  // largest corner error of a detection, pixels

struct Tally {
    int scenes = 0, detected = 0, wrong = 0, none = 0;
    double sum_sq = 0;  // squared corner errors of detected boards, px²
    int corners = 0;
    std::vector<double> ms;

    // Returns what happened: "" detected or correctly nothing, else a short reason.
    const char* add(const sc::BoardBenchScene& s, bool found, const Corners& c, double elapsed_ms) {
        ++scenes;
        ms.push_back(elapsed_ms);
        if (!found) {
            ++none;
            return s.has_board ? "missed" : "";
        }
        if (!s.has_board) {
            ++wrong;
            return "false detection";
        }
        double worst = 0, sq = 0;
        for (int i = 0; i < 4; ++i) {
            const double e = std::hypot(c[i].x - s.corners[i].x, c[i].y - s.corners[i].y);
            worst = std::max(worst, e);
            sq += e * e;
        }
        if (worst > kHitPx) {
            ++wrong;
            return "wrong quadrangle";
        }
        ++detected;
        sum_sq += sq;
        corners += 4;
        return "";
    }
    double median_ms() {
        std::sort(ms.begin(), ms.end());
        return ms.empty() ? 0 : ms[ms.size() / 2];
    }
};

qt::BoardDetectorQvga g_det;

bool detect_with(const qt::io::GreyImage& img, const qt::BoardParams& params, Corners& c) {
    const qt::Status s = qt::io::push_frame(g_det, img, params);
    if (s != qt::Status::ok && s != qt::Status::capacity_exceeded) {
        std::fprintf(stderr, "bench_quads: %s\n", qt::status_name(s));
        std::exit(1);
    }
    if (g_det.quad_count() == 0) return false;
    for (int i = 0; i < 4; ++i)
        c[i] = {g_det.quads()[0].corners[i].x.raw / 65536.0,
                g_det.quads()[0].corners[i].y.raw / 65536.0};
    return true;
}

bool ours(const qt::io::GreyImage& img, Corners& c) {
    return detect_with(img, qt::BoardParams{}, c);
}

// The paper's five rules alone: rule 5 without the tilt's larger factor, no contrast test, no
// support requirement, no side refinement, no edge evidence, no completion of a hidden side, no
// test of the inside, of lines across or of crossings at the corners.
bool rules_only(const qt::io::GreyImage& img, Corners& c) {
    qt::BoardParams p;
    p.quads.tilted_aspect_tolerance = p.quads.aspect_tolerance;
    p.refine.band = qt::q16_16::from_int(0);
    p.quads.contrast = qt::Contrast::any;
    p.quads.min_side_coverage = qt::q16_16::from_int(0);
    p.quads.min_score = qt::q16_16::from_int(0);
    p.quads.complete_hidden_side = false;
    p.refine.min_side_evidence_percent = qt::kCheckOff;
    p.refine.min_hidden_side_evidence_percent = qt::kCheckOff;
    p.refine.min_evidence_percent = qt::kCheckOff;
    p.refine.max_inside_edge_cells_percent = qt::kCheckOff;
    p.refine.max_lines_across = qt::kCheckOff;
    p.refine.max_junction_corners = qt::kCheckOff;
    return detect_with(img, p, c);
}

// The true board's departures from a rectangle, which the rules' tolerances must admit.
struct TruthGeometry {
    double parallel_deg = 0, perpendicular_deg = 0, aspect_factor = 1;

    void add(const sc::BoardBenchScene& s, double display_aspect) {
        double dir[4], len[4];
        for (int i = 0; i < 4; ++i) {
            const sc::Point2 a = s.corners[i], b = s.corners[(i + 1) % 4];
            dir[i] = std::atan2(b.y - a.y, b.x - a.x) * 180 / 3.14159265358979323846;
            len[i] = std::hypot(b.x - a.x, b.y - a.y);
        }
        auto between = [](double a, double b) {  // angle between two lines, [0, 90]
            const double d = std::fmod(std::fabs(a - b), 180.0);
            return d > 90 ? 180 - d : d;
        };
        parallel_deg = std::max({parallel_deg, between(dir[0], dir[2]), between(dir[1], dir[3])});
        for (int i = 0; i < 4; ++i)
            perpendicular_deg = std::max(perpendicular_deg, 90 - between(dir[i], dir[(i + 1) % 4]));
        const double r = (len[1] + len[3]) / (len[0] + len[2]) / display_aspect;
        aspect_factor = std::max({aspect_factor, r, 1 / r});
    }
};

struct Method {
    const char* name;
    bool (*run)(const qt::io::GreyImage&, Corners&);
};

#ifdef QT_HAVE_OPENCV
bool opencv(const qt::io::GreyImage& img, Corners& c) {
    return qt::bench::opencv_best_square(img, c);
}
#endif

void print_row(const char* method, const char* set, Tally& t, bool board) {
    char rmse[16] = "  —  ";
    if (t.corners) std::snprintf(rmse, sizeof rmse, "%.3f", std::sqrt(t.sum_sq / t.corners));
    if (board)
        std::printf("| %-22s | %-10s | %5d | %6.1f %% | %s | %5d | %7.3f |\n", method, set,
                    t.scenes, 100.0 * t.detected / t.scenes, rmse, t.wrong, t.median_ms());
    else
        std::printf("| %-22s | %-10s | %5d |        — |      — | %5d (%.1f %%) | %7.3f |\n", method,
                    set, t.scenes, t.wrong, 100.0 * t.wrong / t.scenes, t.median_ms());
}

}  // namespace

int main(int argc, char** argv) {
    int scenes = 500;
    bool list_failures = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--scenes") == 0 && i + 1 < argc) {
            scenes = std::atoi(argv[++i]);
        } else if (std::strcmp(argv[i], "--list-failures") == 0) {
            list_failures = true;
        } else {
            std::fprintf(stderr, "usage: bench_quads [--scenes N] [--list-failures]\n");
            return 2;
        }
    }
    if (scenes <= 0) {
        std::fprintf(stderr, "bench_quads: --scenes must be positive\n");
        return 2;
    }
    std::vector<Method> methods = {{"quadtrack (fixed point)", ours},
                                   {"quadtrack, rules 1-5 only", rules_only}};
#ifdef QT_HAVE_OPENCV
    methods.push_back({"OpenCV squares.cpp", opencv});
#endif
    struct Set {
        const char* name;
        bool board, occlude;
        uint64_t seed0;
    };
    const Set sets[] = {{"unoccluded", true, false, 1000000},
                        {"occluded", true, true, 2000000},
                        {"no board", false, false, 3000000}};

    std::printf(
        "board scenes 320x240: tilt <= 40 deg, rotation <= 30 deg, scale 15-80 %%, noise 4, blur "
        "0.7, "
        "lighting gain >= 0.55, clutter; %d scenes per set; detected = every corner within %.0f "
        "px\n",
        scenes, kHitPx);
    std::printf(
        "| method                 | set        | scenes | detected | corner RMSE px | false "
        "detections | median ms/frame |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    TruthGeometry geometry;
    for (const Method& m : methods) {
        for (const Set& set : sets) {
            Tally t;
            for (int k = 0; k < scenes; ++k) {
                sc::BoardBenchOptions o;
                o.board = set.board;
                o.occlude = set.occlude;
                const sc::BoardBenchScene s =
                    sc::make_board_bench_scene(o, set.seed0 + static_cast<uint64_t>(k));
                if (&m == &methods[0] && set.board && !set.occlude) geometry.add(s, o.aspect);
                Corners c{};
                const auto t0 = Clock::now();
                const bool found = m.run(s.image, c);
                const double ms =
                    std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
                const char* failure = t.add(s, found, c, ms);
                if (list_failures && *failure)
                    std::printf(
                        "  %s %s seed %llu: %s (tilt %.1f, rotation %.1f, scale %.2f)\n", m.name,
                        set.name,
                        static_cast<unsigned long long>(set.seed0 + static_cast<uint64_t>(k)),
                        failure, s.tilt_deg, s.rotation_deg, s.scale);
            }
            print_row(m.name, set.name, t, set.board);
        }
    }
    std::printf(
        "true boards (unoccluded set): opposite sides up to %.1f deg apart, adjacent sides up to "
        "%.1f deg "
        "off 90, side ratio off the display's by a factor up to %.2f\n",
        geometry.parallel_deg, geometry.perpendicular_deg, geometry.aspect_factor);
    std::printf("RAM of the QVGA detector: %u B (lines stage %u B, quadrangle search %u B)\n",
                qt::BoardDetectorQvga::ram_bytes(), qt::LineDetectorQvga::ram_bytes(),
                qt::BoardDetectorQvga::quad_bytes());
    return 0;
}
