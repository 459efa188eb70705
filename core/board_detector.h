// The detection chain of one frame: the lines stage (line_detector.h), then the quadrangle
// rules (quad_detector.h) on its clustered lines. All memory inside, fixed at compile time.
//
//   static qt::BoardDetectorQvga det;
//   det.begin_frame(320, 240, params);
//   for each camera row: det.push_row(row, 320);        // or push_gradient_row(words, 320)
//   det.finish();                              // lines, then quadrangles
//   det.quads()[0 .. det.quad_count()), best first; det.lines() for the lines stage
#pragma once
#include <stdint.h>

#include "line_detector.h"
#include "quad_detector.h"

namespace qt {

struct BoardParams {
    LineParams lines;
    QuadParams quads;
};

template <class Lines, uint16_t PairCapacity, uint16_t MaxQuads>
class BoardDetector {
public:
    static constexpr uint32_t ram_bytes() { return sizeof(BoardDetector); }
    static constexpr uint32_t quad_bytes() {
        return sizeof(LinePair) * PairCapacity + sizeof(SinCos) * Lines::max_lines() + sizeof(Quad) * MaxQuads;
    }
    static constexpr uint16_t max_quads() { return MaxQuads; }

    Status begin_frame(uint16_t width, uint16_t height, const BoardParams& params) {
        params_ = params;
        quad_count_ = 0;
        quad_stats_ = QuadStats{};
        return lines_.begin_frame(width, height, params.lines);
    }
    Status push_row(const uint8_t* pixels, uint16_t length) { return lines_.push_row(pixels, length); }
    Status push_gradient_row(const gradient_word* words, uint16_t width) {
        return lines_.push_gradient_row(words, width);
    }

    // After the last row. Errors of the lines stage are returned as they are; otherwise the
    // quadrangles are searched and capacity_exceeded reports a capacity that filled in either
    // stage (the results are valid, the stats say what was cut).
    Status finish() {
        return finish([](FinishStage) {});
    }
    // The same, calling mark(stage) as each stage ends (line_detector.h's FinishStage).
    template <class Mark>
    Status finish(Mark&& mark) {
        const Status l = lines_.finish(mark);
        if (l != Status::ok && l != Status::capacity_exceeded) return l;
        const Status q = detect_quads(lines_.lines(), lines_.line_count(), lines_.width(), lines_.height(), params_.quads, pairs_,
                                      PairCapacity, normals_, quads_, MaxQuads, &quad_count_, &quad_stats_);
        mark(FinishStage::quads);
        if (q != Status::ok && q != Status::capacity_exceeded) return q;
        return l == Status::ok && q == Status::ok ? Status::ok : Status::capacity_exceeded;
    }

    const Lines& lines() const { return lines_; }
    const Quad* quads() const { return quads_; }
    uint16_t quad_count() const { return quad_count_; }
    const QuadStats& quad_stats() const { return quad_stats_; }

private:
    Lines lines_;
    LinePair pairs_[PairCapacity] = {};
    SinCos normals_[Lines::max_lines()] = {};
    Quad quads_[MaxQuads] = {};
    BoardParams params_;
    QuadStats quad_stats_;
    uint16_t quad_count_ = 0;
};

// QVGA: the QVGA lines stage, 128 parallel pairs, the best 4 quadrangles.
using BoardDetectorQvga = BoardDetector<LineDetectorQvga, 128, 4>;
// VGA: the VGA lines stage, 256 parallel pairs, the best 4 quadrangles.
using BoardDetectorVga = BoardDetector<LineDetectorVga, 256, 4>;

}  // namespace qt
