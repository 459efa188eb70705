#include "photo_chain.h"

#include <string>

#include "scene/photo_board_scene.h"

namespace qt::vec {

ChainCase photo_chain_case(const std::vector<io::NamedImage>& photos) {
    ChainCase c{"photos_qvga", {}};
    for (int k = 0; k < 12; ++k) {
        scene::PhotoBoardOptions o;
        o.width = 320;
        o.height = 240;
        o.board = k < 9;
        o.occlude = k >= 6 && k < 9;
        const io::GreyImage& photo = photos[static_cast<size_t>(k) * 7 % photos.size()].image;
        c.frames.push_back(
            scene::make_photo_board_scene(o, photo, 8000000u + static_cast<uint64_t>(k)).image);
    }
    return c;
}

std::vector<ChainCase> photo_sequence_cases(const std::vector<io::NamedImage>& photos) {
    std::vector<ChainCase> cases;
    for (int n = 0; n < kPhotoSequences; ++n) {
        ChainCase c{"photoseq" + std::to_string(n + 1) + "_qvga", {}};
        scene::PhotoSequenceOptions o;
        o.width = 320;
        o.height = 240;
        const io::GreyImage& photo = photos[photos.size() * static_cast<size_t>(n) / 3].image;
        for (int k = 0; k < kPhotoSequenceFrames; ++k)
            c.frames.push_back(scene::make_photo_sequence_frame(o, photo, k).image);
        cases.push_back(c);
    }
    return cases;
}

}  // namespace qt::vec
