// photo_chain PHOTO_DIR OUT_DIR: writes OUT_DIR/photos_qvga_NN.pgm, photos_qvga.chain.txt and
// photos_qvga-bands.chain.txt (tracking mode) (photo_chain.h) for the firmware's chain case of
// real photographs; built and run at build time by the Cortex-M presets
// (platform/firmware/CMakeLists.txt).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "photo_chain.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: photo_chain PHOTO_DIR OUT_DIR\n");
        return 2;
    }
    std::vector<qt::io::NamedImage> photos;
    std::string error;
    if (!qt::io::read_image_folder(argv[1], photos, error)) {
        std::fprintf(stderr, "photo_chain: %s\n", error.c_str());
        return 1;
    }
    // After the committed cases, as the firmware runs them: track ids run on from case to case.
    std::vector<qt::vec::ChainCase> cases = qt::vec::chain_cases();
    cases.push_back(qt::vec::photo_chain_case(photos));
    const qt::vec::ChainCase& photo_case = cases.back();
    const std::string dir = argv[2];
    auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream f(dir + "/" + name, std::ios::binary);
        if (!(f << text)) {
            std::fprintf(stderr, "photo_chain: cannot write %s/%s\n", dir.c_str(), name.c_str());
            std::exit(1);
        }
    };
    for (size_t k = 0; k < photo_case.frames.size(); ++k)
        write(qt::vec::frame_name(photo_case, k) + ".pgm",
              qt::vec::format_pgm(photo_case.frames[k]));
    for (const bool tracking_mode : {false, true})
        write(qt::vec::text_name(photo_case, tracking_mode) + ".chain.txt",
              qt::vec::chain_texts(cases, tracking_mode).back());
    return 0;
}
