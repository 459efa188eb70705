// The moving-board sequence of the demo and of the firmware's chain vectors: the default board
// (board_scene.h) moving and turning over kBoardSequenceFrames frames; in frames
// kFirstHiddenFrame .. kLastHiddenFrame two dark bars hide its top and bottom sides (as in
// the Quadrangle Detection paper's frames 41–43, where those sides are not extracted), so a tracker
// has to predict them.
#pragma once
#include "io/grey_image.h"
#include "scene/board_scene.h"

namespace qt::scene {

constexpr int kBoardSequenceFrames = 12;
constexpr int kFirstHiddenFrame = 5, kLastHiddenFrame = 7;

// Bars: every pixel within this distance of the hidden side's line, across the whole frame, px.
// Their edges lie this far from the side, well outside the tracker's 12 px gate, so the bars'
// own edges are not taken for the side.
constexpr double kBarHalfWidth = 24;

struct BoardSequenceFrame {
    BoardScene scene;     // the board as generated: corners (1/256 px) top-left, top-right,
                          // bottom-right, bottom-left
    io::GreyImage image;  // with the bars on hidden frames
    bool hidden = false;  // bars over the top and bottom sides
};

// `base` turned by angle_deg (clockwise as seen, y down) about the centroid of its corners,
// then moved by (dx, dy) px; corners rounded to 1/256 px.
BoardScene turned_board(const BoardScene& base, double angle_deg, double dx, double dy);

// Darkens every pixel within half_width px of the line through a and b (1/256 px), across the
// whole frame, hiding the side between them.
void draw_bar(io::GreyImage& image, SubPixel a, SubPixel b, double half_width = kBarHalfWidth);

// Frame f (0 <= f < kBoardSequenceFrames): the default board turned by (f − 6)·2.5° and moved
// by (6f − 33, 2f − 11) px, seed 100 + f, at 640 × 480; with shrink 2 the same at 320 × 240
// (corners and motion halved; the bars keep their half-width, so they cover relatively more).
BoardSequenceFrame board_sequence_frame(int f, int shrink = 1);

// A board sequence at any camera size: the motion, the sides hidden and when, as seen in the
// demo's 640 × 480 frame; sized_sequence_frame() scales it to the camera's frame.
struct BoardMotionSpec {
    int frames = kBoardSequenceFrames;
    double turn_deg = 2.5;  // turn per frame, degrees (clockwise as seen)
    int turn_zero = 6;      // the frame in which the board has the default scene's pose
    double dx = 6, dy = 2;  // motion per frame, px at 640 × 480
    int first_hidden = kFirstHiddenFrame, last_hidden = kLastHiddenFrame;
    bool hide_top = true, hide_bottom = true;  // sides under a bar in the hidden frames
};

// The demo's sequence (board_sequence_frame's).
constexpr BoardMotionSpec kDemoSequence{};
// A side hidden while the board turns: 20 frames, 3°/frame, a bar over the bottom side only,
// in frames 6-9; then the whole board again.
constexpr BoardMotionSpec kTurningSequence{20, 3, 10, 4, -1.5, 6, 9, false, true};

// Frame f of `spec` in a width × height frame (each at least 64 × 48): the default board scene
// and its motion scaled by s = min(width / 640, height / 480) and centred (at 640 × 480, and
// for kDemoSequence, the same bytes as board_sequence_frame(f)); the bars' half-width scales
// too, but not below kBarHalfWidth (as board_sequence_frame(f, 2) keeps it). Seed 100 + f.
BoardSequenceFrame sized_sequence_frame(const BoardMotionSpec& spec, int f, int width, int height);

}  // namespace qt::scene
