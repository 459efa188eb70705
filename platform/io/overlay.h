// Drawing on RGB pictures for people to look at (host only): the demo's overlays.
#pragma once
#include <stdint.h>

#include <vector>

#include "io/grey_image.h"

namespace qt::io {

struct Rgb {
    uint8_t r, g, b;
};

struct RgbImage {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  // row-major RGB, 3 bytes per pixel

    // The grey frame, dimmed to `percent` % so that drawings stand out.
    static RgbImage from_grey(const GreyImage& grey, int percent);
    void set(int x, int y, Rgb c);  // ignores points outside
    // A line between two points in pixels (centres at integers), one pixel wide.
    void line(double x1, double y1, double x2, double y2, Rgb c);
    // A ring of radius r pixels around (x, y).
    void ring(double x, double y, double r, Rgb c);
};

}  // namespace qt::io
