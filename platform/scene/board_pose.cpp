#include "scene/board_pose.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/det_math.h"
#include "scene/random.h"

namespace qt::scene {

namespace {

constexpr double kPlacementMargin = 4;  // px between placed corners and the outermost pixel centres

struct Vec3 {
    double x, y, z;
};

Vec3 add(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 mul(Vec3 a, double k) { return {a.x * k, a.y * k, a.z * k}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Rodrigues: v turned by the angle with sine s and cosine c about the unit axis k.
Vec3 rotate(Vec3 v, Vec3 k, double s, double c) {
    return add(add(mul(v, c), mul(cross(k, v), s)), mul(k, dot(k, v) * (1 - c)));
}

// The board in camera coordinates: unit axes e1 (display x) and e2 (display y) for a board of
// height 1 and width `aspect`, centred on a point of depth z on the viewing ray (rx, ry, 1).
struct Board {
    Vec3 e1, e2;
    double u[4], v[4];  // corner coordinates on the board: TL, BL, BR, TR
};

Board make_board(const BoardPose& pose, double aspect) {
    Board b{};
    double sr, cr, st, ct, sa, ca;
    det_sincos(det_radians(pose.rotation_deg), sr, cr);
    det_sincos(det_radians(pose.tilt_deg), st, ct);
    det_sincos(det_radians(pose.tilt_axis_deg), sa, ca);
    const Vec3 axis{ca, sa, 0};
    b.e1 = rotate(Vec3{cr, sr, 0}, axis, st, ct);
    b.e2 = rotate(Vec3{-sr, cr, 0}, axis, st, ct);
    const double hw = aspect / 2;
    const double us[4] = {-hw, -hw, hw, hw}, vs[4] = {-0.5, 0.5, 0.5, -0.5};
    for (int i = 0; i < 4; ++i) b.u[i] = us[i], b.v[i] = vs[i];
    return b;
}

void project(const PinholeCamera& cam, const Board& b, double rx, double ry, double z,
             Point2 out[4]) {
    for (int i = 0; i < 4; ++i) {
        const Vec3 p = add(Vec3{z * rx, z * ry, z}, add(mul(b.e1, b.u[i]), mul(b.e2, b.v[i])));
        out[i] = {cam.cx + cam.f * p.x / p.z, cam.cy + cam.f * p.y / p.z};
    }
}

struct Box {
    double x0, x1, y0, y1;
};

Box bbox(const Point2 p[4]) {
    Box b{p[0].x, p[0].x, p[0].y, p[0].y};
    for (int i = 1; i < 4; ++i) {
        b.x0 = std::min(b.x0, p[i].x), b.x1 = std::max(b.x1, p[i].x);
        b.y0 = std::min(b.y0, p[i].y), b.y1 = std::max(b.y1, p[i].y);
    }
    return b;
}

double scale_of(const PinholeCamera& cam, const Point2 p[4]) {
    const Box b = bbox(p);
    return std::max((b.x1 - b.x0) / cam.w, (b.y1 - b.y0) / cam.h);
}

// The depth on ray (rx, ry) at which the projected board has the given scale, by bisection
// (a fixed number of halvings, so the result is deterministic).
double solve_depth(const PinholeCamera& cam, const Board& b, double rx, double ry, double target) {
    double nearest = 0;  // the depth at which a corner reaches the camera plane
    for (int i = 0; i < 4; ++i) nearest = std::max(nearest, -(b.u[i] * b.e1.z + b.v[i] * b.e2.z));
    Point2 p[4];
    double lo = nearest * (1 + 1e-9) + 1e-9;
    double hi = cam.f * std::max(b.u[3] * 2 / cam.w, 1.0 / cam.h) / target * 2 + lo;
    for (int k = 0; k < 200; ++k) {  // make sure scale(hi) < target
        project(cam, b, rx, ry, hi, p);
        if (scale_of(cam, p) < target) break;
        hi *= 2;
    }
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        project(cam, b, rx, ry, mid, p);
        (scale_of(cam, p) > target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The corners of board b, scaled by `scale`, on the ray corrected until the bbox centre lands
// at (tx, ty).
void project_centred(const PinholeCamera& cam, const Board& b, double scale, double tx, double ty,
                     Point2 p[4]) {
    double rx = (tx - cam.cx) / cam.f, ry = (ty - cam.cy) / cam.f;
    for (int it = 0; it < 12; ++it) {
        project(cam, b, rx, ry, solve_depth(cam, b, rx, ry, scale), p);
        const Box box = bbox(p);
        rx += (tx - 0.5 * (box.x0 + box.x1)) / cam.f;
        ry += (ty - 0.5 * (box.y0 + box.y1)) / cam.f;
    }
    project(cam, b, rx, ry, solve_depth(cam, b, rx, ry, scale), p);
}

double shoelace(
    const Point2 p[4]) {  // Σ x_i·y_{i+1} − x_{i+1}·y_i, px²; < 0: anti-clockwise as seen
    double s = 0;
    for (int i = 0; i < 4; ++i) s += p[i].x * p[(i + 1) % 4].y - p[(i + 1) % 4].x * p[i].y;
    return s;
}

bool convex_anticlockwise(const Point2 p[4]) {  // every turn has the sign of a negative shoelace
    for (int i = 0; i < 4; ++i) {
        const Point2 a = p[i], b = p[(i + 1) % 4], c = p[(i + 2) % 4];
        if (!((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0)) return false;
    }
    return shoelace(p) < 0;
}

// Distance along the unit direction (dx, dy) from p (inside the frame) to beyond the frame.
double exit_distance(Point2 p, double dx, double dy, int w, int h) {
    double t = 1e300;
    if (dx > 0) t = std::min(t, (w + 1 - p.x) / dx);
    if (dx < 0) t = std::min(t, (-2 - p.x) / dx);
    if (dy > 0) t = std::min(t, (h + 1 - p.y) / dy);
    if (dy < 0) t = std::min(t, (-2 - p.y) / dy);
    return t + 2;
}

}  // namespace

PinholeCamera centred_camera(int w, int h, double focal_px) {
    return {focal_px > 0 ? focal_px : static_cast<double>(w), (w - 1) / 2.0, (h - 1) / 2.0, w, h};
}

void project_board_at(const PinholeCamera& cam, double aspect, const BoardPose& pose, double tx,
                      double ty, Point2 out[4]) {
    project_centred(cam, make_board(pose, aspect), pose.scale, tx, ty, out);
}

bool board_fits(const PinholeCamera& cam, const Point2 p[4], double margin) {
    for (int i = 0; i < 4; ++i)
        if (!(p[i].x >= margin && p[i].x <= cam.w - 1 - margin && p[i].y >= margin &&
              p[i].y <= cam.h - 1 - margin))
            return false;
    return convex_anticlockwise(p);
}

BoardPose place_board(const PinholeCamera& cam, double aspect, const PoseRanges& r, Pcg32& rng,
                      Point2 corners[4]) {
    BoardPose pose;
    pose.tilt_deg = uniform(rng, r.tilt_deg_min, r.tilt_deg_max);
    pose.tilt_axis_deg = uniform(rng, 0, 360);
    pose.rotation_deg = uniform(rng, r.rotation_deg_min, r.rotation_deg_max);
    pose.scale = uniform(rng, r.scale_min, r.scale_max);
    const Board b = make_board(pose, aspect);

    Point2 p[4];
    project(cam, b, 0, 0, solve_depth(cam, b, 0, 0, pose.scale), p);
    Box box = bbox(p);
    for (int attempt = 0; attempt < 500; ++attempt) {
        // A bbox centre drawn where the last bbox size fits; the ray is then corrected until
        // the bbox centre lands there (the shape changes a little off the axis).
        const double bw = box.x1 - box.x0, bh = box.y1 - box.y0;
        const double m = kPlacementMargin;
        const double lx = m + bw / 2, hx = cam.w - 1 - m - bw / 2;
        const double ly = m + bh / 2, hy = cam.h - 1 - m - bh / 2;
        const double tx = lx <= hx ? uniform(rng, lx, hx) : cam.cx,
                     ty = ly <= hy ? uniform(rng, ly, hy) : cam.cy;
        project_centred(cam, b, pose.scale, tx, ty, p);
        box = bbox(p);
        if (board_fits(cam, p, kPlacementMargin)) {
            for (int i = 0; i < 4; ++i) corners[i] = p[i];
            return pose;
        }
    }
    throw std::runtime_error("place_board: no board placement");
}

double point_distance(Point2 a, Point2 b) {
    return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
}

double inside_distance(Point2 a, Point2 b, Point2 q) {
    const double len = point_distance(a, b);
    return ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / -len;
}

std::vector<Point2> arm_tip(Point2 a, Point2 b, double dx, double dy, double cos_phi, double width,
                            double depth) {
    const double back = depth / cos_phi;  // along the arm: (d · n) = cos φ
    const Point2 ai{a.x - dx * back, a.y - dy * back}, bi{b.x - dx * back, b.y - dy * back};
    const double cap = 0.5 * width * cos_phi;  // tip depth along the arm, px
    std::vector<Point2> tip;                   // half ellipse on chord ai-bi, from ai to bi
    const Point2 m{0.5 * (ai.x + bi.x), 0.5 * (ai.y + bi.y)};
    for (int k = 0; k <= 8; ++k) {
        double sk, ck;
        det_sincos(kPi * (1 - k / 8.0), sk, ck);
        tip.push_back(
            {m.x + (bi.x - m.x) * ck - dx * cap * sk, m.y + (bi.y - m.y) * ck - dy * cap * sk});
    }
    return tip;
}

std::vector<Point2> arm_outline(Point2 a, Point2 b, const std::vector<Point2>& tip, double dx,
                                double dy, int w, int h) {
    const double far = std::max(exit_distance(a, dx, dy, w, h), exit_distance(b, dx, dy, w, h));
    std::vector<Point2> outline{{a.x + dx * far, a.y + dy * far}};
    outline.insert(outline.end(), tip.begin(), tip.end());
    outline.push_back({b.x + dx * far, b.y + dy * far});
    return outline;
}

Occluder arm_occluder(const Point2 c[4], int board_level, const ArmLimits& limits, int w, int h,
                      Pcg32& rng) {
    Occluder out;
    int eligible[4], n = 0;
    for (int i = 0; i < 4; ++i)
        if (point_distance(c[i], c[(i + 1) % 4]) >= 30) eligible[n++] = i;
    if (n == 0) return out;
    for (int attempt = 0; attempt < 200; ++attempt) {
        const int side = eligible[rng.below(static_cast<uint32_t>(n))];
        const Point2 p = c[side], q = c[(side + 1) % 4];
        const double len = point_distance(p, q);
        const double end =
            std::max(limits.end_px, limits.end_fraction * len);  // px visible at each end
        const double ex = (q.x - p.x) / len, ey = (q.y - p.y) / len;
        const double nx = -ey, ny = ex;  // outward normal for an anti-clockwise-as-seen board
        const double width = uniform(
            rng, 10, std::min(limits.max_fraction * len, len - 2 * end));  // along the side, px
        const double start = uniform(rng, end, len - end - width);
        double sp, cp;
        det_sincos(det_radians(uniform(rng, -30, 30)), sp, cp);
        const double dx = nx * cp - ny * sp, dy = nx * sp + ny * cp;  // arm direction, outward
        const int level = uniform_int(rng, 20, board_level - 60);
        double extent = 0;  // px, the board's depth across the side
        for (int j = 0; j < 4; ++j) extent = std::max(extent, inside_distance(p, q, c[j]));
        double depth =
            uniform(rng, 6, std::max(6.0, std::min(40.0, 0.35 * extent)));  // px, across the side
        const Point2 a{p.x + ex * start, p.y + ey * start},
            b{p.x + ex * (start + width), p.y + ey * (start + width)};
        for (; depth >= 6; depth *= 0.5) {
            const std::vector<Point2> tip = arm_tip(a, b, dx, dy, cp, width, depth);
            bool inside = true;
            for (const Point2& t : tip)
                for (int j = 0; j < 4; ++j)
                    inside = inside && inside_distance(c[j], c[(j + 1) % 4], t) >= 4;
            if (!inside) continue;
            out.outline = arm_outline(a, b, tip, dx, dy, w, h);
            out.level = level;
            out.side = side;
            out.from = start / len;
            out.to = (start + width) / len;
            return out;
        }
    }
    return out;
}

}  // namespace qt::scene
