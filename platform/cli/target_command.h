// `quadtrack target SEQUENCE --roi X,Y,W,H [OPTIONS]`: the target in frame 0's box tracked
// through the sequence by the fused Kalman filter and accumulated homographies
// (core/target/float/target_pipeline.h), one JSON line per frame.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace qt::cli {

// args: everything after "target". Writes one JSON line per frame to `out` (target_json.h),
// flushed frame by frame, and errors as one line to `err`. Returns 0 ok, 1 bad input (an
// unreadable frame — the lines before it stay written —, a frame of another size than the
// first or above 640 × 480, a box not wholly inside frame 0, an empty sequence), 2 bad command
// line.
int run_target(const std::vector<std::string>& args, std::FILE* out, std::FILE* err);

std::string target_usage();

}  // namespace qt::cli
