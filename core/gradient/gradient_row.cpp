#include "gradient/gradient_stage.h"

namespace qt {

namespace {

inline gradient_word word_at(const uint8_t* above, const uint8_t* center, const uint8_t* below,
                             uint16_t left, uint16_t x, uint16_t right) {
    return make_gradient_word(static_cast<int32_t>(center[right]) - center[left],
                              static_cast<int32_t>(below[x]) - above[x]);
}

}  // namespace

void gradient_row(const uint8_t* above, const uint8_t* center, const uint8_t* below, uint16_t width,
                  gradient_word* out) {
    const uint16_t last = static_cast<uint16_t>(width - 1u);
    if (width == 1) {
        out[0] = word_at(above, center, below, 0, 0, 0);
        return;
    }
    out[0] = word_at(above, center, below, 0, 0, 1);
    // Interior: no border tests; a plain counted loop the compiler can vectorise.
    const int n = static_cast<int>(last);
    for (int x = 1; x < n; ++x)
        out[x] = make_gradient_word(static_cast<int32_t>(center[x + 1]) - center[x - 1],
                                    static_cast<int32_t>(below[x]) - above[x]);
    out[last] = word_at(above, center, below, static_cast<uint16_t>(last - 1u), last, last);
}

}  // namespace qt
