// Synthetic board scenes: a bright convex quadrangle (the hand-held board) over a shaded,
// textured background, with sensor noise. Integer arithmetic and the project PRNG only, so
// a (size, corners, seed) triple gives the same bytes on every platform.
#pragma once
#include <stdint.h>

#include "io/grey_image.h"

namespace qt::scene {

// A point in 1/256 pixel (pixel centres at integer coordinates).
struct SubPixel {
    int32_t x;
    int32_t y;
};

struct BoardScene {
    int width = 640;
    int height = 480;
    SubPixel corners[4] = {};     // convex, any winding
    uint8_t board_level = 220;    // grey level of the board
    uint8_t noise_amplitude = 6;  // uniform noise in [-a, a] grey levels
    uint64_t seed = 1;
};

// The default scene of the demo and of the 640×480 vector case: a board tilted and turned
// in a 640×480 frame.
BoardScene default_board_scene();

// Render: background = horizontal and vertical shading plus faint stripes and blobs; board
// coverage from 4×4 supersampling per pixel (anti-aliased edges); then noise, clamped to 0..255.
io::GreyImage render_board(const BoardScene& scene);

}  // namespace qt::scene
