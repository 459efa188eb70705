#include "api/result_text.h"

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

// " x0 y0 x1 y1 x2 y2 x3 y3"
char* put_corners(char* p, const Point16 (&corners)[4]) {
    for (const Point16& c : corners) {
        *p++ = ' ';
        p = put_int(p, c.x.raw);
        *p++ = ' ';
        p = put_int(p, c.y.raw);
    }
    return p;
}

size_t end_line(char* out, char* p) {
    *p++ = '\n';
    *p = 0;
    return static_cast<size_t>(p - out);
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
    return end_line(out, p);
}

size_t format_line_text(const Segment& s, char* out) {
    const int64_t fields[] = {
        s.x1.raw, s.y1.raw, s.x2.raw, s.y2.raw,     s.rho.raw, static_cast<int64_t>(s.theta),
        s.cx.raw, s.cy.raw, s.points, s.bright_side};
    char* p = out;
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; ++i) {
        if (i != 0) *p++ = ' ';
        p = put_int(p, fields[i]);
    }
    return end_line(out, p);
}

size_t format_quads_header(uint16_t quads, Status status, char* out) {
    char* p = put_text(out, "quads ", 6);
    p = put_int(p, quads);
    p = put_text(p, " status ", 8);
    p = put_text(p, status_name(status), 40);
    return end_line(out, p);
}

size_t format_quad_text(const Quad& q, char* out) {
    char* p = put_text(out, "quad", 4);
    p = put_corners(p, q.corners);
    *p++ = ' ';
    p = put_int(p, q.score.raw);
    for (uint8_t line : q.lines) {
        *p++ = ' ';
        p = put_int(p, line);
    }
    return end_line(out, p);
}

size_t format_track_text(const TrackedQuad& t, QuadTrackLost lost_reason, char* out) {
    char* p = put_text(out, "track ", 6);
    p = put_text(p, track_state_name(t.state), 10);
    *p++ = ' ';
    p = put_int(p, t.track_id);
    *p++ = ' ';
    p = put_int(p, t.age);
    *p++ = ' ';
    p = put_int(p, t.detected);
    *p++ = ' ';
    const char* lost = quad_track_lost_name(lost_reason);
    p = put_text(p, lost != nullptr ? lost : "-", 24);
    if (t.state != TrackState::none) p = put_corners(p, t.corners);
    return end_line(out, p);
}

}  // namespace qt
