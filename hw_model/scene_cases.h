// Committed QVGA test frames of the lines stage (vectors/scenes/) and their expected lines as
// the host's core computes them: the firmware must print the same text byte for byte.
#pragma once
#include <string>
#include <vector>

#include "image.h"

namespace qt::vec {

struct SceneCase {
    std::string name;
    scene::GreyImage frame;
};

std::vector<SceneCase> scene_cases();

// Binary PGM (P5, maxval 255) of a frame.
std::string format_pgm(const scene::GreyImage& img);

// Lines text (core/line_text.h) of a frame through LineDetectorQvga with default parameters.
std::string lines_text(const SceneCase& c);

}  // namespace qt::vec
