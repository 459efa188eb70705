// Host benchmark of the line tracker on the Quadrangle Detection paper §3's synthetic motions
// (platform/scene/line_motion.h): Experiment 1 (pure translation, 24 directions × 3 speeds, 20
// random segments) and Experiment 2 (pure rotation at a fixed Hough r, 3 radii × 5 turn rates, 20
// start angles; rotation about the image origin as in the paper, and about the frame centre),
// scored by the overlap ratio (2 px band) of each frame's prediction, for the paper's 1KF, 2KF, 3KF
// and our turn model. Prints Markdown tables and a summary against the aims, and writes the
// paper's Figures 5 and 6 as SVG charts. Everything printed is deterministic. Run by `bash bench.sh
// track-host`.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/svg_plot.h"
#include "scene/line_motion.h"

namespace {

namespace sc = qt::scene;

constexpr int kFrameW = 320, kFrameH = 240;  // QVGA (the paper gives no frame size)
constexpr double kAimTurnAt8 = 0.80;         // issue: turn model at 8 °/frame, each r
constexpr double kAimVs3kf = 0.01;           // issue: turn >= 3KF − 1 point in translation

struct Tracker {
    const char* name;
    qt::LineTrackerParams params;
};

std::vector<Tracker> trackers() {
    std::vector<Tracker> t;
    for (int n = 1; n <= 3; ++n) {
        qt::LineTrackerParams p = qt::default_line_tracker_params(kFrameW, kFrameH);
        p.model = qt::LineModel::closest_points;
        p.filters = static_cast<uint8_t>(n);
        t.push_back({n == 1 ? "1KF" : n == 2 ? "2KF" : "3KF", p});
    }
    qt::LineTrackerParams p = qt::default_line_tracker_params(kFrameW, kFrameH);
    p.model = qt::LineModel::turn;
    t.push_back({"turn", p});
    return t;
}

double pct(double overlap) { return 100 * overlap; }

void print_translation(const std::vector<Tracker>& tr, const std::vector<sc::TranslationTable>& t) {
    const sc::TranslationTable& t0 = t[0];
    std::printf("### Experiment 1: translation, mean overlap %% over %d segments, frames 1-%d\n\n",
                sc::kMotionTracks, sc::kMotionFrames - 1);
    std::printf("| direction (°) |");
    for (double v : t0.speeds)
        for (const Tracker& k : tr) std::printf(" %s v=%g |", k.name, v);
    std::printf("\n|---:|");
    for (std::size_t i = 0; i < t0.speeds.size() * tr.size(); ++i) std::printf("---:|");
    std::printf("\n");
    for (std::size_t d = 0; d < t0.directions_deg.size(); ++d) {
        std::printf("| %g |", t0.directions_deg[d]);
        for (std::size_t s = 0; s < t0.speeds.size(); ++s)
            for (std::size_t k = 0; k < tr.size(); ++k)
                std::printf(" %.1f |", pct(t[k].overlap[s][d]));
        std::printf("\n");
    }
    std::printf("| **mean** |");
    for (std::size_t s = 0; s < t0.speeds.size(); ++s)
        for (std::size_t k = 0; k < tr.size(); ++k)
            std::printf(" **%.1f** |", pct(sc::mean_of(t[k].overlap[s])));
    std::printf("\n\n");
}

void print_rotation(const std::vector<Tracker>& tr, const std::vector<sc::RotationTable>& t,
                    const char* centre_name) {
    const sc::RotationTable& t0 = t[0];
    std::printf(
        "### Experiment 2: rotation about %s (%g, %g), mean overlap %% over %d start angles, "
        "frames 1-%d\n\n",
        centre_name, t0.centre.x, t0.centre.y, sc::kMotionTracks, sc::kMotionFrames - 1);
    std::printf("| ω (°/frame) |");
    for (double r : t0.radii)
        for (const Tracker& k : tr) std::printf(" %s r=%g |", k.name, r);
    std::printf("\n|---:|");
    for (std::size_t i = 0; i < t0.radii.size() * tr.size(); ++i) std::printf("---:|");
    std::printf("\n");
    for (std::size_t w = 0; w < t0.omegas_deg.size(); ++w) {
        std::printf("| %g |", t0.omegas_deg[w]);
        for (std::size_t r = 0; r < t0.radii.size(); ++r)
            for (std::size_t k = 0; k < tr.size(); ++k)
                std::printf(" %.1f |", pct(t[k].overlap[r][w]));
        std::printf("\n");
    }
    std::printf("\n");
}

// Experiment 2 under the settings the Quadrangle Detection paper §3.2 leaves open — the frame size
// (which places the 2nd and 3rd filters' origins), the pivot and measurement noise — against the
// paper's two readings of its Figure 6: (a) "the score of 3KF drops below 20 % when the angular
// velocity reaches 4 degrees per frame and higher for all tested value of r"; (b) 3KF scores above
// 1KF and 2KF (its conclusion). One row per setting.
void print_paper_setting(const sc::MotionOptions& base) {
    std::printf(
        "### Experiment 2 in the settings the paper leaves open: (a) 3KF below 20 %% from "
        "4 °/frame for every r; (b) 3KF above 1KF and 2KF (mean overlap over r and ω)\n\n");
    std::printf(
        "| frame | pivot | noise (px) | 3KF at 4 °/frame, r = 10 / 50 / 100 | 3KF highest at "
        ">= 4 °/frame | (a) | mean 1KF / 2KF / 3KF | (b) |\n");
    std::printf("|---|---|---:|---|---:|---|---|---|\n");
    struct Size {
        int w, h;
    };
    for (const Size f : {Size{320, 240}, Size{640, 480}}) {
        for (const bool about_centre : {false, true}) {
            for (const double noise : {0.0, 0.5}) {
                sc::MotionOptions o = base;
                o.noise_sigma = noise;
                const sc::Point2 pivot =
                    about_centre ? sc::Point2{(f.w - 1) / 2.0, (f.h - 1) / 2.0} : sc::Point2{0, 0};
                double mean[3] = {};
                sc::RotationTable kf3;
                for (int n = 1; n <= 3; ++n) {
                    qt::LineTrackerParams p = qt::default_line_tracker_params(
                        static_cast<uint16_t>(f.w), static_cast<uint16_t>(f.h));
                    p.model = qt::LineModel::closest_points;
                    p.filters = static_cast<uint8_t>(n);
                    const sc::RotationTable t = sc::rotation_experiment(p, pivot, o);
                    std::vector<double> all;
                    for (const std::vector<double>& row : t.overlap)
                        all.insert(all.end(), row.begin(), row.end());
                    mean[n - 1] = sc::mean_of(all);
                    if (n == 3) kf3 = t;
                }
                double highest = 0;
                std::printf("| %dx%d | %s | %g |", f.w, f.h, about_centre ? "centre" : "origin",
                            noise);
                for (std::size_t r = 0; r < kf3.radii.size(); ++r) {
                    for (std::size_t w = 0; w < kf3.omegas_deg.size(); ++w) {
                        if (kf3.omegas_deg[w] < 4) continue;
                        highest = std::max(highest, kf3.overlap[r][w]);
                        if (kf3.omegas_deg[w] == 4)
                            std::printf("%s%.1f", r ? " / " : " ", pct(kf3.overlap[r][w]));
                    }
                }
                const bool b = mean[2] > mean[0] && mean[2] > mean[1];
                std::printf(" | %.1f | %s | %.1f / %.1f / %.1f | %s |\n", pct(highest),
                            highest < 0.20 ? "holds" : "no", pct(mean[0]), pct(mean[1]),
                            pct(mean[2]), b ? "holds" : "no");
            }
        }
    }
    std::printf("\n");
}

bool write_plot(const std::string& dir, const std::string& file, qt::io::LinePlot plot) {
    std::string error;
    if (!qt::io::write_svg_line_plot(dir + "/" + file, plot, error)) {
        std::fprintf(stderr, "bench_track: %s\n", error.c_str());
        return false;
    }
    return true;
}

// Figure 5: overlap % vs direction, one chart per speed.
bool plot_translation(const std::string& dir, const std::vector<Tracker>& tr,
                      const std::vector<sc::TranslationTable>& t, const char* noise_note) {
    const sc::TranslationTable& t0 = t[0];
    for (std::size_t s = 0; s < t0.speeds.size(); ++s) {
        qt::io::LinePlot p;
        p.title = "Pure translation, " + std::to_string(static_cast<int>(t0.speeds[s])) +
                  " px/frame" + noise_note;
        p.x_label = "direction of motion (°)";
        p.y_label = "overlap ratio (%)";
        p.x = t0.directions_deg;
        for (double d = 0; d < 360; d += 45)
            p.ticks.push_back({d, std::to_string(static_cast<int>(d))});
        for (std::size_t k = 0; k < tr.size(); ++k) {
            qt::io::PlotSeries ser{tr[k].name, {}};
            for (double v : t[k].overlap[s]) ser.y.push_back(pct(v));
            p.series.push_back(ser);
        }
        if (!write_plot(dir, "exp1_speed" + std::to_string(static_cast<int>(t0.speeds[s])) + ".svg",
                        p))
            return false;
    }
    return true;
}

// Figure 6: overlap % vs turn rate, one chart per radius; the turn rates (1, 2, 4, 8, 16) are
// equally spaced on the chart, as in the paper.
bool plot_rotation(const std::string& dir, const std::string& prefix, const char* centre_text,
                   const std::vector<Tracker>& tr, const std::vector<sc::RotationTable>& t,
                   const char* noise_note) {
    const sc::RotationTable& t0 = t[0];
    for (std::size_t r = 0; r < t0.radii.size(); ++r) {
        const std::string rs = std::to_string(static_cast<int>(t0.radii[r]));
        qt::io::LinePlot p;
        p.title =
            "Pure rotation about " + std::string(centre_text) + ", r = " + rs + " px" + noise_note;
        p.x_label = "angular velocity (°/frame)";
        p.y_label = "overlap ratio (%)";
        for (std::size_t w = 0; w < t0.omegas_deg.size(); ++w) {
            p.x.push_back(static_cast<double>(w));
            char label[16];
            std::snprintf(label, sizeof label, "%g", t0.omegas_deg[w]);
            p.ticks.push_back({static_cast<double>(w), label});
        }
        for (std::size_t k = 0; k < tr.size(); ++k) {
            qt::io::PlotSeries ser{tr[k].name, {}};
            for (double v : t[k].overlap[r]) ser.y.push_back(pct(v));
            p.series.push_back(ser);
        }
        if (!write_plot(dir, prefix + "_r" + rs + ".svg", p)) return false;
    }
    return true;
}

void usage(FILE* f) {
    std::fprintf(f,
                 "usage: bench_track [--out DIR] [--noise SIGMA]\n"
                 "  --out DIR      where the SVG charts go (default bench_out/track; created)\n"
                 "  --noise SIGMA  Gaussian noise on each measured end-point coordinate, px,\n"
                 "                 >= 0 (default 0: the paper's exact data)\n");
}

}  // namespace

int main(int argc, char** argv) {
    std::string out = "bench_out/track";
    sc::MotionOptions opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help") {
            usage(stdout);
            return 0;
        } else if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else if (a == "--noise" && i + 1 < argc) {
            char* end = nullptr;
            errno = 0;
            opt.noise_sigma = std::strtod(argv[++i], &end);
            if (errno || *end || end == argv[i] || !std::isfinite(opt.noise_sigma) ||
                opt.noise_sigma < 0) {
                std::fprintf(stderr, "bench_track: --noise needs a number >= 0, got '%s'\n",
                             argv[i]);
                return 2;
            }
        } else {
            std::fprintf(stderr, "bench_track: unknown or incomplete option '%s' (try --help)\n",
                         a.c_str());
            return 2;
        }
    }
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) {
        std::fprintf(stderr, "bench_track: %s: %s\n", out.c_str(), ec.message().c_str());
        return 1;
    }

    const std::vector<Tracker> tr = trackers();
    const sc::Point2 origin{0, 0}, centre{(kFrameW - 1) / 2.0, (kFrameH - 1) / 2.0};
    std::vector<sc::TranslationTable> exp1;
    std::vector<sc::RotationTable> exp2o, exp2c;
    for (const Tracker& k : tr) {
        exp1.push_back(sc::translation_experiment(k.params, opt));
        exp2o.push_back(sc::rotation_experiment(k.params, origin, opt));
        exp2c.push_back(sc::rotation_experiment(k.params, centre, opt));
    }

    std::printf(
        "## Line tracker on the Quadrangle Detection paper §3 motions (%dx%d, band %g px, noise %g "
        "px)\n\n",
        kFrameW, kFrameH, opt.band_px, opt.noise_sigma);
    print_translation(tr, exp1);
    print_rotation(tr, exp2o, "the image origin");
    print_rotation(tr, exp2c, "the frame centre");
    print_paper_setting(opt);

    // Summary against the aims. Index 2 is 3KF, 3 the turn model.
    const sc::RotationTable& turn_o = exp2o[3];
    std::size_t w8 = 0;
    while (w8 + 1 < turn_o.omegas_deg.size() && turn_o.omegas_deg[w8] != 8) ++w8;
    bool met = true;
    std::printf("turn model at 8 °/frame (about the origin):");
    for (std::size_t r = 0; r < turn_o.radii.size(); ++r) {
        std::printf("%s r=%g %.1f %%", r ? "," : "", turn_o.radii[r], pct(turn_o.overlap[r][w8]));
        met = met && turn_o.overlap[r][w8] >= kAimTurnAt8;
    }
    std::printf(" (aim >= %.0f %%): %s\n", pct(kAimTurnAt8), met ? "met" : "NOT met");
    met = true;
    std::printf("translation, mean over directions, turn vs 3KF:");
    for (std::size_t s = 0; s < exp1[3].speeds.size(); ++s) {
        const double turn = sc::mean_of(exp1[3].overlap[s]), kf3 = sc::mean_of(exp1[2].overlap[s]);
        std::printf("%s v=%g %.1f %% vs %.1f %%", s ? "," : "", exp1[3].speeds[s], pct(turn),
                    pct(kf3));
        met = met && turn >= kf3 - kAimVs3kf;
    }
    std::printf(" (aim: turn >= 3KF - %.0f point): %s\n", pct(kAimVs3kf), met ? "met" : "NOT met");

    // Experiment 1 under the conditions §3 names but does not tabulate: segments of varying
    // length (half to whole, a new piece every frame) and measurement noise, each alone and
    // together; means over the 24 directions.
    std::printf(
        "\n### Experiment 1 with varying lengths and noise: mean overlap %% over 24 "
        "directions\n\n");
    std::printf("| condition |");
    for (double v : exp1[0].speeds)
        for (const Tracker& k : tr) std::printf(" %s v=%g |", k.name, v);
    std::printf("\n|---|");
    for (std::size_t i = 0; i < exp1[0].speeds.size() * tr.size(); ++i) std::printf("---:|");
    std::printf("\n");
    struct Condition {
        const char* name;
        double noise, share;
    };
    const Condition conditions[] = {{"fixed length, exact", 0, 1},
                                    {"length 50-100 %, exact", 0, 0.5},
                                    {"fixed length, noise 0.5 px", 0.5, 1},
                                    {"length 50-100 %, noise 0.5 px", 0.5, 0.5},
                                    {"length 50-100 %, noise 1 px", 1.0, 0.5}};
    for (const Condition& c : conditions) {
        sc::MotionOptions o = opt;
        o.noise_sigma = c.noise;
        o.min_length_share = c.share;
        std::printf("| %s |", c.name);
        std::vector<sc::TranslationTable> t;
        for (const Tracker& k : tr) t.push_back(sc::translation_experiment(k.params, o));
        for (std::size_t s = 0; s < t[0].speeds.size(); ++s)
            for (std::size_t k = 0; k < tr.size(); ++k)
                std::printf(" %.1f |", pct(sc::mean_of(t[k].overlap[s])));
        std::printf("\n");
    }

    const char* note = opt.noise_sigma > 0 ? " (noisy)" : "";
    if (!plot_translation(out, tr, exp1, note) ||
        !plot_rotation(out, "exp2", "the origin", tr, exp2o, note) ||
        !plot_rotation(out, "exp2_centre", "the frame centre", tr, exp2c, note))
        return 1;
    std::printf(
        "\ncharts: %s/exp1_speed{1,2,3}.svg, exp2_r{10,50,100}.svg, exp2_centre_r{10,50,100}.svg\n",
        out.c_str());
    return 0;
}
