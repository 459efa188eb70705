#include "lines/edge_list.h"

#include "base/precondition.h"

namespace qt {

Status EdgeList::begin_frame(uint16_t height) {
    count_ = 0;
    dropped_ = 0;
    next_row_ = 0;
    current_y_ = 0;
    height_ = 0;
    floor_ = 0;
    thin_below_ = 0;
    if (height == 0 || height > max_rows_) return Status::bad_size;
    height_ = height;
    return Status::ok;
}

void EdgeList::begin_row(uint16_t y) {
    QT_PRECONDITION(y < height_ && (next_row_ == 0 || y >= next_row_));  // in order, each once
    while (next_row_ <= y && next_row_ < height_) row_start_[next_row_++] = count_;
    current_y_ = y;
}

bool EdgeList::push(uint16_t x, uint32_t dir, int32_t delta16, uint32_t magnitude) {
    if (count_ == capacity_) drop_weakest();
    const bool refused = magnitude < floor_ || count_ == capacity_;
    const edge_point p = refused ? 0u : ep::make(x, current_y_, dir, delta16);
    if (refused || (magnitude < thin_below_ && ep::thinned_out(p))) {
        ++dropped_;
        return false;
    }
    strength_[count_] = static_cast<uint8_t>(magnitude > 510u ? 255u : magnitude / 2u);
    points_[count_++] = p;
    return true;
}

void EdgeList::drop_weakest() {
    // Strengths are magnitude / 2: the floor and the thinning level move in steps of 2 grey
    // levels. even[s]: the points of strength s on an even step (thinning keeps them).
    uint16_t histogram[256] = {}, even[256] = {};
    uint32_t top = 0;
    for (uint32_t i = 0; i < count_; ++i) {
        const uint32_t st = strength_[i];
        ++histogram[st];
        even[st] = static_cast<uint16_t>(even[st] + !ep::thinned_out(points_[i]));
        top = st > top ? st : top;
    }
    const uint32_t keep_at_most = capacity_ - capacity_ / 4u;
    // whole: the lowest strength whose points, all of them, fill a quarter of what is kept;
    // s: the lowest from which the even points below `whole` fill the rest. Neither moves
    // down (no point below the old floor was kept, and none below the old level on an odd
    // step).
    uint32_t kept = 0, whole = 256;
    while (whole > thin_below_ / 2u && kept + histogram[whole - 1] <= keep_at_most / 4u)
        kept += histogram[--whole];
    uint32_t s = whole;
    while (s > floor_ / 2u && kept + even[s - 1] <= keep_at_most) kept += even[--s];
    if (s > top) {
        // The strongest value alone fills more than 3/4: no point can be called weaker than the
        // others. They all stay, the floor rises above them, and push() refuses what follows
        // (a stronger point comes back here, so this happens at most 256 times a frame).
        floor_ = static_cast<uint16_t>(2u * (top + 1u));
        return;
    }
    floor_ = static_cast<uint16_t>(2u * s);
    thin_below_ = static_cast<uint16_t>(2u * whole);
    // Rows begun so far: 0 .. next_row_ - 1; the last of them runs to count_.
    uint32_t write = 0;
    for (uint32_t y = 0; y < next_row_; ++y) {
        const uint32_t end = y + 1 < next_row_ ? row_start_[y + 1] : count_;
        const uint32_t begin = row_start_[y];
        row_start_[y] = static_cast<uint16_t>(write);
        for (uint32_t i = begin; i < end; ++i) {
            if (strength_[i] < s || (strength_[i] < whole && ep::thinned_out(points_[i]))) continue;
            points_[write] = points_[i];
            strength_[write] = strength_[i];
            ++write;
        }
    }
    dropped_ += count_ - write;
    count_ = static_cast<uint16_t>(write);
}

uint32_t EdgeList::hysteresis(uint16_t high, uint8_t* scratch, uint32_t scratch_bytes) {
    if (scratch_bytes / 2u < count_) return 0;
    // Marked points (state 3, unused before PPHT) go on the stack once each, as two bytes.
    constexpr uint32_t kKept = 3;
    uint32_t top = 0;
    auto push = [&](uint32_t i) {
        points_[i] = ep::with_state(points_[i], kKept);
        scratch[2 * top] = static_cast<uint8_t>(i & 0xFFu);
        scratch[2 * top + 1] = static_cast<uint8_t>(i >> 8);
        ++top;
    };
    for (uint32_t i = 0; i < count_; ++i)
        if (2u * strength_[i] >= high && ep::state(points_[i]) != kKept) push(i);
    while (top > 0) {
        --top;
        const uint32_t i = scratch[2 * top] | (uint32_t{scratch[2 * top + 1]} << 8);
        const int32_t x = static_cast<int32_t>(ep::x(points_[i]));
        const int32_t y = static_cast<int32_t>(ep::y(points_[i]));
        for (int32_t dy = -1; dy <= 1; ++dy) {
            uint32_t first = 0, end = 0;
            span(x - 1, x + 1, y + dy, &first, &end);
            for (uint32_t j = first; j < end; ++j)
                if (ep::state(points_[j]) != kKept) push(j);
        }
    }
    // Keep the marked points, rows in order, states back to fresh.
    uint32_t write = 0;
    for (uint32_t y = 0; y < height_; ++y) {
        const uint32_t begin = row_start_[y], end = row_start_[y + 1];
        row_start_[y] = static_cast<uint16_t>(write);
        for (uint32_t i = begin; i < end; ++i) {
            if (ep::state(points_[i]) != kKept) continue;
            points_[write] = ep::with_state(points_[i], ep::kFresh);
            strength_[write] = strength_[i];
            ++write;
        }
    }
    const uint32_t removed = count_ - write;
    row_start_[height_] = static_cast<uint16_t>(write);
    count_ = static_cast<uint16_t>(write);
    return removed;
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
    return i < row_start_[y + 1] && ep::x(points_[i]) == static_cast<uint32_t>(x)
               ? static_cast<int32_t>(i)
               : -1;
}

int32_t EdgeList::search_and_probe(int32_t x, int32_t y, RowProbe& probe, bool forward) const {
    // Keys past the largest x are outside too.
    if (static_cast<uint32_t>(y) >= height_ || static_cast<uint32_t>(x) > ep::kMaxCoordinate)
        return -1;
    const uint32_t key = static_cast<uint32_t>(x);
    const uint32_t row_begin = row_start_[y], row_end = row_start_[y + 1];
    uint32_t i = 0;
    bool settled = false;
    if (probe.y == static_cast<uint32_t>(y)) {
        // At most kSteps moves from the probe's point, forward or back, then the binary
        // search: a probe far off costs no more than a few compares on top of find().
        constexpr uint32_t kSteps = 4;
        uint32_t steps = 0;
        i = probe.at;
        if (i < row_end && x_at(i) < key) {
            do ++i;
            while (i < row_end && x_at(i) < key && ++steps < kSteps);
            settled = i == row_end || x_at(i) >= key;
        } else {
            while (i > row_begin && x_at(i - 1) >= key && steps < kSteps) --i, ++steps;
            settled = i == row_begin || x_at(i - 1) < key;
        }
    }
    if (!settled) i = lower_bound(key, static_cast<uint32_t>(y));
    // i: the first point at or after key. The probe keeps the pair about key; on a hit, the
    // pair from the hit on in the expected way.
    const bool hit = i < row_end && x_at(i) == key;
    const uint32_t at = hit && forward ? i + 1u : i;
    probe.y = static_cast<uint16_t>(y);
    probe.at = static_cast<uint16_t>(at);
    probe.lo1 = static_cast<uint16_t>(at > row_begin ? x_at(at - 1u) + 1u : 0u);
    probe.hi = static_cast<uint16_t>(at < row_end ? x_at(at) : ep::kMaxCoordinate + 1u);
    return hit ? static_cast<int32_t>(i) : -1;
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
