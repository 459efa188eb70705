// Feeds a grey frame to a row-streaming detector of core/ (LineDetector, BoardDetector) as a
// camera would: begin_frame, every row, finish. Host only.
#pragma once
#include "base/status.h"
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

}  // namespace qt::io
