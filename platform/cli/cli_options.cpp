#include "cli/cli_options.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "cli/flag_table.h"
#include "host/board_runner.h"
#include "host/draw_results.h"
#include "host/parse_number.h"
#include "io/error_line.h"
#include "quads/display_homography.h"
#include "tracking/quad_tracker.h"

namespace qt::cli {

namespace {

using Option = Flag<DetectOptions, Command>;

// The same flag for `quadtrack track` only.
Option track_only(Option o) {
    o.command = Command::track;
    return o;
}

// A decimal number into q16_16 (rounded to nearest 2^-16) within [lo, hi].
bool parse_q16(const std::string& text, double lo, double hi, q16_16& out, std::string& error) {
    double v = 0;
    if (!host::parse_double(text, lo, hi, v, error)) return false;
    out = q16_16::from_raw(std::llround(v * 65536.0));
    return true;
}

bool parse_yes_no(const std::string& text, bool& out, std::string& error) {
    if (text == "yes" || text == "no") {
        out = text == "yes";
        return true;
    }
    error = "'" + text + "' is not yes or no";
    return false;
}

std::string show_q16(q16_16 v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v.raw / 65536.0);
    return buf;
}

std::string show_deg(angle_t a) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", a / 4294967296.0 * 360.0);
    return buf;
}

// An integer flag stored in a uint8_t, uint16_t, uint32_t or uint64_t field, within `range`.
template <typename T>
Option integer(const char* name, const char* value, const char* what, const SettingRange& range,
               std::function<T&(DetectOptions&)> field, const char* note = "") {
    return integer_flag<T, DetectOptions>(name, value, what, range, field, Command::detect, note);
}

// A decimal flag stored as q16_16 (rounded to the nearest 2^-16), within `range`.
Option decimal(const char* name, const char* value, const char* what, const SettingRange& range,
               std::function<q16_16&(DetectOptions&)> field, const char* note = "") {
    return {name,
            value,
            described(what, range, note),
            [field](DetectOptions o) { return show_q16(field(o)); },
            [field, range](const std::string& t, DetectOptions& o, std::string& e) {
                return parse_q16(t, range_lo(range), range_hi(range), field(o), e);
            },
            Command::detect,
            &range};
}

// An angle flag in degrees (range's unit), stored as a binary angle.
Option degrees(const char* name, const char* what, const SettingRange& range,
               std::function<angle_t&(DetectOptions&)> field) {
    return {name,
            "DEG",
            described(what, range),
            [field](DetectOptions o) { return show_deg(field(o)); },
            [field, range](const std::string& t, DetectOptions& o, std::string& e) {
                q16_16 deg;
                if (!parse_q16(t, range_lo(range), range_hi(range), deg, e)) return false;
                field(o) = angle_from_deg(deg);
                return true;
            },
            Command::detect,
            &range};
}

}  // namespace

const FlagTable<DetectOptions, Command>& detect_flags() {
    const HoughRanges& hough = kHoughRanges;
    const ClusterRanges& cluster = kClusterRanges;
    const QuadRanges& quads = kQuadRanges;
    const RefineRanges& refine = kRefineRanges;
    const QuadTrackerRanges& track = kQuadTrackerRanges;
    // Command::detect: every command's; track_only(): track's only.
    static const FlagTable<DetectOptions, Command> options{
        {
            integer<uint16_t>(
                "edge-threshold", "LEVEL",
                "edge pixel: L1 gradient magnitude |gx|+|gy| at least this",
                kLineRanges.edge_threshold,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.edge_threshold; }),
            {"edge-front-end", "NAME",
             "threshold_nms (ours: one threshold and NMS on the raw rows) or canny (the paper's: "
             "Gaussian smoothing, NMS, hysteresis --edge-threshold..--canny-high)",
             [](DetectOptions o) {
                 return std::string(edge_front_end_name(o.params.lines.front_end));
             },
             [](const std::string& t, DetectOptions& o, std::string& e) {
                 for (EdgeFrontEnd f : {EdgeFrontEnd::threshold_nms, EdgeFrontEnd::canny})
                     if (t == edge_front_end_name(f)) {
                         o.params.lines.front_end = f;
                         return true;
                     }
                 e = "'" + t + "' is not threshold_nms or canny";
                 return false;
             }},
            integer<uint16_t>(
                "canny-high", "LEVEL", "canny: hysteresis high threshold", kLineRanges.canny_high,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.canny_high; },
                "0: twice --edge-threshold"),
            integer<uint16_t>(
                "theta-bins", "N", "Hough accumulator angle bins over 180 degrees",
                hough.theta_bins,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.theta_bins; },
                "90 = 2 degrees each"),
            {"rho", "PX",
             described("Hough accumulator distance resolution", hough.rho_step,
                       "2 or 4: the VGA build's accumulator has no room for 1"),
             [](DetectOptions o) { return std::to_string(o.params.lines.hough.rho_step); },
             [](const std::string& t, DetectOptions& o, std::string& e) {
                 long v = 0;
                 if (!parse_in_range(t, kHoughRanges.rho_step, v, e)) return false;
                 if (v == 3) {
                     e = "3 is not 2 or 4";
                     return false;
                 }
                 o.params.lines.hough.rho_step = static_cast<uint16_t>(v);
                 return true;
             },
             Command::detect, &hough.rho_step},
            integer<uint16_t>(
                "threshold", "VOTES",
                "PPHT vote threshold: votes a bin needs before its line is followed",
                hough.threshold,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.threshold; }),
            integer<uint16_t>(
                "min-line-length", "PX", "PPHT minimum line length", hough.min_line_length,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.min_line_length; }),
            integer<uint16_t>(
                "max-gap", "PX", "PPHT maximum gap inside a line", hough.max_line_gap,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.max_line_gap; }),
            integer<uint16_t>(
                "vote-window", "DEG",
                "a point votes for normals within +-DEG of its gradient direction",
                hough.vote_window_deg,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.vote_window_deg; },
                "90 = all"),
            integer<uint16_t>(
                "corridor", "PX", "PPHT line following: pixels either side of the line searched",
                hough.corridor,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.corridor; }),
            integer<uint32_t>(
                "max-walk-steps", "N", "PPHT line-following budget per frame", hough.max_walk_steps,
                [](DetectOptions& o) -> uint32_t& { return o.params.lines.hough.max_walk_steps; }),
            integer<uint16_t>(
                "max-voters", "N", "PPHT voting budget per frame: edge points that vote",
                hough.max_voters,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.max_voters; },
                "0: half the edge capacity, 2048 at QVGA, 8192 at VGA"),
            integer<uint16_t>(
                "min-peak", "PERCENT",
                "PPHT: a bin at the threshold is followed only when its count is at least this "
                "percentage of its flank's on one side (the larger of the bins 2 and 3 away in "
                "its theta row)",
                hough.min_peak_percent,
                [](DetectOptions& o) -> uint16_t& { return o.params.lines.hough.min_peak_percent; },
                "0: every bin"),
            integer<uint64_t>(
                "seed", "N", "PPHT visiting order seed", hough.seed,
                [](DetectOptions& o) -> uint64_t& { return o.params.lines.hough.seed; }),
            decimal("cluster-distance", "PX",
                    "clustering similarity threshold S(li,lj) = |Ci - Cj|", cluster.distance,
                    [](DetectOptions& o) -> q16_16& { return o.params.lines.cluster.distance; }),
            degrees("cluster-angle", "clustering: largest orientation difference of merged lines",
                    cluster.max_angle,
                    [](DetectOptions& o) -> angle_t& { return o.params.lines.cluster.max_angle; }),
            decimal("cluster-gap", "PX",
                    "clustering: largest gap between merged segments along the line", cluster.gap,
                    [](DetectOptions& o) -> q16_16& { return o.params.lines.cluster.gap; }),
            decimal("cluster-offset", "PX",
                    "clustering: ends of the shorter segment at most this far from the longer "
                    "one's line",
                    cluster.offset,
                    [](DetectOptions& o) -> q16_16& { return o.params.lines.cluster.offset; }),
            decimal(
                "corner-join-distance", "PX",
                "line ends move to the lines' intersection when at most this far from it",
                cluster.corner_distance,
                [](DetectOptions& o) -> q16_16& { return o.params.lines.corners.max_distance; }),
            degrees("corner-join-angle",
                    "line ends are joined only for lines at least this far from parallel",
                    cluster.corner_angle,
                    [](DetectOptions& o) -> angle_t& { return o.params.lines.corners.min_angle; }),
            degrees("parallel-tolerance", "rule 1: largest angle between opposite sides",
                    quads.parallel_tolerance,
                    [](DetectOptions& o) -> angle_t& { return o.params.quads.parallel_tolerance; }),
            degrees("perpendicular-tolerance",
                    "rule 2: largest deviation of adjacent sides from 90 degrees",
                    quads.perpendicular_tolerance,
                    [](DetectOptions& o) -> angle_t& {
                        return o.params.quads.perpendicular_tolerance;
                    }),
            decimal("corner-margin", "PX", "rule 3: corners at least this far inside the frame",
                    quads.corner_margin,
                    [](DetectOptions& o) -> q16_16& { return o.params.quads.corner_margin; }),
            decimal(
                "min-side", "PX", "rule 4: shortest side", quads.min_side_length,
                [](DetectOptions& o) -> q16_16& { return o.params.quads.min_side_length; },
                "0: a tenth of the frame height"),
            decimal("max-side", "PX", "rule 4: longest side", quads.max_side_length,
                    [](DetectOptions& o) -> q16_16& { return o.params.quads.max_side_length; }),
            decimal("aspect-tolerance", "FACTOR",
                    "rule 5: largest factor between the side ratio and the display's",
                    quads.aspect_tolerance,
                    [](DetectOptions& o) -> q16_16& { return o.params.quads.aspect_tolerance; }),
            decimal(
                "tilted-aspect-tolerance", "FACTOR",
                "rule 5: the larger factor allowed when opposite sides converge by at least "
                "--perspective-convergence (a tilted board)",
                quads.tilted_aspect_tolerance,
                [](DetectOptions& o) -> q16_16& { return o.params.quads.tilted_aspect_tolerance; }),
            degrees("perspective-convergence",
                    "rule 5: least angle between a pair of opposite sides for "
                    "--tilted-aspect-tolerance",
                    quads.perspective_convergence,
                    [](DetectOptions& o) -> angle_t& {
                        return o.params.quads.perspective_convergence;
                    }),
            decimal("min-coverage", "FRACTION",
                    "each side covered by its line's segment at least this much",
                    quads.min_side_coverage,
                    [](DetectOptions& o) -> q16_16& { return o.params.quads.min_side_coverage; }),
            decimal("min-score", "FRACTION",
                    "the four sides together covered at least this share of the perimeter",
                    quads.min_score,
                    [](DetectOptions& o) -> q16_16& { return o.params.quads.min_score; }),
            decimal("collinear-distance", "PX",
                    "lines with both ends this close to a side's line also cover it",
                    quads.collinear_distance,
                    [](DetectOptions& o) -> q16_16& { return o.params.quads.collinear_distance; }),
            {"contrast", "bright|dark|any",
             "the board is brighter (or darker) than its surroundings on every side, or either",
             [](DetectOptions o) {
                 return std::string(o.params.quads.contrast == Contrast::bright_board ? "bright"
                                    : o.params.quads.contrast == Contrast::dark_board ? "dark"
                                                                                      : "any");
             },
             [](const std::string& t, DetectOptions& o, std::string& e) {
                 if (t == "bright")
                     o.params.quads.contrast = Contrast::bright_board;
                 else if (t == "dark")
                     o.params.quads.contrast = Contrast::dark_board;
                 else if (t == "any")
                     o.params.quads.contrast = Contrast::any;
                 else {
                     e = "'" + t + "' is not bright, dark or any";
                     return false;
                 }
                 return true;
             }},
            {"display", "WxH",
             described("display area: its aspect W/H is rule 5's ratio, and the display "
                       "homography maps it",
                       kDisplaySizeRange, "each of W and H"),
             [](DetectOptions o) {
                 return std::to_string(o.display_width) + "x" + std::to_string(o.display_height);
             },
             [](const std::string& t, DetectOptions& o, std::string& e) {
                 const size_t x = t.find('x');
                 long w = 0, h = 0;
                 if (x == std::string::npos) {
                     e = "'" + t + "' is not WxH";
                     return false;
                 }
                 if (!parse_in_range(t.substr(0, x), kDisplaySizeRange, w, e) ||
                     !parse_in_range(t.substr(x + 1), kDisplaySizeRange, h, e))
                     return false;
                 o.display_width = static_cast<uint16_t>(w);
                 o.display_height = static_cast<uint16_t>(h);
                 o.params.quads.display_aspect = q16_16::from_ratio(w, h);
                 return true;
             },
             Command::detect, &kDisplaySizeRange},
            {"complete-hidden-side", "yes|no",
             "a side hidden along most of its length is completed from its two neighbours",
             [](DetectOptions o) {
                 return std::string(o.params.quads.complete_hidden_side ? "yes" : "no");
             },
             [](const std::string& t, DetectOptions& o, std::string& e) {
                 return parse_yes_no(t, o.params.quads.complete_hidden_side, e);
             }},
            decimal(
                "refine-band", "PX",
                "side refinement: edge points within this of a side, first pass", refine.band,
                [](DetectOptions& o) -> q16_16& { return o.params.refine.band; },
                "0: no refinement, the sides stay the lines the rules chose"),
            decimal("refine-fine-band", "PX", "side refinement: the same, second pass",
                    refine.fine_band,
                    [](DetectOptions& o) -> q16_16& { return o.params.refine.fine_band; }),
            integer<uint8_t>(
                "side-evidence", "PERCENT",
                "each side: edge evidence along at least this share of it, next to both corners",
                refine.min_side_evidence_percent,
                [](DetectOptions& o) -> uint8_t& {
                    return o.params.refine.min_side_evidence_percent;
                }),
            integer<uint8_t>(
                "hidden-side-evidence", "PERCENT",
                "a completed side: edge evidence along at least this share of it, next to both "
                "corners",
                refine.min_hidden_side_evidence_percent,
                [](DetectOptions& o) -> uint8_t& {
                    return o.params.refine.min_hidden_side_evidence_percent;
                }),
            integer<uint8_t>(
                "evidence", "PERCENT",
                "the four sides together: edge evidence along at least this share",
                refine.min_evidence_percent,
                [](DetectOptions& o) -> uint8_t& { return o.params.refine.min_evidence_percent; }),
            integer<uint8_t>(
                "max-inside-edges", "PERCENT",
                "a kept quadrangle has at most this share of the 2x2 px cells inside it holding "
                "an edge point (farther than --inside-margin from its sides), at 240 rows, "
                "scaled by sqrt(240 / rows)",
                refine.max_inside_edge_cells_percent,
                [](DetectOptions& o) -> uint8_t& {
                    return o.params.refine.max_inside_edge_cells_percent;
                }),
            integer<uint8_t>(
                "max-lines-across", "N",
                "a kept quadrangle is crossed by at most this many lines, each inside it over at "
                "least half its shortest side (a pattern's lines cross it, a board's print does "
                "not)",
                refine.max_lines_across,
                [](DetectOptions& o) -> uint8_t& { return o.params.refine.max_lines_across; }),
            integer<uint8_t>(
                "max-junction-corners", "N",
                "a kept quadrangle has at most this many corners where both its sides run on past "
                "it (a checkerboard's square)",
                refine.max_junction_corners,
                [](DetectOptions& o) -> uint8_t& { return o.params.refine.max_junction_corners; }),
            decimal("inside-margin", "PX",
                    "edge points this close to a side are not counted inside", refine.inside_margin,
                    [](DetectOptions& o) -> q16_16& { return o.params.refine.inside_margin; }),
            integer<uint16_t>("max-quads", "N", "quadrangles reported, best first",
                              host::HostBoardDetector::quads_range,
                              [](DetectOptions& o) -> uint16_t& { return o.max_quads; }),
            bin_flag<DetectOptions, Command>(
                [](DetectOptions& o) -> uint8_t& { return o.bin; }, Command::detect,
                "frames larger than 640 x 480 (320 x 240 with --capacity qvga)"),
            {"capacity", "vga|qvga",
             "the detector build: vga = qt::Vga, frames up to 640 x 480 (the CLI's own); qvga = "
             "qt::Qvga, frames up to 320 x 240, the capacities of the firmware and the C API, "
             "so the same frame gives their results (larger frames binned to fit either way)",
             [](DetectOptions o) { return std::string(host::capacity_name(o.capacity)); },
             [](const std::string& t, DetectOptions& o, std::string& e) {
                 if (t != "vga" && t != "qvga") {
                     e = "expected vga or qvga, got '" + t + "'";
                     return false;
                 }
                 o.capacity =
                     t == "qvga" ? host::DetectorCapacity::qvga : host::DetectorCapacity::vga;
                 return true;
             },
             Command::detect},
            {"draw", "FILE",
             "detect: write the frame with its lines and quadrangles over it as a PNG; track: "
             "a pattern with one %d or %0Nd, e.g. out/f%03d.png, a PNG per frame drawn with the "
             "tracked board (sides detected solid green, predicted dashed orange)",
             [](DetectOptions o) { return o.draw.empty() ? std::string("none") : o.draw; },
             [](const std::string& t, DetectOptions& o, std::string& e) {
                 if (t.empty()) {
                     e = "expected a file name";
                     return false;
                 }
                 o.draw = t;
                 return true;
             },
             Command::detect},
            track_only({"lines", "yes|no",
                        "each frame's JSON line carries the frame's detected lines (no: only the "
                        "tracked board, about 6 KB a frame less on a busy frame)",
                        [](DetectOptions o) { return std::string(o.track_lines ? "yes" : "no"); },
                        [](const std::string& t, DetectOptions& o, std::string& e) {
                            if (t != "yes" && t != "no") {
                                e = "expected yes or no, got '" + t + "'";
                                return false;
                            }
                            o.track_lines = t == "yes";
                            return true;
                        }}),
            track_only(integer<uint32_t>(
                "draw-every", "N", "track --draw: draw frames 0, N, 2N, ...", host::kDrawEveryRange,
                [](DetectOptions& o) -> uint32_t& { return o.draw_every; })),
            // the Quadrangle Detection paper sections 2.5-2.7 and quad_tracker.h.
            track_only(
                {"model", "paper|turn",
                 "line tracker per side: paper = the paper's N Kalman filters on closest points, "
                 "turn = angle with turn rate and bent offset (line_tracker.h)",
                 [](DetectOptions o) {
                     return std::string(o.track.model == LineModel::turn ? "turn" : "paper");
                 },
                 [](const std::string& t, DetectOptions& o, std::string& e) {
                     if (t == "paper")
                         o.track.model = LineModel::closest_points;
                     else if (t == "turn")
                         o.track.model = LineModel::turn;
                     else {
                         e = "'" + t + "' is not paper or turn";
                         return false;
                     }
                     return true;
                 }}),
            track_only(integer<uint8_t>(
                "filters", "N", "paper model: Kalman filters per line, each on its own origin",
                track.filters, [](DetectOptions& o) -> uint8_t& { return o.track.filters; },
                "3 = 3KF")),
            track_only(degrees("gate-angle",
                               "a detected line serves a tracked side only within this angle of "
                               "its prediction",
                               track.gate_angle,
                               [](DetectOptions& o) -> angle_t& { return o.track.gate_angle; })),
            track_only(decimal("gate-distance", "PX",
                               "a detected line serves a tracked side only with both ends within "
                               "this distance of its prediction",
                               track.gate_distance,
                               [](DetectOptions& o) -> q16_16& { return o.track.gate_distance; })),
            track_only(integer<uint8_t>(
                "max-predicted", "N",
                "a side may be predicted this many frames in a row before the track is dropped",
                track.max_predicted,
                [](DetectOptions& o) -> uint8_t& { return o.track.max_predicted; },
                "off: never for that reason")),
            track_only(
                {"tracking-mode", "on|off",
                 "on: each frame after one that held the board with all four sides is "
                 "processed only in bands around the sides (docs/tracking.md), every "
                 "--full-every-th frame whole",
                 [](DetectOptions o) { return std::string(o.track.mode.enabled ? "on" : "off"); },
                 [](const std::string& t, DetectOptions& o, std::string& e) {
                     if (t != "on" && t != "off") {
                         e = "'" + t + "' is not on or off";
                         return false;
                     }
                     o.track.mode.enabled = t == "on";
                     return true;
                 }}),
            track_only(
                decimal("band-width", "PX",
                        "tracking mode: a band's half width either side of a side's line",
                        kTrackingModeRanges.half_width,
                        [](DetectOptions& o) -> q16_16& { return o.track.mode.half_width; })),
            track_only(integer<uint16_t>(
                "full-every", "N", "tracking mode: every N-th frame is whole",
                kTrackingModeRanges.full_every,
                [](DetectOptions& o) -> uint16_t& { return o.track.mode.full_every; })),
        },
        Command::detect,
        34};
    return options;
}

TrackOptions::TrackOptions() {
    mode.enabled = false;  // the command line's default: every frame whole
    const QuadTrackerParams d;
    model = d.lines.model;
    filters = d.lines.filters;
    gate_angle = d.gate_angle;
    gate_distance = d.gate_distance;
    max_predicted = d.max_predicted;
}

DetectOptions::DetectOptions() {
    params.quads.display_aspect = q16_16::from_ratio(display_width, display_height);
}

std::string options_help(Command command) { return detect_flags().help(command); }

int parse_command_line(const std::vector<std::string>& args, Command command,
                       const std::string& usage, DetectOptions& options, std::string& positional,
                       std::FILE* out, std::FILE* err) {
    const char* name = command == Command::detect ? "detect" : "track";
    const char* what = command == Command::detect ? "image" : "sequence";
    const char* what_upper = command == Command::detect ? "IMAGE" : "SEQUENCE";
    std::vector<std::string> given;
    positional.clear();
    const int parsed = detect_flags().parse(args, command, name, usage, options, given, out, err);
    if (parsed >= 0) return parsed;
    if (given.size() > 1) {
        qt::io::print_error_line(err, "quadtrack %s: one %s only, got '%s' and '%s'", name, what,
                                 given[0].c_str(), given[1].c_str());
        return 2;
    }
    if (given.empty()) {
        qt::io::print_error_line(err, "quadtrack %s: no %s given (see quadtrack %s --help)", name,
                                 what_upper, name);
        return 2;
    }
    // --draw is a file for detect, a pattern for track: checked once the command is known.
    std::string why;
    if (command == Command::track && !options.draw.empty() &&
        !host::draw_pattern_ok(options.draw, why)) {
        qt::io::print_error_line(err, "quadtrack track: --draw: %s", why.c_str());
        return 2;
    }
    if (options.params.quads.min_side_length > options.params.quads.max_side_length) {
        qt::io::print_error_line(err, "quadtrack %s: --min-side is above --max-side", name);
        return 2;
    }
    positional = given[0];
    return -1;
}

}  // namespace qt::cli
