// The chain case of real photographs for the firmware's budget (platform/firmware): boards
// composited onto Debian's opencv-doc photographs at QVGA (platform/scene/photo_board_scene.h) —
// six unoccluded, three with a side partly hidden, three without a board — fixed seeds, so that the
// firmware runs the same frames the host's chain_texts() describes.
#pragma once
#include <vector>

#include "chain_cases.h"
#include "io/image_io.h"

namespace qt::vec {

// Frames photos_qvga_00 .. _11 from `photos` (at least one).
ChainCase photo_chain_case(const std::vector<io::NamedImage>& photos);

}  // namespace qt::vec
