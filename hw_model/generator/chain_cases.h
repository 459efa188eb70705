// Committed QVGA frame sequences of the whole quadrangle chain (vectors/scenes/) and the result
// text (core/api/result_text.h) the host's core computes for them: the firmware must print the same
// text byte for byte.
#pragma once
#include <string>
#include <vector>

#include "io/grey_image.h"

namespace qt::vec {

struct ChainCase {
    std::string name;                   // frames are vectors/scenes/<name>_<NN>.pgm
    std::vector<io::GreyImage> frames;  // 320 × 240
};

std::vector<ChainCase> chain_cases();

// Name of frame k of a case: <name>_<NN>, two digits.
std::string frame_name(const ChainCase& c, size_t k);

// Binary PGM (P5, maxval 255) of a frame.
std::string format_pgm(const io::GreyImage& img);

// The result text of each case, the cases in order and each case's frames in order through
// one BoardDetectorQvga and one QuadTracker (default parameters for 320 × 240), reset() at the
// start of each case (so track ids run on from case to case), as the firmware runs them.
// tracking_mode: each frame after the first through the window TrackingMode (default
// parameters) planned from the frame before (tracking/tracking_mode.h); the case's texts are
// then <name>-bands.
std::vector<std::string> chain_texts(const std::vector<ChainCase>& cases, bool tracking_mode);

// The name of a case's text: <name>, or <name>-bands in tracking mode.
std::string text_name(const ChainCase& c, bool tracking_mode);

}  // namespace qt::vec
