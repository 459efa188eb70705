#include "vector_format.h"

#include <cinttypes>
#include <cstdio>
#include <sstream>

namespace qt::vec {

namespace {

bool parse_hex_lines(const std::string& text, int digits, std::vector<uint64_t>& values,
                     std::string& error) {
    values.clear();
    std::istringstream in(text);
    std::string line;
    size_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.size() != static_cast<size_t>(digits)) {
            error = "line " + std::to_string(number) + ": expected " + std::to_string(digits) +
                    " hex digits, got '" + line + "'";
            return false;
        }
        uint64_t v = 0;
        for (char c : line) {
            int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
            if (d < 0) {
                error = "line " + std::to_string(number) + ": not lower-case hex: '" + line + "'";
                return false;
            }
            v = v * 16 + static_cast<uint64_t>(d);
        }
        values.push_back(v);
    }
    return true;
}

std::string hex(uint64_t v, int digits) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%0*" PRIx64, digits, v);
    return buf;
}

}  // namespace

std::string format_in(const std::vector<InBeat>& beats) {
    std::string s;
    s.reserve(beats.size() * (kInHexDigits + 1));
    for (const InBeat& b : beats) {
        const uint64_t v = (static_cast<uint64_t>(b.height) << kInHeightLsb) |
                           (static_cast<uint64_t>(b.tlast) << kInTlastBit) |
                           (static_cast<uint64_t>(b.tuser) << kInTuserBit) | b.pixel;
        s += hex(v, kInHexDigits);
        s += '\n';
    }
    return s;
}

std::string format_out(const std::vector<OutBeat>& beats) {
    std::string s;
    s.reserve(beats.size() * (kOutHexDigits + 1));
    for (const OutBeat& b : beats) {
        const uint64_t v = (static_cast<uint64_t>(b.eof) << kOutEofBit) |
                           (static_cast<uint64_t>(b.tlast) << kOutTlastBit) |
                           (static_cast<uint64_t>(b.tuser) << kOutTuserBit) | b.word;
        s += hex(v, kOutHexDigits);
        s += '\n';
    }
    return s;
}

bool parse_in(const std::string& text, std::vector<InBeat>& beats, std::string& error) {
    std::vector<uint64_t> values;
    if (!parse_hex_lines(text, kInHexDigits, values, error)) return false;
    beats.clear();
    for (uint64_t v : values) {
        if (v >> kInBits) {
            error = "input beat " + hex(v, kInHexDigits) + " uses bits above " +
                    std::to_string(kInBits - 1);
            return false;
        }
        InBeat b;
        b.pixel = static_cast<uint8_t>(v & 0xFF);
        b.tuser = (v >> kInTuserBit) & 1;
        b.tlast = (v >> kInTlastBit) & 1;
        b.height = static_cast<uint16_t>(v >> kInHeightLsb);
        beats.push_back(b);
    }
    return true;
}

bool parse_out(const std::string& text, std::vector<OutBeat>& beats, std::string& error) {
    std::vector<uint64_t> values;
    if (!parse_hex_lines(text, kOutHexDigits, values, error)) return false;
    beats.clear();
    for (uint64_t v : values) {
        if (v >> kOutBits) {
            error = "output beat " + hex(v, kOutHexDigits) + " uses bits above " +
                    std::to_string(kOutBits - 1);
            return false;
        }
        OutBeat b;
        b.word = static_cast<gradient_word>(v & 0xFFFFFFFFu);
        b.tuser = (v >> kOutTuserBit) & 1;
        b.tlast = (v >> kOutTlastBit) & 1;
        b.eof = (v >> kOutEofBit) & 1;
        beats.push_back(b);
    }
    return true;
}

std::string format_edges(const std::vector<EdgeOutBeat>& beats) {
    std::string s;
    s.reserve(beats.size() * (kEdgeHexDigits + 1));
    for (const EdgeOutBeat& b : beats) {
        const uint64_t v = (static_cast<uint64_t>(b.tlast) << kEdgeTlastBit) |
                           (static_cast<uint64_t>(b.tuser) << kEdgeTuserBit) |
                           (b.data & eb::mask(eb::kBits));
        s += hex(v, kEdgeHexDigits);
        s += '\n';
    }
    return s;
}

bool parse_edges(const std::string& text, std::vector<EdgeOutBeat>& beats, std::string& error) {
    std::vector<uint64_t> values;
    if (!parse_hex_lines(text, kEdgeHexDigits, values, error)) return false;
    beats.clear();
    for (uint64_t v : values) {
        if (v >> kEdgeBits) {
            error = "edge beat " + hex(v, kEdgeHexDigits) + " uses bits above " +
                    std::to_string(kEdgeBits - 1);
            return false;
        }
        EdgeOutBeat b;
        b.data = v & eb::mask(eb::kBits);
        b.tuser = (v >> kEdgeTuserBit) & 1;
        b.tlast = (v >> kEdgeTlastBit) & 1;
        beats.push_back(b);
    }
    return true;
}

std::string format_resets(const std::vector<ResetPoint>& resets) {
    constexpr int field = kResetFieldBits / 4;
    static_assert(kResetInLsb == 3 * kResetFieldBits && kResetOutLsb == 2 * kResetFieldBits &&
                      kResetEdgeLsb == kResetFieldBits && kResetErrorsLsb == 0 &&
                      kResetBits == 4 * kResetFieldBits,
                  "fields written most significant first");
    std::string s;
    s.reserve(resets.size() * (kResetHexDigits + 1));
    for (const ResetPoint& r : resets) {
        s += hex(r.in_beat, field);
        s += hex(r.out_beat, field);
        s += hex(r.edge_beat, field);
        s += hex(r.errors, field);
        s += '\n';
    }
    return s;
}

bool parse_resets(const std::string& text, std::vector<ResetPoint>& resets, std::string& error) {
    constexpr size_t field = kResetFieldBits / 4;
    static_assert(kResetHexDigits == 4 * field, "four 32-bit fields");
    resets.clear();
    std::istringstream in(text);
    std::string line;
    size_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::vector<uint64_t> v;
        std::string part_error;
        // Each line is four fixed-width fields; parse them as four one-line texts.
        if (line.size() != static_cast<size_t>(kResetHexDigits) ||
            !parse_hex_lines(line.substr(0, field) + "\n" + line.substr(field, field) + "\n" +
                                 line.substr(2 * field, field) + "\n" +
                                 line.substr(3 * field, field) + "\n",
                             static_cast<int>(field), v, part_error)) {
            error = "resets line " + std::to_string(number) + ": expected " +
                    std::to_string(kResetHexDigits) + " lower-case hex digits, got '" + line + "'";
            return false;
        }
        resets.push_back(ResetPoint{static_cast<uint32_t>(v[0]), static_cast<uint32_t>(v[1]),
                                    static_cast<uint32_t>(v[2]), static_cast<uint32_t>(v[3])});
    }
    return true;
}

std::string manifest_header() {
    return "# Golden vectors of the gradient block and the FPGA front end, written by qt_vectors\n"
           "# (hw_model/). Format: docs/gradient.md. Regenerate: build/host/hw_model/qt_vectors "
           "--write .\n"
           "# name sizes frames seed in_beats out_beats edge_beats errors resets threshold "
           "max_width fnv1a64\n";
}

std::string format_manifest_line(const ManifestEntry& e) {
    return e.name + " " + e.sizes + " " + std::to_string(e.frames) + " " + std::to_string(e.seed) +
           " " + std::to_string(e.in_beats) + " " + std::to_string(e.out_beats) + " " +
           std::to_string(e.edge_beats) + " " + std::to_string(e.errors) + " " +
           std::to_string(e.resets) + " " + std::to_string(e.threshold) + " " +
           std::to_string(e.max_width) + " " + hex(e.hash, 16) + "\n";
}

bool parse_manifest(const std::string& text, std::vector<ManifestEntry>& entries,
                    std::string& error) {
    entries.clear();
    std::istringstream in(text);
    std::string line;
    size_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        ManifestEntry e;
        std::string hash;
        if (!(fields >> e.name >> e.sizes >> e.frames >> e.seed >> e.in_beats >> e.out_beats >>
              e.edge_beats >> e.errors >> e.resets >> e.threshold >> e.max_width >> hash) ||
            hash.size() != 16) {
            error = "manifest line " + std::to_string(number) + " malformed: '" + line + "'";
            return false;
        }
        e.hash = std::stoull(hash, nullptr, 16);
        entries.push_back(e);
    }
    return true;
}

uint64_t fnv1a64(const std::string& bytes, uint64_t hash) {
    for (unsigned char c : bytes) {
        hash ^= c;
        hash *= 0x100000001b3ULL;
    }
    return hash;
}

std::string verilog_header() {
    std::string s =
        "// Generated by qt_vectors from core/gradient/gradient_word.h and "
        "hw_model/vector_format.h.\n"
        "// Do not edit: the test command regenerates it and fails if it differs.\n";
    auto def = [&s](const char* name, int value) {
        s += std::string("`define ") + name + " " + std::to_string(value) + "\n";
    };
    def("QT_GW_WIDTH", gw::kWordBits);
    def("QT_GW_GX_LSB", gw::kGxLsb);
    def("QT_GW_GX_BITS", gw::kGxBits);
    def("QT_GW_GY_LSB", gw::kGyLsb);
    def("QT_GW_GY_BITS", gw::kGyBits);
    def("QT_GW_MAG_LSB", gw::kMagLsb);
    def("QT_GW_MAG_BITS", gw::kMagBits);
    def("QT_GW_DIR_LSB", gw::kDirLsb);
    def("QT_GW_DIR_BITS", gw::kDirBits);
    def("QT_GW_FILL_BIT", gw::kFillBit);
    def("QT_VEC_IN_HEIGHT_LSB", kInHeightLsb);
    def("QT_VEC_IN_TLAST_BIT", kInTlastBit);
    def("QT_VEC_IN_TUSER_BIT", kInTuserBit);
    def("QT_VEC_IN_BITS", kInBits);
    def("QT_VEC_OUT_TLAST_BIT", kOutTlastBit);
    def("QT_VEC_OUT_TUSER_BIT", kOutTuserBit);
    def("QT_VEC_OUT_EOF_BIT", kOutEofBit);
    def("QT_VEC_OUT_BITS", kOutBits);
    return s;
}

std::string verilog_edge_header() {
    std::string s =
        "// Generated by qt_vectors from core/lines/edge_beat.h, core/lines/edge_list.h and "
        "hw_model/vector_format.h.\n"
        "// Do not edit: the test command regenerates it and fails if it differs.\n";
    auto def = [&s](const char* name, int value) {
        s += std::string("`define ") + name + " " + std::to_string(value) + "\n";
    };
    // The packed point of the edge list (ep::make), field by field.
    static_assert(ep::make(1, 0, 0) == 1u && ep::make(0, 1, 0) == 1u << 11 &&
                      ep::make(0, 0, 1) == 1u << 22 && ep::make(0, 0, 0, 1) == 1u << 28 &&
                      ep::with_state(0, 1) == 1u << 26,
                  "the point's field positions written below");
    def("QT_EP_X_LSB", 0);
    def("QT_EP_Y_LSB", 11);
    def("QT_EP_COORD_BITS", 11);
    def("QT_EP_DIR_LSB", 22);
    def("QT_EP_STATE_LSB", 26);
    def("QT_EP_DELTA_LSB", 28);
    def("QT_EB_BITS", eb::kBits);
    def("QT_EB_POINT_LSB", eb::kPointLsb);
    def("QT_EB_MAG_LSB", eb::kMagLsb);
    def("QT_EB_MAG_BITS", eb::kMagBits);
    def("QT_EB_LAST_X_LSB", eb::kLastXLsb);
    def("QT_EB_LAST_Y_LSB", eb::kLastYLsb);
    def("QT_EB_BROKEN_BIT", eb::kBrokenBit);
    def("QT_EB_TRAILER_BIT", eb::kTrailerBit);
    def("QT_VEC_EDGE_TUSER_BIT", kEdgeTuserBit);
    def("QT_VEC_EDGE_TLAST_BIT", kEdgeTlastBit);
    def("QT_VEC_EDGE_BITS", kEdgeBits);
    def("QT_VEC_RESET_IN_LSB", kResetInLsb);
    def("QT_VEC_RESET_OUT_LSB", kResetOutLsb);
    def("QT_VEC_RESET_EDGE_LSB", kResetEdgeLsb);
    def("QT_VEC_RESET_ERRORS_LSB", kResetErrorsLsb);
    def("QT_VEC_RESET_BITS", kResetBits);
    return s;
}

}  // namespace qt::vec
