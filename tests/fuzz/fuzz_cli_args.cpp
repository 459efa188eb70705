// Fuzz target: the input bytes split at NUL into an argument vector, parsed as the arguments
// of every command: qt::cli::parse_command_line (detect, track) and
// qt::cli::parse_target_command_line (homography, target); usage and errors go to /dev/null.
// Invariants (platform/cli/cli_options.h, platform/cli/target_options.h):
//   - the result is -1 (run), 0 (--help/-h was given) or 2 (bad command line; 1 only when the
//     usage could not be written, which /dev/null never refuses);
//   - on -1 the positional arguments are the required number (detect, track, target: one;
//     homography: two), each one of the arguments and not a flag, and target has its --roi;
//   - on -1 every value lies in its flag's documented range (defaults included).
#include <stddef.h>
#include <stdint.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/target_options.h"
#include "fuzz_check.h"

namespace {

std::FILE* dev_null() {
    static std::FILE* f = std::fopen("/dev/null", "w");
    if (f == nullptr) {
        std::fprintf(stderr, "fuzz_cli_args: cannot open /dev/null\n");
        std::abort();
    }
    return f;
}

bool has(const std::vector<std::string>& args, const std::string& a) {
    return std::find(args.begin(), args.end(), a) != args.end();
}

// A positional argument: one of the arguments, and not a flag ("-" is standard input) unless a
// "--" ended the options.
bool positional_ok(const std::vector<std::string>& args, const std::string& p) {
    const bool flag_like = p.size() > 1 && p[0] == '-';
    return has(args, p) && (!flag_like || has(args, "--"));
}

bool q16_in(qt::q16_16 v, int lo, int hi) {
    return v.raw >= static_cast<int64_t>(lo) * 65536 && v.raw <= static_cast<int64_t>(hi) * 65536;
}

bool deg_at_most(qt::angle_t a, int deg) {
    return a <= qt::angle_from_deg(qt::q16_16::from_int(deg));
}

bool real_in(float v, double lo, double hi) {
    return std::isfinite(v) && v >= static_cast<float>(lo) && v <= static_cast<float>(hi);
}

void check_detect(const qt::cli::DetectOptions& o) {
    const qt::LineParams& l = o.params.lines;
    QT_FUZZ_CHECK(l.edge_threshold >= 1 && l.edge_threshold <= 510);
    QT_FUZZ_CHECK(l.hough.theta_bins >= 2 && l.hough.theta_bins <= 90);
    QT_FUZZ_CHECK(l.hough.rho_step == 2 || l.hough.rho_step == 4);
    QT_FUZZ_CHECK(l.hough.threshold >= 1 && l.hough.threshold <= 255);
    QT_FUZZ_CHECK(l.hough.min_line_length >= 2 && l.hough.min_line_length <= 2048);
    QT_FUZZ_CHECK(l.hough.max_line_gap <= 255);
    QT_FUZZ_CHECK(l.hough.vote_window_deg >= 1 && l.hough.vote_window_deg <= 90);
    QT_FUZZ_CHECK(l.hough.corridor <= 4);
    QT_FUZZ_CHECK(l.hough.max_walk_steps >= 1 && l.hough.max_walk_steps <= 100000000u);
    QT_FUZZ_CHECK(l.hough.seed <= 2147483647u);  // max_voters: every uint16_t is valid
    QT_FUZZ_CHECK(q16_in(l.cluster.distance, 0, 1000));
    QT_FUZZ_CHECK(deg_at_most(l.cluster.max_angle, 90));
    QT_FUZZ_CHECK(q16_in(l.cluster.gap, 0, 2048));
    QT_FUZZ_CHECK(q16_in(l.cluster.offset, 0, 1000));
    QT_FUZZ_CHECK(q16_in(l.corners.max_distance, 0, 100));
    QT_FUZZ_CHECK(deg_at_most(l.corners.min_angle, 90));
    const qt::QuadParams& q = o.params.quads;
    QT_FUZZ_CHECK(deg_at_most(q.parallel_tolerance, 45));
    QT_FUZZ_CHECK(deg_at_most(q.perpendicular_tolerance, 60));
    QT_FUZZ_CHECK(q16_in(q.corner_margin, 0, 1000));
    QT_FUZZ_CHECK(q16_in(q.min_side_length, 0, 2048) && q16_in(q.max_side_length, 1, 2048));
    QT_FUZZ_CHECK(q.min_side_length.raw <= q.max_side_length.raw);
    QT_FUZZ_CHECK(q16_in(q.aspect_tolerance, 1, 10));
    QT_FUZZ_CHECK(q16_in(q.tilted_aspect_tolerance, 1, 10));
    QT_FUZZ_CHECK(deg_at_most(q.perspective_convergence, 90));
    QT_FUZZ_CHECK(q16_in(q.min_side_coverage, 0, 1) && q16_in(q.min_score, 0, 1));
    QT_FUZZ_CHECK(q16_in(q.collinear_distance, 0, 100));
    QT_FUZZ_CHECK(q.contrast == qt::Contrast::bright_board ||
                  q.contrast == qt::Contrast::dark_board || q.contrast == qt::Contrast::any);
    QT_FUZZ_CHECK(o.display_width >= 1 && o.display_width <= 4096 && o.display_height >= 1 &&
                  o.display_height <= 4096);
    QT_FUZZ_CHECK(q.display_aspect.raw ==
                  qt::q16_16::from_ratio(o.display_width, o.display_height).raw);
    QT_FUZZ_CHECK(o.max_quads >= 1 && o.max_quads <= 4);
    QT_FUZZ_CHECK(o.track.model == qt::LineModel::closest_points ||
                  o.track.model == qt::LineModel::turn);
    QT_FUZZ_CHECK(o.track.filters >= 1 && o.track.filters <= 3);
    QT_FUZZ_CHECK(deg_at_most(o.track.gate_angle, 90));
    QT_FUZZ_CHECK(q16_in(o.track.gate_distance, 0, 1000));
    QT_FUZZ_CHECK(o.draw_every >= 1 && o.draw_every <= 100000);
}

void check_target(const qt::cli::TargetOptions& o, bool target) {
    const qt::TargetTrackerParams& t = o.config.tracker;
    QT_FUZZ_CHECK(std::strcmp(qt::target_method_name(t.method), "unknown") != 0);
    QT_FUZZ_CHECK(real_in(t.kalman.q_pos, 0, 10000) && real_in(t.kalman.q_vel, 0, 1000));
    QT_FUZZ_CHECK(real_in(t.kalman.r, 0.01, 10000));
    QT_FUZZ_CHECK(real_in(t.gate_nds, 0.01, 1e6) && real_in(t.gate_rep_px, 0.01, 100));
    QT_FUZZ_CHECK(real_in(t.reset_nds, 0, 1e6) && real_in(t.reset_det_s, 0, 1e12));
    QT_FUZZ_CHECK(real_in(t.min_score, -1, 1) && real_in(t.max_radius_px, 1, 48));
    QT_FUZZ_CHECK(t.max_unseen >= 1);
    const qt::FrameHomographyParams& g = o.config.geometry;
    QT_FUZZ_CHECK(g.match.search_radius_px >= 1 && g.match.search_radius_px <= 128);
    QT_FUZZ_CHECK(real_in(g.ransac.inlier_px, 0.05, 50));
    QT_FUZZ_CHECK(g.ransac.max_iterations >= 1 && g.ransac.seed <= 2147483647u);
    if (target) {
        QT_FUZZ_CHECK(o.roi_set);
        QT_FUZZ_CHECK(o.roi_x >= -100000 && o.roi_x <= 100000 && o.roi_y >= -100000 &&
                      o.roi_y <= 100000);
        // Up to 384 px a side once binned, up to factor 16 (checked when frame 0 is read).
        QT_FUZZ_CHECK(o.roi_w >= 1 && o.roi_w <= 384 * 16 && o.roi_h >= 1 && o.roi_h <= 384 * 16);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> args(1);
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0)
            args.emplace_back();
        else
            args.back().push_back(static_cast<char>(data[i]));
    }
    if (size == 0) args.clear();
    const bool help = has(args, "--help") || has(args, "-h");
    const std::string usage = "usage\n";

    for (qt::cli::Command c : {qt::cli::Command::detect, qt::cli::Command::track}) {
        qt::cli::DetectOptions o;
        std::string positional = "unset";
        const int r =
            qt::cli::parse_command_line(args, c, usage, o, positional, dev_null(), dev_null());
        QT_FUZZ_CHECK(r == -1 || r == 0 || r == 2);
        if (r == 0) QT_FUZZ_CHECK(help);
        if (r == -1) {
            QT_FUZZ_CHECK(positional_ok(args, positional));
            check_detect(o);
        }
    }
    for (qt::cli::GeometryCommand c :
         {qt::cli::GeometryCommand::homography, qt::cli::GeometryCommand::target}) {
        const bool target = c == qt::cli::GeometryCommand::target;
        qt::cli::TargetOptions o;
        std::vector<std::string> positional{"unset"};
        const int r = qt::cli::parse_target_command_line(args, c, usage, o, positional, dev_null(),
                                                         dev_null());
        QT_FUZZ_CHECK(r == -1 || r == 0 || r == 2);
        if (r == 0) QT_FUZZ_CHECK(help);
        if (r == -1) {
            QT_FUZZ_CHECK(positional.size() == (target ? 1u : 2u));
            for (const std::string& p : positional) QT_FUZZ_CHECK(positional_ok(args, p));
            check_target(o, target);
        }
    }
    return 0;
}
