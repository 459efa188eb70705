// The demo's board sequence: a board moving and turning over a few frames, detected and tracked
// (core/quad_tracker.h) frame by frame, each written as an overlay picture with a one-line
// summary on stdout. In a few middle frames two dark bars hide the board's top and bottom
// sides (as in quadrangle-3kf's frames 41–43, where those sides are not extracted), so the
// tracker has to predict them.
#pragma once
#include <string>

#include "board_scene.h"
#include "image.h"

namespace qt::cli {

constexpr int kDemoFrames = 12;
// Frames kDemoFirstHidden .. kDemoLastHidden carry the bars.
constexpr int kDemoFirstHidden = 5, kDemoLastHidden = 7;

struct DemoFrame {
    scene::BoardScene scene;  // the board as generated: corners (1/256 px) top-left, top-right,
                              // bottom-right, bottom-left
    scene::GreyImage image;   // 640 × 480, with the bars on hidden frames
    bool hidden = false;      // bars over the top and bottom sides
};

// Frame f of the sequence, 0 <= f < kDemoFrames.
DemoFrame demo_frame(int f);

// The demo's bar: darkens every pixel within 24 px of the line through a and b (1/256 px),
// across the whole frame, hiding the side between them. The bar's own edges lie 24 px from the
// side, outside the tracker's default 12 px gate.
void draw_bar(scene::GreyImage& image, scene::SubPixel a, scene::SubPixel b);

// Writes board_00.png ... under out_dir (which exists). Returns false after printing an error.
bool run_demo_sequence(const std::string& out_dir);

}  // namespace qt::cli
