#include "line_text.h"

namespace qt {

namespace {

char* put_int(char* p, int64_t v) {
    char digits[24];
    int n = 0;
    const bool negative = v < 0;
    uint64_t u = negative ? static_cast<uint64_t>(-(v + 1)) + 1u : static_cast<uint64_t>(v);
    do {
        digits[n++] = static_cast<char>('0' + u % 10u);
        u /= 10u;
    } while (u != 0);
    if (negative) *p++ = '-';
    while (n > 0) *p++ = digits[--n];
    return p;
}

char* put_text(char* p, const char* text, size_t max) {
    for (size_t i = 0; i < max && text[i] != 0; ++i) *p++ = text[i];
    return p;
}

}  // namespace

size_t format_frame_header(const char* name, uint32_t edges, uint32_t segments, uint32_t lines,
                           char* out) {
    char* p = put_text(out, "frame ", 6);
    p = put_text(p, name, 40);
    p = put_text(p, " edges ", 7);
    p = put_int(p, edges);
    p = put_text(p, " segments ", 10);
    p = put_int(p, segments);
    p = put_text(p, " lines ", 7);
    p = put_int(p, lines);
    *p++ = '\n';
    *p = 0;
    return static_cast<size_t>(p - out);
}

size_t format_line_text(const Segment& s, char* out) {
    const int64_t fields[] = {s.x1.raw, s.y1.raw, s.x2.raw, s.y2.raw, s.rho.raw,
                              static_cast<int64_t>(s.theta), s.cx.raw, s.cy.raw, s.points, s.bright_side};
    char* p = out;
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; ++i) {
        if (i != 0) *p++ = ' ';
        p = put_int(p, fields[i]);
    }
    *p++ = '\n';
    *p = 0;
    return static_cast<size_t>(p - out);
}

}  // namespace qt
