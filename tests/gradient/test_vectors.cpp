// core's gradient stage against the committed golden vectors (the same files the HDL test
// bench checks), frame by frame and beat by beat, framing included.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gradient/gradient_stage.h"
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
    auto sink = [&](uint16_t, const gradient_word* words, uint16_t width) {
        for (uint16_t x = 0; x < width; ++x) {
            out.push_back(OutBeat{words[x], first, x + 1u == width});
            first = false;
        }
    };
    std::vector<uint8_t> row;
    uint16_t height = 0;
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
        const std::string in_text = slurp(dir + "/" + c.name + ".in.hex");
        const std::string out_text = slurp(dir + "/" + c.name + ".out.hex");
        REQUIRE(fnv1a64(out_text, fnv1a64(in_text)) == c.hash);
        std::vector<InBeat> in;
        std::vector<OutBeat> expected;
        REQUIRE(parse_in(in_text, in, error));
        REQUIRE(parse_out(out_text, expected, error));
        REQUIRE(in.size() == c.in_beats);
        REQUIRE(expected.size() == c.out_beats);
        if (c.errors != 0) continue;  // torn streams: core rejects whole rows (its own test)
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

TEST_CASE("vector parsers reject malformed text with a reason", "[vectors]") {
    std::vector<InBeat> in;
    std::vector<OutBeat> out;
    std::vector<ManifestEntry> m;
    std::string error;
    REQUIRE_FALSE(parse_in("00001ff\n0001\n", in, error));
    REQUIRE(error.find("line 2") != std::string::npos);
    REQUIRE_FALSE(parse_in("400000g\n", in, error));
    REQUIRE_FALSE(parse_in("4000000\n", in, error));  // bit 26 is beyond the format
    REQUIRE_FALSE(parse_out("400000000\n", out, error));
    REQUIRE_FALSE(parse_manifest("case 1x1 1\n", m, error));
    REQUIRE(parse_in("", in, error));
    REQUIRE(in.empty());
}
