// What a command found, drawn over its frame for people to look at (quadtrack detect/track
// --draw, the demo): the frame dimmed, the clustered lines in red, quadrangles with their
// corners, a tracked board's sides solid green where detected and dashed orange where predicted,
// a tracked target's box. Corner 0 is ringed in cyan, the others in yellow. Host only.
#pragma once
#include <stdint.h>

#include <cstdio>
#include <string>
#include <vector>

#include "base/setting_range.h"
#include "io/grey_image.h"
#include "io/overlay.h"
#include "quads/quad_detector.h"
#include "target/float/target_tracker.h"
#include "tracking/quad_tracker.h"

namespace qt::host {

// A 2 px wide line from a to b (pixels); dashed: 8 px on, 6 px off.
void side_line(io::RgbImage& pic, Point16 a, Point16 b, io::Rgb colour, bool dashed);
// Lines in red.
void draw_lines(io::RgbImage& pic, const std::vector<Segment>& lines);
// Quadrangles: the first (the best) in green with its corners ringed, the others in thin yellow.
void draw_quads(io::RgbImage& pic, const std::vector<Quad>& quads);
// A tracked board (nothing when its state is none).
void draw_tracked(io::RgbImage& pic, const TrackedQuad& t);
// The target's w × h box centred at (x, y) px: solid green when measured or reacquired, dashed
// orange when predicted or out of view, red when lost.
void draw_target(io::RgbImage& pic, double x, double y, int w, int h, TargetState state);

// --draw-every N of a sequence command: frames 0, N, 2N, ... are drawn.
inline constexpr SettingRange kDrawEveryRange{"frames", 1, 100000};

// --draw PATTERN of a sequence command: false with the reason in `why` unless the pattern holds
// one %d or %0Nd for the frame number.
bool draw_pattern_ok(const std::string& pattern, std::string& why);
// The picture of frame k under --draw PATTERN --draw-every N, in *file; false when frame k is not
// drawn (no pattern, or k not a multiple of N). The pattern was checked by draw_pattern_ok.
bool frame_picture(const std::string& pattern, uint32_t every, int k, std::string* file);

// `pic` written to `path` as a PNG; false after one line "WHO: --draw: ..." on `err`.
bool write_picture(const std::string& path, const io::RgbImage& pic, std::FILE* err,
                   const char* who);
// The frame dimmed, draw(pic) over it, written to `path` as a PNG; false after one line
// "WHO: --draw: ..." on `err` when it cannot be written.
template <class Draw>
bool write_drawn(const std::string& path, const io::GreyImage& frame, Draw&& draw, std::FILE* err,
                 const char* who) {
    io::RgbImage pic = io::RgbImage::from_grey(frame, 60);
    draw(pic);
    return write_picture(path, pic, err, who);
}

}  // namespace qt::host
