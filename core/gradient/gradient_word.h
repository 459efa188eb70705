// The gradient word: the seam between the FPGA block and the microcontroller. This file is
// the one definition of its layout; hdl/rtl/gradient_word.vh is generated from it (qt_vectors) and
// docs/gradient.md explains it. Layout, LSB first:
//   [8:0]   gx   signed 9-bit, p(x+1,y) - p(x-1,y), grey levels, -255..255
//   [17:9]  gy   signed 9-bit, p(x,y+1) - p(x,y-1), grey levels, -255..255
//   [26:18] mag  unsigned 9-bit, |gx| + |gy|, 0..510
//   [30:27] dir  unsigned 4-bit, direction bin 0..15 of 22.5° each (see direction_bin)
//   [31]    fill 0 for a gradient; 1 on the words the FPGA block emits, all other bits 0, to
//                complete the row of a frame whose input broke off (docs/gradient.md)
#pragma once
#include <stdint.h>

namespace qt {

using gradient_word = uint32_t;

namespace gw {
constexpr int kGxLsb = 0, kGxBits = 9;
constexpr int kGyLsb = 9, kGyBits = 9;
constexpr int kMagLsb = 18, kMagBits = 9;
constexpr int kDirLsb = 27, kDirBits = 4;
constexpr int kFillBit = 31;
constexpr int kWordBits = 32;
constexpr int kDirBins = 1 << kDirBits;  // 16 bins, 360° / 16 = 22.5° per bin
constexpr uint32_t field_mask(int bits) { return (1u << bits) - 1u; }
static_assert(kDirLsb + kDirBits <= kFillBit && kFillBit < kWordBits, "fields fit the word");
static_assert(255 + 255 <= static_cast<int>(field_mask(kMagBits)), "L1 magnitude fits");
static_assert(kGxBits == 9 && kGyBits == 9, "accessors below sign-extend 9-bit fields");
}  // namespace gw

// The slopes tan(11.25°) ≈ 51/256 and tan(33.75°) ≈ 171/256 that separate the direction
// bins. hdl/rtl/gradient_direction.v forms 51·v and 171·v by shifts and adds (no multiplier
// block); here the compiler picks (one MUL on Cortex-M4, shift-adds elsewhere). Same values.
constexpr uint32_t times_51(uint32_t v) { return v * 51u; }
constexpr uint32_t times_171(uint32_t v) { return v * 171u; }

// Direction bin of (gx, gy): bin k is centred on k·22.5°, angle measured from +x towards +y
// (image coordinates, y down: clockwise on screen). Boundaries at ±11.25° and ±33.75° around
// each axis come from the slopes above; a boundary value goes to the bin nearer the axis.
// (0, 0) gives bin 0. Compares and constant multiplies only (shift-adds in logic), no table
// and no branches, so per-pixel loops vectorise on hosts and stay short on Cortex-M.
constexpr uint32_t direction_bin(int32_t gx, int32_t gy) {
    const uint32_t ax = static_cast<uint32_t>(gx < 0 ? -gx : gx);
    const uint32_t ay = static_cast<uint32_t>(gy < 0 ? -gy : gy);
    const uint32_t steep = ay > ax;  // 45°..90° within the quadrant
    const uint32_t lo = steep ? ax : ay, hi = steep ? ay : ax;
    // Sector 0..2 within 0°..45°, mirrored about the diagonal to 4..2 when steep.
    const uint32_t s = static_cast<uint32_t>((lo << 8) > times_51(hi)) +
                       static_cast<uint32_t>((lo << 8) > times_171(hi));
    const uint32_t q = steep ? 4u - s : s;
    // Quadrants: bin = q (+x,+y), 8 - q (-x,+y), 8 + q (-x,-y), 16 - q (+x,-y), i.e.
    // 8·[gx < 0] ± q modulo 16, with q negated when exactly one component is negative.
    const uint32_t nx = gx < 0, ny = gy < 0;
    const uint32_t negate = 0u - (nx ^ ny);  // all ones or zero
    return ((nx << 3) + ((q ^ negate) - negate)) & 15u;
}

// Pack gx, gy (each -255..255) with their L1 magnitude and direction bin.
constexpr gradient_word make_gradient_word(int32_t gx, int32_t gy) {
    const uint32_t mag = static_cast<uint32_t>((gx < 0 ? -gx : gx) + (gy < 0 ? -gy : gy));
    return ((static_cast<uint32_t>(gx) & gw::field_mask(gw::kGxBits)) << gw::kGxLsb) |
           ((static_cast<uint32_t>(gy) & gw::field_mask(gw::kGyBits)) << gw::kGyLsb) |
           (mag << gw::kMagLsb) | (direction_bin(gx, gy) << gw::kDirLsb);
}

// gx and gy (each -255..255) alone, magnitude and direction bin 0: for a consumer that reads
// nothing else (the Harris detector), without the direction's work.
constexpr gradient_word make_gradient_word_xy(int32_t gx, int32_t gy) {
    return ((static_cast<uint32_t>(gx) & gw::field_mask(gw::kGxBits)) << gw::kGxLsb) |
           ((static_cast<uint32_t>(gy) & gw::field_mask(gw::kGyBits)) << gw::kGyLsb);
}

// The word that completes a broken-off frame's row: no gradient (magnitude 0), fill bit set.
constexpr gradient_word kFillWord = gradient_word{1} << gw::kFillBit;
constexpr bool gradient_fill(gradient_word w) { return ((w >> gw::kFillBit) & 1u) != 0; }

// Field accessors. Sign extension by xor-and-subtract: no shift of a negative value.
constexpr int32_t gradient_gx(gradient_word w) {
    return static_cast<int32_t>(((w >> gw::kGxLsb) & 0x1FFu) ^ 0x100u) - 0x100;
}
constexpr int32_t gradient_gy(gradient_word w) {
    return static_cast<int32_t>(((w >> gw::kGyLsb) & 0x1FFu) ^ 0x100u) - 0x100;
}
constexpr uint32_t gradient_mag(gradient_word w) {
    return (w >> gw::kMagLsb) & gw::field_mask(gw::kMagBits);
}
constexpr uint32_t gradient_dir(gradient_word w) {
    return (w >> gw::kDirLsb) & gw::field_mask(gw::kDirBits);
}

}  // namespace qt
