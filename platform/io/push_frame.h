// Feeds a grey frame to a row-streaming detector of core/ (LineDetector, BoardDetector) as a
// camera would: begin_frame, every row, finish; or first through core's binning stage, for
// frames larger than the detector. Host only.
#pragma once
#include "base/status.h"
#include "gradient/binning.h"
#include "io/grey_image.h"

namespace qt::io {

// The first error of begin_frame (previous_frame_incomplete is not one: the new frame starts
// normally) or push_row, else finish()'s status (ok or capacity_exceeded when it ran).
template <class Detector, class Params>
Status push_frame(Detector& det, const io::GreyImage& img, const Params& params) {
    const uint16_t w = static_cast<uint16_t>(img.width), h = static_cast<uint16_t>(img.height);
    Status s = det.begin_frame(w, h, params);
    if (s == Status::previous_frame_incomplete) s = Status::ok;
    for (uint16_t y = 0; y < h && s == Status::ok; ++y) s = det.push_row(img.row(y), w);
    return s == Status::ok ? det.finish() : s;
}

// img's rows through `bin` with `factor`, as a camera delivers them: row(pixels, width) for each
// of the floor(height / factor) binned rows, in order, returning a Status. The first error of
// the binning stage or of `row`, else ok. The caller begins its stage's frame at
// floor(width / factor) × floor(height / factor) first.
template <uint16_t MaxWidth, class Row>
Status push_binned_rows(BinningStage<MaxWidth>& bin, const io::GreyImage& img, uint8_t factor,
                        Row&& row) {
    const uint16_t w = static_cast<uint16_t>(img.width), h = static_cast<uint16_t>(img.height);
    Status s = bin.begin_frame(w, h, factor);
    if (s == Status::previous_frame_incomplete) s = Status::ok;
    for (uint16_t y = 0; y < h && s == Status::ok; ++y)
        s = bin.push_row(img.row(y), w,
                         [&](uint16_t, const uint8_t* p, uint16_t n) { return row(p, n); });
    return s;
}

}  // namespace qt::io
