// A corner feature with the grey-level patch around it: what harris.h produces for one frame
// and ncc_match.h matches between two frames. Integer only.
#pragma once
#include <stdint.h>

namespace qt {

template <int PatchRadius>
struct Feature {
    static_assert(PatchRadius >= 1 && PatchRadius <= 7, "patches of 3x3 .. 15x15 pixels");
    static constexpr int kRadius = PatchRadius;
    static constexpr int kSide = 2 * PatchRadius + 1;  // patch side, px

    int64_t response = 0;        // 25·det(M) - trace(M)² (Harris with k = 1/25 = 0.04, times 25),
                                 // M the structure tensor summed over the window, grey levels^4
                                 // (first: no padding before the 8-byte member)
    int32_t x_q8 = 0, y_q8 = 0;  // position, 1/256 px, pixel centres at integers; sub-pixel
                                 // from a parabola through the response at x-1, x, x+1 (and y)
    int16_t px = 0, py = 0;      // the pixel the patch is centred on (the response maximum)
    uint8_t patch[static_cast<unsigned>(kSide * kSide)] =
        {};  // grey levels, row-major, rows py-R..py+R, columns px-R..px+R
};

// The features of one frame, strongest first within the frame-wide order harris.h documents.
template <int PatchRadius, uint16_t MaxFeatures>
struct FeatureSet {
    uint16_t width = 0, height = 0;  // size of the frame they came from, px
    uint16_t count = 0;              // items[0 .. count) are valid
    Feature<PatchRadius> items[MaxFeatures];
};

}  // namespace qt
