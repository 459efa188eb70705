// The golden-vector cases of the gradient block and the FPGA front end: each a named input beat
// stream, the MAX_WIDTH and edge threshold its expectations assume, and its reset points.
#pragma once
#include <stdint.h>

#include <string>
#include <utility>
#include <vector>

#include "io/grey_image.h"
#include "vector_format.h"

namespace qt::vec {

constexpr int kVectorMaxWidth = 640;  // MAX_WIDTH the vectors assume (the HDL default)

constexpr uint16_t kVectorThreshold = 40;  // edge threshold of most cases (LineParams' default)

struct GradientCase {
    GradientCase(std::string n, uint64_t s, std::string z, int f, std::vector<InBeat> beats)
        : name(std::move(n)), seed(s), sizes(std::move(z)), frames(f), in(std::move(beats)) {}

    std::string name;
    uint64_t seed = 0;
    std::string sizes;  // "WxH" per frame joined by '+'; "soak" for soak streams
    int frames = 0;
    std::vector<InBeat> in;
    int max_width = kVectorMaxWidth;
    uint16_t threshold = kVectorThreshold;
    std::vector<size_t> reset_before;  // input beats a reset comes before (expected_outputs)
};

// Append one well-formed frame to a beat stream.
void append_frame(const io::GreyImage& img, std::vector<InBeat>& beats);

std::vector<GradientCase> gradient_cases();

}  // namespace qt::vec
