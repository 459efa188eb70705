// edge_beats OUT_DIR FRAME.pgm...: the FPGA front end's edge beats for each frame, as the
// microcontroller receives them (lines/edge_beat.h: 6 bytes a beat, the frame's points in raster
// order, then its trailer), written to OUT_DIR/<frame's stem>.beats. The beats come from
// FrontModel (edge_model.h), which the HDL benches hold bit for bit to hdl/rtl/frontend.v, at
// the lines stage's default edge threshold. Built and run at build time by the Cortex-M presets
// (platform/firmware/CMakeLists.txt) for the chain's mode with edges from the FPGA.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "edge_model.h"
#include "io/image_io.h"
#include "lines/line_detector.h"

namespace {

// The frame's pixels as the camera's AXI4-Stream beats: start of frame on the first, end of
// line on each row's last; the height rides on the first beat (vector_format.h).
std::vector<qt::vec::EdgeOutBeat> front_end_beats(const qt::io::GreyImage& image) {
    qt::vec::FrontModel model(image.width, qt::LineParams{}.edge_threshold);
    std::vector<qt::vec::OutBeat> words;
    std::vector<qt::vec::EdgeOutBeat> edges;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            qt::vec::InBeat b;
            b.pixel = image.at(x, y);
            b.tuser = x == 0 && y == 0;
            b.tlast = x == image.width - 1;
            b.height = b.tuser ? static_cast<uint16_t>(image.height) : 0;
            model.push(b, words, edges);
        }
    return edges;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: edge_beats OUT_DIR FRAME.pgm...\n");
        return 2;
    }
    for (int i = 2; i < argc; ++i) {
        const std::string path = argv[i];
        qt::io::GreyImage image;
        std::string error;
        if (!qt::io::read_image(path, image, error)) {
            std::fprintf(stderr, "edge_beats: %s\n", error.c_str());
            return 1;
        }
        const std::vector<qt::vec::EdgeOutBeat> beats = front_end_beats(image);
        if (beats.empty() || !qt::eb::is_trailer(beats.back().data) ||
            qt::eb::broken(beats.back().data)) {
            std::fprintf(stderr, "edge_beats: %s: the front end did not close the frame\n",
                         path.c_str());
            return 1;
        }
        std::vector<uint8_t> bytes(beats.size() * qt::eb::kBytes);
        for (size_t k = 0; k < beats.size(); ++k)
            qt::eb::store(beats[k].data, bytes.data(), static_cast<uint32_t>(k));
        const size_t slash = path.find_last_of('/'), dot = path.find_last_of('.');
        const size_t from = slash == std::string::npos ? 0 : slash + 1;
        const std::string out =
            std::string(argv[1]) + "/" + path.substr(from, dot - from) + ".beats";
        std::ofstream f(out, std::ios::binary);
        if (!f.write(reinterpret_cast<const char*>(bytes.data()),
                     static_cast<std::streamsize>(bytes.size()))) {
            std::fprintf(stderr, "edge_beats: %s: cannot write\n", out.c_str());
            return 1;
        }
    }
    return 0;
}
