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

uint32_t EdgeList::lower_bound(uint32_t key, uint32_t y) const {
    // Halving without a data-dependent branch (a conditional move): the rows are short and the
    // keys random, so a branch would mispredict about every other step.
    uint32_t first = row_start_[y], n = row_start_[y + 1] - first;
    if (n == 0) return first;
    while (n > 1) {
        const uint32_t half = n / 2;
        first = ep::x(points_[first + half - 1]) < key ? first + half : first;
        n -= half;
    }
    return first + (ep::x(points_[first]) < key ? 1u : 0u);
}

int32_t EdgeList::find(int32_t x, int32_t y) const {
    if (y < 0 || y >= static_cast<int32_t>(height_) || x < 0) return -1;
    const uint32_t i = lower_bound(static_cast<uint32_t>(x), static_cast<uint32_t>(y));
    return i < row_start_[y + 1] && ep::x(points_[i]) == static_cast<uint32_t>(x) ? static_cast<int32_t>(i) : -1;
}

void EdgeList::span(int32_t x_lo, int32_t x_hi, int32_t y, uint32_t* first, uint32_t* end) const {
    *first = *end = 0;
    if (y < 0 || y >= static_cast<int32_t>(height_) || x_hi < 0 || x_hi < x_lo) return;
    uint32_t i = lower_bound(x_lo < 0 ? 0u : static_cast<uint32_t>(x_lo), static_cast<uint32_t>(y));
    *first = i;
    const uint32_t row_end = row_start_[y + 1];
    while (i < row_end && ep::x(points_[i]) <= static_cast<uint32_t>(x_hi)) ++i;
    *end = i;
}

}  // namespace qt
