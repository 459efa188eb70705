// The chain cases of real photographs for the firmware's budget (platform/firmware): boards
// composited onto Debian's opencv-doc photographs at QVGA (platform/scene/photo_board_scene.h) —
// six unoccluded, three with a side partly hidden, three without a board — and short sequences
// of a moving board, fixed seeds, so that the firmware runs the same frames the host's
// chain_texts() describes.
#pragma once
#include <vector>

#include "chain_cases.h"
#include "io/image_io.h"

namespace qt::vec {

// Frames photos_qvga_00 .. _11 from `photos` (at least one).
ChainCase photo_chain_case(const std::vector<io::NamedImage>& photos);

// Sequences in front of three of the photographs (the first, and those a third and two thirds
// down the list): frames photoseq<N>_qvga_00 .. _03 of the photo bench's moving board
// (make_photo_sequence_frame), for tracking mode's cost on real backgrounds.
constexpr int kPhotoSequences = 3, kPhotoSequenceFrames = 4;
std::vector<ChainCase> photo_sequence_cases(const std::vector<io::NamedImage>& photos);

}  // namespace qt::vec
