// `quadtrack homography A B [OPTIONS]`: the homography mapping image A's pixels into image B's
// by Table I (Harris corners, NCC matches, RANSAC and the least-squares refit), as one JSON line.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace qt::cli {

// args: everything after "homography". Writes one JSON line to `out` (target_json.h) — also
// when no homography was found (then "H" is null and "status" says why) — and errors as one
// line to `err`. Returns 0 when a JSON line was written, 1 for an unreadable image or one over
// 640 × 480, 2 for a bad command line.
int run_homography(const std::vector<std::string>& args, std::FILE* out, std::FILE* err);

std::string homography_usage();

}  // namespace qt::cli
