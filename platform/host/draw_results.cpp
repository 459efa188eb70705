#include "host/draw_results.h"

#include <cmath>

#include "io/error_line.h"
#include "io/image_io.h"
#include "io/png_writer.h"

namespace qt::host {

namespace {

double px(q16_16 v) { return v.raw / 65536.0; }

constexpr io::Rgb kLine{255, 50, 50}, kDetected{60, 255, 60}, kPredicted{255, 140, 0},
    kOther{255, 230, 0}, kFirstCorner{0, 230, 255}, kCorner{255, 230, 0};

void corner_rings(io::RgbImage& pic, const Point16 (&corners)[4]) {
    for (int i = 0; i < 4; ++i) {
        const io::Rgb colour = i == 0 ? kFirstCorner : kCorner;
        pic.ring(px(corners[i].x), px(corners[i].y), 4, colour);
        pic.ring(px(corners[i].x), px(corners[i].y), 5, colour);
    }
}

}  // namespace

void side_line(io::RgbImage& pic, Point16 a, Point16 b, io::Rgb colour, bool dashed) {
    const double x1 = px(a.x), y1 = px(a.y), x2 = px(b.x), y2 = px(b.y);
    const double len = std::hypot(x2 - x1, y2 - y1);
    if (len < 1) return;
    const double ux = (x2 - x1) / len, uy = (y2 - y1) / len;
    const double on = dashed ? 8 : len, period = dashed ? 14 : len + 1;
    for (double t = 0; t < len; t += period) {
        const double e = std::fmin(t + on, len);
        for (double o : {-0.5, 0.5})
            pic.line(x1 + ux * t - uy * o, y1 + uy * t + ux * o, x1 + ux * e - uy * o,
                     y1 + uy * e + ux * o, colour);
    }
}

void draw_lines(io::RgbImage& pic, const std::vector<Segment>& lines) {
    for (const Segment& l : lines) pic.line(px(l.x1), px(l.y1), px(l.x2), px(l.y2), kLine);
}

void draw_quads(io::RgbImage& pic, const std::vector<Quad>& quads) {
    for (size_t k = quads.size(); k-- > 0;) {  // the best last, on top
        const Quad& q = quads[k];
        for (int i = 0; i < 4; ++i) {
            if (k == 0)
                side_line(pic, q.corners[i], q.corners[(i + 1) & 3], kDetected, false);
            else
                pic.line(px(q.corners[i].x), px(q.corners[i].y), px(q.corners[(i + 1) & 3].x),
                         px(q.corners[(i + 1) & 3].y), kOther);
        }
        if (k == 0) corner_rings(pic, q.corners);
    }
}

void draw_tracked(io::RgbImage& pic, const TrackedQuad& t) {
    if (t.state == TrackState::none) return;
    for (int i = 0; i < 4; ++i) {
        const bool detected = (t.detected >> i) & 1;
        side_line(pic, t.corners[i], t.corners[(i + 1) & 3], detected ? kDetected : kPredicted,
                  !detected);
    }
    corner_rings(pic, t.corners);
}

void draw_target(io::RgbImage& pic, double x, double y, int w, int h, TargetState state) {
    const bool seen = state == TargetState::measured || state == TargetState::reacquired;
    const io::Rgb colour = seen                         ? kDetected
                           : state == TargetState::lost ? io::Rgb{255, 40, 40}
                                                        : kPredicted;
    const auto at = [](double v) { return q16_16::from_raw(static_cast<int32_t>(v * 65536.0)); };
    const double x0 = x - (w - 1) / 2.0, y0 = y - (h - 1) / 2.0, x1 = x0 + w - 1, y1 = y0 + h - 1;
    const Point16 box[4] = {{at(x0), at(y0)}, {at(x1), at(y0)}, {at(x1), at(y1)}, {at(x0), at(y1)}};
    for (int i = 0; i < 4; ++i) side_line(pic, box[i], box[(i + 1) & 3], colour, !seen);
    pic.line(x - 3, y, x + 3, y, colour);
    pic.line(x, y - 3, x, y + 3, colour);
}

bool draw_pattern_ok(const std::string& pattern, std::string& why) {
    std::string name;
    if (io::numbered_file(pattern, 0, name)) return true;
    why = "'" + pattern + "' needs one %d or %0Nd (N 1..9) for the frame number";
    return false;
}

bool frame_picture(const std::string& pattern, uint32_t every, int k, std::string* file) {
    return !pattern.empty() && static_cast<uint32_t>(k) % every == 0 &&
           io::numbered_file(pattern, k, *file);
}

bool write_picture(const std::string& path, const io::RgbImage& pic, std::FILE* err,
                   const char* who) {
    std::string error;
    if (io::write_png(path, pic.width, pic.height, 3, pic.pixels, error)) return true;
    io::print_error_line(err, "%s: --draw: %s", who, error.c_str());
    return false;
}

}  // namespace qt::host
