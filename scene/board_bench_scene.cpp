#include "board_bench_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "det_math.h"
#include "prng.h"
#include "random.h"

namespace qt::scene {

namespace {

constexpr double kMargin = 4;  // px between the board corners and the outermost pixel centres

// One PCG stream per purpose: a board-free frame of the same seed draws the same levels,
// lighting, clutter and noise as the frame with the board (LineScene's own streams, seeded
// with the same seed, are different constants).
constexpr uint64_t kStreamPose = 0xb0a4d9053u, kStreamLook = 0xb0a4d1008u, kStreamClutter = 0xb0a4dc1a7u,
                   kStreamOcclusion = 0xb0a4d0cc1u;

int uniform_int(Pcg32& rng, int lo, int hi) {  // [lo, hi], lo <= hi
    return lo + static_cast<int>(rng.below(static_cast<uint32_t>(hi - lo + 1)));
}

struct Vec3 {
    double x, y, z;
};

Vec3 add(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 mul(Vec3 a, double k) { return {a.x * k, a.y * k, a.z * k}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Rodrigues: v turned by the angle with sine s and cosine c about the unit axis k.
Vec3 rotate(Vec3 v, Vec3 k, double s, double c) {
    return add(add(mul(v, c), mul(cross(k, v), s)), mul(k, dot(k, v) * (1 - c)));
}

// The board in camera coordinates (x right, y down, z forward): unit axes e1 (display x) and
// e2 (display y) for a board of height 1 and width `aspect`, centred on a point of depth z
// on the viewing ray (rx, ry, 1).
struct Camera {
    double f, cx, cy;  // px
    int w, h;          // px
};

struct Board {
    Vec3 e1, e2;
    double u[4], v[4];  // corner coordinates on the board: TL, BL, BR, TR
};

void project(const Camera& cam, const Board& b, double rx, double ry, double z, Point2 out[4]) {
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

double scale_of(const Camera& cam, const Point2 p[4]) {
    const Box b = bbox(p);
    return std::max((b.x1 - b.x0) / cam.w, (b.y1 - b.y0) / cam.h);
}

// The depth on ray (rx, ry) at which the projected board has the given scale, by bisection
// (a fixed number of halvings, so the result is deterministic).
double solve_depth(const Camera& cam, const Board& b, double rx, double ry, double target) {
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

double shoelace(const Point2 p[4]) {  // Σ x_i·y_{i+1} − x_{i+1}·y_i, px²; < 0: anti-clockwise as seen
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

bool fits(const Camera& cam, const Point2 p[4]) {
    for (int i = 0; i < 4; ++i)
        if (!(p[i].x >= kMargin && p[i].x <= cam.w - 1 - kMargin && p[i].y >= kMargin && p[i].y <= cam.h - 1 - kMargin))
            return false;
    return true;
}

double distance(Point2 a, Point2 b) { return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y)); }

// Signed distance of q from the side a -> b of an anti-clockwise-as-seen polygon, px;
// positive inside.
double inside_distance(Point2 a, Point2 b, Point2 q) {
    const double len = distance(a, b);
    return ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / -len;
}

// Grey level of clutter: in 10..background − 25 or background + 25..board − 50.
int clutter_level(Pcg32& rng, int background, int board) {
    const int dark = std::max(0, background - 25 - 10 + 1);
    const int bright = std::max(0, board - 50 - (background + 25) + 1);
    const int i = uniform_int(rng, 0, dark + bright - 1);
    return i < dark ? 10 + i : background + 25 + (i - dark);
}

// Vertices of a random clutter shape centred at (cx, cy): 0 a triangle with inner angles
// >= 13°, 1 a thin bar (length 6–14 × its width), 2 a parallelogram with a 15–40° angle.
std::vector<Point2> clutter_shape(Pcg32& rng, int kind, double cx, double cy, double base) {
    double s, c;
    det_sincos(uniform(rng, 0, 2 * kPi), s, c);  // orientation
    std::vector<Point2> local;                   // before turning and moving
    if (kind == 0) {
        const double r = uniform(rng, 0.04, 0.15) * base;
        double a[3];
        for (;;) {  // arcs between the vertices >= 0.45 rad: inner angles >= 0.225 rad
            for (double& t : a) t = uniform(rng, 0, 2 * kPi);
            std::sort(a, a + 3);
            if (a[1] - a[0] >= 0.45 && a[2] - a[1] >= 0.45 && 2 * kPi - (a[2] - a[0]) >= 0.45) break;
        }
        for (double t : a) {
            double st, ct;
            det_sincos(t, st, ct);
            local.push_back({r * ct, r * st});
        }
    } else if (kind == 1) {
        const double len = uniform(rng, 0.1, 0.45) * base;
        const double wid = std::max(2.0, len / uniform(rng, 6, 14));
        local = {{-len / 2, -wid / 2}, {len / 2, -wid / 2}, {len / 2, wid / 2}, {-len / 2, wid / 2}};
    } else {
        const double a = uniform(rng, 0.08, 0.3) * base, b = a * uniform(rng, 0.5, 1.2);
        double sa, ca;
        det_sincos(det_radians(uniform(rng, 15, 40)), sa, ca);
        const double ox = -(a + b * ca) / 2, oy = -(b * sa) / 2;  // centre the parallelogram
        local = {{ox, oy}, {ox + a, oy}, {ox + a + b * ca, oy + b * sa}, {ox + b * ca, oy + b * sa}};
    }
    std::vector<Point2> out;
    for (const Point2& p : local) out.push_back({cx + p.x * c - p.y * s, cy + p.x * s + p.y * c});
    return out;
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

void check(const BoardBenchOptions& o) {
    const bool ok =
        o.width >= 64 && o.height >= 48 && o.aspect >= 0.25 && o.aspect <= 4 && o.focal_px >= 0 &&
        std::isfinite(o.focal_px) && o.tilt_deg_min >= 0 && o.tilt_deg_min <= o.tilt_deg_max &&
        o.tilt_deg_max <= 80 && o.rotation_deg_min >= -180 && o.rotation_deg_min <= o.rotation_deg_max &&
        o.rotation_deg_max <= 180 && o.scale_min > 0 && o.scale_min <= o.scale_max &&
        o.scale_max <= std::min((o.width - 9.0) / o.width, (o.height - 9.0) / o.height) &&
        o.noise_sigma_min >= 0 && o.noise_sigma_min <= o.noise_sigma_max && std::isfinite(o.noise_sigma_max) &&
        o.blur_sigma_min >= 0 && o.blur_sigma_min <= o.blur_sigma_max && o.blur_sigma_max <= 10 &&
        o.light_gain_min > 0 && o.light_gain_min <= 1 && o.board_level_min >= 130 &&
        o.board_level_min <= o.board_level_max && o.board_level_max <= 255 && o.clutter_texture >= 0 &&
        o.clutter_blobs >= 0 && o.clutter_lines >= 0 && o.clutter_shapes >= 0;
    if (!ok) throw std::invalid_argument("make_board_bench_scene: option out of range");
}

// Places the board: draws tilt, axis, rotation and scale, then a position whose projected
// corners all fit, and returns the corners (TL, BL, BR, TR).
void place_board(const BoardBenchOptions& o, const Camera& cam, Pcg32& rng, BoardBenchScene& scene) {
    scene.tilt_deg = uniform(rng, o.tilt_deg_min, o.tilt_deg_max);
    scene.tilt_axis_deg = uniform(rng, 0, 360);
    scene.rotation_deg = uniform(rng, o.rotation_deg_min, o.rotation_deg_max);
    scene.scale = uniform(rng, o.scale_min, o.scale_max);

    Board b{};
    double sr, cr, st, ct, sa, ca;
    det_sincos(det_radians(scene.rotation_deg), sr, cr);
    det_sincos(det_radians(scene.tilt_deg), st, ct);
    det_sincos(det_radians(scene.tilt_axis_deg), sa, ca);
    const Vec3 axis{ca, sa, 0};
    b.e1 = rotate(Vec3{cr, sr, 0}, axis, st, ct);
    b.e2 = rotate(Vec3{-sr, cr, 0}, axis, st, ct);
    const double hw = o.aspect / 2;
    const double us[4] = {-hw, -hw, hw, hw}, vs[4] = {-0.5, 0.5, 0.5, -0.5};
    for (int i = 0; i < 4; ++i) b.u[i] = us[i], b.v[i] = vs[i];

    Point2 p[4];
    project(cam, b, 0, 0, solve_depth(cam, b, 0, 0, scene.scale), p);
    Box box = bbox(p);
    for (int attempt = 0; attempt < 500; ++attempt) {
        // A bbox centre drawn where the last bbox size fits; the ray is then corrected until
        // the bbox centre lands there (the shape changes a little off the axis).
        const double bw = box.x1 - box.x0, bh = box.y1 - box.y0;
        const double lx = kMargin + bw / 2, hx = cam.w - 1 - kMargin - bw / 2;
        const double ly = kMargin + bh / 2, hy = cam.h - 1 - kMargin - bh / 2;
        const double tx = lx <= hx ? uniform(rng, lx, hx) : cam.cx, ty = ly <= hy ? uniform(rng, ly, hy) : cam.cy;
        double rx = (tx - cam.cx) / cam.f, ry = (ty - cam.cy) / cam.f;
        for (int it = 0; it < 12; ++it) {
            project(cam, b, rx, ry, solve_depth(cam, b, rx, ry, scene.scale), p);
            box = bbox(p);
            rx += (tx - 0.5 * (box.x0 + box.x1)) / cam.f;
            ry += (ty - 0.5 * (box.y0 + box.y1)) / cam.f;
        }
        project(cam, b, rx, ry, solve_depth(cam, b, rx, ry, scene.scale), p);
        box = bbox(p);
        if (fits(cam, p) && convex_anticlockwise(p)) {
            for (int i = 0; i < 4; ++i) scene.corners[i] = p[i];
            return;
        }
    }
    throw std::runtime_error("make_board_bench_scene: no board placement");
}

// An arm from beyond the frame edge over part of one side: a band with a rounded tip, whose
// outer part lies wholly outside the board (rays leaving across the side cannot re-enter a
// convex board) and whose tip stays >= 4 px inside the other sides.
void add_occluder(LineScene& ls, Pcg32& rng, BoardBenchScene& scene, int w, int h) {
    const Point2* c = scene.corners;
    int eligible[4], n = 0;
    for (int i = 0; i < 4; ++i)
        if (distance(c[i], c[(i + 1) % 4]) >= 30) eligible[n++] = i;
    if (n == 0) return;
    for (int attempt = 0; attempt < 200; ++attempt) {
        const int side = eligible[rng.below(static_cast<uint32_t>(n))];
        const Point2 p = c[side], q = c[(side + 1) % 4];
        const double len = distance(p, q);
        const double ex = (q.x - p.x) / len, ey = (q.y - p.y) / len;
        const double nx = -ey, ny = ex;  // outward normal for an anti-clockwise-as-seen board
        const double width = uniform(rng, 10, std::min(0.5 * len, len - 20));  // along the side, px
        const double start = uniform(rng, 10, len - 10 - width);
        double sp, cp;
        det_sincos(det_radians(uniform(rng, -30, 30)), sp, cp);
        const double dx = nx * cp - ny * sp, dy = nx * sp + ny * cp;  // arm direction, outward
        const int level = uniform_int(rng, 20, scene.board_level - 60);
        double extent = 0;  // px, the board's depth across the side
        for (int j = 0; j < 4; ++j) extent = std::max(extent, inside_distance(p, q, c[j]));
        double depth = uniform(rng, 6, std::max(6.0, std::min(40.0, 0.35 * extent)));  // px, across the side
        const Point2 a{p.x + ex * start, p.y + ey * start}, b{p.x + ex * (start + width), p.y + ey * (start + width)};
        for (; depth >= 6; depth *= 0.5) {
            const double back = depth / cp;  // along the arm: (d · n) = cos φ
            const Point2 ai{a.x - dx * back, a.y - dy * back}, bi{b.x - dx * back, b.y - dy * back};
            const double cap = 0.5 * width * cp;  // tip depth along the arm, px
            std::vector<Point2> tip;              // half ellipse on chord ai-bi, from ai to bi
            const Point2 m{0.5 * (ai.x + bi.x), 0.5 * (ai.y + bi.y)};
            for (int k = 0; k <= 8; ++k) {
                double sk, ck;
                det_sincos(kPi * (1 - k / 8.0), sk, ck);
                tip.push_back({m.x + (bi.x - m.x) * ck - dx * cap * sk, m.y + (bi.y - m.y) * ck - dy * cap * sk});
            }
            bool inside = true;
            for (const Point2& t : tip)
                for (int j = 0; j < 4; ++j) inside = inside && inside_distance(c[j], c[(j + 1) % 4], t) >= 4;
            if (!inside) continue;
            const double far = std::max(exit_distance(a, dx, dy, w, h), exit_distance(b, dx, dy, w, h));
            std::vector<Point2> arm{{a.x + dx * far, a.y + dy * far}};
            arm.insert(arm.end(), tip.begin(), tip.end());
            arm.push_back({b.x + dx * far, b.y + dy * far});
            ls.add_polygon(arm, static_cast<uint8_t>(level));
            scene.occluded_side = side;
            scene.occluded_from = start / len;
            scene.occluded_to = (start + width) / len;
            return;
        }
    }
}

}  // namespace

BoardBenchScene make_board_bench_scene(const BoardBenchOptions& o, uint64_t seed) {
    check(o);
    BoardBenchScene scene;
    const int w = o.width, h = o.height;
    const Camera cam{o.focal_px > 0 ? o.focal_px : static_cast<double>(w), (w - 1) / 2.0, (h - 1) / 2.0, w, h};
    scene.focal_px = cam.f;

    // Levels, imaging and lighting: drawn alike with and without a board.
    Pcg32 look(seed, kStreamLook);
    scene.board_level = uniform_int(look, o.board_level_min, o.board_level_max);
    scene.background_level = uniform_int(look, 30, std::min(120, scene.board_level - 90));
    scene.noise_sigma = uniform(look, o.noise_sigma_min, o.noise_sigma_max);
    scene.blur_sigma = uniform(look, o.blur_sigma_min, o.blur_sigma_max);
    const double gain_lo = uniform(look, o.light_gain_min, 1);
    // Pattern: a ramp of up to 1 per half diagonal along a random direction, minus a radial
    // falloff of 0.25–1 per half diagonal squared around a hot spot near the frame; then
    // rescaled so that its range over the pixel centres is [gain_lo, 1].
    const double half_diag = 0.5 * std::sqrt(static_cast<double>(w) * w + static_cast<double>(h) * h);
    const double hot_x = uniform(look, -0.25 * w, 1.25 * w), hot_y = uniform(look, -0.25 * h, 1.25 * h);
    double sd, cd;
    det_sincos(uniform(look, 0, 2 * kPi), sd, cd);
    const double ramp = uniform(look, 0, 1) / half_diag, falloff = uniform(look, 0.25, 1) / (half_diag * half_diag);
    double lo = 1e300, hi = -1e300;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = x - hot_x, dy = y - hot_y;
            const double g = ramp * cd * dx + ramp * sd * dy - falloff * (dx * dx + dy * dy);
            lo = std::min(lo, g), hi = std::max(hi, g);
        }
    SceneOptions so;
    so.width = w;
    so.height = h;
    so.background = static_cast<uint8_t>(scene.background_level);
    so.noise_sigma = scene.noise_sigma;
    so.blur_sigma = scene.blur_sigma;
    so.clutter_blobs = o.clutter_blobs;
    so.clutter_texture = o.clutter_texture;
    so.clutter_blob_max = static_cast<uint8_t>(scene.board_level - 50);
    so.seed = seed;
    if (gain_lo < 1 && hi > lo) {
        const double k = (1 - gain_lo) / (hi - lo);
        so.illumination.centre_x = hot_x;
        so.illumination.centre_y = hot_y;
        so.illumination.centre_gain = gain_lo - k * lo;
        so.illumination.ramp_x = k * ramp * cd;
        so.illumination.ramp_y = k * ramp * sd;
        so.illumination.falloff = k * falloff;
        scene.light_gain_min = gain_lo;
    }
    LineScene ls(so);

    // Clutter: lines, then shapes, anywhere (partly outside the frame is fine).
    Pcg32 clutter(seed, kStreamClutter);
    const double base = std::min(w, h);
    for (int i = 0; i < o.clutter_lines; ++i) {
        const double mx = uniform(clutter, 0, w - 1), my = uniform(clutter, 0, h - 1);
        const double len = uniform(clutter, 0.08, 0.6) * base;
        double s, c;
        det_sincos(uniform(clutter, 0, 2 * kPi), s, c);
        const double width = uniform(clutter, 1, 3);
        const int level = clutter_level(clutter, scene.background_level, scene.board_level);
        const Point2 a{mx - c * len / 2, my - s * len / 2}, b{mx + c * len / 2, my + s * len / 2};
        ls.add_line(a, b, width, static_cast<uint8_t>(level));
        scene.clutter_lines.push_back({a, b});
    }
    for (int i = 0; i < o.clutter_shapes; ++i) {
        const int kind = static_cast<int>(clutter.below(3));
        const double cx = uniform(clutter, 0, w - 1), cy = uniform(clutter, 0, h - 1);
        std::vector<Point2> shape = clutter_shape(clutter, kind, cx, cy, base);
        const int level = clutter_level(clutter, scene.background_level, scene.board_level);
        ls.add_polygon(shape, static_cast<uint8_t>(level));
        scene.clutter_shapes.push_back(std::move(shape));
    }

    if (o.board) {
        Pcg32 pose(seed, kStreamPose);
        place_board(o, cam, pose, scene);
        scene.has_board = true;
        ls.add_polygon({scene.corners, scene.corners + 4}, static_cast<uint8_t>(scene.board_level));
        if (o.occlude) {
            Pcg32 occ(seed, kStreamOcclusion);
            add_occluder(ls, occ, scene, w, h);
        }
    }
    scene.image = ls.render();
    return scene;
}

}  // namespace qt::scene
