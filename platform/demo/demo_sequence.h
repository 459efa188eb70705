// The demo's board sequence (platform/scene/board_sequence.h) detected and tracked
// (core/tracking/quad_tracker.h) frame by frame, each frame written as an overlay picture with a
// one-line summary on stdout.
#pragma once
#include <string>

namespace qt::cli {

// Writes board_00.png ... under out_dir (which exists). Returns false after printing an error.
bool run_demo_sequence(const std::string& out_dir);

}  // namespace qt::cli
