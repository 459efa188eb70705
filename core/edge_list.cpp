#include "edge_list.h"

namespace qt {

Status EdgeList::begin_frame(uint16_t height) {
    count_ = 0;
    dropped_ = 0;
    next_row_ = 0;
    current_y_ = 0;
    height_ = 0;
    if (height == 0 || height > max_rows_) return Status::bad_size;
    height_ = height;
    return Status::ok;
}

void EdgeList::begin_row(uint16_t y) {
    while (next_row_ <= y && next_row_ < height_) row_start_[next_row_++] = count_;
    current_y_ = y;
}

bool EdgeList::push(uint16_t x, uint32_t dir, int32_t delta16) {
    if (count_ == capacity_) {
        ++dropped_;
        return false;
    }
    points_[count_++] = ep::make(x, current_y_, dir, delta16);
    return true;
}

void EdgeList::end_frame() {
    while (next_row_ <= height_) row_start_[next_row_++] = count_;
}

int32_t EdgeList::find(int32_t x, int32_t y) const {
    if (y < 0 || y >= static_cast<int32_t>(height_) || x < 0) return -1;
    uint32_t lo = row_start_[y], hi = row_start_[y + 1];  // search [lo, hi)
    const uint32_t ux = static_cast<uint32_t>(x);
    while (lo < hi) {
        const uint32_t mid = (lo + hi) / 2;
        const uint32_t mx = ep::x(points_[mid]);
        if (mx == ux) return static_cast<int32_t>(mid);
        if (mx < ux) lo = mid + 1;
        else hi = mid;
    }
    return -1;
}

}  // namespace qt
