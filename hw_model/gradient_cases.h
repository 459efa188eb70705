// The golden-vector cases of the gradient block: each a named input beat stream.
#pragma once
#include <stdint.h>

#include <string>
#include <vector>

#include "io/grey_image.h"
#include "vector_format.h"

namespace qt::vec {

constexpr int kVectorMaxWidth = 640;  // MAX_WIDTH the vectors assume (the HDL default)

struct GradientCase {
    std::string name;
    uint64_t seed = 0;
    std::string sizes;  // "WxH" per frame joined by '+'
    int frames = 0;
    std::vector<InBeat> in;
};

// Append one well-formed frame to a beat stream.
void append_frame(const io::GreyImage& img, std::vector<InBeat>& beats);

std::vector<GradientCase> gradient_cases();

}  // namespace qt::vec
