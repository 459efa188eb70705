// The detection parameters as command-line flags: one table gives each flag its parameter, unit,
// range and help line, so parsing and --help cannot disagree. Names follow the papers.
#pragma once
#include <stdint.h>

#include <string>

#include "board_detector.h"

namespace qt::cli {

struct DetectOptions {
    BoardParams params;
    uint16_t display_width = 1024, display_height = 768;  // display pixels (rule 5, homography)
    uint16_t max_quads = 4;                                // quadrangles reported, 1..4

    DetectOptions();  // params.quads.display_aspect follows the display size
};

// Applies flag `name` (without the leading "--") with `value`. Returns false with a one-line
// message in `error` for an unknown flag, a malformed number or a value out of range.
bool apply_option(const std::string& name, const std::string& value, DetectOptions& options, std::string& error);

// True if `name` is one of the table's flags.
bool is_option(const std::string& name);

// The help lines of every flag: "  --name VALUE   text (unit, range; default d)".
std::string options_help();

}  // namespace qt::cli
