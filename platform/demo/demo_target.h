// The demo's target part: the test command's airborne sequence written as PGM files and tracked
// by the fused tracker, with pictures of frames on a canvas wider than the image so that the
// estimate stays visible while the target is out of view.
#pragma once
#include <string>

namespace qt::cli {

// Writes out_dir/ground/f000.pgm … (the sequence, inputs for `quadtrack target` and
// `quadtrack homography`) and out_dir/target_NN.png for a few frames; a summary on stdout.
// False after an error line on stderr.
bool run_demo_target(const std::string& out_dir);

}  // namespace qt::cli
