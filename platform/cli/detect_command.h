// `quadtrack detect IMAGE [OPTIONS]`: one frame in, its lines and quadrangles as JSON out.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "host/board_runner.h"

namespace qt::cli {

// One frame through the detection chain as detect and track both run it: binned by `bin`
// (choose_bin()'s factor for this frame), the best options.max_quads quadrangles kept; the
// result in the binned frame's pixels (to_input_pixels() maps it back). On failure returns false
// with a one-line reason (no command prefix) in `error`.
// window: tracking mode's bands (track), or null.
bool detect_frame(const io::GreyImage& frame, const DetectOptions& options, uint8_t bin,
                  host::DetectResult& result, std::string& error, BandWindow* window = nullptr);

// args: everything after "detect". Writes the JSON (one line) to `out`, one error line to
// `err`. Returns the exit status: 0 ok, 1 bad input file or frame, 2 bad command line.
int run_detect(const std::vector<std::string>& args, std::FILE* out, std::FILE* err);

// The usage text of detect, with every option.
std::string detect_usage();

}  // namespace qt::cli
