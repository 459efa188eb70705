// The lines stage fed with the FPGA front end's edge beats (push_edge_beats) finds the lines it
// finds from camera rows: the committed board frame's edges.hex (the front end's output, checked
// against the Verilog by the HDL benches) against the same frame's pixels.
#include <catch2/catch.hpp>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "lines/line_detector.h"
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

void same_lines(const LineDetectorVga& a, const LineDetectorVga& b) {
    REQUIRE(a.line_count() == b.line_count());
    for (int i = 0; i < a.line_count(); ++i) {
        INFO("line " << i);
        REQUIRE(a.lines()[i].x1 == b.lines()[i].x1);
        REQUIRE(a.lines()[i].y1 == b.lines()[i].y1);
        REQUIRE(a.lines()[i].x2 == b.lines()[i].x2);
        REQUIRE(a.lines()[i].y2 == b.lines()[i].y2);
        REQUIRE(a.lines()[i].points == b.lines()[i].points);
    }
}

}  // namespace

TEST_CASE("lines from the front end's edge beats equal lines from camera rows", "[edge_beats]") {
    const std::string base = std::string(QT_VECTOR_DIR) + "/board_640x480";
    std::vector<InBeat> in;
    std::vector<EdgeOutBeat> edges;
    std::string error;
    REQUIRE(parse_in(slurp(base + ".in.hex"), in, error));
    REQUIRE(parse_edges(slurp(base + ".edges.hex"), edges, error));
    constexpr uint16_t kW = 640, kH = 480;
    REQUIRE(in.size() == size_t{kW} * kH);

    LineParams params;  // the vectors' threshold is LineParams' default
    auto rows = std::make_unique<LineDetectorVga>();
    REQUIRE(rows->begin_frame(kW, kH, params) == Status::ok);
    std::vector<uint8_t> row(kW);
    for (uint16_t y = 0; y < kH; ++y) {
        for (uint16_t x = 0; x < kW; ++x) row[x] = in[size_t{y} * kW + x].pixel;
        REQUIRE(rows->push_row(row.data(), kW) == Status::ok);
    }
    REQUIRE(rows->finish() != Status::not_in_frame);
    REQUIRE(rows->line_count() > 0);

    // The beats as the microcontroller receives them: 6 bytes each, in two bursts.
    std::vector<uint8_t> bytes(edges.size() * eb::kBytes);
    for (size_t i = 0; i < edges.size(); ++i)
        eb::store(edges[i].data, bytes.data(), static_cast<uint32_t>(i));
    auto fpga = std::make_unique<LineDetectorVga>();
    REQUIRE(fpga->begin_frame(kW, kH, params) == Status::ok);
    const uint32_t half = static_cast<uint32_t>(edges.size() / 2),
                   n = static_cast<uint32_t>(edges.size());
    uint32_t used = 0;
    REQUIRE(fpga->push_edge_beats(bytes.data(), half, &used) == Status::ok);
    REQUIRE(used == half);
    REQUIRE_FALSE(fpga->edge_beats_done());
    REQUIRE(fpga->push_edge_beats(bytes.data() + size_t{half} * eb::kBytes, n - half, &used) ==
            Status::ok);
    REQUIRE(used == n - half);
    REQUIRE(fpga->edge_beats_done());
    REQUIRE(fpga->finish() != Status::not_in_frame);
    same_lines(*rows, *fpga);

    SECTION("a broken-off frame's trailer abandons the frame") {
        std::vector<uint8_t> broken(bytes);
        eb::store(eb::trailer(kW - 1, kH - 1, true), broken.data(), n - 1);
        REQUIRE(fpga->begin_frame(kW, kH, params) == Status::ok);
        REQUIRE(fpga->push_edge_beats(broken.data(), n, &used) == Status::bad_stream);
        REQUIRE(fpga->finish() == Status::not_in_frame);
    }
    SECTION("rows after edge beats are refused") {
        REQUIRE(fpga->begin_frame(kW, kH, params) == Status::ok);
        REQUIRE(fpga->push_edge_beats(bytes.data(), 1, &used) == Status::ok);
        REQUIRE(fpga->push_row(row.data(), kW) == Status::not_in_frame);
    }
}
