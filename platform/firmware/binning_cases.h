// The binning stage's cross-target cases (core/gradient/binning.h): frames whose pixels are a
// hash of their coordinates, so that a target makes any row on the fly without a frame buffer.
// Shared by the Cortex-M image binning_check (which bins them on the target and compares every
// output pixel with a brute-force block mean computed there) and the host test
// tests/gradient/test_binning.cpp (which holds the stage and these checksums to a
// double-precision reference). The checksums were computed by that reference, not by the stage.
#pragma once
#include <stdint.h>

namespace qt {

struct BinningCase {
    const char* name;
    uint16_t width, height;  // input, px
    uint8_t factor;
    uint32_t seed;
    uint8_t mode;       // 0: hashed grey levels; 1: only 0 and 255 (block sums up to N²·255)
    uint32_t checksum;  // FNV-1a of the binned frame's bytes in row order
};

// The grey level of pixel (x, y) of a case with `seed` and `mode`.
constexpr uint8_t binning_pixel(uint32_t seed, uint8_t mode, uint32_t x, uint32_t y) {
    uint32_t h = seed * 0x9E3779B9u ^ x * 0x85EBCA6Bu ^ y * 0xC2B2AE35u;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    const uint8_t v = static_cast<uint8_t>(h >> 24);
    return mode == 1 ? (v < 64 ? 0 : 255) : v;
}

// FNV-1a, 32 bits: the running hash after one more byte.
constexpr uint32_t fnv1a(uint32_t hash, uint8_t byte) { return (hash ^ byte) * 16777619u; }
constexpr uint32_t kFnvOffset = 2166136261u;

// Odd sizes, sizes not divisible by the factor, the camera sizes of the CLI, the largest factor.
constexpr BinningCase kBinningCases[] = {
    {"odd_333x217_by2", 333, 217, 2, 1, 0, 0x10b83fddu},
    {"odd_333x217_by3", 333, 217, 3, 2, 0, 0x3dfc69d7u},
    {"odd_101x77_by1", 101, 77, 1, 3, 0, 0xb7a354bcu},
    {"720p_by2", 1280, 720, 2, 4, 0, 0x355950a9u},
    {"1921x1081_by3", 1921, 1081, 3, 5, 0, 0x9b3644beu},
    {"576p_by2", 768, 576, 2, 6, 0, 0xd9262533u},
    {"saturated_1283x963_by4", 1283, 963, 4, 7, 1, 0x6d72b766u},
    {"by16_650x490", 650, 490, 16, 8, 1, 0x39a94c42u},
};
constexpr int kBinningCaseCount = sizeof kBinningCases / sizeof kBinningCases[0];

}  // namespace qt
