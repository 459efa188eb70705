#include "gradient/gradient_stage.h"

namespace qt {

namespace {

// Pack(gx, gy) of pixel x, with its left and right neighbours' indices (borders replicated).
template <gradient_word (*Pack)(int32_t, int32_t)>
inline gradient_word word_at(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                             uint16_t left, uint16_t x, uint16_t right) {
    return Pack(static_cast<int32_t>(center[right]) - center[left],
                static_cast<int32_t>(below[x]) - above[x]);
}

template <gradient_word (*Pack)(int32_t, int32_t)>
void row_of(const uint8_t* above, const uint8_t* center, const uint8_t* below, uint16_t width,
            gradient_word* out) {
    const uint16_t last = static_cast<uint16_t>(width - 1u);
    if (width == 1) {
        out[0] = word_at<Pack>(above, center, below, 0, 0, 0);
        return;
    }
    out[0] = word_at<Pack>(above, center, below, 0, 0, 1);
    // Interior: no border tests; a plain counted loop the compiler can vectorise.
    const int n = static_cast<int>(last);
    for (int x = 1; x < n; ++x)
        out[x] = Pack(static_cast<int32_t>(center[x + 1]) - center[x - 1],
                      static_cast<int32_t>(below[x]) - above[x]);
    out[last] = word_at<Pack>(above, center, below, static_cast<uint16_t>(last - 1u), last, last);
}

}  // namespace

void gradient_row(const uint8_t* above, const uint8_t* center, const uint8_t* below, uint16_t width,
                  gradient_word* out) {
    row_of<make_gradient_word>(above, center, below, width, out);
}

void gradient_row_xy(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                     uint16_t width, gradient_word* out) {
    row_of<make_gradient_word_xy>(above, center, below, width, out);
}

}  // namespace qt
