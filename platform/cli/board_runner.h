// One grey frame through core's detection chain on the host (CLI, demo, benches): rows are
// pushed as a camera would, the results copied out. Uses one static VGA-capacity detector.
#pragma once
#include <stdint.h>

#include <vector>

#include "io/grey_image.h"
#include "quads/board_detector.h"

namespace qt::cli {

// The CLI's detector: frames up to 640 × 480.
using HostBoardDetector = BoardDetectorVga;
constexpr int kMaxFrameWidth = 640, kMaxFrameHeight = 480;

struct DetectResult {
    Status status = Status::ok;  // of the chain (ok or capacity_exceeded when it ran)
    uint16_t width = 0, height = 0;
    std::vector<Segment> lines;  // clustered lines, ends joined at corners
    std::vector<Quad> quads;     // best first
    LineStats line_stats;
    QuadStats quad_stats;
};

// Runs the chain on `frame`. Returns false (with result.status saying why) on an error status;
// capacity_exceeded still returns true with the results found.
bool detect_board(const io::GreyImage& frame, const BoardParams& params, DetectResult& result);

}  // namespace qt::cli
