#include "lines/edge_beat.h"

namespace qt {

void EdgeBeatFeed::begin_frame(EdgeList& list, uint16_t width, uint16_t height,
                               uint16_t edge_threshold, BandWindow* window) {
    list_ = &list;
    window_ = window;
    width_ = width;
    height_ = height;
    threshold_ = edge_threshold;
    last_x_ = -1;
    row_ = -1;
    list_row_ = -1;
    done_ = false;
    failed_ = false;
}

bool EdgeBeatFeed::in_bands(int32_t x, int32_t y) {
    if (window_ == nullptr) return true;
    const ColumnSpan* spans = nullptr;
    const uint8_t n = window_->row(y, &spans);
    for (uint8_t i = 0; i < n; ++i)
        if (x >= spans[i].begin && x < spans[i].end) return true;
    return false;
}

Status EdgeBeatFeed::push(const uint8_t* beats, uint32_t count, uint32_t* used) {
    *used = 0;
    if (list_ == nullptr || done_) return Status::not_in_frame;
    if (failed_) return Status::bad_stream;
    for (uint32_t i = 0; i < count; ++i) {
        const edge_beat b = eb::load(beats, i);
        *used = i + 1;
        if (eb::is_trailer(b)) {
            const edge_beat known = eb::trailer(eb::last_x(b), eb::last_y(b), eb::broken(b));
            if (b != known || eb::broken(b) || eb::last_x(b) + 1u != width_ ||
                eb::last_y(b) + 1u != height_) {
                failed_ = true;
                return Status::bad_stream;
            }
            list_->end_frame();
            done_ = true;
            return Status::ok;
        }
        const edge_point p = eb::point_of(b);
        const int32_t x = static_cast<int32_t>(ep::x(p)), y = static_cast<int32_t>(ep::y(p));
        // Raster order inside the frame: rows in order, columns increasing within a row.
        if (b != eb::point(ep::x(p), ep::y(p), ep::dir(p), ep::delta16(p), eb::magnitude(b)) ||
            ep::state(p) != ep::kFresh || x >= width_ || y >= height_ || y < row_ ||
            (y == row_ && x <= last_x_)) {
            failed_ = true;
            return Status::bad_stream;
        }
        row_ = y;
        last_x_ = x;
        if (eb::magnitude(b) < threshold_ || !in_bands(x, y)) continue;
        if (y != list_row_) list_->begin_row(static_cast<uint16_t>(y));
        list_row_ = y;
        list_->push(static_cast<uint16_t>(x), ep::dir(p), ep::delta16(p), eb::magnitude(b));
    }
    return Status::ok;
}

}  // namespace qt
