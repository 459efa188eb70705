// Minimal PNG writer for pictures a person can open: 8-bit grey or RGB, no compression
// (stored deflate blocks), CRC-32 and Adler-32 as the format requires. Host only.
#pragma once
#include <stdint.h>

#include <string>
#include <vector>

namespace qt::io {

// channels = 1 (grey) or 3 (RGB); pixels row-major, width·height·channels bytes.
// Returns false and sets error on a bad size or an I/O failure.
bool write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& pixels, std::string& error);

}  // namespace qt::io
