// Bit-accurate, beat-level model of hdl/rtl/edge_stage.v, the FPGA's edge stage: gradient beats
// in (the gradient block's output, vector_format.h's OutBeat), edge beats out (edge_beat.h),
// with none of its clocks. It decides each pixel as soon as the block can (when the word to its
// lower right has arrived), so before a reset the block has emitted a prefix of what the model
// emits. Written from the block's structure (the eight neighbours in a ring, docs/gradient.md), not
// from core's edge stage, which the tests compare with it.
#pragma once
#include <stdint.h>

#include <vector>

#include "gradient_model.h"
#include "vector_format.h"

namespace qt::vec {

// The soak's thresholds drawn per frame (tb_front.v's +vary_threshold computes the same): a
// frame's cfg_threshold, 1..128, is a hash of `base` and the frame's first gradient word, so the
// bench and the model agree on it without counting frames across resets and faults.
inline uint16_t frame_threshold(uint16_t base, uint32_t first_word) {
    const uint32_t h = first_word * 0x9E3779B1u + base;
    return static_cast<uint16_t>(1 + (h >> 25));
}

class EdgeModel {
public:
    // threshold: cfg_threshold, L1 magnitude in grey levels (read at each start of frame);
    // per_frame: frame_threshold(threshold, the frame's first word) instead.
    EdgeModel(int max_width, uint16_t threshold, bool per_frame = false);

    // One gradient beat accepted; appends the edge beats it makes the block emit. The input must
    // be a stream the gradient block can emit (frames from tuser to eof, rows of one width up to
    // max_width); anything else throws std::logic_error.
    void push(const OutBeat& beat, std::vector<EdgeOutBeat>& out);

private:
    // Decides pixel x of `center` (row y) with its neighbour rows; appends its point if it is one.
    void decide(int x, int y, const std::vector<uint16_t>& above,
                const std::vector<uint16_t>& center, const std::vector<uint8_t>& center_dir,
                const std::vector<uint16_t>& below, std::vector<EdgeOutBeat>& out);
    void emit(edge_beat b, bool last, std::vector<EdgeOutBeat>& out);

    int max_width_;
    uint16_t cfg_threshold_, threshold_ = 0;
    bool per_frame_;
    bool active_ = false, broken_ = false, sof_due_ = true;
    int width_ = 0, x_ = 0, y_ = 0;  // y_: row of the arriving words
    // Magnitudes of rows y - 2, y - 1, y (the arriving one) and the direction bins of rows
    // y - 1 and y; zero rows for "outside the frame".
    std::vector<uint16_t> above_, center_, below_, zero_;
    std::vector<uint8_t> center_dir_, below_dir_;
};

// The FPGA front end (hdl/rtl/frontend.v): the gradient block, then the edge stage. Heights above
// kFrontMaxRows are refused as a height of 0 is (the edge point's y has 11 bits).
constexpr int kFrontMaxRows = 2048;

class FrontModel {
public:
    FrontModel(int max_width, uint16_t threshold, bool per_frame_threshold = false)
        : gradient_(max_width), edges_(max_width, threshold, per_frame_threshold) {}
    void push(const InBeat& beat, std::vector<OutBeat>& words, std::vector<EdgeOutBeat>& edges);
    int errors() const { return gradient_.errors(); }

private:
    GradientModel gradient_;
    EdgeModel edges_;
    std::vector<OutBeat> scratch_;
};

}  // namespace qt::vec
