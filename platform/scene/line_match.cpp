#include "scene/line_match.h"

#include <algorithm>
#include <cmath>

namespace qt::scene {

namespace {

constexpr double kPi = 3.14159265358979323846;

double orientation_deg(Point2 a, Point2 b) {
    return std::atan2(b.y - a.y, b.x - a.x) * 180.0 / kPi;
}

double orientation_error(double a, double b) {
    const double d = std::fmod(std::fabs(a - b), 180.0);
    return std::min(d, 180.0 - d);
}

double dist(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Distance from p to the segment a-b.
double dist_to_segment(Point2 p, Point2 a, Point2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return dist(p, {a.x + t * dx, a.y + t * dy});
}

}  // namespace

MatchResult match_lines(const std::vector<TrueSegment>& truth,
                        const std::vector<DetectedLine>& detected, const MatchRule& rule) {
    MatchResult r;
    r.detected = static_cast<int>(detected.size());
    for (const TrueSegment& t : truth) {
        if (dist(t.a, t.b) < rule.min_length) continue;
        ++r.scored;
        for (const DetectedLine& d : detected) {
            const double angle =
                orientation_error(orientation_deg(t.a, t.b), orientation_deg(d.a, d.b));
            const double ends = std::min(std::max(dist(d.a, t.a), dist(d.b, t.b)),
                                         std::max(dist(d.a, t.b), dist(d.b, t.a)));
            if (angle <= rule.max_angle_deg && ends <= rule.max_endpoint_px) {
                ++r.found;
                r.worst_angle_deg = std::max(r.worst_angle_deg, angle);
                r.worst_endpoint_px = std::max(r.worst_endpoint_px, ends);
                break;
            }
        }
    }
    // A detection is true when both of its ends lie within 3 px of one truth segment (of any
    // length) and its orientation is within 3° of that segment's: a piece of a real edge.
    for (const DetectedLine& d : detected) {
        bool on_truth = false;
        for (const TrueSegment& t : truth)
            on_truth =
                on_truth ||
                (dist_to_segment(d.a, t.a, t.b) <= 3 && dist_to_segment(d.b, t.a, t.b) <= 3 &&
                 orientation_error(orientation_deg(t.a, t.b), orientation_deg(d.a, d.b)) <= 3);
        if (!on_truth) ++r.false_positives;
    }
    return r;
}

}  // namespace qt::scene
