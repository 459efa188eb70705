// The Filtering and Geometry paper's comparison (§IV, Figs. 10–12) on generated airborne sequences
// (platform/scene/ground_sequence.h): template matching only, filter only, homography only and the
// fused method, plus the fused method without Table III's reset, on the same frames. Prints a
// table for each of the first sequences and over all of them, one line per sequence on the
// default's end of the out-of-view spell, and SVG charts of the position error over time.
// Usage: bench_target [--out DIR] [--seeds N] [--tables K]
//   (default bench_out/target, 15 seeds, the tables of the first 3)
#include <sys/stat.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "demo/target_runner.h"
#include "io/svg_plot.h"
#include "scene/homography3.h"

namespace {

using qt::TargetMethod;
using qt::TargetState;
using qt::cli::TargetRunFrame;

using Params = qt::TargetPipelineParams;

struct Variant {
    const char* name;
    TargetMethod method;
    bool reset;
    float q_pos, q_vel;  // Kalman Q's diagonal, px² and (px/frame)² per frame
    // The paper's version of one of the project's choices (docs/fidelity.md), or none.
    void (*choice)(Params&) = nullptr;
};

using qt::RepGate;
using qt::SearchRegionShape;
using qt::TargetDetector;
using qt::TargetFormulation;

// The paper's Q = diag(20, 20, 1, 1), and one for a target that keeps its speed (a vehicle on
// a straight road): the velocity then averages over many frames, which is what carries it
// through a long spell unseen. Then the paper's version of each choice the project made
// differently, and the paper's formulation with and without Table III's reset (Fig. 12).
const Variant kVariants[] = {
    {"template only", TargetMethod::template_only, true, 20, 1},
    {"filter only", TargetMethod::filter_only, true, 20, 1},
    {"homography only", TargetMethod::homography_only, true, 20, 1},
    {"fused, no reset", TargetMethod::fused, false, 20, 1},
    {"fused (paper Q)", TargetMethod::fused, true, 20, 1},
    {"fused, Q 1/0.01", TargetMethod::fused, true, 1, 0.01f},
    {"fused, paper D_rep", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.tracker.rep_gate = RepGate::paper; }},
    {"fused, paper ROI", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.tracker.region = SearchRegionShape::paper; }},
    {"fused, morphology", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.detector = TargetDetector::morphological; }},
    {"fused, velocity coast", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.tracker.coast_fit_frames = 0; }},
    {"fused, straight coast", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.tracker.coast_projective = false; }},
    {"fused, all corners", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.ground_corners_only = false; }},
    {"fused, corner pairs", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.geometry.pairs = qt::PairSource::corners; }},
    {"fused, template re-cut", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.template_blend = 1; }},
    {"fused, template as cut", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.template_follows_ground = false; }},
    {"fused, full search", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.template_search_step = 1; }},
    {"fused, every row", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.harris.band_rows = 0; }},
    {"fused, no motion prior", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.motion_prior_q15 = 0; }},
    {"paper form.", TargetMethod::fused, true, 20, 1,
     [](Params& p) { p.tracker.formulation = TargetFormulation::paper; }},
    {"paper form., no reset", TargetMethod::fused, false, 20, 1,
     [](Params& p) { p.tracker.formulation = TargetFormulation::paper; }},
};
constexpr size_t kDefault = 4;  // "fused (paper Q)": the pipeline's defaults

constexpr double kLossPx = 10;  // an estimate this far from the truth has lost the target

struct Summary {
    double median_visible = 0;  // median error over frames with the target visible, px
    double max_occluded = 0;    // worst error under the flare, px
    double max_out = 0;         // worst error while out of view, px
    double end_out = 0;         // error in the last out-of-view frame, px
    double max_after = 0;       // worst error in the 50 frames after it is back, px
    int frames_to_loss = -1;    // first frame with error > kLossPx (-1: never)
    int lost_state = -1;        // first frame in state lost (-1: never)
};

Summary summarise(const std::vector<TargetRunFrame>& run) {
    Summary s;
    std::vector<double> visible;
    int last_out = -1;
    for (size_t k = 0; k < run.size(); ++k) {
        const TargetRunFrame& f = run[k];
        const double e = f.error_px;
        if (f.truth.in_view && !f.truth.occluded) visible.push_back(e);
        if (f.truth.occluded) s.max_occluded = std::max(s.max_occluded, e);
        if (!f.truth.in_view) {
            s.max_out = std::max(s.max_out, e);
            s.end_out = e;
            last_out = static_cast<int>(k);
        }
        if (s.frames_to_loss < 0 && e > kLossPx) s.frames_to_loss = static_cast<int>(k);
        if (s.lost_state < 0 && f.result.estimate.state == TargetState::lost)
            s.lost_state = static_cast<int>(k);
    }
    for (int k = last_out + 1;
         last_out >= 0 && k < static_cast<int>(run.size()) && k <= last_out + 50; ++k)
        s.max_after = std::max(s.max_after, run[static_cast<size_t>(k)].error_px);
    if (!visible.empty()) {
        std::nth_element(visible.begin(), visible.begin() + static_cast<long>(visible.size() / 2),
                         visible.end());
        s.median_visible = visible[visible.size() / 2];
    }
    return s;
}

// The error in the spell's last out-of-view frame, split by where it comes from. The estimate
// is A·x̂, x̂ the filter's position in the reference image m (the last reset) and A the
// accumulated homography; A_true, the product of the truth's frame homographies since m, is
// what A should be. homography = |A·x̂ − A_true·x̂|: the accumulated homography's error, carried
// far outside the image; filter = |A_true·x̂ − truth|: where the filter's own prediction of the
// target's motion (its velocity, extrapolated in image m) leaves it. They add up to at least
// the error (triangle inequality). Zero split when no frame is out of view.
struct ErrorSplit {
    double homography = 0, filter = 0;
};

ErrorSplit split_end_error(const std::vector<TargetRunFrame>& run) {
    ErrorSplit split;
    int last_out = -1;
    for (size_t k = 0; k < run.size(); ++k)
        if (!run[k].truth.in_view) last_out = static_cast<int>(k);
    if (last_out < 0) return split;
    double truth_a[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // A_true since the last reset
    for (int k = 1; k <= last_out; ++k) {
        const TargetRunFrame& f = run[static_cast<size_t>(k)];
        double product[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        if (!f.result.estimate.reset)
            qt::scene::multiply(f.truth.h_from_previous, truth_a, product);
        std::memcpy(truth_a, product, sizeof truth_a);
    }
    const TargetRunFrame& f = run[static_cast<size_t>(last_out)];
    double a[9], a_inv[9], mx, my, tx, ty;
    for (int i = 0; i < 9; ++i) a[i] = f.accumulated.m[i];
    qt::scene::invert(a, a_inv);
    qt::scene::apply(a_inv, f.result.estimate.x, f.result.estimate.y, mx, my);  // x̂ in image m
    qt::scene::apply(truth_a, mx, my, tx, ty);
    split.homography = std::hypot(f.result.estimate.x - tx, f.result.estimate.y - ty);
    split.filter = std::hypot(tx - f.truth.target_x, ty - f.truth.target_y);
    return split;
}

std::string frame_text(int k) { return k < 0 ? "never" : std::to_string(k); }

void print_row(const char* name, const Summary& s) {
    std::printf("| %-21s | %8.2f | %8.1f | %8.1f | %8.1f | %8.1f | %7s | %7s |\n", name,
                s.median_visible, s.max_occluded, s.max_out, s.end_out, s.max_after,
                frame_text(s.frames_to_loss).c_str(), frame_text(s.lost_state).c_str());
}

// How far a straight line at constant speed can carry the target through the spell, whatever
// the tracker: the line fitted by least squares to the truth's own track over the last `window`
// frames in view (the coasting's fit, without measurement error or homography drift), in the
// image of the last frame in view, against the truth at the spell's last frame in that image,
// px. Under perspective the track is straight there but not at constant speed (the vehicle's
// distance from the camera changes), which this measures. -1 when there is no spell.
double straight_line_floor(const std::vector<TargetRunFrame>& run, int window) {
    int last_out = -1;
    for (size_t k = 0; k < run.size(); ++k)
        if (!run[k].truth.in_view) last_out = static_cast<int>(k);
    int exit = last_out;  // then the last frame in view before the spell
    while (exit >= 0 && !run[static_cast<size_t>(exit)].truth.in_view) --exit;
    if (last_out < 0 || exit < window) return -1;
    const double* gm = run[static_cast<size_t>(exit)].truth.h_ground_to_image;
    auto in_exit_image = [&](int k, double& x, double& y) {
        const qt::scene::GroundTruth& t = run[static_cast<size_t>(k)].truth;
        double to_ground[9], to_exit[9];
        qt::scene::invert(t.h_ground_to_image, to_ground);
        qt::scene::multiply(gm, to_ground, to_exit);
        qt::scene::apply(to_exit, t.target_x, t.target_y, x, y);
    };
    double n = 0, sk = 0, sx = 0, sy = 0;
    std::vector<double> xs, ys;
    for (int k = exit - window; k <= exit; ++k) {
        double x = 0, y = 0;
        in_exit_image(k, x, y);
        xs.push_back(x);
        ys.push_back(y);
        n += 1;
        sk += k;
        sx += x;
        sy += y;
    }
    const double km = sk / n, xm = sx / n, ym = sy / n;
    double skk = 0, skx = 0, sky = 0;
    for (int k = exit - window; k <= exit; ++k) {
        const double d = k - km;
        skk += d * d;
        skx += d * (xs[static_cast<size_t>(k - exit + window)] - xm);
        sky += d * (ys[static_cast<size_t>(k - exit + window)] - ym);
    }
    double ex = 0, ey = 0;
    in_exit_image(last_out, ex, ey);
    const double d = last_out - km;
    return std::hypot(xm + skx / skk * d - ex, ym + sky / skk * d - ey);
}

void print_header() {
    std::printf(
        "| method                | visible  | occluded | out max  | out end  | after max| to loss "
        "| "
        "lost at |\n");
    std::printf(
        "|-----------------------|----------|----------|----------|----------|----------|---------|"
        "-----"
        "----|\n");
}

// Spans of consecutive frames where pred holds, for shading the charts.
template <class Pred>
void add_spans(const std::vector<TargetRunFrame>& run, const char* label, Pred pred,
               qt::io::LinePlot& plot) {
    for (size_t k = 0; k < run.size(); ++k) {
        if (!pred(run[k].truth) || (k > 0 && pred(run[k - 1].truth))) continue;
        size_t e = k;
        while (e + 1 < run.size() && pred(run[e + 1].truth)) ++e;
        plot.spans.push_back({static_cast<double>(k) - 0.5, static_cast<double>(e) + 0.5, label});
    }
}

bool write_plot(const std::string& path, const qt::io::LinePlot& plot) {
    std::string error;
    if (!qt::io::write_svg_line_plot(path, plot, error)) {
        std::fprintf(stderr, "bench_target: %s\n", error.c_str());
        return false;
    }
    std::printf("wrote %s\n", path.c_str());
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    std::string out = "bench_out/target";
    int seeds = 15, tables = 3;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            out = argv[++i];
        } else if (std::strcmp(argv[i], "--seeds") == 0 && i + 1 < argc) {
            seeds = std::max(1, std::atoi(argv[++i]));
        } else if (std::strcmp(argv[i], "--tables") == 0 && i + 1 < argc) {
            tables = std::max(0, std::atoi(argv[++i]));
        } else {
            std::fprintf(stderr, "usage: bench_target [--out DIR] [--seeds N] [--tables K]\n");
            return 2;
        }
    }
    std::printf(
        "RAM (sizeof): TargetPipelineQvga %zu B, of which HarrisDetector<320, 96> %zu B and the "
        "previous "
        "frame's FeatureSet<4, 96> %zu B\n",
        sizeof(qt::TargetPipelineQvga), sizeof(qt::HarrisDetector<320, 96>),
        sizeof(qt::FeatureSet<4, 96>));
    mkdir("bench_out", 0755);
    mkdir(out.c_str(), 0755);
    const size_t nv = sizeof kVariants / sizeof kVariants[0];
    std::vector<std::vector<Summary>> all(nv);
    std::vector<ErrorSplit> splits;  // kDefault's, per seed
    std::vector<double> floors;      // straight_line_floor, per seed
    for (int seed = 1; seed <= seeds; ++seed) {
        qt::scene::GroundSequenceConfig cfg = qt::scene::long_ground_sequence();
        cfg.seed = static_cast<uint64_t>(seed);
        const qt::scene::GroundSequence seq(cfg);
        std::vector<qt::io::GreyImage> frames;
        for (int k = 0; k < seq.frames(); ++k) frames.push_back(seq.render(k));
        const bool table = seed <= tables;
        if (table) {
            std::printf(
                "\nsequence seed %d: %d frames %dx%d, flare over frames %d-%d, out of view %d-%d; "
                "errors in px\n",
                seed, seq.frames(), cfg.width, cfg.height, cfg.occlusion_start,
                cfg.occlusion_start + cfg.occlusion_frames - 1, cfg.out_of_view_start,
                cfg.out_of_view_start + cfg.out_of_view_frames - 1);
            print_header();
        }
        qt::io::LinePlot plot;
        plot.title = "Target position error, sequence seed " + std::to_string(seed);
        plot.x_label = "frame";
        plot.y_label = "error (px), clipped at 40";
        plot.y_max = 40;
        plot.markers = false;
        for (int k = 0; k < seq.frames(); k += 50)
            plot.ticks.push_back({static_cast<double>(k), std::to_string(k)});
        qt::io::LinePlot reset_plot = plot;
        reset_plot.y_max = 150;
        reset_plot.y_label = "error (px), clipped at 150";
        reset_plot.title =
            "Fig. 12: the paper's formulation with and without Table III's reset, seed " +
            std::to_string(seed);
        for (size_t v = 0; v < nv; ++v) {
            qt::TargetPipelineParams config =
                qt::cli::qvga_target_config(kVariants[v].method, kVariants[v].reset);
            config.tracker.kalman.q_pos = kVariants[v].q_pos;
            config.tracker.kalman.q_vel = kVariants[v].q_vel;
            if (kVariants[v].choice) kVariants[v].choice(config);
            const auto run = qt::cli::run_target_sequence(seq, config, &frames);
            const Summary s = summarise(run);
            if (v == kDefault) {
                splits.push_back(split_end_error(run));
                floors.push_back(straight_line_floor(run, config.tracker.coast_fit_frames));
            }
            all[v].push_back(s);
            if (table) print_row(kVariants[v].name, s);
            if (plot.x.empty()) {
                for (size_t k = 0; k < run.size(); ++k) plot.x.push_back(static_cast<double>(k));
                reset_plot.x = plot.x;
                add_spans(
                    run, "flare", [](const qt::scene::GroundTruth& t) { return t.occluded; }, plot);
                add_spans(
                    run, "out of view", [](const qt::scene::GroundTruth& t) { return !t.in_view; },
                    plot);
                reset_plot.spans = plot.spans;
            }
            qt::io::PlotSeries series{kVariants[v].name, {}};
            for (const TargetRunFrame& f : run) series.y.push_back(f.error_px);
            if (kVariants[v].method == TargetMethod::fused &&
                config.tracker.formulation == TargetFormulation::paper)
                reset_plot.series.push_back(series);
            plot.series.push_back(series);
        }
        if (seed == 1 && (!write_plot(out + "/error_seed1.svg", plot) ||
                          !write_plot(out + "/fig12_reset_seed1.svg", reset_plot)))
            return 1;
    }
    std::printf(
        "\nmedians over %d sequences (seeds 1-%d, the same long sequence otherwise; columns as "
        "above)\n",
        seeds, seeds);
    print_header();
    double default_end_out = 0;
    for (size_t v = 0; v < nv; ++v) {
        auto med = [&](auto field) {
            std::vector<double> xs;
            for (const Summary& s : all[v]) xs.push_back(field(s));
            std::sort(xs.begin(), xs.end());
            return xs[xs.size() / 2];
        };
        Summary m;
        m.median_visible = med([](const Summary& s) { return s.median_visible; });
        m.max_occluded = med([](const Summary& s) { return s.max_occluded; });
        m.max_out = med([](const Summary& s) { return s.max_out; });
        m.end_out = med([](const Summary& s) { return s.end_out; });
        m.max_after = med([](const Summary& s) { return s.max_after; });
        m.frames_to_loss = static_cast<int>(
            med([](const Summary& s) { return s.frames_to_loss < 0 ? 1e9 : s.frames_to_loss; }));
        m.lost_state = static_cast<int>(
            med([](const Summary& s) { return s.lost_state < 0 ? 1e9 : s.lost_state; }));
        if (m.frames_to_loss >= 1000000000) m.frames_to_loss = -1;
        if (m.lost_state >= 1000000000) m.lost_state = -1;
        print_row(kVariants[v].name, m);
        if (v == kDefault) default_end_out = m.end_out;
    }
    std::printf(
        "\nthe '%s' tracker at the end of the out-of-view spell, per sequence (px): out end = its "
        "error in the\nspell's last frame, split into homography = the accumulated homography's "
        "error carried to the\nestimate and filter = the filter's own prediction against the "
        "truth, in the same image; line = a\nstraight line at constant speed fitted to the "
        "truth's own track over the last %d frames in view\n(no measurement error, no homography "
        "drift), at the spell's last frame, in the image of the last\nframe in view: what "
        "coasting on a straight line cannot do better than; to loss: as in the columns below\n",
        kVariants[kDefault].name, static_cast<int>(qt::TargetTrackerParams{}.coast_fit_frames));
    std::printf(
        "\n| seed | out end | homography | filter | line | to loss |\n"
        "|---:|---:|---:|---:|---:|---:|\n");
    for (size_t i = 0; i < splits.size(); ++i) {
        const Summary& d = all[kDefault][i];
        std::printf("| %zu | %.1f | %.2f | %.2f | %.2f | ", i + 1, d.end_out, splits[i].homography,
                    splits[i].filter, floors[i]);
        if (d.frames_to_loss < 0)
            std::printf("never |\n");
        else
            std::printf("%d |\n", d.frames_to_loss);
    }
    std::vector<double> sorted_floors = floors;
    std::sort(sorted_floors.begin(), sorted_floors.end());
    std::printf(
        "\nthe straight line's own error at the spell's end, median over %d sequences: %.1f px\n",
        seeds, sorted_floors[sorted_floors.size() / 2]);
    constexpr double kOutOfViewAimPx = 5;  // issue 22: at the end of a 100-frame spell
    std::printf(
        "\n'%s' error in the last out-of-view frame, median over %d sequences: %.1f px "
        "(aim %.0f px): %s\n",
        kVariants[kDefault].name, seeds, default_end_out, kOutOfViewAimPx,
        default_end_out <= kOutOfViewAimPx ? "met" : "NOT met");
    std::printf(
        "\ncolumns: visible = median error over frames with the target in view and not under the "
        "flare;\n"
        "occluded / out max = worst error under the flare / out of view; out end = error in the "
        "last\n"
        "out-of-view frame; after max = worst error in the 50 frames after the target is back;\n"
        "to loss = first frame with error > %.0f px; lost at = first frame the tracker said "
        "lost.\n",
        kLossPx);
    return 0;
}
