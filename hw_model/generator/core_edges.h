// core's edge stage (GradientStage + EdgeStage into an EdgeList) on one frame, as edge beats the
// FPGA front end would emit for it: what the vector tests and the soak generator compare with
// the model (edge_model.h) to show core = model.
#pragma once
#include <stdint.h>

#include <string>
#include <vector>

#include "io/grey_image.h"
#include "vector_format.h"

namespace qt::vec {

// The point beats and the trailer of one frame (no tuser/tlast framing), from core. Returns
// false (and says why) when core's list could not hold every edge, so no comparison is possible.
bool core_edge_beats(const io::GreyImage& img, uint16_t threshold, std::vector<edge_beat>& beats,
                     std::string& why);

}  // namespace qt::vec
