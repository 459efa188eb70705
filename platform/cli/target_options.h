// The flags of `quadtrack target` and `quadtrack homography`: one table gives each flag its
// parameter, unit, range and help line, so parsing and --help cannot disagree. Names follow
// the Filtering and Geometry paper (Q, R, the NDS and reprojection gates, the reset).
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "cli/flag_table.h"
#include "target/float/target_pipeline.h"

namespace qt::cli {

// The CLI's pipeline: frames up to 640 × 480, 160 corners a frame, templates up to 24 × 24
// (a larger box is seen in blocks of 2..16 px: TargetPipeline::set_target), search windows up to
// 48 px around the expected position, a captured region up to 160 px (or blocks) a side.
struct CliTargetCapacity : Vga {
    static constexpr uint8_t max_template = 24;
    static constexpr uint16_t max_region = 160;
};
using CliTargetPipeline = TargetPipeline<CliTargetCapacity>;
// The largest --roi side once binned, px (384: more than half a 640 x 480 frame).
constexpr int kMaxRoiSide = static_cast<int>(CliTargetPipeline::max_box_side());

enum class GeometryCommand { homography, target };

struct TargetOptions {
    TargetPipelineParams config;                     // defaults: default_target_config()
    bool roi_set = false;                            // target: --roi is required
    int roi_x = 0, roi_y = 0, roi_w = 0, roi_h = 0;  // px, frame 0 (the input's pixels)
    uint8_t bin = 0;  // binning factor of frames over 640 × 480, 1..16; 0: the smallest that fits
    // target --draw: a pattern with one %d or %0Nd, a PNG per frame drawn (frames 0, N, 2N, ...
    // with draw_every N); empty: none.
    std::string draw;
    uint32_t draw_every = 1;
    TargetOptions();
};

// The pipeline's defaults for the CLI (HarrisParams for VGA-sized frames, the paper's Q).
TargetPipelineParams default_target_config();

// The help lines of every flag of `command`: "  --name VALUE   text, unit, range (default d)".
std::string target_options_help(GeometryCommand command);

// homography's and target's flags (each flag's `command` says which), for the range test.
const FlagTable<TargetOptions, GeometryCommand>& target_flags();

// Parses a command's arguments into `options` and its positional arguments (target: exactly
// one SEQUENCE; homography: exactly two images A B). Returns -1 when the command should run;
// otherwise the exit status after printing: 0 after `usage` on `out` for --help/-h, 2 after
// one error line on `err`.
int parse_target_command_line(const std::vector<std::string>& args, GeometryCommand command,
                              const std::string& usage, TargetOptions& options,
                              std::vector<std::string>& positional, std::FILE* out, std::FILE* err);

}  // namespace qt::cli
