#include "scene/photo_board_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "scene/det_math.h"
#include "scene/random.h"

namespace qt::scene {

namespace {

// One PCG stream per purpose: a board-free frame of the same seed has the same crop, lighting,
// blur and noise as the frame with the board.
constexpr uint64_t kStreamCrop = 0x9407c409u, kStreamLook = 0x940710c5u, kStreamPose = 0x94079053u,
                   kStreamPrint = 0x9407971du, kStreamOcclusion = 0x94070cc1u;

constexpr double kEndMarginPx = 6, kEndFraction = 0.1;  // of a side left visible at each end
constexpr double kMaxCovered = 0.7;                     // of a side an occluder covers, at most

// Weights of a box filter resampling n_src samples into n_dst: output i covers
// [start + i·step, start + (i + 1)·step] in input coordinates (input pixel j spans
// [j − 0.5, j + 0.5]), widened to one input pixel when step < 1; inputs outside [0, n_src)
// repeat the border.
std::vector<std::vector<std::pair<int, double>>> box_weights(int n_src, int n_dst, double start,
                                                             double step) {
    std::vector<std::vector<std::pair<int, double>>> out(static_cast<std::size_t>(n_dst));
    const double r = 0.5 * std::max(step, 1.0);
    for (int i = 0; i < n_dst; ++i) {
        const double c = start + (i + 0.5) * step, lo = c - r, hi = c + r;
        for (int j = static_cast<int>(std::floor(lo + 0.5));
             j <= static_cast<int>(std::floor(hi + 0.5)); ++j) {
            const double overlap = std::min(hi, j + 0.5) - std::max(lo, j - 0.5);
            if (overlap > 0)
                out[static_cast<std::size_t>(i)].push_back(
                    {std::min(n_src - 1, std::max(0, j)), overlap / (2 * r)});
        }
    }
    return out;
}

// Heckbert's square-to-quadrangle map: (s, t) in the unit square -> the board, with (0, 0) at
// the top-left corner, (1, 0) top-right, (1, 1) bottom-right, (0, 1) bottom-left.
struct BoardMap {
    double a, b, c, d, e, f, g, h;
    explicit BoardMap(const Point2 corners[4]) {
        const Point2 p0 = corners[0], p1 = corners[3], p2 = corners[2],
                     p3 = corners[1];  // TL, TR, BR, BL
        const double sx = p0.x - p1.x + p2.x - p3.x, sy = p0.y - p1.y + p2.y - p3.y;
        const double dx1 = p1.x - p2.x, dx2 = p3.x - p2.x, dy1 = p1.y - p2.y, dy2 = p3.y - p2.y;
        const double det = dx1 * dy2 - dx2 * dy1;
        g = (sx * dy2 - sy * dx2) / det;
        h = (dx1 * sy - dy1 * sx) / det;
        a = p1.x - p0.x + g * p1.x;
        b = p3.x - p0.x + h * p3.x;
        c = p0.x;
        d = p1.y - p0.y + g * p1.y;
        e = p3.y - p0.y + h * p3.y;
        f = p0.y;
    }
    Point2 operator()(double s, double t) const {
        const double w = g * s + h * t + 1;
        return {(a * s + b * t + c) / w, (d * s + e * t + f) / w};
    }
};

void check(const PhotoBoardOptions& o) {
    const bool ok =
        o.width >= 64 && o.height >= 48 && o.tilt_deg_max >= 0 && o.tilt_deg_max <= 80 &&
        o.roll_deg_max >= 0 && o.roll_deg_max <= 180 && o.scale_min > 0 &&
        o.scale_min <= o.scale_max &&
        o.scale_max <= std::min((o.width - 9.0) / o.width, (o.height - 9.0) / o.height) &&
        o.board_level_min >= 130 && o.board_level_min <= o.board_level_max &&
        o.board_level_max <= 255 && o.shading_max >= 0 && o.shading_max < 1 && o.print_share >= 0 &&
        o.print_share <= 1 && o.darken_min > 0 && o.darken_min <= o.darken_max &&
        o.darken_max <= 1.25 && o.light_gain_min > 0 && o.light_gain_min <= 1 &&
        o.blur_sigma_max >= 0 && o.blur_sigma_max <= 10 && o.noise_sigma_min >= 0 &&
        o.noise_sigma_min <= o.noise_sigma_max && std::isfinite(o.noise_sigma_max);
    if (!ok) throw std::invalid_argument("make_photo_board_scene: option out of range");
}

// The board, shaded by up to shading_max of its level across it along a random direction (the
// mean level stays `level`), and faint print: 2–5 "lines of text", 12–35 levels darker.
void draw_board(LineScene& ls, const Point2 corners[4], int level, double shading_max, bool print,
                Pcg32& rng) {
    const std::vector<Point2> outline(corners, corners + 4);
    double cx = 0, cy = 0, diag = 0;
    for (const Point2& p : outline) cx += p.x / 4, cy += p.y / 4;
    for (int i = 0; i < 2; ++i) diag = std::max(diag, point_distance(corners[i], corners[i + 2]));
    double s, c;
    det_sincos(uniform(rng, 0, 2 * kPi), s, c);
    const double slope = uniform(rng, 0, shading_max) * level / diag;  // grey levels per px
    const double ramp_x = slope * c, ramp_y = slope * s;
    ls.add_shaded_polygon(outline,
                          level - ramp_x * (cx - corners[0].x) - ramp_y * (cy - corners[0].y),
                          ramp_x, ramp_y);
    if (!print) return;
    const BoardMap map(corners);
    const int lines = uniform_int(rng, 2, 5);
    const double pitch = 0.6 / lines;
    for (int k = 0; k < lines; ++k) {
        const double t0 = 0.2 + k * pitch, t1 = t0 + uniform(rng, 0.25, 0.5) * pitch;
        const double s0 = uniform(rng, 0.1, 0.2), s1 = std::min(0.9, s0 + uniform(rng, 0.3, 0.75));
        ls.add_polygon({map(s0, t0), map(s0, t1), map(s1, t1), map(s1, t0)},
                       static_cast<uint8_t>(level - uniform_int(rng, 12, 35)));
    }
}

double segment_distance(Point2 a, Point2 b, Point2 q) {  // px
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t =
        std::min(1.0, std::max(0.0, ((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy)));
    return point_distance({a.x + t * dx, a.y + t * dy}, q);
}

// A dark disc over part of one side: its chord on the side covers up to kMaxCovered of it with
// the ends visible, it reaches into the board 30–90 % of half the chord (at most 35 % of the
// board's depth across that side), and it stays >= 3 px from the other sides.
Occluder disc_occluder(const Point2 c[4], int board_level, Pcg32& rng) {
    Occluder out;
    int eligible[4], n = 0;
    for (int i = 0; i < 4; ++i)
        if (point_distance(c[i], c[(i + 1) % 4]) >= 30) eligible[n++] = i;
    if (n == 0) return out;
    for (int attempt = 0; attempt < 200; ++attempt) {
        const int side = eligible[rng.below(static_cast<uint32_t>(n))];
        const Point2 p = c[side], q = c[(side + 1) % 4];
        const double len = point_distance(p, q);
        const double end = std::max(kEndMarginPx, kEndFraction * len);
        const double ex = (q.x - p.x) / len, ey = (q.y - p.y) / len;
        const double nx = -ey, ny = ex;  // outward normal
        const double chord =
            uniform(rng, std::min(10.0, len - 2 * end), std::min(kMaxCovered * len, len - 2 * end));
        const double start = uniform(rng, end, len - end - chord);
        double extent = 0;
        for (int j = 0; j < 4; ++j) extent = std::max(extent, inside_distance(p, q, c[j]));
        const double half = chord / 2;
        const double depth =
            std::min(uniform(rng, 0.3, 0.9) * half, 0.35 * extent);  // px into the board
        const int level = uniform_int(rng, 20, board_level - 60);
        if (!(depth > 1)) continue;
        const double e = (half * half - depth * depth) / (2 * depth);  // centre beyond the side, px
        const double r = depth + e;
        const Point2 centre{p.x + ex * (start + half) + nx * e, p.y + ey * (start + half) + ny * e};
        bool clear = true;
        for (int j = 0; j < 4; ++j)
            if (j != side) clear = clear && segment_distance(c[j], c[(j + 1) % 4], centre) > r + 3;
        if (!clear) continue;
        for (int k = 0; k < 96; ++k) {
            double sk, ck;
            det_sincos(2 * kPi * k / 96, sk, ck);
            out.outline.push_back({centre.x + r * ck, centre.y + r * sk});
        }
        out.side = side;
        out.from = start / len;
        out.to = (start + chord) / len;
        out.level = level;
        return out;
    }
    return out;
}

// The frame's look: photograph gain, lighting, blur and noise, and the board's level.
struct Look {
    double darken, gain_lo, blur, noise;
    int board_level;
};

Look draw_look(const PhotoBoardOptions& o, Pcg32& rng) {
    Look k;
    k.board_level = uniform_int(rng, o.board_level_min, o.board_level_max);
    k.darken = uniform(rng, o.darken_min, o.darken_max);
    k.gain_lo = uniform(rng, o.light_gain_min, 1);
    k.blur = uniform(rng, 0, o.blur_sigma_max);
    k.noise = uniform(rng, o.noise_sigma_min, o.noise_sigma_max);
    return k;
}

std::vector<double> darkened(std::vector<double> levels, double gain) {
    for (double& v : levels) v *= gain;
    return levels;
}

void occlude(LineScene& ls, const Occluder& occ, bool disc, PhotoBoardScene& scene) {
    if (occ.side < 0) return;
    ls.add_polygon(occ.outline, static_cast<uint8_t>(occ.level));
    scene.occluded_side = occ.side;
    scene.occluded_from = occ.from;
    scene.occluded_to = occ.to;
    scene.occluder_is_disc = disc;
}

}  // namespace

std::vector<double> photo_background(const io::GreyImage& photo, int w, int h, double min_share,
                                     Pcg32& rng) {
    if (photo.width < 1 || photo.height < 1)
        throw std::invalid_argument("photo_background: empty photograph");
    double max_w = photo.width, max_h = photo.width * static_cast<double>(h) / w;
    if (max_h > photo.height)
        max_h = photo.height, max_w = photo.height * static_cast<double>(w) / h;
    const double share = uniform(rng, min_share, 1);
    const double cw = share * max_w, ch = share * max_h;
    const double x0 = uniform(rng, -0.5, photo.width - 0.5 - cw),
                 y0 = uniform(rng, -0.5, photo.height - 0.5 - ch);
    const auto wx = box_weights(photo.width, w, x0, cw / w),
               wy = box_weights(photo.height, h, y0, ch / h);
    std::vector<double> rows(static_cast<std::size_t>(w) * photo.height, 0.0);
    for (int y = 0; y < photo.height; ++y)
        for (int x = 0; x < w; ++x)
            for (const auto& [j, k] : wx[static_cast<std::size_t>(x)])
                rows[static_cast<std::size_t>(y) * w + x] += k * photo.at(j, y);
    std::vector<double> out(static_cast<std::size_t>(w) * h, 0.0);
    for (int y = 0; y < h; ++y)
        for (const auto& [j, k] : wy[static_cast<std::size_t>(y)])
            for (int x = 0; x < w; ++x)
                out[static_cast<std::size_t>(y) * w + x] +=
                    k * rows[static_cast<std::size_t>(j) * w + x];
    return out;
}

PhotoBoardScene make_photo_board_scene(const PhotoBoardOptions& o, const io::GreyImage& photo,
                                       uint64_t seed) {
    check(o);
    const int w = o.width, h = o.height;
    PhotoBoardScene scene;
    Pcg32 crop(seed, kStreamCrop), look_rng(seed, kStreamLook);
    const std::vector<double> background = photo_background(photo, w, h, 0.6, crop);
    const Look look = draw_look(o, look_rng);
    scene.board_level = look.board_level;
    scene.darken = look.darken;
    scene.blur_sigma = look.blur;
    scene.noise_sigma = look.noise;
    SceneOptions so;
    so.width = w;
    so.height = h;
    so.noise_sigma = look.noise;
    so.blur_sigma = look.blur;
    so.seed = seed;
    if (uneven_illumination(w, h, look.gain_lo, look_rng, &so.illumination))
        scene.light_gain_min = look.gain_lo;
    LineScene ls(so);
    ls.set_background(darkened(background, look.darken * look.board_level / 255.0));
    if (o.board) {
        Pcg32 pose_rng(seed, kStreamPose), print_rng(seed, kStreamPrint);
        scene.aspect = kPhotoBoardAspects[pose_rng.below(3)];
        const PoseRanges ranges{0,           o.tilt_deg_max, -o.roll_deg_max, o.roll_deg_max,
                                o.scale_min, o.scale_max};
        scene.pose =
            place_board(centred_camera(w, h, 0), scene.aspect, ranges, pose_rng, scene.corners);
        scene.has_board = true;
        scene.printed = uniform01(print_rng) < o.print_share;
        draw_board(ls, scene.corners, look.board_level, o.shading_max, scene.printed, print_rng);
        if (o.occlude) {
            Pcg32 occ(seed, kStreamOcclusion);
            const bool disc = occ.below(2) == 0;
            const ArmLimits limits{kMaxCovered, kEndMarginPx, kEndFraction};
            occlude(ls,
                    disc ? disc_occluder(scene.corners, look.board_level, occ)
                         : arm_occluder(scene.corners, look.board_level, limits, w, h, occ),
                    disc, scene);
        }
    }
    scene.image = ls.render();
    return scene;
}

PhotoBoardScene make_photo_sequence_frame(const PhotoSequenceOptions& o, const io::GreyImage& photo,
                                          int index) {
    if (o.width < 64 || o.height < 48 || o.frames < 1 || index < 0 || index >= o.frames ||
        !(o.scale > 0) || o.scale > 0.6 || o.arm_frames < 0)
        throw std::invalid_argument("make_photo_sequence_frame: option or index out of range");
    const int w = o.width, h = o.height;
    PhotoBoardScene scene;
    Pcg32 crop(o.seed, kStreamCrop), look_rng(o.seed, kStreamLook);
    const std::vector<double> background = photo_background(photo, w, h, 0.6, crop);
    PhotoBoardOptions defaults;
    defaults.blur_sigma_max = 0.8;
    defaults.noise_sigma_max = 4;
    const Look look = draw_look(defaults, look_rng);
    SceneOptions so;
    so.width = w;
    so.height = h;
    so.noise_sigma = look.noise;
    so.blur_sigma = look.blur;
    so.seed = o.seed * 1000003u + static_cast<uint64_t>(index);  // noise of this frame
    if (uneven_illumination(w, h, look.gain_lo, look_rng, &so.illumination))
        scene.light_gain_min = look.gain_lo;
    LineScene ls(so);
    ls.set_background(darkened(background, look.darken * look.board_level / 255.0));

    const double phase = 2 * kPi * index / o.frames;
    double s1, c1, s2, c2, sr, cr, ss, cs;
    det_sincos(phase, s1, c1);
    det_sincos(2 * phase, s2, c2);
    det_sincos(2 * kPi * index / 100.0, sr, cr);  // turn: one period in 100 frames
    det_sincos(2 * kPi * index / 75.0, ss, cs);   // scale: one period in 75 frames
    scene.aspect = 4.0 / 3.0;
    scene.pose = BoardPose{20, 10 * sr, 30, o.scale * (1 + 0.1 * ss)};
    project_board_at(centred_camera(w, h, 0), scene.aspect, scene.pose,
                     0.5 * (w - 1) + 0.18 * w * s1, 0.5 * (h - 1) + 0.12 * h * s2, scene.corners);
    scene.has_board = true;
    scene.board_level = look.board_level;
    scene.darken = look.darken;
    scene.blur_sigma = look.blur;
    scene.noise_sigma = look.noise;
    Pcg32 print_rng(o.seed, kStreamPrint);
    draw_board(ls, scene.corners, look.board_level, 0, false, print_rng);
    if (index >= o.arm_first && index < o.arm_first + o.arm_frames) {
        const Point2 p = scene.corners[1], q = scene.corners[2];  // the bottom side, BL -> BR
        const double len = point_distance(p, q), ex = (q.x - p.x) / len, ey = (q.y - p.y) / len;
        const Point2 a{p.x + 0.35 * len * ex, p.y + 0.35 * len * ey},
            b{p.x + 0.65 * len * ex, p.y + 0.65 * len * ey};
        const double depth = 0.12 * point_distance(scene.corners[0], scene.corners[1]);
        const std::vector<Point2> tip = arm_tip(a, b, -ey, ex, 1, 0.3 * len, depth);
        Occluder arm;
        arm.side = 1;
        arm.from = 0.35;
        arm.to = 0.65;
        arm.level = 40;
        arm.outline = arm_outline(a, b, tip, -ey, ex, w, h);
        occlude(ls, arm, false, scene);
    }
    scene.image = ls.render();
    return scene;
}

}  // namespace qt::scene
