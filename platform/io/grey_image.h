// An 8-bit grey image owned on the heap: host-side files, pictures and generated scenes only
// (core/ never sees this type; it gets rows).
#pragma once
#include <stdint.h>

#include <cstddef>
#include <vector>

namespace qt::io {

struct GreyImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> pixels;  // row-major, width·height bytes

    GreyImage() = default;
    GreyImage(int w, int h, uint8_t fill = 0)
        : width(w),
          height(h),
          pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}
    uint8_t& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    uint8_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const uint8_t* row(int y) const { return pixels.data() + static_cast<std::size_t>(y) * width; }
};

}  // namespace qt::io
