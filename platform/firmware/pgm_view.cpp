#include "pgm_view.h"

static bool is_space(uint8_t c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// Skips whitespace and comments; false if there was none (a token must follow whitespace).
static bool skip_separator(const uint8_t*& p, const uint8_t* end) {
    const uint8_t* start = p;
    while (p != end) {
        if (is_space(*p)) {
            ++p;
        } else if (*p == '#') {
            while (p != end && *p != '\n' && *p != '\r') ++p;
        } else {
            break;
        }
    }
    return p != start;
}

// A decimal number of 1..5 digits, not followed by another digit.
static bool parse_number(const uint8_t*& p, const uint8_t* end, uint32_t& value) {
    value = 0;
    unsigned digits = 0;
    while (p != end && *p >= '0' && *p <= '9') {
        if (++digits > 5) return false;
        value = value * 10u + static_cast<uint32_t>(*p - '0');
        ++p;
    }
    return digits != 0;
}

Pgm parse_pgm(const uint8_t* p, const uint8_t* end, uint16_t max_width, uint16_t max_height) {
    Pgm pgm;
    uint32_t width = 0, height = 0, maxval = 0;
    if (end - p < 2 || p[0] != 'P' || p[1] != '5') {
        pgm.error = "not a binary PGM (magic P5)";
        return pgm;
    }
    p += 2;
    if (!skip_separator(p, end) || !parse_number(p, end, width)) {
        pgm.error = "bad width";
        return pgm;
    }
    if (!skip_separator(p, end) || !parse_number(p, end, height)) {
        pgm.error = "bad height";
        return pgm;
    }
    if (!skip_separator(p, end) || !parse_number(p, end, maxval)) {
        pgm.error = "bad maxval";
        return pgm;
    }
    if (maxval != 255) {
        pgm.error = "maxval is not 255";
        return pgm;
    }
    if (p == end || !is_space(*p)) {
        pgm.error = "no whitespace after maxval";
        return pgm;
    }
    ++p;  // exactly one: the raster may start with a byte that looks like whitespace
    if (width == 0 || height == 0 || width > max_width || height > max_height) {
        pgm.error = "size is 0 or over the capacity";
        return pgm;
    }
    if (static_cast<uint32_t>(end - p) != width * height) {
        pgm.error = "raster is not width x height bytes";
        return pgm;
    }
    pgm.raster = p;
    pgm.width = static_cast<uint16_t>(width);
    pgm.height = static_cast<uint16_t>(height);
    return pgm;
}
