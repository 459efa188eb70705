// The detection and tracking parameters as command-line flags: one table gives each flag its
// parameter, unit, range and help line, so parsing and --help cannot disagree. Names follow the
// papers. `quadtrack detect` takes the detection flags, `quadtrack track` those and the
// tracker's.
#pragma once
#include <stdint.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cli/flag_table.h"
#include "host/board_runner.h"
#include "quads/board_detector.h"
#include "tracking/line_tracker.h"
#include "tracking/tracking_mode.h"

namespace qt::cli {

// The command a flag belongs to: detect's flags apply to track too.
enum class Command { detect, track };

// The QuadTrackerParams a user sets (the rest follows the frame size, see run_track).
struct TrackOptions {
    LineModel model = LineModel::closest_points;  // core's default (see the constructor)
    uint8_t filters = 3;                          // closest_points filters, 1..3
    angle_t gate_angle = 0;  // defaults from QuadTrackerParams (see the constructor)
    q16_16 gate_distance = {};
    uint8_t max_predicted = 0;
    TrackingModeParams mode;  // tracking mode's bands; mode.enabled false: every frame whole

    TrackOptions();
};

struct DetectOptions {
    BoardParams params;
    uint16_t display_width = 1024, display_height = 768;  // display pixels (rule 5, homography)
    uint16_t max_quads = 4;                               // quadrangles reported, 1..4
    uint8_t bin = 0;  // binning factor of frames over the capacity's size, 1..16; 0: the smallest
                      // that fits
    host::DetectorCapacity capacity =
        host::DetectorCapacity::vga;  // the detector build the frames run on
    TrackOptions track;               // track only
    // --draw: detect, a PNG file; track, a pattern with one %d or %0Nd (a PNG per frame drawn,
    // numbered by frame). Empty: nothing drawn. draw_every: track draws frames 0, N, 2N, ...
    std::string draw;
    uint32_t draw_every = 1;
    bool track_lines = true;  // track: each frame's line carries the detected lines

    DetectOptions();  // params.quads.display_aspect follows the display size
};

// The help lines of every flag of `command`: "  --name VALUE   text, unit, range (default d)".
std::string options_help(Command command = Command::detect);

// detect's and track's flags (each flag's `command` says which), for the range test.
const FlagTable<DetectOptions, Command>& detect_flags();

// Parses a command's arguments (everything after its name): flags of `command` as --name VALUE
// or --name=VALUE, and exactly one positional argument (detect's IMAGE, track's SEQUENCE) into
// `positional`. Returns -1 when the command should run; otherwise the exit status after
// printing: 0 after `usage` on `out` for --help/-h, 2 after one error line on `err`.
int parse_command_line(const std::vector<std::string>& args, Command command,
                       const std::string& usage, DetectOptions& options, std::string& positional,
                       std::FILE* out, std::FILE* err);

}  // namespace qt::cli
