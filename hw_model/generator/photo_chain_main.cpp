// photo_chain PHOTO_DIR OUT_DIR: writes the frames (NAME_NN.pgm) and texts (NAME.chain.txt,
// NAME-bands.chain.txt in tracking mode) of the firmware's chain cases of real photographs
// (photo_chain.h): photos_qvga and photoseq1_qvga .. photoseq3_qvga; built and run at build time
// by the Cortex-M presets (platform/firmware/CMakeLists.txt).
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
    const size_t first = cases.size();
    cases.push_back(qt::vec::photo_chain_case(photos));
    for (qt::vec::ChainCase& c : qt::vec::photo_sequence_cases(photos)) cases.push_back(c);
    const std::string dir = argv[2];
    auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream f(dir + "/" + name, std::ios::binary);
        if (!(f << text)) {
            std::fprintf(stderr, "photo_chain: cannot write %s/%s\n", dir.c_str(), name.c_str());
            std::exit(1);
        }
    };
    for (const bool tracking_mode : {false, true}) {
        const std::vector<std::string> texts = qt::vec::chain_texts(cases, tracking_mode);
        for (size_t i = first; i < cases.size(); ++i)
            write(qt::vec::text_name(cases[i], tracking_mode) + ".chain.txt", texts[i]);
    }
    for (size_t i = first; i < cases.size(); ++i)
        for (size_t k = 0; k < cases[i].frames.size(); ++k)
            write(qt::vec::frame_name(cases[i], k) + ".pgm",
                  qt::vec::format_pgm(cases[i].frames[k]));
    return 0;
}
