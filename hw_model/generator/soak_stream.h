// The soak stream of the gradient block and the FPGA front end (docs/gradient.md, "Soak"): from
// a seed, a random run of frames of random sizes with framing faults and block resets between
// and inside frames, and what the blocks must emit for it. The expected output comes from
// FrontModel (the gradient model, then the edge model); at each reset point the model is
// replaced by a fresh one, as the blocks lose their state. Every clean frame's edges are also
// computed by core and must equal the model's (core = model), or generation fails.
#pragma once
#include <stdint.h>

#include <vector>

#include "vector_format.h"

namespace qt::vec {

// What the generator injected. A frame carries at most one of the frame faults; a reset kind
// names where a reset point was placed.
enum class SoakFault {
    short_row,          // a row y >= 1 ends (tlast) before column W - 1
    long_row,           // a row y >= 1 has no tlast at column W - 1
    early_end,          // the frame stops mid-way; the next start of frame is an error
    height_zero,        // start of frame with s_height = 0
    wide_row0,          // row 0 without tlast by column MAX_WIDTH - 1
    stray,              // a run of beats without tuser between frames
    reset_mid,          // reset before a random beat of a frame (the rest of the frame follows)
    reset_after_error,  // reset right after the beat of a short row, long row or height 0
    reset_last_row,     // reset inside the last row of a frame
    reset_flush,        // reset right after the last beat of a frame (the block is flushing)
    reset_between,      // reset between frames, sometimes two in a row
    count
};
constexpr int kSoakFaultKinds = static_cast<int>(SoakFault::count);
const char* soak_fault_name(SoakFault f);

// What the blocks emit for an input stream with resets: the model's output segment after
// segment.
struct Expected {
    std::vector<OutBeat> out;        // gradient words
    std::vector<EdgeOutBeat> edges;  // the front end's edge beats
    std::vector<ResetPoint> resets;  // in stream order (vector_format.h)
    int errors = 0;                  // error pulses over the whole stream
};

// reset_before: input beat indices, non-decreasing; a reset comes before each (two equal ones:
// two resets in a row). per_frame_threshold: each frame's threshold is
// frame_threshold(threshold, its first gradient word) (edge_model.h).
Expected expected_outputs(const std::vector<InBeat>& in, const std::vector<size_t>& reset_before,
                          int max_width, uint16_t threshold, bool per_frame_threshold = false);

struct SoakStream {
    std::vector<InBeat> in;
    Expected expected;
    // The front end's cfg_threshold: each frame's is frame_threshold(threshold, the frame's
    // first gradient word) (edge_model.h), set between frames as software would.
    uint16_t threshold = 0;
    uint64_t pixels = 0;   // input beats inside frames (all but the stray beats)
    int frames = 0;        // start-of-frame beats
    int clean_frames = 0;  // frames sent whole with no fault and no reset inside
    int core_frames = 0;   // clean frames whose edges core computed and matched the model
    int faults[kSoakFaultKinds] = {};
};

// At least `pixels` input beats, and every fault kind at least once. Widths 1..max_width,
// heights 1..64; the base threshold 1..128 from the seed, each frame's drawn from it. Throws
// std::logic_error when core's edges of a clean frame differ from the model's.
SoakStream make_soak_stream(uint64_t seed, uint64_t pixels, int max_width);

}  // namespace qt::vec
