// Host benchmark of the lines stage (gradient -> edges -> PPHT -> clustering): accuracy on
// synthetic QVGA scenes with known truth, the effect of the direction vote window, VGA time
// per frame (beside OpenCV's Canny + HoughLinesP when OpenCV was found at configure time) and
// the RAM of the parts. Everything printed is deterministic except the timings.
// Run by `bash bench.sh lines-host`; `--scenes N` sets the scenes per accuracy row (1000).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

#include "io/push_frame.h"
#include "lines/line_detector.h"
#include "scene/board_scene.h"
#include "scene/line_match.h"
#include "scene/line_scene.h"

#ifdef QT_HAVE_OPENCV
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#endif

namespace {

namespace sc = qt::scene;
using Clock = std::chrono::steady_clock;

constexpr int kVgaRepeats = 31;  // medians over this many timings at VGA

[[noreturn]] void fail(const char* what, qt::Status s) {
    std::fprintf(stderr, "bench_lines: %s: %s\n", what, qt::status_name(s));
    std::exit(1);
}

double px(qt::q16_16 v) { return v.raw / 65536.0; }

std::vector<sc::DetectedLine> to_detected(const qt::Segment* s, uint16_t n) {
    std::vector<sc::DetectedLine> d;
    for (uint16_t i = 0; i < n; ++i)
        d.push_back({{px(s[i].x1), px(s[i].y1)}, {px(s[i].x2), px(s[i].y2)}});
    return d;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

// One frame through the detector, gradient through clustering; returns the seconds it took.
template <class Det>
double detect(Det& det, const qt::io::GreyImage& img, const qt::LineParams& params) {
    const auto t0 = Clock::now();
    const qt::Status s = qt::io::push_frame(det, img, params);
    const auto t1 = Clock::now();
    // A full capacity is counted in the stats and the lines found are still scored.
    if (s != qt::Status::ok && s != qt::Status::capacity_exceeded) fail("frame", s);
    return std::chrono::duration<double>(t1 - t0).count();
}

double pct(int a, int b) { return b > 0 ? 100.0 * a / b : 0; }

double dist(sc::Point2 a, sc::Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Smaller inner angle, degrees, of the two polygon corners at the ends of truth[i] (sides of a
// polygon are consecutive and share end points exactly); 180 where no side joins.
double corner_deg(const std::vector<sc::TrueSegment>& truth, size_t i) {
    const sc::TrueSegment& t = truth[i];
    double least = 180;
    for (const sc::TrueSegment& u : truth) {
        sc::Point2 v, far_t, far_u;  // shared vertex and the other ends
        if (u.a.x == t.b.x && u.a.y == t.b.y) {
            v = t.b, far_t = t.a, far_u = u.b;
        } else if (u.b.x == t.a.x && u.b.y == t.a.y) {
            v = t.a, far_t = t.b, far_u = u.a;
        } else {
            continue;
        }
        const double ux = far_t.x - v.x, uy = far_t.y - v.y, wx = far_u.x - v.x, wy = far_u.y - v.y;
        least = std::min(least, std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 /
                                    3.14159265358979323846);
    }
    return least;
}

// Detected lines lying on t: both ends within 3 px of it and orientation within 3 deg (the
// true-detection test of match_lines, for one truth segment).
int lines_on(const sc::TrueSegment& t, const std::vector<sc::DetectedLine>& d) {
    int n = 0;
    for (const sc::DetectedLine& l : d)
        n += match_lines({t}, {l}, sc::MatchRule{}).false_positives == 0 ? 1 : 0;
    return n;
}

// ---- 1. Accuracy ----------------------------------------------------------------------------

struct Totals {
    int frames = 0;
    sc::MatchResult lines;  // summed over frames (worst_* are maxima)
    int seg_found = 0;      // truth found by the PPHT segments, before clustering
    long edges = 0, segments = 0, line_count = 0, votes = 0, followed = 0;
    long edges_dropped = 0, segments_dropped = 0, lines_dropped = 0, budget_exhausted = 0;
    std::vector<double> seconds;
    int sharp_scored = 0, sharp_found = 0;       // truth with a polygon corner < 60 deg at an end
    long lines_on_truth = 0, segs_on_truth = 0;  // detections lying on a scored truth segment
};

void add(Totals& t, const sc::LineScene& scene, const qt::LineDetectorQvga& det, double seconds,
         const sc::MatchRule& rule) {
    const std::vector<sc::DetectedLine> lines = to_detected(det.lines(), det.line_count());
    const std::vector<sc::DetectedLine> segs = to_detected(det.segments(), det.segment_count());
    for (size_t i = 0; i < scene.truth().size(); ++i) {
        const sc::TrueSegment& tr = scene.truth()[i];
        if (dist(tr.a, tr.b) < rule.min_length) continue;
        t.lines_on_truth += lines_on(tr, lines);
        t.segs_on_truth += lines_on(tr, segs);
        if (corner_deg(scene.truth(), i) < 60) {
            ++t.sharp_scored;
            t.sharp_found += match_lines({tr}, lines, rule).found;
        }
    }
    const sc::MatchResult m = match_lines(scene.truth(), lines, rule);
    const sc::MatchResult ms = match_lines(scene.truth(), segs, rule);
    const qt::LineStats& st = det.stats();
    ++t.frames;
    t.lines.scored += m.scored;
    t.lines.found += m.found;
    t.lines.detected += m.detected;
    t.lines.false_positives += m.false_positives;
    t.lines.worst_angle_deg = std::max(t.lines.worst_angle_deg, m.worst_angle_deg);
    t.lines.worst_endpoint_px = std::max(t.lines.worst_endpoint_px, m.worst_endpoint_px);
    t.seg_found += ms.found;
    t.edges += st.edges;
    t.segments += det.segment_count();
    t.line_count += det.line_count();
    t.votes += st.hough.votes;
    t.followed += st.hough.lines_followed;
    t.edges_dropped += st.edges_dropped;
    t.segments_dropped += st.hough.segments_dropped;
    t.lines_dropped += st.cluster.clusters_dropped;
    t.budget_exhausted += st.hough.budget_bound() ? 1 : 0;
    t.seconds.push_back(seconds);
}

struct RowSpec {
    char id;
    const char* what;
    std::function<sc::LineScene(uint64_t seed)> make;
};

sc::SceneOptions qvga(uint64_t seed, double noise, double blur, int blobs, int texture) {
    sc::SceneOptions o;
    o.seed = seed;
    o.noise_sigma = noise;
    o.blur_sigma = blur;
    o.clutter_blobs = blobs;
    o.clutter_texture = texture;
    return o;
}

std::vector<RowSpec> rows() {
    return {
        {'a', "2 polygons (side>=40, corners>=60deg), clean",
         [](uint64_t s) { return sc::random_polygon_scene(qvga(s, 0, 0, 0, 0), 2, 40, 60); }},
        {'b', "as a + noise 5 + blur 0.7",
         [](uint64_t s) { return sc::random_polygon_scene(qvga(s, 5, 0.7, 0, 0), 2, 40, 60); }},
        {'c', "as b + 20 clutter blobs + texture 20",
         [](uint64_t s) { return sc::random_polygon_scene(qvga(s, 5, 0.7, 20, 20), 2, 40, 60); }},
        {'d', "4 drawn lines 2 px wide, length 40..150, noise 5, blur 0.7",
         [](uint64_t s) { return sc::random_line_scene(qvga(s, 5, 0.7, 0, 0), 4, 40, 150); }},
        {'e', "2 polygons, any corner angle (acute), noise 5, blur 0.7",
         [](uint64_t s) { return sc::random_polygon_scene(qvga(s, 5, 0.7, 0, 0), 2, 40, 0); }},
    };
}

void accuracy(int scenes, const qt::LineParams& params, const char* title) {
    static qt::LineDetectorQvga det;
    const sc::MatchRule rule;
    std::printf("\n%s, QVGA 320x240, LineDetectorQvga; %d scenes per row, scene seeds 1..%d\n",
                title, scenes, scenes);
    std::printf(
        "   (same seeds => rows a, b, c share geometry). A truth segment >= %.0f px is found when\n"
        "   a clustered line is within %.0f deg and both ends within %.0f px; FP = line on no "
        "truth "
        "(3 px, 3 deg).\n",
        rule.min_length, rule.max_angle_deg, rule.max_endpoint_px);
    for (const RowSpec& r : rows()) std::printf("   %c: %s\n", r.id, r.what);
    std::vector<std::pair<char, Totals>> notes;
    std::printf(
        "   row scored found recall%% seg-rec%% FP/fr worst-deg worst-px edges/fr segs/fr lines/fr"
        "  drops e/s/l budget\n");
    for (const RowSpec& r : rows()) {
        Totals t;
        for (int i = 1; i <= scenes; ++i) {
            const sc::LineScene scene = r.make(static_cast<uint64_t>(i));
            const qt::io::GreyImage img = scene.render();
            const double s = detect(det, img, params);
            add(t, scene, det, s, rule);
        }
        const double n = t.frames;
        std::printf(
            "   %c   %6d %5d %7.1f %8.1f %5.2f %9.3f %8.2f %8.0f %7.1f %8.1f  %5ld/%ld/%ld %6ld\n",
            r.id, t.lines.scored, t.lines.found, pct(t.lines.found, t.lines.scored),
            pct(t.seg_found, t.lines.scored), t.lines.false_positives / n, t.lines.worst_angle_deg,
            t.lines.worst_endpoint_px, t.edges / n, t.segments / n, t.line_count / n,
            t.edges_dropped, t.segments_dropped, t.lines_dropped, t.budget_exhausted);
        notes.emplace_back(r.id, t);
    }
    std::printf(
        "   seg-rec: the same rule on the PPHT segments before clustering. drops: edge points/"
        "segments/lines\n   lost to capacity, budget: frames that hit max_walk_steps or max_voters "
        "(totals over the row).\n");
    for (const auto& [id, t] : notes) {
        if (id == 'd')
            std::printf(
                "   d: detections lying on a scored drawn line (3 px, 3 deg), per line: PPHT "
                "segments "
                "%.2f, clustered lines %.2f\n",
                static_cast<double>(t.segs_on_truth) / t.lines.scored,
                static_cast<double>(t.lines_on_truth) / t.lines.scored);
        if (id == 'e')
            std::printf(
                "   e: sides with a corner < 60 deg at an end: %d/%d found (%.1f%%); other sides: "
                "%d/%d (%.1f%%)\n",
                t.sharp_found, t.sharp_scored, pct(t.sharp_found, t.sharp_scored),
                t.lines.found - t.sharp_found, t.lines.scored - t.sharp_scored,
                pct(t.lines.found - t.sharp_found, t.lines.scored - t.sharp_scored));
    }
}

// ---- 2. Vote window ---------------------------------------------------------------------------

void vote_window(int scenes) {
    static qt::LineDetectorQvga det;
    qt::LineParams narrow, wide;
    wide.hough.vote_window_deg = 90;
    const sc::MatchRule rule;
    std::printf(
        "\n2. Vote window: each point votes for theta within +-%u deg of its gradient direction "
        "(default)\n   vs every theta (90); rows b and c, %d scenes each, both settings on each "
        "frame in turn;\n   time = median host time per frame, gradient..clustering.\n",
        static_cast<unsigned>(narrow.hough.vote_window_deg), scenes);
    std::printf("   row window  votes/fr followed/fr recall%%  FP/frame  ms/frame\n");
    const std::vector<RowSpec> all = rows();
    for (const RowSpec& r : all) {
        if (r.id != 'b' && r.id != 'c') continue;
        Totals tn, tw;
        for (int i = 1; i <= scenes; ++i) {
            const sc::LineScene scene = r.make(static_cast<uint64_t>(i));
            const qt::io::GreyImage img = scene.render();
            double s = detect(det, img, narrow);
            add(tn, scene, det, s, rule);
            s = detect(det, img, wide);
            add(tw, scene, det, s, rule);
        }
        for (const Totals* t : {&tn, &tw}) {
            const double n = t->frames;
            std::printf("   %c   %6u %9.0f %11.1f %7.1f %9.2f %9.3f\n", r.id,
                        static_cast<unsigned>(t == &tn ? narrow.hough.vote_window_deg : 90),
                        t->votes / n, t->followed / n, pct(t->lines.found, t->lines.scored),
                        t->lines.false_positives / n, median(t->seconds) * 1e3);
        }
        std::printf("   %c   ratio 90/%u: votes x%.2f, time x%.2f\n", r.id,
                    static_cast<unsigned>(narrow.hough.vote_window_deg),
                    static_cast<double>(tw.votes) / static_cast<double>(tn.votes),
                    median(tw.seconds) / median(tn.seconds));
    }
}

// ---- 3. VGA time ------------------------------------------------------------------------------

struct VgaFrame {
    const char* name;
    qt::io::GreyImage img;
    std::vector<sc::TrueSegment> truth;
};

#ifdef QT_HAVE_OPENCV
// Canny + HoughLinesP settings: with these the board's four sides come out as four segments,
// one per side (maxLineGap 4 splits or loses sides, threshold 40 splits the left one).
constexpr double kCannyLow = 50, kCannyHigh = 150;
constexpr int kCannyAperture = 3;
constexpr double kHoughRho = 1, kHoughThetaDeg = 1;
constexpr int kHoughThreshold = 80, kHoughMinLength = 20, kHoughMaxGap = 8;
#endif

// For one truth side: "yes"/"no" by `rule`, and the end-point error of the best detection
// within the rule's angle (worse end, px), or "-" when none is that close in angle.
void print_side(const sc::TrueSegment& t, const std::vector<sc::DetectedLine>& d,
                const sc::MatchRule& rule) {
    double best = -1;
    for (const sc::DetectedLine& l : d) {
        sc::MatchRule angle_only = rule;
        angle_only.max_endpoint_px = 1e9;
        if (match_lines({t}, {l}, angle_only).found == 0) continue;
        const double e = std::min(std::max(dist(l.a, t.a), dist(l.b, t.b)),
                                  std::max(dist(l.a, t.b), dist(l.b, t.a)));
        best = best < 0 ? e : std::min(best, e);
    }
    const bool found = match_lines({t}, d, rule).found == 1;
    if (best < 0)
        std::printf(" %-3s (   -  )", found ? "yes" : "no");
    else
        std::printf(" %-3s (%4.1f px)", found ? "yes" : "no", best);
}

void vga_time() {
    std::vector<VgaFrame> frames;
    {
        const sc::BoardScene b = sc::default_board_scene();
        VgaFrame f{"board", sc::render_board(b), {}};
        for (int i = 0; i < 4; ++i) {
            const sc::SubPixel p = b.corners[i], q = b.corners[(i + 1) % 4];
            f.truth.push_back({{p.x / 256.0, p.y / 256.0}, {q.x / 256.0, q.y / 256.0}});
        }
        frames.push_back(f);
    }
    {
        sc::SceneOptions o;
        o.width = 640;
        o.height = 480;
        o.noise_sigma = 5;
        o.blur_sigma = 0.8;
        o.clutter_blobs = 40;
        o.clutter_texture = 20;
        o.seed = 7;
        const sc::LineScene scene = sc::random_polygon_scene(o, 3, 80, 60);
        frames.push_back({"clutter", scene.render(), scene.truth()});
    }
    static qt::LineDetectorVga det;
    const qt::LineParams params;
    sc::MatchRule rule;
    rule.max_endpoint_px = 3;
    std::printf(
        "\n3. VGA 640x480 host time per frame, gradient..clustering (LineDetectorVga, default "
        "LineParams),\n   median of %d, methods timed alternately in one run. "
        "board = render_board(default_board_scene());\n   clutter = 3 polygons (side>=80, "
        "corners>=60deg) + 40 blobs + texture 20 + noise 5 + blur 0.8, seed 7.\n"
        "   found = truth sides matched (angle 1 deg, both ends 3 px).\n",
        kVgaRepeats);
#ifdef QT_HAVE_OPENCV
    cv::setNumThreads(1);  // one core each: a per-core comparison
    std::printf(
        "   OpenCV %s, 1 thread: cv::Canny(%.0f, %.0f, aperture %d) + cv::HoughLinesP(rho %.0f, "
        "theta %.0f deg, threshold %d,\n   minLineLength %d, maxLineGap %d); time = OpenCV ms / "
        "ours ms (> 1: ours faster).\n",
        CV_VERSION, kCannyLow, kCannyHigh, kCannyAperture, kHoughRho, kHoughThetaDeg,
        kHoughThreshold, kHoughMinLength, kHoughMaxGap);
#endif
    std::printf(
        "   frame    ours ms edges segs lines found edrop/sdrop/ldrop/budget"
#ifdef QT_HAVE_OPENCV
        "  OpenCV ms edge-px segs found   time"
#endif
        "\n");
    for (const VgaFrame& f : frames) {
        std::vector<double> ours;
#ifdef QT_HAVE_OPENCV
        const cv::Mat img(f.img.height, f.img.width, CV_8UC1,
                          const_cast<uint8_t*>(f.img.pixels.data()));
        cv::Mat edges;
        std::vector<cv::Vec4i> segs;
        std::vector<double> theirs;
#endif
        for (int r = 0; r < kVgaRepeats; ++r) {
            ours.push_back(detect(det, f.img, params));
#ifdef QT_HAVE_OPENCV
            const auto t0 = Clock::now();
            cv::Canny(img, edges, kCannyLow, kCannyHigh, kCannyAperture);
            cv::HoughLinesP(edges, segs, kHoughRho, kHoughThetaDeg * CV_PI / 180, kHoughThreshold,
                            kHoughMinLength, kHoughMaxGap);
            theirs.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
#endif
        }
        const std::vector<sc::DetectedLine> ours_d = to_detected(det.lines(), det.line_count());
        const sc::MatchResult mo = match_lines(f.truth, ours_d, rule);
        const qt::LineStats& st = det.stats();
        std::printf("   %-8s %7.2f %5u %4u %5u %2d/%-2d  %5u/%u/%u/%d", f.name, median(ours) * 1e3,
                    static_cast<unsigned>(st.edges), static_cast<unsigned>(det.segment_count()),
                    static_cast<unsigned>(det.line_count()), mo.found, mo.scored,
                    static_cast<unsigned>(st.edges_dropped),
                    static_cast<unsigned>(st.hough.segments_dropped),
                    static_cast<unsigned>(st.cluster.clusters_dropped),
                    st.hough.budget_bound() ? 1 : 0);
#ifdef QT_HAVE_OPENCV
        std::vector<sc::DetectedLine> cv_d;
        for (const cv::Vec4i& s : segs)
            cv_d.push_back({{static_cast<double>(s[0]), static_cast<double>(s[1])},
                            {static_cast<double>(s[2]), static_cast<double>(s[3])}});
        const sc::MatchResult mc = match_lines(f.truth, cv_d, rule);
        std::printf("      %9.2f %7d %4zu %2d/%-2d %6.2f", median(theirs) * 1e3,
                    cv::countNonZero(edges), segs.size(), mc.found, mc.scored,
                    median(theirs) / median(ours));
#endif
        std::printf("\n");
        if (std::strcmp(f.name, "board") == 0) {
            std::printf(
                "   board side i = corner i -> i+1: found? (worse end-point error of the best "
                "detection within 1 deg)\n");
            for (size_t i = 0; i < f.truth.size(); ++i) {
                std::printf("     side %zu  ours", i);
                print_side(f.truth[i], ours_d, rule);
#ifdef QT_HAVE_OPENCV
                std::printf("  OpenCV");
                print_side(f.truth[i], cv_d, rule);
#endif
                std::printf("\n");
            }
        }
    }
#ifndef QT_HAVE_OPENCV
    std::printf(
        "   OpenCV not found at configure time: no comparison (apt-get install "
        "libopencv-imgproc-dev, then reconfigure)\n");
#endif
    std::printf(
        "   Timings are medians on a noisy shared 2-core box: compare within one run only.\n");
}

// ---- 4. RAM -----------------------------------------------------------------------------------

template <class Det>
struct Caps;
template <class C>
struct Caps<qt::LineDetector<C>> {
    static constexpr uint32_t width = C::max_width, height = C::max_height, edges = C::edge_points,
                              bins = qt::hough_bins_for(C::max_width, C::max_height, C::theta_bins,
                                                        C::rho_step),
                              theta = C::theta_bins, segments = C::segments, lines = C::lines;
};

struct RamColumn {
    uint32_t bytes[8];  // the parts, other, total
    uint32_t edges, theta, rho, segments, lines;
};

template <class Det>
RamColumn ram_column() {
    using C = Caps<Det>;
    const qt::HoughParams
        hp;  // the accumulator the aliases are sized for: default theta_bins, rho_step
    constexpr uint32_t bins = qt::hough_bins_for(C::width, C::height, qt::HoughParams{}.theta_bins,
                                                 qt::HoughParams{}.rho_step);
    static_assert(bins == C::bins && C::theta == qt::HoughParams{}.theta_bins,
                  "alias sized for the defaults");
    const uint32_t parts = Det::smoothing_bytes() + Det::gradient_bytes() +
                           Det::edge_stage_bytes() + Det::edge_list_bytes() +
                           Det::accumulator_bytes() + Det::line_list_bytes();
    return {{Det::smoothing_bytes(), Det::gradient_bytes(), Det::edge_stage_bytes(),
             Det::edge_list_bytes(), Det::accumulator_bytes(), Det::line_list_bytes(),
             Det::ram_bytes() - parts, Det::ram_bytes()},
            C::edges,
            hp.theta_bins,
            bins / hp.theta_bins,
            C::segments,
            C::lines};
}

void ram() {
    const RamColumn q = ram_column<qt::LineDetectorQvga>(), v = ram_column<qt::LineDetectorVga>();
    std::printf(
        "\n4. RAM of one detector (all static, no heap), bytes, from LineDetector's static "
        "functions;"
        "\n   capacities: template arguments of LineDetectorQvga / LineDetectorVga, rho bins from "
        "hough_bins_for.\n");
    std::printf("   %-36s %12s %12s\n", "part", "QVGA 320x240", "VGA 640x480");
    const char* names[8] = {"Canny smoothing rows",
                            "gradient stage",
                            "edge stage (NMS rows)",
                            "edge list (points + row index)",
                            "accumulator (8-bit bins + cos/sin)",
                            "segment + line lists + scratch",
                            "other (params, stats, views)",
                            "total = ram_bytes()"};
    for (int i = 0; i < 8; ++i)
        std::printf("   %-36s %12u %12u\n", names[i], q.bytes[i], v.bytes[i]);
    std::printf("   %-36s %12u %12u\n", "capacity: edge points", q.edges, v.edges);
    char qb[24], vb[24];
    std::snprintf(qb, sizeof qb, "%u x %u", q.theta, q.rho);
    std::snprintf(vb, sizeof vb, "%u x %u", v.theta, v.rho);
    std::printf("   %-36s %12s %12s\n", "capacity: theta x rho bins, 2deg x 2px", qb, vb);
    std::printf("   %-36s %12u %12u\n", "capacity: segments", q.segments, v.segments);
    std::printf("   %-36s %12u %12u\n", "capacity: lines", q.lines, v.lines);
}

}  // namespace

int main(int argc, char** argv) {
    int scenes = 1000;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--scenes") == 0 && i + 1 < argc) {
            scenes = std::atoi(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: bench_lines [--scenes N]\n");
            return 2;
        }
    }
    if (scenes < 1) {
        std::fprintf(stderr, "bench_lines: --scenes needs N >= 1\n");
        return 2;
    }
    std::printf("lines stage host benchmark (timings: medians on a noisy shared 2-core machine)\n");
    accuracy(scenes, qt::LineParams{}, "1. Accuracy, default LineParams (threshold + NMS)");
    // The paper's Canny edge map (the Quadrangle Detection paper §2.3), thresholds chosen for its
    // smoothed gradient (a step's central difference is 3/4 of the raw one's): low 30, high 60.
    qt::LineParams canny;
    canny.front_end = qt::EdgeFrontEnd::canny;
    canny.edge_threshold = 30;
    canny.canny_high = 60;
    accuracy(scenes, canny,
             "1b. Accuracy, the paper's Canny front end (smoothing, NMS, hysteresis 30/60)");
    vote_window(scenes);
    vga_time();
    ram();
    return 0;
}
