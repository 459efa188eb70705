// The golden-vector file format, defined once (docs/gradient.md explains it):
//   <case>.in.hex   one input beat per line, 7 hex digits: {height[15:0], tlast, tuser, pixel}
//   <case>.out.hex  one output beat per line, 9 hex digits: {tlast, tuser, word[31:0]}
//   manifest.txt    name sizes frames seed in_beats out_beats errors max_width fnv1a64
#pragma once
#include <stdint.h>

#include <string>
#include <vector>

#include "gradient_word.h"

namespace qt::vec {

struct InBeat {
    uint8_t pixel = 0;
    bool tuser = false;   // start of frame
    bool tlast = false;   // end of line
    uint16_t height = 0;  // rows of the frame; meaningful on start-of-frame beats, 0 elsewhere
};

struct OutBeat {
    gradient_word word = 0;
    bool tuser = false;
    bool tlast = false;
    friend bool operator==(const OutBeat& a, const OutBeat& b) {
        return a.word == b.word && a.tuser == b.tuser && a.tlast == b.tlast;
    }
};

constexpr int kInPixelLsb = 0, kInTuserBit = 8, kInTlastBit = 9, kInHeightLsb = 10;
constexpr int kInBits = 26, kInHexDigits = 7;
constexpr int kOutTuserBit = 32, kOutTlastBit = 33;
constexpr int kOutBits = 34, kOutHexDigits = 9;

struct ManifestEntry {
    std::string name;
    std::string sizes;  // "WxH" per frame joined by '+'
    int frames = 0;
    uint64_t seed = 0;
    size_t in_beats = 0;
    size_t out_beats = 0;
    int errors = 0;      // framing errors the block must report on this stream
    int max_width = 0;   // MAX_WIDTH the expectations assume
    uint64_t hash = 0;   // FNV-1a 64 of the .in.hex bytes followed by the .out.hex bytes
};

std::string format_in(const std::vector<InBeat>& beats);
std::string format_out(const std::vector<OutBeat>& beats);
std::string format_manifest_line(const ManifestEntry& e);
std::string manifest_header();

// Parsers return false and set `error` to a one-line reason on malformed text.
bool parse_in(const std::string& text, std::vector<InBeat>& beats, std::string& error);
bool parse_out(const std::string& text, std::vector<OutBeat>& beats, std::string& error);
bool parse_manifest(const std::string& text, std::vector<ManifestEntry>& entries,
                    std::string& error);

uint64_t fnv1a64(const std::string& bytes, uint64_t hash = 0xcbf29ce484222325ULL);

// The Verilog include with the word layout and vector bit positions (hdl/gradient_word.vh).
std::string verilog_header();

}  // namespace qt::vec
