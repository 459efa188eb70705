// The golden-vector file format, defined once (docs/gradient.md explains it):
//   <case>.in.hex     one input beat per line, 7 hex digits: {height[15:0], tlast, tuser, pixel}
//   <case>.out.hex    one gradient beat per line, 9 hex digits: {eof, tlast, tuser, word[31:0]}
//   <case>.edges.hex  one edge beat of the front end per line, 13 hex digits:
//                     {tlast, tuser, beat[47:0]} (lines/edge_beat.h)
//   <case>.resets.hex (cases with resets) one reset point per line, 32 hex digits:
//                     {in_beat[31:0], out_beat[31:0], edge_beat[31:0], errors[31:0]}
//   manifest.txt      name sizes frames seed in_beats out_beats edge_beats errors resets
//                     threshold max_width fnv1a64
#pragma once
#include <stdint.h>

#include <string>
#include <vector>

#include "gradient/gradient_word.h"
#include "lines/edge_beat.h"

namespace qt::vec {

struct InBeat {
    uint8_t pixel = 0;
    bool tuser = false;   // start of frame
    bool tlast = false;   // end of line
    uint16_t height = 0;  // rows of the frame; meaningful on start-of-frame beats, 0 elsewhere
};

// A beat of the gradient block's output: m_axis_tuser[0] = tuser (start of frame),
// m_axis_tuser[1] = eof (the frame's last beat), m_axis_tlast = tlast (end of row).
struct OutBeat {
    gradient_word word = 0;
    bool tuser = false;
    bool tlast = false;
    bool eof = false;
    friend bool operator==(const OutBeat& a, const OutBeat& b) {
        return a.word == b.word && a.tuser == b.tuser && a.tlast == b.tlast && a.eof == b.eof;
    }
};

// A beat of the front end's output (edge_beat.h): tuser on a frame's first beat, tlast on its
// trailer.
struct EdgeOutBeat {
    edge_beat data = 0;
    bool tuser = false;
    bool tlast = false;
    friend bool operator==(const EdgeOutBeat& a, const EdgeOutBeat& b) {
        return a.data == b.data && a.tuser == b.tuser && a.tlast == b.tlast;
    }
};

constexpr int kInPixelLsb = 0, kInTuserBit = 8, kInTlastBit = 9, kInHeightLsb = 10;
constexpr int kInBits = 26, kInHexDigits = 7;
constexpr int kOutTuserBit = 32, kOutTlastBit = 33, kOutEofBit = 34;
constexpr int kOutBits = 35, kOutHexDigits = 9;
constexpr int kEdgeTuserBit = 48, kEdgeTlastBit = 49;
constexpr int kEdgeBits = 50, kEdgeHexDigits = 13;

// A reset of the block inside a stream (.resets.hex): aresetn is asserted once the beats before
// `in_beat` have been accepted and before beat `in_beat` is offered. The block loses its state:
// the output beats [previous reset's out_beat, out_beat) are those of the segment before (the
// block may emit any prefix of them before the reset takes it), and the first beat it emits
// after the reset must be beat `out_beat`, the first of the next segment (a start of frame).
// The same for the front end's edge beats with `edge_beat`.
struct ResetPoint {
    uint32_t in_beat = 0;    // index into .in.hex; resets are in stream order, equal ones allowed
    uint32_t out_beat = 0;   // index into .out.hex of the next segment's first expected beat
    uint32_t edge_beat = 0;  // index into .edges.hex of the next segment's first expected beat
    uint32_t errors = 0;     // error pulses of all input beats before in_beat, from the start
    friend bool operator==(const ResetPoint& a, const ResetPoint& b) {
        return a.in_beat == b.in_beat && a.out_beat == b.out_beat && a.edge_beat == b.edge_beat &&
               a.errors == b.errors;
    }
};

constexpr int kResetInLsb = 96, kResetOutLsb = 64, kResetEdgeLsb = 32, kResetErrorsLsb = 0;
constexpr int kResetFieldBits = 32, kResetBits = 128, kResetHexDigits = 32;

struct ManifestEntry {
    std::string name;
    std::string sizes;  // "WxH" per frame joined by '+'
    int frames = 0;
    uint64_t seed = 0;
    size_t in_beats = 0;
    size_t out_beats = 0;
    size_t edge_beats = 0;
    int errors = 0;     // framing errors the block must report on this stream
    size_t resets = 0;  // reset points (.resets.hex; none: no file)
    int threshold = 0;  // the front end's edge threshold (cfg_threshold), grey levels
    int max_width = 0;  // MAX_WIDTH the expectations assume
    // FNV-1a 64 of the .in.hex bytes followed by the .out.hex bytes: the pair a gradient stage
    // recomputes (the firmware's gradient bench); vectors_current proves every file current.
    uint64_t hash = 0;
};

std::string format_in(const std::vector<InBeat>& beats);
std::string format_out(const std::vector<OutBeat>& beats);
std::string format_edges(const std::vector<EdgeOutBeat>& beats);
std::string format_resets(const std::vector<ResetPoint>& resets);
std::string format_manifest_line(const ManifestEntry& e);
std::string manifest_header();

// Parsers return false and set `error` to a one-line reason on malformed text.
bool parse_in(const std::string& text, std::vector<InBeat>& beats, std::string& error);
bool parse_out(const std::string& text, std::vector<OutBeat>& beats, std::string& error);
bool parse_edges(const std::string& text, std::vector<EdgeOutBeat>& beats, std::string& error);
bool parse_resets(const std::string& text, std::vector<ResetPoint>& resets, std::string& error);
bool parse_manifest(const std::string& text, std::vector<ManifestEntry>& entries,
                    std::string& error);

uint64_t fnv1a64(const std::string& bytes, uint64_t hash = 0xcbf29ce484222325ULL);

// The Verilog includes: the gradient word and its vector bit positions
// (hdl/rtl/gradient_word.vh); the edge beat and its vector and reset-point bit positions
// (hdl/rtl/edge_beat.vh).
std::string verilog_header();
std::string verilog_edge_header();

}  // namespace qt::vec
