#include "cli/target_options.h"

#include <cmath>
#include <functional>
#include <initializer_list>
#include <vector>

#include "cli/flag_table.h"
#include "host/draw_results.h"
#include "host/parse_number.h"
#include "io/error_line.h"

namespace qt::cli {

namespace {

using Option = Flag<TargetOptions, GeometryCommand>;

std::string show_float(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// A decimal flag within `range`, of `target` only unless `command` says homography (then both
// commands').
Option real(const char* name, const char* value, const char* what, const SettingRange& range,
            std::function<float&(TargetOptions&)> field,
            GeometryCommand command = GeometryCommand::target, const char* note = "") {
    return {name,
            value,
            described(what, range, note),
            [field](TargetOptions o) { return show_float(field(o)); },
            [field, range](const std::string& t, TargetOptions& o, std::string& e) {
                double v = 0;
                if (!parse_in_range(t, range, v, e)) return false;
                field(o) = static_cast<float>(v);
                return true;
            },
            command,
            &range};
}

template <typename T>
Option integer(const char* name, const char* value, const char* what, const SettingRange& range,
               std::function<T&(TargetOptions&)> field,
               GeometryCommand command = GeometryCommand::target, const char* note = "") {
    return integer_flag<T, TargetOptions>(name, value, what, range, field, command, note);
}

// An NCC score within `range` (-1..1) stored as Q15.
Option score_q15(const char* name, const char* what, const SettingRange& range,
                 std::function<int16_t&(TargetOptions&)> field,
                 GeometryCommand command = GeometryCommand::homography) {
    return {name,
            "NCC",
            described(what, range),
            [field](TargetOptions o) { return show_float(field(o) / 32768.0); },
            [field, range](const std::string& t, TargetOptions& o, std::string& e) {
                double v = 0;
                if (!parse_in_range(t, range, v, e)) return false;
                field(o) = static_cast<int16_t>(std::lround(std::fmin(v * 32768.0, 32767.0)));
                return true;
            },
            command,
            &range};
}

// A flag naming one of two words (value: "yes|no" for the help); `field` is true for the first.
Option either(const char* name, const char* value, const char* yes, const char* no,
              const char* help, std::function<bool&(TargetOptions&)> field) {
    return {name,
            value,
            help,
            [field, yes, no](TargetOptions o) { return std::string(field(o) ? yes : no); },
            [field, yes, no](const std::string& t, TargetOptions& o, std::string& e) {
                if (t != yes && t != no) {
                    e = "'" + t + "' is not " + yes + " or " + no;
                    return false;
                }
                field(o) = t == yes;
                return true;
            },
            GeometryCommand::target};
}

// A flag choosing one of an enumeration's values by name: the paper's version of a choice is
// named "paper" (docs/fidelity.md).
template <typename E>
Option choice(const char* name, const char* help, std::initializer_list<E> values,
              const char* (*to_name)(E), std::function<E&(TargetOptions&)> field,
              GeometryCommand scope = GeometryCommand::target) {
    const std::vector<E> all(values);
    return {name,
            "NAME",
            help,
            [field, to_name](TargetOptions o) { return std::string(to_name(field(o))); },
            [field, to_name, all](const std::string& t, TargetOptions& o, std::string& e) {
                std::string names;
                for (E v : all) {
                    if (t == to_name(v)) {
                        field(o) = v;
                        return true;
                    }
                    names += std::string(names.empty() ? "" : ", ") + to_name(v);
                }
                e = "'" + t + "' is not one of " + names;
                return false;
            },
            scope};
}

static_assert(kMaxRoiSide == 384 && CliTargetCapacity::max_template == 24,
              "the --roi help line gives these figures");

bool parse_roi(const std::string& t, TargetOptions& o, std::string& e) {
    int v[4];
    size_t start = 0;
    for (int i = 0; i < 4; ++i) {
        const size_t comma = i < 3 ? t.find(',', start) : t.size();
        if (comma == std::string::npos) {
            e = "'" + t + "' is not x,y,w,h";
            return false;
        }
        long n = 0;
        // Sizes up to kMaxRoiSide px once binned (checked when frame 0's bin factor is known),
        // binned by up to 16.
        const long lo = i < 2 ? -100000 : 1, hi = i < 2 ? 100000 : long{kMaxRoiSide} * 16;
        std::string why;
        if (!host::parse_int(t.substr(start, comma - start), lo, hi, n, why)) {
            e = std::string(i < 2 ? "position " : "size ") + why;
            return false;
        }
        v[i] = static_cast<int>(n);
        start = comma + 1;
    }
    o.roi_x = v[0];
    o.roi_y = v[1];
    o.roi_w = v[2];
    o.roi_h = v[3];
    o.roi_set = true;
    return true;
}

}  // namespace

// GeometryCommand::homography: both commands' flags; GeometryCommand::target: target's only.
const FlagTable<TargetOptions, GeometryCommand>& target_flags() {
    const TargetKalmanRanges& kalman = kTargetKalmanRanges;
    const TargetTrackerRanges& tracker = kTargetTrackerRanges;
    static const FlagTable<TargetOptions, GeometryCommand> options{
        {
            {"roi", "X,Y,W,H",
             "the target's box in frame 0: top-left pixel and size, px (W, H up to 384 once "
             "binned; a box over 24 px is tracked in blocks of 2..16 px)",
             [](TargetOptions o) {
                 return o.roi_set ? std::to_string(o.roi_x) + "," + std::to_string(o.roi_y) + "," +
                                        std::to_string(o.roi_w) + "," + std::to_string(o.roi_h)
                                  : std::string("none, required");
             },
             parse_roi, GeometryCommand::target},
            {"draw", "PATTERN",
             "a pattern with one %d or %0Nd, e.g. out/f%03d.png: a PNG per frame drawn with the "
             "target's box (solid green measured or reacquired, dashed orange predicted or out "
             "of view, red lost)",
             [](TargetOptions o) { return o.draw.empty() ? std::string("none") : o.draw; },
             [](const std::string& t, TargetOptions& o, std::string& e) {
                 if (!host::draw_pattern_ok(t, e)) return false;
                 o.draw = t;
                 return true;
             },
             GeometryCommand::target},
            integer<uint32_t>("draw-every", "N", "--draw: frames 0, N, 2N, ...",
                              host::kDrawEveryRange,
                              [](TargetOptions& o) -> uint32_t& { return o.draw_every; }),
            {"method", "NAME",
             "fused (the paper's method), filter_only, homography_only or template_only",
             [](TargetOptions o) {
                 return std::string(target_method_name(o.config.tracker.method));
             },
             [](const std::string& t, TargetOptions& o, std::string& e) {
                 for (TargetMethod m : {TargetMethod::fused, TargetMethod::filter_only,
                                        TargetMethod::homography_only, TargetMethod::template_only})
                     if (t == target_method_name(m)) {
                         o.config.tracker.method = m;
                         return true;
                     }
                 e = "'" + t + "' is not fused, filter_only, homography_only or template_only";
                 return false;
             },
             GeometryCommand::target},
            either("reset", "on|off", "on", "off",
                   "Table III's reset of the accumulated homography when the target is found again",
                   [](TargetOptions& o) -> bool& { return o.config.tracker.reset; }),
            bin_flag<TargetOptions, GeometryCommand>(
                [](TargetOptions& o) -> uint8_t& { return o.bin; }, GeometryCommand::homography),
            real("q-pos", "PX2", "Kalman Q's position variance per frame", kalman.q_pos,
                 [](TargetOptions& o) -> float& { return o.config.tracker.kalman.q_pos; }),
            real("q-vel", "PX2", "Kalman Q's velocity variance per frame", kalman.q_vel,
                 [](TargetOptions& o) -> float& { return o.config.tracker.kalman.q_vel; }),
            real("r", "PX2", "Kalman R: template match variance", kalman.r,
                 [](TargetOptions& o) -> float& { return o.config.tracker.kalman.r; }),
            real("gate-nds", "D", "NDS gate of equation (6): a match is used when D_nds <= this",
                 tracker.gate_nds,
                 [](TargetOptions& o) -> float& { return o.config.tracker.gate_nds; }),
            real("gate-rep", "PX",
                 "capped D_rep gate of equation (7): homography trusted when the capped RMS over "
                 "all matched pairs <= this",
                 tracker.gate_rep_px,
                 [](TargetOptions& o) -> float& { return o.config.tracker.gate_rep_px; }),
            choice<TargetFormulation>(
                "formulation",
                "where the filter lives: reference (ours: the image of the last reset frame) or "
                "paper (the current image; unseen, x_n = A x_m, equation (11), with no velocity of "
                "the target's own: --coast-fit and --coast-track do not apply)",
                {TargetFormulation::reference, TargetFormulation::paper}, target_formulation_name,
                [](TargetOptions& o) -> TargetFormulation& {
                    return o.config.tracker.formulation;
                }),
            choice<SearchRegionShape>(
                "search-region",
                "square (ours: 3 sigma, clamped to --min-radius..--max-radius) or paper (four "
                "corners mapped by the accumulated homography, carried while unseen)",
                {SearchRegionShape::square, SearchRegionShape::paper}, search_region_name,
                [](TargetOptions& o) -> SearchRegionShape& { return o.config.tracker.region; }),
            choice<RepGate>(
                "rep-gate",
                "D_rep of equation (7) over all matched pairs: capped (ours: RMS of terms capped "
                "at (2 inlier-px)^2, <= --gate-rep) or paper (the sum, <= --th-rep)",
                {RepGate::capped, RepGate::paper}, rep_gate_name,
                [](TargetOptions& o) -> RepGate& { return o.config.tracker.rep_gate; }),
            real("th-rep", "PX2", "paper D_rep gate: the sum over the pairs", tracker.th_rep_px2,
                 [](TargetOptions& o) -> float& { return o.config.tracker.th_rep_px2; }),
            choice<TargetDetector>(
                "detector",
                "the measurement (Table III step 2): ncc_template (ours) or morphological (the "
                "paper's top-hat and clustering)",
                {TargetDetector::ncc_template, TargetDetector::morphological}, target_detector_name,
                [](TargetOptions& o) -> TargetDetector& { return o.config.detector; }),
            real("reset-nds", "D", "reset when D_nds <= this ...", tracker.reset_nds,
                 [](TargetOptions& o) -> float& { return o.config.tracker.reset_nds; }),
            real("reset-det-s", "PX4", "... and det S <= this", tracker.reset_det_s,
                 [](TargetOptions& o) -> float& { return o.config.tracker.reset_det_s; }),
            real("min-score", "NCC", "a template match counts when its NCC >= this",
                 tracker.min_score,
                 [](TargetOptions& o) -> float& { return o.config.tracker.min_score; }),
            integer<uint8_t>(
                "template-blend", "N",
                "1: the template is replaced by the cut at a match whose NCC fell below 0.85; "
                "N > 1: every accepted match moves it 1/N of the way to the cut there (a running "
                "mean over about N frames)",
                kTargetPipelineRanges.template_blend,
                [](TargetOptions& o) -> uint8_t& { return o.config.template_blend; }),
            either("template-pose", "ground|fixed", "ground", "fixed",
                   "the template is searched (and blended) as the ground's motion since its cut "
                   "shows it: ground (ours: warped by that motion's Jacobian) or fixed (as cut)",
                   [](TargetOptions& o) -> bool& { return o.config.template_follows_ground; }),
            integer<int16_t>(
                "motion-prior", "Q15",
                "the template search takes this times (distance / window half-side)^2 off a "
                "placement's NCC before keeping the best (0: the best NCC anywhere)",
                kTargetPipelineRanges.motion_prior_q15,
                [](TargetOptions& o) -> int16_t& { return o.config.motion_prior_q15; }),
            integer<uint16_t>(
                "redetect-after", "FRAMES",
                "after this many frames without a match, every other frame searches the whole "
                "frame (coarse) for the template (0: never)",
                kTargetPipelineRanges.redetect_after,
                [](TargetOptions& o) -> uint16_t& { return o.config.redetect_after; }),
            score_q15(
                "redetect-score",
                "least NCC of the whole-frame search's best, and of the match in the next "
                "frame's window there that restarts the track",
                kTargetPipelineRanges.redetect_score,
                [](TargetOptions& o) -> int16_t& { return o.config.redetect_score_q15; },
                GeometryCommand::target),
            integer<uint16_t>(
                "harris-band", "ROWS",
                "corners are sought in a band of this many rows about each cell row's middle "
                "(0: every row)",
                kHarrisRanges.band_rows,
                [](TargetOptions& o) -> uint16_t& { return o.config.harris.band_rows; }),
            integer<uint8_t>(
                "search-step", "N",
                "the template search scores every Nth placement of its window along each axis, "
                "then those beside the three best (1: every placement)",
                kTargetPipelineRanges.template_search_step,
                [](TargetOptions& o) -> uint8_t& { return o.config.template_search_step; }),
            real("max-radius", "PX", "largest search window half-side around the prediction",
                 tracker.max_radius_px,
                 [](TargetOptions& o) -> float& { return o.config.tracker.max_radius_px; }),
            integer<uint16_t>(
                "max-unseen", "FRAMES", "lost after this many frames without a match",
                tracker.max_unseen,
                [](TargetOptions& o) -> uint16_t& { return o.config.tracker.max_unseen; }),
            real("max-outside", "FRAMES",
                 "lost when the estimate is more than this many frame widths (heights) outside "
                 "the image",
                 tracker.max_outside,
                 [](TargetOptions& o) -> float& { return o.config.tracker.max_outside; }),
            integer<uint8_t>(
                "max-unconfirmed-exit", "FRAMES",
                "lost when the estimate leaves the image after more than this many frames "
                "searched in vain while the camera keeps the last measured position inside",
                tracker.max_unconfirmed_exit,
                [](TargetOptions& o) -> uint8_t& { return o.config.tracker.max_unconfirmed_exit; }),
            real("lost-search", "PX",
                 "a target lost so is searched for around its last measured position, the "
                 "window growing by this much a frame up to --max-radius (0: not searched for)",
                 tracker.lost_search_px,
                 [](TargetOptions& o) -> float& { return o.config.tracker.lost_search_px; }),
            integer<uint16_t>(
                "coast-fit", "FRAMES",
                "leaving the image, the estimate coasts on the track (--coast-track) fitted to "
                "the measurements of this many last frames",
                tracker.coast_fit_frames,
                [](TargetOptions& o) -> uint16_t& { return o.config.tracker.coast_fit_frames; },
                GeometryCommand::target, "0: the filter's velocity; --formulation reference only"),
            either("coast-track", "perspective|line", "perspective", "line",
                   "the coasting track: perspective (ours: (a + b t)/(1 + c t), a target at "
                   "constant velocity on the ground) or line (constant velocity in the reference "
                   "image)",
                   [](TargetOptions& o) -> bool& { return o.config.tracker.coast_projective; }),
            either("frame-corners", "ground|all", "ground", "all",
                   "the frame homography's corners: ground (ours: not those whose patch reaches "
                   "the target's box) or all (the paper)",
                   [](TargetOptions& o) -> bool& { return o.config.ground_corners_only; }),
            choice<PairSource>(
                "pairs",
                "the homography's point pairs: displacement (ours: A's corner and its patch's "
                "Lucas-Kanade displacement into B) or corners (the paper: the two matched corners)",
                {PairSource::displacement, PairSource::corners}, pair_source_name,
                [](TargetOptions& o) -> PairSource& { return o.config.geometry.pairs; },
                GeometryCommand::homography),
            integer<uint16_t>(
                "search-radius", "PX",
                "corner matching: candidates within this of the expected position",
                kMatchRanges.search_radius_px,
                [](TargetOptions& o) -> uint16_t& {
                    return o.config.geometry.match.search_radius_px;
                },
                GeometryCommand::homography),
            score_q15(
                "min-match", "corner matching: least NCC of a match", kMatchRanges.min_score,
                [](TargetOptions& o) -> int16_t& { return o.config.geometry.match.min_score_q15; }),
            real(
                "inlier-px", "PX", "RANSAC inlier threshold on the transfer error",
                kRansacRanges.inlier_px,
                [](TargetOptions& o) -> float& { return o.config.geometry.ransac.inlier_px; },
                GeometryCommand::homography),
            integer<uint16_t>(
                "max-iterations", "N", "RANSAC hypotheses at most", kRansacRanges.max_iterations,
                [](TargetOptions& o) -> uint16_t& {
                    return o.config.geometry.ransac.max_iterations;
                },
                GeometryCommand::homography),
            integer<uint64_t>(
                "seed", "N", "RANSAC's PRNG seed", kRansacRanges.seed,
                [](TargetOptions& o) -> uint64_t& { return o.config.geometry.ransac.seed; },
                GeometryCommand::homography),
        },
        GeometryCommand::homography,
        28};
    return options;
}

TargetPipelineParams default_target_config() {
    TargetPipelineParams c;
    c.harris.grid_cols = 10;
    c.harris.grid_rows = 8;
    c.harris.per_cell = 2;
    return c;
}

TargetOptions::TargetOptions() : config(default_target_config()) {}

std::string target_options_help(GeometryCommand command) { return target_flags().help(command); }

int parse_target_command_line(const std::vector<std::string>& args, GeometryCommand command,
                              const std::string& usage, TargetOptions& options,
                              std::vector<std::string>& positional, std::FILE* out,
                              std::FILE* err) {
    const bool target = command == GeometryCommand::target;
    const char* name = target ? "target" : "homography";
    const int parsed =
        target_flags().parse(args, command, name, usage, options, positional, out, err);
    if (parsed >= 0) return parsed;
    const size_t wanted = target ? 1 : 2;
    if (positional.size() != wanted) {
        qt::io::print_error_line(
            err, "quadtrack %s: expected %s, got %zu argument%s (see quadtrack %s --help)", name,
            target ? "one SEQUENCE" : "two images A B", positional.size(),
            positional.size() == 1 ? "" : "s", name);
        return 2;
    }
    if (target && !options.roi_set) {
        qt::io::print_error_line(err, "quadtrack target: --roi X,Y,W,H is required");
        return 2;
    }
    return -1;
}

}  // namespace qt::cli
