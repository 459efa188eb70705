// The moving-board sequence of the demo and of the firmware's chain vectors: the default board
// (board_scene.h) moving and turning over kBoardSequenceFrames frames; in frames
// kFirstHiddenFrame .. kLastHiddenFrame two dark bars hide its top and bottom sides (as in
// quadrangle-3kf's frames 41–43, where those sides are not extracted), so a tracker has to
// predict them.
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

// Darkens every pixel within kBarHalfWidth px of the line through a and b (1/256 px), across
// the whole frame, hiding the side between them.
void draw_bar(io::GreyImage& image, SubPixel a, SubPixel b);

// Frame f (0 <= f < kBoardSequenceFrames): the default board turned by (f − 6)·2.5° and moved
// by (6f − 33, 2f − 11) px, seed 100 + f, at 640 × 480; with shrink 2 the same at 320 × 240
// (corners and motion halved; the bars keep their half-width, so they cover relatively more).
BoardSequenceFrame board_sequence_frame(int f, int shrink = 1);

}  // namespace qt::scene
