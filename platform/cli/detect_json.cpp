#include "cli/detect_json.h"

#include <cstdio>

#include "quads/display_homography.h"

namespace qt::cli {

namespace {

// Fixed-point values in decimal: q16_16 pixels to 1e-4 px (finer than their 1.5e-5 step
// matters to nobody), angles to 1e-4 degree, homography entries to 9 significant digits.
void px(std::string& out, q16_16 v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", v.raw / 65536.0);
    out += buf;
}

void number(std::string& out, const char* format, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    out += buf;
}

void homography(std::string& out, const Point16 (&corners)[4], uint16_t w, uint16_t h) {
    DisplayHomography m;
    if (!display_homography(corners, w, h, m)) {
        out += "null";
        return;
    }
    const double r20 = 1.0 / (1 << 20), r16 = 1.0 / 65536, r30 = 1.0 / (1 << 30);
    const double e[9] = {m.a.raw * r20, m.b.raw * r20, m.c.raw * r16,
                         m.d.raw * r20, m.e.raw * r20, m.f.raw * r16,
                         m.g.raw * r30, m.h.raw * r30, 1.0};
    out += "[";
    for (int i = 0; i < 9; ++i) {
        out += i % 3 == 0 ? (i == 0 ? "[" : "],[") : ",";
        number(out, "%.9g", e[i]);
    }
    out += "]]";
}

// "width":W,"height":H,"bin":N,"status":"...","full":[...] (no braces). "full" names each
// capacity or work budget that filled (status capacity_exceeded exactly when one did).
void frame_fields(std::string& out, const host::DetectResult& r) {
    out += "\"width\":" + std::to_string(r.width) + ",\"height\":" + std::to_string(r.height) +
           ",\"bin\":" + std::to_string(r.bin) + ",\"status\":\"" +
           (r.status == Status::ok ? "ok" : "capacity_exceeded") + "\",\"full\":[";
    const LineStats& l = r.line_stats;
    const bool filled[] = {l.edges_dropped > 0,
                           l.hough.voters_exhausted,
                           l.hough.budget_exhausted,
                           l.hough.segments_dropped > 0,
                           l.cluster.clusters_dropped > 0,
                           r.quad_stats.pairs_dropped > 0};
    static const char* const kNames[] = {"edges",    "voters", "walk_steps",
                                         "segments", "lines",  "pairs"};
    bool first = true;
    for (size_t i = 0; i < sizeof filled / sizeof filled[0]; ++i) {
        if (!filled[i]) continue;
        out += first ? "\"" : ",\"";
        out += kNames[i];
        out += "\"";
        first = false;
    }
    out += "]";
}

// [{"x1":..,...,"theta_deg":..}, ...]
void lines_array(std::string& out, const host::DetectResult& r) {
    out += "[";
    for (size_t i = 0; i < r.lines.size(); ++i) {
        const Segment& s = r.lines[i];
        out += i ? ",{\"x1\":" : "{\"x1\":";
        px(out, s.x1);
        out += ",\"y1\":";
        px(out, s.y1);
        out += ",\"x2\":";
        px(out, s.x2);
        out += ",\"y2\":";
        px(out, s.y2);
        out += ",\"rho\":";
        px(out, s.rho);
        out += ",\"theta_deg\":";
        number(out, "%.4f", s.theta / 4294967296.0 * 360.0);
        out += "}";
    }
    out += "]";
}

// [[x,y],[x,y],[x,y],[x,y]]
void corners_array(std::string& out, const Point16 (&corners)[4]) {
    for (int k = 0; k < 4; ++k) {
        out += k ? ",[" : "[[";
        px(out, corners[k].x);
        out += ",";
        px(out, corners[k].y);
        out += "]";
    }
    out += "]";
}

}  // namespace

std::string detect_json(const host::DetectResult& r, uint16_t display_width,
                        uint16_t display_height) {
    std::string out = "{";
    frame_fields(out, r);
    out += ",\"lines\":";
    lines_array(out, r);
    out += ",\"quads\":[";
    for (size_t i = 0; i < r.quads.size(); ++i) {
        const Quad& q = r.quads[i];
        out += i ? ",{\"corners\":" : "{\"corners\":";
        corners_array(out, q.corners);
        out += ",\"score\":";
        number(out, "%.4f", q.score.raw / 65536.0);
        out += ",\"display_homography\":";
        homography(out, q.corners, display_width, display_height);
        out += "}";
    }
    out += "]}";
    return out;
}

std::string track_json(int frame, const host::DetectResult& r, const TrackedQuad& t, q16_16 score,
                       QuadTrackLost lost_reason, uint16_t display_width, uint16_t display_height,
                       bool with_lines) {
    const bool has_quad = t.state != TrackState::none;
    std::string out = "{\"frame\":" + std::to_string(frame) + ",";
    frame_fields(out, r);
    out += ",\"state\":\"";
    out += track_state_name(t.state);
    out += "\",\"track_id\":" + std::to_string(has_quad ? t.track_id : 0) + ",\"quad\":";
    if (has_quad) {
        out += "{\"corners\":";
        corners_array(out, t.corners);
        out += ",\"source\":[";
        for (int i = 0; i < 4; ++i) {
            out += i ? "," : "";
            out += (t.detected >> i) & 1 ? "\"detected\"" : "\"predicted\"";
        }
        out += "],\"score\":";
        number(out, "%.4f", score.raw / 65536.0);
        out += ",\"display_homography\":";
        homography(out, t.corners, display_width, display_height);
        out += "}";
    } else {
        out += "null";
    }
    out += ",\"lost\":";
    const char* lost = quad_track_lost_name(lost_reason);
    out += lost ? std::string("\"") + lost + "\"" : std::string("null");
    if (with_lines) {
        out += ",\"lines\":";
        lines_array(out, r);
    }
    out += "}";
    return out;
}

}  // namespace qt::cli
