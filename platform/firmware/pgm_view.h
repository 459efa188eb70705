// A binary greymap (netpbm P5) linked into flash, viewed in place: no copy of the raster.
// Format: "P5", width, height, maxval as decimal ASCII separated by whitespace (and '#'
// comments to the end of a line), exactly one whitespace character, then width × height bytes
// and nothing after them. Only maxval 255 (one byte per pixel).
#pragma once
#include <stdint.h>

struct Pgm {
    const char* error = nullptr;  // why the file was rejected, or nullptr
    const uint8_t* raster = nullptr;
    uint16_t width = 0, height = 0;
};

// The PGM in [p, end), or .error saying why it was refused; sizes over max_width × max_height
// are refused too.
Pgm parse_pgm(const uint8_t* p, const uint8_t* end, uint16_t max_width, uint16_t max_height);
