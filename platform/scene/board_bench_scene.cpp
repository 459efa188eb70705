#include "scene/board_bench_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "base/prng.h"
#include "scene/board_pose.h"
#include "scene/det_math.h"
#include "scene/random.h"

namespace qt::scene {

namespace {

// One PCG stream per purpose: a board-free frame of the same seed draws the same levels,
// lighting, clutter and noise as the frame with the board (LineScene's own streams, seeded
// with the same seed, are different constants).
constexpr uint64_t kStreamPose = 0xb0a4d9053u, kStreamLook = 0xb0a4d1008u,
                   kStreamClutter = 0xb0a4dc1a7u, kStreamOcclusion = 0xb0a4d0cc1u;

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
            if (a[1] - a[0] >= 0.45 && a[2] - a[1] >= 0.45 && 2 * kPi - (a[2] - a[0]) >= 0.45)
                break;
        }
        for (double t : a) {
            double st, ct;
            det_sincos(t, st, ct);
            local.push_back({r * ct, r * st});
        }
    } else if (kind == 1) {
        const double len = uniform(rng, 0.1, 0.45) * base;
        const double wid = std::max(2.0, len / uniform(rng, 6, 14));
        local = {
            {-len / 2, -wid / 2}, {len / 2, -wid / 2}, {len / 2, wid / 2}, {-len / 2, wid / 2}};
    } else {
        const double a = uniform(rng, 0.08, 0.3) * base, b = a * uniform(rng, 0.5, 1.2);
        double sa, ca;
        det_sincos(det_radians(uniform(rng, 15, 40)), sa, ca);
        const double ox = -(a + b * ca) / 2, oy = -(b * sa) / 2;  // centre the parallelogram
        local = {
            {ox, oy}, {ox + a, oy}, {ox + a + b * ca, oy + b * sa}, {ox + b * ca, oy + b * sa}};
    }
    std::vector<Point2> out;
    for (const Point2& p : local) out.push_back({cx + p.x * c - p.y * s, cy + p.x * s + p.y * c});
    return out;
}

void check(const BoardBenchOptions& o) {
    const bool ok =
        o.width >= 64 && o.height >= 48 && o.aspect >= 0.25 && o.aspect <= 4 && o.focal_px >= 0 &&
        std::isfinite(o.focal_px) && o.tilt_deg_min >= 0 && o.tilt_deg_min <= o.tilt_deg_max &&
        o.tilt_deg_max <= 80 && o.rotation_deg_min >= -180 &&
        o.rotation_deg_min <= o.rotation_deg_max && o.rotation_deg_max <= 180 && o.scale_min > 0 &&
        o.scale_min <= o.scale_max &&
        o.scale_max <= std::min((o.width - 9.0) / o.width, (o.height - 9.0) / o.height) &&
        o.noise_sigma_min >= 0 && o.noise_sigma_min <= o.noise_sigma_max &&
        std::isfinite(o.noise_sigma_max) && o.blur_sigma_min >= 0 &&
        o.blur_sigma_min <= o.blur_sigma_max && o.blur_sigma_max <= 10 && o.light_gain_min > 0 &&
        o.light_gain_min <= 1 && o.board_level_min >= 130 &&
        o.board_level_min <= o.board_level_max && o.board_level_max <= 255 &&
        o.clutter_texture >= 0 && o.clutter_blobs >= 0 && o.clutter_lines >= 0 &&
        o.clutter_shapes >= 0;
    if (!ok) throw std::invalid_argument("make_board_bench_scene: option out of range");
}

}  // namespace

BoardBenchScene make_board_bench_scene(const BoardBenchOptions& o, uint64_t seed) {
    check(o);
    BoardBenchScene scene;
    const int w = o.width, h = o.height;
    const PinholeCamera cam = centred_camera(w, h, o.focal_px);
    scene.focal_px = cam.f;

    // Levels, imaging and lighting: drawn alike with and without a board.
    Pcg32 look(seed, kStreamLook);
    scene.board_level = uniform_int(look, o.board_level_min, o.board_level_max);
    scene.background_level = uniform_int(look, 30, std::min(120, scene.board_level - 90));
    scene.noise_sigma = uniform(look, o.noise_sigma_min, o.noise_sigma_max);
    scene.blur_sigma = uniform(look, o.blur_sigma_min, o.blur_sigma_max);
    const double gain_lo = uniform(look, o.light_gain_min, 1);
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
    if (uneven_illumination(w, h, gain_lo, look, &so.illumination)) scene.light_gain_min = gain_lo;
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
        Pcg32 rng(seed, kStreamPose);
        const PoseRanges ranges{o.tilt_deg_min,     o.tilt_deg_max, o.rotation_deg_min,
                                o.rotation_deg_max, o.scale_min,    o.scale_max};
        const BoardPose pose = place_board(cam, o.aspect, ranges, rng, scene.corners);
        scene.tilt_deg = pose.tilt_deg;
        scene.rotation_deg = pose.rotation_deg;
        scene.tilt_axis_deg = pose.tilt_axis_deg;
        scene.scale = pose.scale;
        scene.has_board = true;
        ls.add_polygon({scene.corners, scene.corners + 4}, static_cast<uint8_t>(scene.board_level));
        if (o.occlude) {
            Pcg32 occ(seed, kStreamOcclusion);
            const Occluder arm =
                arm_occluder(scene.corners, scene.board_level, ArmLimits{}, w, h, occ);
            if (arm.side >= 0) {
                ls.add_polygon(arm.outline, static_cast<uint8_t>(arm.level));
                scene.occluded_side = arm.side;
                scene.occluded_from = arm.from;
                scene.occluded_to = arm.to;
            }
        }
    }
    scene.image = ls.render();
    return scene;
}

}  // namespace qt::scene
