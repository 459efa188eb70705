// core's gradient and edge stages against the committed golden vectors (the same files the HDL
// test benches check), frame by frame and beat by beat, framing included.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core_edges.h"
#include "gradient/gradient_stage.h"
#include "io/grey_image.h"
#include "vector_format.h"

using namespace qt;
using namespace qt::vec;

namespace {

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    REQUIRE(f.good());
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// Runs a well-formed beat stream through the core stage, row by row as a camera delivers them.
std::vector<OutBeat> run_core(const std::vector<InBeat>& in) {
    static GradientStage<640> stage;
    std::vector<OutBeat> out;
    bool first = false;
    uint16_t height = 0;
    auto sink = [&](uint16_t y, const gradient_word* words, uint16_t width) {
        for (uint16_t x = 0; x < width; ++x) {
            const bool last = x + 1u == width;
            out.push_back(OutBeat{words[x], first, last, last && y + 1u == height});
            first = false;
        }
    };
    std::vector<uint8_t> row;
    for (const InBeat& b : in) {
        if (b.tuser) height = b.height;
        row.push_back(b.pixel);
        if (!b.tlast) continue;
        // The first row of a frame starts it; its width is the row's length.
        if (!stage.in_frame()) {
            REQUIRE(stage.begin_frame(static_cast<uint16_t>(row.size()), height) == Status::ok);
            first = true;
        }
        REQUIRE(stage.push_row(row.data(), static_cast<uint16_t>(row.size()), sink) == Status::ok);
        row.clear();
    }
    REQUIRE(row.empty());
    REQUIRE_FALSE(stage.in_frame());
    return out;
}

}  // namespace

TEST_CASE("core gradient stage reproduces every well-formed golden vector case", "[vectors]") {
    const std::string dir = QT_VECTOR_DIR;
    std::vector<ManifestEntry> cases;
    std::string error;
    REQUIRE(parse_manifest(slurp(dir + "/manifest.txt"), cases, error));
    REQUIRE(cases.size() >= 13);
    int checked = 0;
    for (const ManifestEntry& c : cases) {
        INFO("case " << c.name);
        const std::string base = dir + "/" + c.name;
        const std::string in_text = slurp(base + ".in.hex");
        const std::string out_text = slurp(base + ".out.hex");
        const std::string edge_text = slurp(base + ".edges.hex");
        REQUIRE(fnv1a64(out_text, fnv1a64(in_text)) == c.hash);
        std::vector<InBeat> in;
        std::vector<OutBeat> expected;
        std::vector<EdgeOutBeat> edges;
        REQUIRE(parse_in(in_text, in, error));
        REQUIRE(parse_out(out_text, expected, error));
        REQUIRE(parse_edges(edge_text, edges, error));
        REQUIRE(in.size() == c.in_beats);
        REQUIRE(expected.size() == c.out_beats);
        REQUIRE(edges.size() == c.edge_beats);
        // Torn streams and streams with resets: core rejects whole rows (its own test).
        if (c.errors != 0 || c.resets != 0) continue;
        const std::vector<OutBeat> got = run_core(in);
        REQUIRE(got.size() == expected.size());
        for (size_t i = 0; i < got.size(); ++i) {
            if (!(got[i] == expected[i]))
                FAIL("beat " << i << ": expected word " << std::hex << expected[i].word << " tuser "
                             << expected[i].tuser << " tlast " << expected[i].tlast << ", got "
                             << got[i].word << " tuser " << got[i].tuser << " tlast "
                             << got[i].tlast);
        }
        ++checked;
    }
    REQUIRE(checked >= 12);
}

TEST_CASE("core edge stage gives the front end's edge beats of every one-frame golden case",
          "[vectors]") {
    const std::string dir = QT_VECTOR_DIR;
    std::vector<ManifestEntry> cases;
    std::string error;
    REQUIRE(parse_manifest(slurp(dir + "/manifest.txt"), cases, error));
    int checked = 0;
    for (const ManifestEntry& c : cases) {
        if (c.frames != 1 || c.errors != 0 || c.resets != 0) continue;
        INFO("case " << c.name);
        std::vector<InBeat> in;
        std::vector<EdgeOutBeat> expected;
        REQUIRE(parse_in(slurp(dir + "/" + c.name + ".in.hex"), in, error));
        REQUIRE(parse_edges(slurp(dir + "/" + c.name + ".edges.hex"), expected, error));
        // The frame's image from its beats: the width is the first row's length.
        size_t width = 0;
        while (!in[width].tlast) ++width;
        ++width;
        io::GreyImage img(static_cast<int>(width), static_cast<int>(in.size() / width));
        for (size_t i = 0; i < in.size(); ++i)
            img.at(static_cast<int>(i % width), static_cast<int>(i / width)) = in[i].pixel;
        std::vector<edge_beat> got;
        std::string why;
        REQUIRE(core_edge_beats(img, static_cast<uint16_t>(c.threshold), got, why));
        REQUIRE(got.size() == expected.size());
        for (size_t i = 0; i < got.size(); ++i) {
            INFO("edge beat " << i);
            REQUIRE(got[i] == expected[i].data);
            REQUIRE(expected[i].tuser == (i == 0));
            REQUIRE(expected[i].tlast == (i + 1 == got.size()));
        }
        ++checked;
    }
    REQUIRE(checked >= 10);
}

TEST_CASE("vector parsers reject malformed text with a reason", "[vectors]") {
    std::vector<InBeat> in;
    std::vector<OutBeat> out;
    std::vector<ManifestEntry> m;
    std::string error;
    REQUIRE_FALSE(parse_in("00001ff\n0001\n", in, error));
    REQUIRE(error.find("line 2") != std::string::npos);
    REQUIRE_FALSE(parse_in("400000g\n", in, error));
    REQUIRE_FALSE(parse_in("4000000\n", in, error));      // bit 26 is beyond the format
    REQUIRE_FALSE(parse_out("800000000\n", out, error));  // bit 35 is beyond the format
    REQUIRE_FALSE(parse_manifest("case 1x1 1\n", m, error));
    REQUIRE(parse_in("", in, error));
    REQUIRE(in.empty());
}
