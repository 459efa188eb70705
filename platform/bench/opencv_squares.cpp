// The squares.cpp recipe on one grey channel; see opencv_squares.h.
#include "bench/opencv_squares.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace qt::bench {
namespace {

// |cos| of the angle at `apex` between the rays to `a` and `b` (0 for a right angle).
double abs_corner_cosine(const cv::Point& a, const cv::Point& apex, const cv::Point& b) {
    const double ux = a.x - apex.x, uy = a.y - apex.y;
    const double vx = b.x - apex.x, vy = b.y - apex.y;
    const double norm = std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
    if (norm <= 0) return 1.0;  // coincident vertices: as bad as a straight angle
    return std::fabs(ux * vx + uy * vy) / norm;
}

// Largest |cos| over all four corners of the 4-gon q.
double max_abs_cosine(const std::vector<cv::Point>& q) {
    double worst = 0;
    for (std::size_t i = 0; i < 4; ++i)
        worst = std::max(worst, abs_corner_cosine(q[(i + 3) % 4], q[i], q[(i + 1) % 4]));
    return worst;
}

// Corners anti-clockwise as seen on screen (y down: negative shoelace sum), starting with the
// smallest x + y (ties: the smaller x).
std::array<scene::Point2, 4> ordered(const std::vector<cv::Point>& q) {
    std::array<scene::Point2, 4> c;
    for (std::size_t i = 0; i < 4; ++i)
        c[i] = {static_cast<double>(q[i].x), static_cast<double>(q[i].y)};
    double twice_area = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        const scene::Point2& a = c[i];
        const scene::Point2& b = c[(i + 1) % 4];
        twice_area += a.x * b.y - b.x * a.y;
    }
    if (twice_area > 0) std::reverse(c.begin(), c.end());  // clockwise on screen → flip
    std::size_t first = 0;
    for (std::size_t i = 1; i < 4; ++i) {
        const double s = c[i].x + c[i].y, best = c[first].x + c[first].y;
        if (s < best || (s == best && c[i].x < c[first].x)) first = i;
    }
    std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(first), c.end());
    return c;
}

// The 4-gon area (shoelace), px².
double area(const std::array<scene::Point2, 4>& c) {
    double twice = 0;
    for (std::size_t i = 0; i < 4; ++i)
        twice += c[i].x * c[(i + 1) % 4].y - c[(i + 1) % 4].x * c[i].y;
    return std::fabs(twice) / 2;
}

}  // namespace

std::vector<std::array<scene::Point2, 4>> opencv_squares(const io::GreyImage& grey,
                                                         const SquaresParams& p) {
    std::vector<std::array<scene::Point2, 4>> found;
    // pyrDown needs a destination of at least 1×1; the pixel buffer must match the size.
    if (grey.width < 2 || grey.height < 2 ||
        grey.pixels.size() !=
            static_cast<std::size_t>(grey.width) * static_cast<std::size_t>(grey.height))
        return found;
    const int levels = std::max(1, p.threshold_levels);

    const cv::Mat src(grey.height, grey.width, CV_8UC1, const_cast<uint8_t*>(grey.pixels.data()));
    // Noise suppression of the sample: down to half size and back up.
    cv::Mat half, smooth;
    cv::pyrDown(src, half, cv::Size(grey.width / 2, grey.height / 2));
    cv::pyrUp(half, smooth, src.size());

    cv::Mat mask;
    std::vector<std::vector<cv::Point>> contours;
    std::vector<cv::Point> poly;
    for (int l = 0; l < levels; ++l) {
        if (l == 0) {
            // Edges catch boards whose grey straddles every threshold; the dilation closes gaps.
            cv::Canny(smooth, mask, 0, p.canny_high, 5);
            cv::dilate(mask, mask, cv::Mat(), cv::Point(-1, -1));
        } else {
            cv::compare(smooth, cv::Scalar((l + 1) * 255 / levels), mask, cv::CMP_GE);
        }
        cv::findContours(mask, contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
        for (const std::vector<cv::Point>& contour : contours) {
            cv::approxPolyDP(contour, poly, p.approx_epsilon * cv::arcLength(contour, true), true);
            if (poly.size() != 4) continue;
            if (std::fabs(cv::contourArea(poly)) <= p.min_area_px2) continue;
            if (!cv::isContourConvex(poly)) continue;
            if (max_abs_cosine(poly) >= p.max_cosine) continue;
            found.push_back(ordered(poly));
        }
    }
    return found;
}

bool opencv_best_square(const io::GreyImage& grey, std::array<scene::Point2, 4>& corners,
                        const SquaresParams& p) {
    const std::vector<std::array<scene::Point2, 4>> all = opencv_squares(grey, p);
    const double x_max = grey.width - 2.0, y_max = grey.height - 2.0;
    const std::array<scene::Point2, 4>* best = nullptr;
    double best_area = -1;
    for (const std::array<scene::Point2, 4>& q : all) {
        const bool on_frame = std::any_of(q.begin(), q.end(), [&](const scene::Point2& c) {
            return c.x <= 1 || c.y <= 1 || c.x >= x_max || c.y >= y_max;
        });
        if (on_frame) continue;
        const double a = area(q);
        if (a > best_area) best_area = a, best = &q;
    }
    if (!best) return false;
    corners = *best;
    return true;
}

}  // namespace qt::bench
