// Host benchmark of board detection and tracking in front of real photographs
// (platform/scene/photo_board_scene.h): boards composited under perspective onto the photographs of
// a folder (Debian's opencv-doc samples, converted to PNM by the build), at QVGA and VGA, in three
// sets — unoccluded, one side partly hidden by a dark disc or arm, no board — with OpenCV's
// squares.cpp recipe on the same frames when it was built in; then a 150-frame sequence of a board
// moving, turning and scaling in front of a photograph, tracked. Also how far the boards' true
// corners read from the display aspect (rule 5) and how much their opposite sides converge.
//
// Detected: every corner of the best quadrangle, in the order returned, within kHitPx of the
// truth. Corner RMSE over the detected boards' corners. A false detection: any quadrangle on a
// board-free frame, or a best quadrangle on a board frame that is not the board. Everything
// printed is deterministic except the times (median and worst over the frames, one run).
//
// usage: bench_photo_boards PHOTO_DIR [--scenes N] [--size qvga|vga|both] [--no-sequence]
//        [--list-failures] [--pictures DIR] [detection flags of quadtrack detect]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "io/image_io.h"
#include "io/overlay.h"
#include "io/png_writer.h"
#include "io/push_frame.h"
#include "quads/board_detector.h"
#include "quads/quad_interior.h"
#include "scene/photo_board_scene.h"
#include "tracking/quad_tracker.h"
#include "tracking/tracking_mode.h"

#ifdef QT_HAVE_OPENCV
#include "bench/opencv_squares.h"
#endif

namespace {

namespace sc = qt::scene;
using Clock = std::chrono::steady_clock;
using Corners = std::array<sc::Point2, 4>;

constexpr double kHitPx = 3.0;  // largest corner error of a detection, px

using Photo = qt::io::NamedImage;

std::vector<Photo> load_photos(const std::string& dir) {
    std::vector<Photo> photos;
    std::string error;
    if (!qt::io::read_image_folder(dir, photos, error)) {
        std::fprintf(stderr, "bench_photo_boards: %s\n", error.c_str());
        std::exit(1);
    }
    return photos;
}

// Rule 5 on a board's true corners, in detect_quads' order (the smallest x + y first): the
// factor between (s1 + s3) / (s0 + s2) and the display aspect, and the larger angle between
// the two pairs of opposite sides, degrees.
struct AspectReading {
    double factor, convergence_deg;
};

AspectReading read_aspect(const sc::Point2 truth[4], double display_aspect) {
    int first = 0;
    for (int k = 1; k < 4; ++k)
        if (truth[k].x + truth[k].y < truth[first].x + truth[first].y) first = k;
    double len[4], dir[4];
    for (int k = 0; k < 4; ++k) {
        const sc::Point2 a = truth[(first + k) & 3], b = truth[(first + k + 1) & 3];
        len[k] = std::hypot(b.x - a.x, b.y - a.y);
        dir[k] = std::atan2(b.y - a.y, b.x - a.x) * 180.0 / 3.14159265358979323846;
    }
    auto apart = [](double a, double b) {  // orientation difference, [0, 90]
        double d = std::fmod(std::fabs(a - b), 180.0);
        return d > 90.0 ? 180.0 - d : d;
    };
    const double ratio = (len[1] + len[3]) / (len[0] + len[2]);
    return {std::max(ratio / display_aspect, display_aspect / ratio),
            std::max(apart(dir[0], dir[2]), apart(dir[1], dir[3]))};
}

// Per size and board aspect: how far the unoccluded boards' true corners read from the
// display aspect, and how much the sides of those beyond aspect_tolerance converge.
struct AspectSpread {
    int boards = 0, beyond = 0, beyond_tilted = 0;
    double worst = 0, least_convergence = 90;
    void add(const AspectReading& r, const qt::QuadParams& q) {
        ++boards;
        worst = std::max(worst, r.factor);
        if (r.factor > q.aspect_tolerance.raw / 65536.0) {
            ++beyond;
            least_convergence = std::min(least_convergence, r.convergence_deg);
        }
        if (r.factor > q.tilted_aspect_tolerance.raw / 65536.0) ++beyond_tilted;
    }
};

double corner_error(const Corners& c, const sc::Point2 truth[4], double* rms) {
    double worst = 0, sq = 0;
    for (int i = 0; i < 4; ++i) {
        const double e = std::hypot(c[i].x - truth[i].x, c[i].y - truth[i].y);
        worst = std::max(worst, e);
        sq += e * e;
    }
    if (rms) *rms = std::sqrt(sq / 4);
    return worst;
}

// The weakest side's contrast, grey levels: for each side, |the pixel 4 px inside the board − the
// pixel 4 px outside| at each pixel step along it (8 px clear of the corners), its 30th
// percentile (a side is as visible as most of its length, not its best stretch); the least over
// the four sides. Read on the rendered frame, so blur, noise and lighting count.
double weakest_contrast(const sc::PhotoBoardScene& s) {
    double weakest = 1e9;
    const double cx = (s.corners[0].x + s.corners[2].x) / 2,
                 cy = (s.corners[0].y + s.corners[2].y) / 2;  // inside the convex board
    for (int i = 0; i < 4; ++i) {
        const sc::Point2 a = s.corners[i], b = s.corners[(i + 1) % 4];
        const double len = std::hypot(b.x - a.x, b.y - a.y), ex = (b.x - a.x) / len,
                     ey = (b.y - a.y) / len;
        // sign: +1 when (ey, -ex) points into the board (towards its centre).
        const double sign = (cx - a.x) * ey - (cy - a.y) * ex >= 0 ? 1 : -1;
        std::vector<double> steps;
        for (double t = 8; t <= len - 8; t += 1) {
            auto at = [&](double depth) {
                const int x = static_cast<int>(std::lround(a.x + ex * t + sign * ey * depth));
                const int y = static_cast<int>(std::lround(a.y + ey * t - sign * ex * depth));
                return static_cast<double>(
                    s.image.at(std::min(s.image.width - 1, std::max(0, x)),
                               std::min(s.image.height - 1, std::max(0, y))));
            };
            steps.push_back(std::fabs(at(4) - at(-4)));
        }
        if (steps.empty()) continue;
        std::sort(steps.begin(), steps.end());
        weakest = std::min(weakest, steps[steps.size() * 3 / 10]);
    }
    return weakest;
}

// Detection of unoccluded boards by the weakest side's contrast (weakest_contrast) and by noise σ.
struct ContrastBins {
    static constexpr int kContrast = 4, kNoise = 3;
    static constexpr double kContrastEdges[kContrast - 1] = {10, 20, 40};
    static constexpr double kNoiseEdges[kNoise - 1] = {4, 6};
    int boards[kContrast] = {}, found[kContrast] = {};
    int noise_boards[kNoise] = {}, noise_found[kNoise] = {};
    static int bin(double v, const double* edges, int n) {
        int k = 0;
        while (k < n - 1 && v >= edges[k]) ++k;
        return k;
    }
    void add(const sc::PhotoBoardScene& s, bool detected) {
        const int c = bin(weakest_contrast(s), kContrastEdges, kContrast);
        const int z = bin(s.noise_sigma, kNoiseEdges, kNoise);
        ++boards[c];
        found[c] += detected;
        ++noise_boards[z];
        noise_found[z] += detected;
    }
    static std::string cell(int f, int n) {
        if (n == 0) return "—";
        char text[48];
        std::snprintf(text, sizeof text, "%.1f %% (%d)", 100.0 * f / n, n);
        return text;
    }
    std::string row(const char* method, const char* size) const {
        std::string r = std::string("| ") + method + " | " + size;
        for (int k = 0; k < kContrast; ++k) r += " | " + cell(found[k], boards[k]);
        for (int k = 0; k < kNoise; ++k) r += " | " + cell(noise_found[k], noise_boards[k]);
        return r + " |\n";
    }
};

struct Tally {
    int scenes = 0, detected = 0, wrong = 0, capacity = 0;
    double sum_sq = 0;
    int corners = 0;
    std::vector<double> ms;

    const char* add(const sc::PhotoBoardScene& s, bool found, const Corners& c,
                    bool capacity_exceeded, double elapsed_ms) {
        ++scenes;
        ms.push_back(elapsed_ms);
        capacity += capacity_exceeded;
        if (!found) return s.has_board ? "missed" : "";
        if (!s.has_board) {
            ++wrong;
            return "false detection";
        }
        if (corner_error(c, s.corners, nullptr) > kHitPx) {
            ++wrong;
            return "wrong quadrangle";
        }
        for (int i = 0; i < 4; ++i)
            sum_sq += std::pow(std::hypot(c[i].x - s.corners[i].x, c[i].y - s.corners[i].y), 2);
        corners += 4;
        ++detected;
        return "";
    }
    double median_ms() {
        std::sort(ms.begin(), ms.end());
        return ms.empty() ? 0 : ms[ms.size() / 2];
    }
    double worst_ms() const { return ms.empty() ? 0 : *std::max_element(ms.begin(), ms.end()); }
};

// The share of the 2 × 2 px cells inside the last quadrangle ours reported that hold an edge
// point, % at 240 rows (quad_interior.h's measure, which --max-inside-edges limits).
double g_inside_percent = 0;

// The measure's spread over a set's reported quadrangles, as "median / 99th percentile / max".
std::string spread(std::vector<double> v) {
    if (v.empty()) return "—";
    std::sort(v.begin(), v.end());
    char text[64];
    std::snprintf(text, sizeof text, "%.1f / %.1f / %.1f", v[v.size() / 2],
                  v[std::min(v.size() - 1, v.size() * 99 / 100)], v.back());
    return text;
}

// One detector per frame size, as firmware would compile them.
template <class Detector>
struct Ours {
    Detector det;
    qt::BoardParams params;
    bool run(const qt::io::GreyImage& img, Corners& c, bool* capacity) {
        const qt::Status s = qt::io::push_frame(det, img, params);
        if (s != qt::Status::ok && s != qt::Status::capacity_exceeded) {
            std::fprintf(stderr, "bench_photo_boards: %s\n", qt::status_name(s));
            std::exit(1);
        }
        *capacity = s == qt::Status::capacity_exceeded;
        if (det.quad_count() == 0) return false;
        const qt::InteriorCount in = qt::count_inside_edges(
            det.lines().edges(), det.quads()[0].corners, params.refine.inside_margin);
        g_inside_percent =
            in.area_px == 0 ? 0.0 : 400.0 * in.cells * std::sqrt(img.height / 240.0) / in.area_px;
        for (int i = 0; i < 4; ++i)
            c[i] = {det.quads()[0].corners[i].x.raw / 65536.0,
                    det.quads()[0].corners[i].y.raw / 65536.0};
        return true;
    }
};

Ours<qt::BoardDetectorQvga> g_qvga;
Ours<qt::BoardDetectorVga> g_vga;

bool detect(const qt::io::GreyImage& img, Corners& c, bool* capacity) {
    return img.width <= 320 && img.height <= 240 ? g_qvga.run(img, c, capacity)
                                                 : g_vga.run(img, c, capacity);
}

// The lines of the last frame detected at that frame's size.
uint16_t last_line_count(const qt::io::GreyImage& img, const qt::Segment** lines) {
    if (img.width <= 320 && img.height <= 240) {
        *lines = g_qvga.det.lines().lines();
        return g_qvga.det.lines().line_count();
    }
    *lines = g_vga.det.lines().lines();
    return g_vga.det.lines().line_count();
}

void save_picture(const std::string& path, const sc::PhotoBoardScene& s, bool found,
                  const Corners& c) {
    qt::io::RgbImage rgb = qt::io::RgbImage::from_grey(s.image, 70);
    const qt::Segment* lines = nullptr;
    const uint16_t n = last_line_count(s.image, &lines);
    for (uint16_t i = 0; i < n; ++i)
        rgb.line(lines[i].x1.raw / 65536.0, lines[i].y1.raw / 65536.0, lines[i].x2.raw / 65536.0,
                 lines[i].y2.raw / 65536.0, {255, 60, 60});
    if (s.has_board)
        for (int i = 0; i < 4; ++i) rgb.ring(s.corners[i].x, s.corners[i].y, 5, {255, 0, 255});
    if (found)
        for (int i = 0; i < 4; ++i) {
            const sc::Point2 a = c[i], b = c[(i + 1) % 4];
            rgb.line(a.x, a.y, b.x, b.y, {60, 255, 60});
            rgb.ring(a.x, a.y, 3, {255, 255, 0});
        }
    std::string error;
    if (!qt::io::write_png(path, rgb.width, rgb.height, 3, rgb.pixels, error))
        std::fprintf(stderr, "bench_photo_boards: %s\n", error.c_str());
}

struct Method {
    const char* name;
    bool (*run)(const qt::io::GreyImage&, Corners&, bool*);
};

#ifdef QT_HAVE_OPENCV
bool opencv(const qt::io::GreyImage& img, Corners& c, bool* capacity) {
    *capacity = false;
    return qt::bench::opencv_best_square(img, c);
}
#endif

void print_row(const char* method, const char* size, const char* set, Tally& t, bool board) {
    char rmse[16] = "—";
    if (t.corners) std::snprintf(rmse, sizeof rmse, "%.3f", std::sqrt(t.sum_sq / t.corners));
    char detected[32] = "—";
    if (board) std::snprintf(detected, sizeof detected, "%.1f %%", 100.0 * t.detected / t.scenes);
    std::printf("| %s | %s | %s | %d | %s | %s | %d (%.1f %%) | %.1f %% | %.2f | %.2f |\n", method,
                size, set, t.scenes, detected, rmse, t.wrong, 100.0 * t.wrong / t.scenes,
                100.0 * t.capacity / t.scenes, t.median_ms(), t.worst_ms());
}

std::string g_sequence_photo =
    "building";  // the sequence's background: the first photograph of that name

// Tracking mode on the sequence: its tracked corners against the truth and against those of
// the whole frames.
struct TrackingModeTally {
    int frames = 0, good = 0, occluded = 0, occluded_good = 0, banded = 0, both = 0;
    double worst_rms = 0, sq_apart = 0;
    void add(bool in_bands, const qt::TrackedQuad& whole, const qt::TrackedQuad& t,
             const sc::PhotoBoardScene& s) {
        ++frames;
        banded += in_bands;
        double rms = 1e9;
        if (t.state != qt::TrackState::none) {
            Corners tc{};
            for (int i = 0; i < 4; ++i)
                tc[i] = {t.corners[i].x.raw / 65536.0, t.corners[i].y.raw / 65536.0};
            corner_error(tc, s.corners, &rms);
            worst_rms = std::max(worst_rms, rms);
        }
        good += rms <= kHitPx;
        if (s.occluded_side >= 0) {
            ++occluded;
            occluded_good += rms <= kHitPx;
        }
        if (t.state != qt::TrackState::none && whole.state != qt::TrackState::none) {
            ++both;
            for (int i = 0; i < 4; ++i) {
                const double dx = (t.corners[i].x.raw - whole.corners[i].x.raw) / 65536.0,
                             dy = (t.corners[i].y.raw - whole.corners[i].y.raw) / 65536.0;
                sq_apart += (dx * dx + dy * dy) / 4;
            }
        }
    }
    std::string row(int w, int h, const std::string& photo, int count) const {
        char line[256];
        std::snprintf(
            line, sizeof line,
            "| %dx%d | %s | %d | %.1f %% (%d) | %.1f %% (%d of %d) | %d | %.3f | %.3f |\n", w, h,
            photo.c_str(), count, 100.0 * good / count, good,
            100.0 * occluded_good / std::max(1, occluded), occluded_good, occluded, banded,
            worst_rms, both > 0 ? std::sqrt(sq_apart / both) : 0.0);
        return line;
    }
};
std::string g_tracking_mode_rows;

// One frame through `det` in the window (null: whole) and `tracker`'s step on it.
template <class Detector>
qt::TrackedQuad banded_step(Detector& det, const qt::io::GreyImage& img,
                            const qt::BoardParams& params, qt::BandWindow* window,
                            qt::QuadTracker& tracker) {
    const uint16_t w = static_cast<uint16_t>(img.width), h = static_cast<uint16_t>(img.height);
    qt::Status s = det.begin_frame(w, h, params, window);
    if (s == qt::Status::previous_frame_incomplete) s = qt::Status::ok;
    for (uint16_t y = 0; y < h && s == qt::Status::ok; ++y) s = det.push_row(img.row(y), w);
    if (s == qt::Status::ok) s = det.finish();
    if (s != qt::Status::ok && s != qt::Status::capacity_exceeded) {
        std::fprintf(stderr, "bench_photo_boards: %s\n", qt::status_name(s));
        std::exit(1);
    }
    return tracker.step(det.lines().lines(), det.lines().line_count(), det.quads(),
                        det.quad_count());
}

// The sequence: tracked frames within kHitPx RMS of the truth, overall and while the arm hides
// a side.
void run_sequence(const std::vector<Photo>& photos, int w, int h, const qt::BoardParams& params,
                  const std::string& pictures) {
    sc::PhotoSequenceOptions so;
    so.width = w;
    so.height = h;
    const Photo* chosen = &photos[0];
    for (const Photo& p : photos)
        if (p.name.rfind(g_sequence_photo, 0) == 0) chosen = &p;
    const Photo& photo = *chosen;
    qt::QuadTracker tracker(
        qt::default_quad_tracker_params(static_cast<uint16_t>(w), static_cast<uint16_t>(h)));
    qt::QuadTrackerParams tp =
        qt::default_quad_tracker_params(static_cast<uint16_t>(w), static_cast<uint16_t>(h));
    tp.shape = qt::sized_quad_params(params.quads, static_cast<uint16_t>(h));
    tracker.set_params(tp);
    int good = 0, occluded = 0, occluded_good = 0, detected_good = 0;
    double worst_rms = 0;
    // The same frames in tracking mode (tracking/tracking_mode.h): a second tracker fed by the
    // detector run through the bands planned from its own last frame.
    qt::QuadTracker banded_tracker(tp);
    qt::TrackingMode mode;
    qt::BandWindow* window = nullptr;
    TrackingModeTally tm;
    std::vector<int> misses;
    for (int k = 0; k < so.frames; ++k) {
        const sc::PhotoBoardScene s = sc::make_photo_sequence_frame(so, photo.image, k);
        Corners c{};
        bool capacity = false;
        const bool found = detect(s.image, c, &capacity);
        double rms_detect = 1e9;
        if (found) corner_error(c, s.corners, &rms_detect);
        detected_good += rms_detect <= kHitPx;
        const qt::Segment* lines = nullptr;
        uint16_t n = 0;
        const qt::Quad* quads = nullptr;
        uint16_t nq = 0;
        if (w <= 320 && h <= 240) {
            n = last_line_count(s.image, &lines);
            quads = g_qvga.det.quads();
            nq = g_qvga.det.quad_count();
        } else {
            n = last_line_count(s.image, &lines);
            quads = g_vga.det.quads();
            nq = g_vga.det.quad_count();
        }
        const qt::TrackedQuad t = tracker.step(lines, n, quads, nq);
        const qt::TrackedQuad tb =
            w <= 320 && h <= 240 ? banded_step(g_qvga.det, s.image, params, window, banded_tracker)
                                 : banded_step(g_vga.det, s.image, params, window, banded_tracker);
        tm.add(window != nullptr, t, tb, s);
        window = mode.plan(tb);
        double rms = 1e9;
        Corners tc{};
        if (t.state != qt::TrackState::none) {
            for (int i = 0; i < 4; ++i)
                tc[i] = {t.corners[i].x.raw / 65536.0, t.corners[i].y.raw / 65536.0};
            corner_error(tc, s.corners, &rms);
        }
        const bool ok = rms <= kHitPx;
        good += ok;
        if (!ok) misses.push_back(k);
        if (t.state != qt::TrackState::none) worst_rms = std::max(worst_rms, rms);
        if (s.occluded_side >= 0) {
            ++occluded;
            occluded_good += ok;
        }
        if (!pictures.empty() && (k % 10 == 0 || (s.occluded_side >= 0 && k % 5 == 0)))
            save_picture(
                pictures + "/sequence_" + std::to_string(w) + "_" + std::to_string(k) + ".png", s,
                t.state != qt::TrackState::none, tc);
    }
    std::printf(
        "| sequence | %dx%d | %s | %d | %.1f %% (%d) | %.1f %% (%d of %d) | %.1f %% | %.3f |\n", w,
        h, photo.name.c_str(), so.frames, 100.0 * good / so.frames, good,
        100.0 * occluded_good / std::max(1, occluded), occluded_good, occluded,
        100.0 * detected_good / so.frames, worst_rms);
    if (!misses.empty()) {
        std::printf("  frames not within %.0f px:", kHitPx);
        for (int k : misses) std::printf(" %d", k);
        std::printf("\n");
    }
    g_tracking_mode_rows += tm.row(w, h, photo.name, so.frames);
}

}  // namespace

int main(int argc, char** argv) {
    int scenes = 300;
    bool list_failures = false, sequence = true;
    std::string size = "both", pictures;
    std::vector<std::string> rest;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--scenes" && i + 1 < argc) {
            scenes = std::atoi(argv[++i]);
        } else if (a == "--size" && i + 1 < argc) {
            size = argv[++i];
        } else if (a == "--pictures" && i + 1 < argc) {
            pictures = argv[++i];
        } else if (a == "--list-failures") {
            list_failures = true;
        } else if (a == "--sequence-photo" && i + 1 < argc) {
            g_sequence_photo = argv[++i];
        } else if (a == "--no-sequence") {
            sequence = false;
        } else {
            rest.push_back(a);
        }
    }
    qt::cli::DetectOptions options;
    std::string photo_dir;
    const int parsed =
        qt::cli::parse_command_line(rest, qt::cli::Command::detect,
                                    "usage: bench_photo_boards PHOTO_DIR [--scenes N] [--size "
                                    "qvga|vga|both] [--no-sequence] [--list-failures] "
                                    "[--pictures DIR] [detection flags]\n" +
                                        qt::cli::options_help(),
                                    options, photo_dir, stdout, stderr);
    if (parsed >= 0) return parsed;
    if (scenes <= 0 || (size != "qvga" && size != "vga" && size != "both")) {
        std::fprintf(stderr,
                     "bench_photo_boards: --scenes must be positive, --size qvga, vga or both\n");
        return 2;
    }
    const std::vector<Photo> photos = load_photos(photo_dir);
    g_qvga.params = g_vga.params = options.params;

    std::vector<Method> methods = {{"quadtrack", detect}};
#ifdef QT_HAVE_OPENCV
    methods.push_back({"OpenCV squares.cpp", opencv});
#endif
    // The photograph's white over the board's level: below 1 the board is the brightest surface;
    // the bright set puts it in front of a background up to 10 % brighter than itself.
    struct Set {
        const char* name;
        bool board, occlude;
        uint64_t seed0;
        double darken_min, darken_max;
    };
    const Set sets[] = {{"unoccluded", true, false, 1000000, 0.5, 0.9},
                        {"occluded", true, true, 2000000, 0.5, 0.9},
                        {"no board", false, false, 3000000, 0.5, 0.9},
                        {"bright background", true, false, 4000000, 0.8, 1.1}};
    struct Size {
        const char* name;
        int w, h;
    };
    std::vector<Size> sizes;
    if (size != "vga") sizes.push_back({"QVGA", 320, 240});
    if (size != "qvga") sizes.push_back({"VGA", 640, 480});

    std::printf(
        "boards on %zu photographs of %s: aspect 4:3, 16:9, 1:1; tilt <= 35 deg, roll <= 25 deg, "
        "scale 25-70 %%; "
        "board grey 200-245, shading <= 10 %%, print on half; photograph white at 0.5-0.9 x the "
        "board (bright background: 0.8-1.1), lighting >= 0.6, "
        "blur sigma 0-1.25 px, noise sigma 2-7; %d scenes per set and size; detected = every "
        "corner within "
        "%.0f px\n",
        photos.size(), photo_dir.c_str(), scenes, kHitPx);
    std::printf(
        "| method | size | set | scenes | detected | corner RMSE px | false detections | "
        "capacity_exceeded | "
        "median ms | worst ms |\n|---|---|---|---|---|---|---|---|---|---|\n");
    std::string inside_lines, aspect_lines, contrast_lines;
    const double display_aspect = options.params.quads.display_aspect.raw / 65536.0;
    for (const Size& sz : sizes) {
        AspectSpread spreads[3];  // boards of aspect 1:1, 4:3, 16:9
        for (const Method& m : methods) {
            ContrastBins bins;
            for (const Set& set : sets) {
                Tally t;
                std::vector<double> inside_boards, inside_others;
                for (int k = 0; k < scenes; ++k) {
                    sc::PhotoBoardOptions o;
                    o.width = sz.w;
                    o.height = sz.h;
                    o.board = set.board;
                    o.occlude = set.occlude;
                    o.darken_min = set.darken_min;
                    o.darken_max = set.darken_max;
                    const uint64_t seed = set.seed0 + static_cast<uint64_t>(k);
                    const Photo& photo = photos[static_cast<std::size_t>(k) % photos.size()];
                    const sc::PhotoBoardScene s = sc::make_photo_board_scene(o, photo.image, seed);
                    Corners c{};
                    bool capacity = false;
                    const auto t0 = Clock::now();
                    const bool found = m.run(s.image, c, &capacity);
                    const double ms =
                        std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
                    const char* failure = t.add(s, found, c, capacity, ms);
                    if (set.board && !set.occlude) bins.add(s, !*failure);
                    if (&m == &methods[0] && set.board && !set.occlude)
                        spreads[s.aspect < 1.2   ? 0
                                : s.aspect < 1.5 ? 1
                                                 : 2]
                            .add(read_aspect(s.corners, display_aspect), options.params.quads);
                    if (found && &m == &methods[0])
                        (*failure ? inside_others : inside_boards).push_back(g_inside_percent);
                    if (list_failures && *failure)
                        std::printf(
                            "  %s %s %s seed %llu %s: %s (tilt %.1f, roll %.1f, scale %.2f, aspect "
                            "%.2f, "
                            "blur %.2f, noise %.1f, contrast %.0f%s)\n",
                            m.name, sz.name, set.name, static_cast<unsigned long long>(seed),
                            photo.name.c_str(), failure, s.pose.tilt_deg, s.pose.rotation_deg,
                            s.pose.scale, s.aspect, s.blur_sigma, s.noise_sigma,
                            s.has_board ? weakest_contrast(s) : 0.0,
                            capacity ? ", capacity_exceeded" : "");
                    if (!pictures.empty() && &m == &methods[0] && (*failure || k < 4)) {
                        const std::string stem =
                            pictures + "/" + sz.name + "_" + set.name[0] + std::to_string(seed);
                        save_picture(stem + ".png", s, found, c);
                        std::string error;
                        qt::io::write_pgm(stem + ".pgm", s.image, error);
                    }
                }
                print_row(m.name, sz.name, set.name, t, set.board);
                if (&m == &methods[0])
                    inside_lines += std::string("| ") + sz.name + " | " + set.name + " | " +
                                    spread(inside_boards) + " | " + spread(inside_others) + " |\n";
            }
            contrast_lines += bins.row(m.name, sz.name);
        }
        const char* aspect_names[3] = {"1:1", "4:3", "16:9"};
        for (int a = 0; a < 3; ++a) {
            const AspectSpread& sp = spreads[a];
            char convergence[16] = "-", line[200];
            if (sp.beyond > 0)
                std::snprintf(convergence, sizeof convergence, "%.1f", sp.least_convergence);
            std::snprintf(line, sizeof line, "| %s | %s | %d | %.2f | %d | %s | %d |\n", sz.name,
                          aspect_names[a], sp.boards, sp.worst, sp.beyond, convergence,
                          sp.beyond_tilted);
            aspect_lines += line;
        }
    }
    std::printf(
        "\nUnoccluded boards (the unoccluded and bright-background sets) detected, by the weakest "
        "side's contrast (30th percentile of |4 px inside - 4 px outside| along the side, grey "
        "levels) and by noise sigma (boards in brackets)\n| method | size | < 10 | 10-20 | 20-40 | "
        ">= 40 | noise < 4 | 4-6 | >= 6 |\n|---|---|---|---|---|---|---|---|---|\n%s",
        contrast_lines.c_str());
    std::printf(
        "\n2x2 px cells inside the reported quadrangle holding an edge point, %% at 240 rows "
        "(limit: --max-inside-edges %u), median / 99th percentile / max\n| size | set | the board "
        "| "
        "another quadrangle |\n|---|---|---|---|\n%s",
        options.params.refine.max_inside_edge_cells_percent, inside_lines.c_str());
    std::printf(
        "\nRule 5 on the unoccluded boards' true corners against the display aspect %.3f: the "
        "factor off it, and the least convergence (larger angle between opposite sides) of "
        "those beyond --aspect-tolerance %.2f, which --tilted-aspect-tolerance %.2f needs >= "
        "--perspective-convergence %.1f deg\n| size | board | boards | largest factor | "
        "beyond %.2f | their least convergence, deg | beyond %.2f |\n|---|---|---|---|---|---|---|"
        "\n%s",
        display_aspect, options.params.quads.aspect_tolerance.raw / 65536.0,
        options.params.quads.tilted_aspect_tolerance.raw / 65536.0,
        qt::angle_to_deg(options.params.quads.perspective_convergence).raw / 65536.0,
        options.params.quads.aspect_tolerance.raw / 65536.0,
        options.params.quads.tilted_aspect_tolerance.raw / 65536.0, aspect_lines.c_str());
    if (sequence) {
        std::printf(
            "\n| sequence | size | photograph | frames | tracked within %.0f px RMS | while a side "
            "is hidden | "
            "detected within %.0f px | worst RMS px |\n|---|---|---|---|---|---|---|---|\n",
            kHitPx, kHitPx);
        for (const Size& sz : sizes) run_sequence(photos, sz.w, sz.h, options.params, pictures);
        std::printf(
            "\nThe sequence in tracking mode (tracking/tracking_mode.h): each frame after one that "
            "held the board with all four sides measured in bands around them\n| size | "
            "photograph | frames | tracked within %.0f px RMS | while a side is hidden | frames in "
            "bands | worst RMS px | RMS px from the whole frames' corners |\n"
            "|---|---|---|---|---|---|---|---|\n%s",
            kHitPx, g_tracking_mode_rows.c_str());
    }
    return 0;
}
