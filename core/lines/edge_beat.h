// The edge beat: what the FPGA front end (hdl/rtl/edge_stage.v) emits and the microcontroller's
// edge list takes. This file is the one definition of its layout; hdl/rtl/edge_beat.vh is
// generated from it (qt_vectors) and docs/gradient.md ("The front end") explains it. 48 bits,
// LSB first (in memory: 6 bytes, little-endian, as AXI4-Stream numbers its bytes):
//
//   point beat    [31:0]  the edge list's packed point (edge_list.h: x, y, dir, state 0, delta)
//                 [40:32] its L1 gradient magnitude, grey levels 0..510
//                 [46:41] 0
//                 [47]    0
//   trailer beat  [10:0]  W - 1, the frame's last column
//                 [21:11] H - 1, its last row (a broken-off frame: the last row it reached)
//                 [45:22] 0
//                 [46]    broken: the frame's input broke off (the gradient block's fill words)
//                 [47]    1
//
// Each frame is its point beats in raster order (row by row, x increasing) and then one trailer;
// on the stream, tuser marks a frame's first beat and tlast its trailer. The FPGA emits every
// point at or above its threshold with its magnitude; which ones the list keeps when it is full
// is the list's business (edge_list.h: the weakest go), as for the software edge stage.
#pragma once
#include <stdint.h>

#include "base/status.h"
#include "lines/band_window.h"
#include "lines/edge_list.h"

namespace qt {

using edge_beat = uint64_t;  // bits 47:0 used

namespace eb {
constexpr int kBits = 48, kBytes = 6;
constexpr int kPointLsb = 0, kPointBits = 32;
constexpr int kMagLsb = 32, kMagBits = 9;
constexpr int kLastXLsb = 0, kLastYLsb = 11, kCoordBits = 11;
constexpr int kBrokenBit = 46, kTrailerBit = 47;
static_assert(kMagLsb + kMagBits <= kBrokenBit, "fields below the flags");
static_assert((1u << kCoordBits) - 1u == ep::kMaxCoordinate, "coordinates as the edge list's");

constexpr uint64_t mask(int bits) { return (uint64_t{1} << bits) - 1u; }

constexpr edge_beat point(uint32_t x, uint32_t y, uint32_t dir, int32_t delta16, uint32_t mag) {
    return (uint64_t{ep::make(x, y, dir, delta16)} << kPointLsb) |
           ((uint64_t{mag} & mask(kMagBits)) << kMagLsb);
}
constexpr edge_beat trailer(uint32_t last_x, uint32_t last_y, bool broken) {
    return ((uint64_t{last_x} & mask(kCoordBits)) << kLastXLsb) |
           ((uint64_t{last_y} & mask(kCoordBits)) << kLastYLsb) | (uint64_t{broken} << kBrokenBit) |
           (uint64_t{1} << kTrailerBit);
}

constexpr bool is_trailer(edge_beat b) { return ((b >> kTrailerBit) & 1u) != 0; }
constexpr edge_point point_of(edge_beat b) {
    return static_cast<edge_point>((b >> kPointLsb) & mask(kPointBits));
}
constexpr uint32_t magnitude(edge_beat b) {
    return static_cast<uint32_t>((b >> kMagLsb) & mask(kMagBits));
}
constexpr uint32_t last_x(edge_beat b) {
    return static_cast<uint32_t>((b >> kLastXLsb) & mask(kCoordBits));
}
constexpr uint32_t last_y(edge_beat b) {
    return static_cast<uint32_t>((b >> kLastYLsb) & mask(kCoordBits));
}
constexpr bool broken(edge_beat b) { return ((b >> kBrokenBit) & 1u) != 0; }

// Beat i of a buffer of 6-byte little-endian beats.
inline edge_beat load(const uint8_t* beats, uint32_t i) {
    const uint8_t* p = beats + static_cast<uintptr_t>(i) * kBytes;
    edge_beat b = 0;
    for (int k = kBytes - 1; k >= 0; --k) b = (b << 8) | p[k];
    return b;
}
inline void store(edge_beat b, uint8_t* beats, uint32_t i) {
    uint8_t* p = beats + static_cast<uintptr_t>(i) * kBytes;
    for (int k = 0; k < kBytes; ++k) p[k] = static_cast<uint8_t>(b >> (8 * k));
}
}  // namespace eb

// Takes one frame's beats from the FPGA front end into an edge list begun for that frame:
//   feed.begin_frame(list, width, height, edge_threshold);   // list.begin_frame(height) done
//   feed.push(beats, n, &used) ... until feed.done()
// Points below edge_threshold are skipped (the FPGA may run a lower one), the others pushed as
// the software edge stage pushes them, so the list ends the same. bad_stream (and no more
// points taken) when the FPGA reports the frame broken off or the beats do not fit the frame:
// a point outside it or out of raster order, a trailer of another size, or bits set that the
// format leaves 0.
class EdgeBeatFeed {
public:
    // window: tracking mode's bands (band_window.h): the points outside them are checked and
    // passed over, as the rows stage does not compute them; null: every point.
    void begin_frame(EdgeList& list, uint16_t width, uint16_t height, uint16_t edge_threshold,
                     BandWindow* window = nullptr);
    // Takes beats in stream order up to and including the frame's trailer; *used: how many
    // (the rest belong to the next frame). ok while the frame is open and once it is complete.
    Status push(const uint8_t* beats, uint32_t count, uint32_t* used);
    // The trailer was taken: the list is complete (EdgeList::end_frame called).
    bool done() const { return done_; }

private:
    bool in_bands(int32_t x, int32_t y);  // (x, y) in the window's bands (always, without one)

    EdgeList* list_ = nullptr;
    BandWindow* window_ = nullptr;
    uint16_t width_ = 0, height_ = 0, threshold_ = 0;
    int32_t last_x_ = -1, row_ = -1;  // the previous point's column and row (-1: none yet)
    int32_t list_row_ = -1;           // the row begun last in the list
    bool done_ = false, failed_ = false;
};

}  // namespace qt
