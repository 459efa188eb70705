// One grey frame through core's detection chain on the host (CLI, demo, benches): rows are
// pushed as a camera would, through the binning stage when the frame is larger than the
// detector, and the results copied out. Uses one static detector of the chosen capacity: the
// VGA build, or the QVGA build the firmware and the C API run (core/base/capacity.h).
#pragma once
#include <stdint.h>

#include <string>
#include <vector>

#include "io/grey_image.h"
#include "quads/board_detector.h"
#include "tracking/quad_tracker.h"

namespace qt::host {

// The CLI's detectors: the VGA build (frames up to 640 × 480, the default) and the QVGA build
// (320 × 240: what firmware built with qt::Qvga finds in the same frame); larger frames are
// binned to fit.
using HostBoardDetector = BoardDetectorVga;
constexpr int kMaxFrameWidth = 640, kMaxFrameHeight = 480;
enum class DetectorCapacity : uint8_t { vga, qvga };
const char* capacity_name(DetectorCapacity c);
// The largest frame a capacity takes, px.
int max_frame_width(DetectorCapacity c);
int max_frame_height(DetectorCapacity c);

struct DetectResult {
    Status status = Status::ok;      // of the chain (ok or capacity_exceeded when it ran)
    uint16_t width = 0, height = 0;  // the frame the coordinates below refer to, px
    uint8_t bin = 1;                 // the input was binned by this factor (binning.h)
    std::vector<Segment> lines;      // clustered lines, ends joined at corners
    std::vector<Quad> quads;         // best first
    LineStats line_stats;
    QuadStats quad_stats;
};

// Runs the chain on `frame` binned by `bin` (1: as it is) with the detector of `capacity`: the
// result is in the binned frame's pixels (width, height its size; to_input_pixels() maps it
// back). Returns false (with result.status saying why) on an error status, bad_size when the
// binned frame is empty or larger than the capacity's frame; capacity_exceeded still returns
// true with the results found.
// window: tracking mode's bands for this frame (in the binned frame's pixels), or null.
bool detect_board(const io::GreyImage& frame, const BoardParams& params, DetectResult& result,
                  uint8_t bin = 1, DetectorCapacity capacity = DetectorCapacity::vga,
                  BandWindow* window = nullptr);

// The share of a tracked board's perimeter with edge evidence of each side's polarity in the
// last frame detect_board ran with `capacity` (its edge list; the board in that frame's binned
// pixels), [0, 1]: what detect's "score" measures for its quadrangles (quad_refine.h), 0
// without a board.
q16_16 evidence_share(const TrackedQuad& quad, const RefineParams& params,
                      DetectorCapacity capacity);

// The bin factor for a width × height frame: `requested` (1..kMaxBinFactor) when not 0,
// otherwise the smallest that brings the frame within the capacity's frame (640 × 480 for
// vga, 320 × 240 for qvga). Returns 0 with one line in `error` when none does, or the
// requested one leaves the frame larger than that or empty.
uint8_t choose_bin(int width, int height, uint8_t requested, std::string& error,
                   DetectorCapacity capacity = DetectorCapacity::vga);

// A coordinate in the binned frame's pixels -> the input's: binned pixel u is input pixel
// N·u + (N − 1)/2 (binning.h).
inline double input_pixel(double u, uint8_t bin) { return bin * u + (bin - 1) / 2.0; }
// A line in the binned frame's pixels -> the same line in the input's (x = N·u + (N − 1)/2):
// end points and closest point mapped, theta kept unless rho's sign turns (rho >= 0 always).
Segment to_input_pixels(const Segment& s, uint8_t bin);
// Every coordinate of `result` in the input's pixels, width and height the input's (an input
// width × height, binned by result.bin).
void to_input_pixels(DetectResult& result, int input_width, int input_height);
void to_input_pixels(TrackedQuad& quad, uint8_t bin);

}  // namespace qt::host
