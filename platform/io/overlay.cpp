#include "io/overlay.h"

#include <cmath>

namespace qt::io {

RgbImage RgbImage::from_grey(const GreyImage& grey, int percent) {
    RgbImage img;
    img.width = grey.width;
    img.height = grey.height;
    img.pixels.reserve(grey.pixels.size() * 3);
    for (uint8_t v : grey.pixels)
        for (int c = 0; c < 3; ++c) img.pixels.push_back(static_cast<uint8_t>(v * percent / 100));
    return img;
}

void RgbImage::set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    uint8_t* p = &pixels[3 * (static_cast<size_t>(y) * width + x)];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
}

void RgbImage::line(double x1, double y1, double x2, double y2, Rgb c) {
    const int steps =
        static_cast<int>(std::ceil(std::max(std::fabs(x2 - x1), std::fabs(y2 - y1)))) + 1;
    for (int i = 0; i <= steps; ++i) {
        const double t = static_cast<double>(i) / steps;
        set(static_cast<int>(std::lround(x1 + (x2 - x1) * t)),
            static_cast<int>(std::lround(y1 + (y2 - y1) * t)), c);
    }
}

void RgbImage::ring(double x, double y, double r, Rgb c) {
    const int steps = static_cast<int>(std::ceil(8 * r)) + 8;
    for (int i = 0; i < steps; ++i) {
        const double a = 6.283185307179586 * i / steps;
        set(static_cast<int>(std::lround(x + r * std::cos(a))),
            static_cast<int>(std::lround(y + r * std::sin(a))), c);
    }
}

}  // namespace qt::io
