#include "scene/ground_sequence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/det_math.h"
#include "scene/homography3.h"
#include "scene/random.h"

namespace qt::scene {

namespace {

// ---- Terrain ------------------------------------------------------------------------------

// Fields: columns kColumnM wide, edges jittered by up to ±kColumnJitterM; each column cut into
// fields kRowM long, edges jittered by up to ±kRowJitterM (independently per column, so the
// cuts make T-junctions, not a grid). The jitter is below half the spacing, so a point lies in
// its nominal cell or the next one over.
constexpr double kColumnM = 11, kColumnJitterM = 3.5;
constexpr double kRowM = 8.5, kRowJitterM = 3;
constexpr int kFieldLow = 70, kFieldRange = 110;  // field grey levels 70 .. 180
// Roads: some column edges (probability kRoadShare) carry a north–south road; each band of
// kBandM metres of Y holds an east–west road with probability 1/2, within ±kBandJitterM of the
// band's middle. Half-width in metres, grey level.
constexpr double kRoadShare = 0.13, kRoadHalfM = 1.8, kBandM = 60, kBandJitterM = 20;
constexpr int kRoadLevel = 190;
// Bushes and huts: on a kBlobCellM lattice, a cell holds one (probability kBlobShare): a disc or
// a square (half-size kBlobMinM .. kBlobMinM + kBlobSpanM), wholly inside the cell, darker than
// a bright background or lighter than a dark one by 35 .. 65 levels.
constexpr double kBlobCellM = 3.6, kBlobShare = 0.7, kBlobMinM = 0.45, kBlobSpanM = 0.75;
constexpr int kBlobLow = 35, kBlobHigh = 210;

enum Layer : uint64_t { kColumnLayer = 1, kRowLayer, kFieldLayer, kBandLayer, kBlobLayer };

uint64_t mix64(uint64_t z) {  // splitmix64's finaliser
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

// Five 12-bit uniform fields in [0, 1) from one hash.
double field(uint64_t h, int k) { return static_cast<double>((h >> (12 * k)) & 4095u) / 4096.0; }

// The cell of x on a lattice of the given step, multiplying by its reciprocal (cheaper than a
// division; a point within an ulp of a cell edge may go either way, and no feature reaches an
// edge).
int64_t cell(double x, double inverse_step) {
    return static_cast<int64_t>(std::floor(x * inverse_step));
}

// The ground's grey level at (X, Y) metres, before anti-aliasing and noise. Keeps the last
// column and field it found: neighbouring samples mostly fall in the same ones.
class Terrain {
public:
    explicit Terrain(uint64_t seed) : key_(mix64(seed ^ 0x7465727261696EULL)) {}

    int level(double x, double y) {
        find_column(x);
        find_row(y);
        int base = field_level_;
        if ((left_road_ && x - left_ < kRoadHalfM) || (right_road_ && right_ - x < kRoadHalfM) ||
            on_band_road(y))
            base = kRoadLevel;
        return blob(x, y, base);
    }

private:
    uint64_t hash(uint64_t layer, int64_t i, int64_t j) const {
        return mix64(key_ + layer * 0xD6E8FEB86659FD93ULL +
                     static_cast<uint64_t>(i) * 0x9E3779B97F4A7C15ULL +
                     static_cast<uint64_t>(j) * 0xC2B2AE3D27D4EB4FULL);
    }
    double column_edge(int64_t c, bool& road) const {
        const uint64_t h = hash(kColumnLayer, c, 0);
        road = field(h, 1) < kRoadShare;
        return c * kColumnM + (2 * field(h, 0) - 1) * kColumnJitterM;
    }
    double row_edge(int64_t c, int64_t r) const {
        return r * kRowM + (2 * field(hash(kRowLayer, c, r), 0) - 1) * kRowJitterM;
    }

    void find_column(double x) {
        if (have_column_ && x >= left_ && x < right_) return;
        int64_t c = cell(x, 1 / kColumnM);
        bool road_c = false, road_n = false;
        double edge_c = column_edge(c, road_c), edge_n = 0;
        if (x < edge_c) {
            edge_n = edge_c;
            road_n = road_c;
            --c;
            edge_c = column_edge(c, road_c);
        } else {
            edge_n = column_edge(c + 1, road_n);
            if (x >= edge_n) {
                ++c;
                edge_c = edge_n;
                road_c = road_n;
                edge_n = column_edge(c + 1, road_n);
            }
        }
        column_ = c;
        left_ = edge_c;
        right_ = edge_n;
        left_road_ = road_c;
        right_road_ = road_n;
        have_column_ = true;
        have_row_ = false;
    }

    void find_row(double y) {
        if (have_row_ && y >= bottom_ && y < top_) return;
        int64_t r = cell(y, 1 / kRowM);
        double edge_r = row_edge(column_, r), edge_n = 0;
        if (y < edge_r) {
            edge_n = edge_r;
            --r;
            edge_r = row_edge(column_, r);
        } else {
            edge_n = row_edge(column_, r + 1);
            if (y >= edge_n) {
                ++r;
                edge_r = edge_n;
                edge_n = row_edge(column_, r + 1);
            }
        }
        bottom_ = edge_r;
        top_ = edge_n;
        field_level_ =
            kFieldLow + static_cast<int>(kFieldRange * field(hash(kFieldLayer, column_, r), 0));
        have_row_ = true;
    }

    bool on_band_road(double y) {
        const int64_t k = cell(y, 1 / kBandM);
        if (!have_band_ || k != band_) {
            const uint64_t h = hash(kBandLayer, k, 0);
            band_ = k;
            band_road_ = field(h, 1) < 0.5;
            band_centre_ = (k + 0.5) * kBandM + (2 * field(h, 0) - 1) * kBandJitterM;
            have_band_ = true;
        }
        return band_road_ && std::fabs(y - band_centre_) < kRoadHalfM;
    }

    int blob(double x, double y, int base) {
        const int64_t i = cell(x, 1 / kBlobCellM), j = cell(y, 1 / kBlobCellM);
        if (!have_blob_ || i != blob_i_ || j != blob_j_) {
            blob_hash_ = hash(kBlobLayer, i, j);
            blob_i_ = i;
            blob_j_ = j;
            have_blob_ = true;
        }
        const uint64_t h = blob_hash_;
        if (field(h, 0) >= kBlobShare) return base;
        const double r = kBlobMinM + kBlobSpanM * field(h, 1);
        const double cx = i * kBlobCellM + r + (kBlobCellM - 2 * r) * field(h, 2);
        const double cy = j * kBlobCellM + r + (kBlobCellM - 2 * r) * field(h, 3);
        const double dx = x - cx, dy = y - cy;
        const bool square = (h >> 60) & 1u;
        const bool inside =
            square ? std::fabs(dx) <= r && std::fabs(dy) <= r : dx * dx + dy * dy <= r * r;
        if (!inside) return base;
        const int step = 35 + static_cast<int>(30 * field(h, 4));
        return std::clamp(base >= 110 ? base - step : base + step, kBlobLow, kBlobHigh);
    }

    uint64_t key_;
    bool have_column_ = false, have_row_ = false;
    int64_t column_ = 0;
    double left_ = 0, right_ = 0, bottom_ = 0, top_ = 0;
    bool left_road_ = false, right_road_ = false;
    int field_level_ = 0;
    bool have_band_ = false, band_road_ = false;
    int64_t band_ = 0;
    double band_centre_ = 0;
    bool have_blob_ = false;
    int64_t blob_i_ = 0, blob_j_ = 0;
    uint64_t blob_hash_ = 0;
};

// ---- Vehicle and flare --------------------------------------------------------------------

constexpr int kBodyLevel = 25, kRoofLevel = 235;                  // outside the terrain's 35 .. 210
constexpr double kRoofLengthShare = 0.55, kRoofWidthShare = 0.7;  // of the body's size
// Flare: a core of kFlareCoreLevel within kFlareCorePx of its centre, a halo fading out to
// kFlareHaloPx; its centre drifts kFlareDriftPx across the vehicle's centre over the spell, so
// the core covers the vehicle's box (half-diagonal ≤ 10 px at the default scale, ≤ 12 px near
// the image's edges) throughout.
constexpr double kFlareCorePx = 17, kFlareHaloPx = 30, kFlareDriftPx = 8;
constexpr double kFlareCoreLevel = 250;

// ---- Swing --------------------------------------------------------------------------------

// Each ramp of the swing speeds up over kSwingAccelFrames, keeps swing_speed_px, slows down
// over kSwingAccelFrames: position 0 → 1 over u in [0, 1] with accel share a.
constexpr double kSwingAccelFrames = 12;
double ramp(double u, double a) {
    if (u <= 0) return 0;
    if (u >= 1) return 1;
    const double v = 1 / (1 - a);  // top speed
    if (u < a) return v * u * u / (2 * a);
    if (u <= 1 - a) return v * (u - a / 2);
    return 1 - v * (1 - u) * (1 - u) / (2 * a);
}

double det_atan(double x) {             // Newton on sin(a) − x·cos(a) = 0, for x >= 0
    double a = x / (1 + 0.28 * x * x);  // within 0.005 rad
    for (int i = 0; i < 6; ++i) {
        double s = 0, c = 0;
        det_sincos(a, s, c);
        a -= (s - x * c) / (c + x * s);
    }
    return a;
}

double sine(double x) {
    double s = 0, c = 0;
    det_sincos(x, s, c);
    return s;
}

}  // namespace

struct GroundSequence::State {
    double g[9];              // ground → image, third row = depth (m)
    double tx, ty;            // vehicle centre on the ground, m
    double along_x, along_y;  // vehicle heading, unit vector on the ground
};

GroundSequence::State GroundSequence::state_at(double t) const {
    const GroundSequenceConfig& c = config_;
    State s{};
    // Vehicle: constant speed v on a circle of turn rate w (straight if w = 0).
    const double w = det_radians(c.target_turn_deg), v = c.target_speed_m;
    const double heading = start_heading_ + w * t;
    double sh0 = 0, ch0 = 0, sh = 0, ch = 0;
    det_sincos(start_heading_, sh0, ch0);
    det_sincos(heading, sh, ch);
    s.tx = start_x_ + (w == 0 ? v * t * ch0 : v / w * (sh - sh0));
    s.ty = start_y_ + (w == 0 ? v * t * sh0 : -v / w * (ch - ch0));
    s.along_x = ch;
    s.along_y = sh;

    // Camera orientation: rows of the world → camera rotation. x right (the heading's right),
    // z the optical axis (tilted forward from nadir), y = z × x (image down).
    const double altitude =
        c.altitude_m *
        (1 + c.altitude_variation * sine(2 * kPi * t / c.altitude_period_frames + altitude_phase_));
    const double tilt = det_radians(
        c.tilt_deg + c.tilt_variation_deg * sine(2 * kPi * t / c.tilt_period_frames + tilt_phase_));
    double sp = 0, cp = 0, st = 0, ct = 0;
    det_sincos(yaw0_ + det_radians(c.yaw_rate_deg) * t, sp, cp);
    det_sincos(tilt, st, ct);
    double rx[3] = {sp, -cp, 0};
    double rz[3] = {st * cp, st * sp, -ct};
    double ry[3] = {-ct * cp, -ct * sp, -st};

    // Home aim point: where the vehicle's centre appears before the swing. The camera sits on
    // the ray through it that ends at the vehicle, at `altitude`.
    const double cx = (c.width - 1) / 2.0, cy = (c.height - 1) / 2.0;
    const double a = c.wander_px * sine(2 * kPi * t / 170 + wander_phase_x_) / c.focal_px;
    const double b = c.wander_px * sine(2 * kPi * t / 230 + wander_phase_y_) / c.focal_px;
    const double d[3] = {a * rx[0] + b * ry[0] + rz[0], a * rx[1] + b * ry[1] + rz[1],
                         a * rx[2] + b * ry[2] + rz[2]};
    const double mu = altitude / -d[2];
    const double cam[3] = {s.tx - mu * d[0], s.ty - mu * d[1], altitude};

    // The swing: the camera turns by `swing` about the image axis across the swing direction
    // e = (side_x, side_y), so the image moves along e (by f·tan(swing) at the centre). A turn,
    // not a shift, moves near and far ground alike.
    double ss = 0, cs = 1;
    det_sincos(swing_at(t) * swing_rad_, ss, cs);
    double e[3], p[3];
    for (int i = 0; i < 3; ++i) {
        e[i] = side_x_ * rx[i] + side_y_ * ry[i];
        p[i] = -side_y_ * rx[i] + side_x_ * ry[i];
    }
    for (int i = 0; i < 3; ++i) {
        const double ei = cs * e[i] + ss * rz[i];
        rz[i] = cs * rz[i] - ss * e[i];
        rx[i] = side_x_ * ei - side_y_ * p[i];
        ry[i] = side_y_ * ei + side_x_ * p[i];
    }

    // G = K [r1 r2 −R·C].
    const double t0 = -(rx[0] * cam[0] + rx[1] * cam[1] + rx[2] * cam[2]);
    const double t1 = -(ry[0] * cam[0] + ry[1] * cam[1] + ry[2] * cam[2]);
    const double t2 = -(rz[0] * cam[0] + rz[1] * cam[1] + rz[2] * cam[2]);
    const double m0[3] = {rx[0], rx[1], t0}, m1[3] = {ry[0], ry[1], t1}, m2[3] = {rz[0], rz[1], t2};
    for (int j = 0; j < 3; ++j) {
        s.g[j] = c.focal_px * m0[j] + cx * m2[j];
        s.g[3 + j] = c.focal_px * m1[j] + cy * m2[j];
        s.g[6 + j] = m2[j];
    }
    return s;
}

double GroundSequence::swing_at(double t) const {
    if (config_.out_of_view_frames <= 0) return 0;
    const double a = kSwingAccelFrames / swing_frames_;
    return std::min(ramp((t - rise_t0_) / swing_frames_, a),
                    1 - ramp((t - fall_t0_) / swing_frames_, a));
}

namespace {

struct Box {
    double x0, y0, x1, y1;  // image bounding box of the vehicle, px
};

Box vehicle_box(const double g[9], double tx, double ty, double ax, double ay, double length,
                double width) {
    Box b{1e300, 1e300, -1e300, -1e300};
    for (int i = 0; i < 4; ++i) {
        const double l = (i & 1 ? 0.5 : -0.5) * length, w = (i & 2 ? 0.5 : -0.5) * width;
        double u = 0, v = 0;
        apply(g, tx + l * ax - w * ay, ty + l * ay + w * ax, u, v);
        b.x0 = std::min(b.x0, u);
        b.x1 = std::max(b.x1, u);
        b.y0 = std::min(b.y0, v);
        b.y1 = std::max(b.y1, v);
    }
    return b;
}

}  // namespace

double GroundSequence::box_excess(double t) const {
    const State s = state_at(t);
    const Box b = vehicle_box(s.g, s.tx, s.ty, s.along_x, s.along_y, config_.target_length_m,
                              config_.target_width_m);
    const double right = config_.width - 0.5, bottom = config_.height - 0.5;
    return std::max({-0.5 - b.x0, b.x1 - right, -0.5 - b.y0, b.y1 - bottom});
}

// The ramp out must put the box's edge on the border half a frame before out_of_view_start,
// the ramp back half a frame before the spell's end; box_excess grows with the ramp out's
// lateness reversed, so bisection finds each start time. The two ramps meet in short spells
// (swing_at takes the lower), so they are solved in turn a few times.
void GroundSequence::time_swing() {
    const GroundSequenceConfig& c = config_;
    const double out_t = c.out_of_view_start - 0.5,
                 in_t = c.out_of_view_start + c.out_of_view_frames - 0.5;
    rise_t0_ = out_t - swing_frames_ / 2;
    fall_t0_ = 1e9;
    for (int round = 0; round < 4; ++round) {
        double lo = out_t - swing_frames_, hi = out_t;  // box out at lo, in at hi
        for (int i = 0; i < 60; ++i) {
            rise_t0_ = (lo + hi) / 2;
            (box_excess(out_t) > 0 ? lo : hi) = rise_t0_;
        }
        lo = in_t - swing_frames_;  // swung back by in_t: box in
        hi = in_t;                  // still out at in_t
        for (int i = 0; i < 60; ++i) {
            fall_t0_ = (lo + hi) / 2;
            (box_excess(in_t) > 0 ? hi : lo) = fall_t0_;
        }
    }
}

GroundSequence::GroundSequence(const GroundSequenceConfig& config) : config_(config) {
    const GroundSequenceConfig& c = config_;
    if (c.width < 32 || c.height < 32 || c.frames < 1 || !(c.focal_px > 0) || !(c.altitude_m > 0) ||
        c.altitude_period_frames <= 0 || c.tilt_period_frames <= 0 || !(c.swing_speed_px > 0) ||
        c.out_of_view_frames < 0 || c.occlusion_frames < 0 || !(c.noise_sigma >= 0))
        throw std::invalid_argument("GroundSequenceConfig: bad size, frame count or parameter");

    Pcg32 rng(c.seed, 0x67726F756E64ULL);  // stream "ground"
    start_x_ = uniform(rng, -2000, 2000);
    start_y_ = uniform(rng, -2000, 2000);
    start_heading_ = uniform(rng, -kPi, kPi);
    yaw0_ = uniform(rng, -kPi, kPi);
    altitude_phase_ = uniform(rng, -kPi, kPi);
    tilt_phase_ = uniform(rng, -kPi, kPi);
    wander_phase_x_ = uniform(rng, -kPi, kPi);
    wander_phase_y_ = uniform(rng, -kPi, kPi);
    // Exit side: right, top or left, with a sideways component of up to ±0.3. Not the bottom:
    // the camera would turn up towards the horizon.
    const int side = static_cast<int>(rng.below(3));
    const double across = uniform(rng, -0.3, 0.3);
    const double ax = side == 0 ? 1 : side == 2 ? -1 : across, ay = side == 1 ? -1 : across;
    const double norm = std::sqrt(ax * ax + ay * ay);
    side_x_ = ax / norm;
    side_y_ = ay / norm;
    double fs = 0, fc = 0;
    det_sincos(uniform(rng, -kPi, kPi), fs, fc);
    flare_dx_ = fc;
    flare_dy_ = fs;

    // A full swing carries the aim point from home past the border by out_of_view_depth_px
    // (measured at the image centre's scale), whatever the wander.
    const double half = side == 1 ? c.height / 2.0 : c.width / 2.0;
    const double swing_px = (half + c.wander_px + c.out_of_view_depth_px) /
                            std::max(std::fabs(side_x_), std::fabs(side_y_));
    swing_rad_ = det_atan(swing_px / c.focal_px);
    swing_frames_ = swing_rad_ * c.focal_px / c.swing_speed_px + kSwingAccelFrames;
    if (c.out_of_view_frames > 0) time_swing();

    for (int f = 0; f < c.frames; ++f) {
        const bool out = f >= c.out_of_view_start && f < c.out_of_view_start + c.out_of_view_frames;
        if ((box_excess(f) > 0) != out)
            throw std::invalid_argument(
                "GroundSequenceConfig: the out-of-view spell cannot be produced");
    }
}

// The flare burns in frames occlusion_start .. occlusion_start + occlusion_frames − 1; its
// centre drifts by kFlareDriftPx across the vehicle's centre, along a seeded direction.
bool GroundSequence::flare_offset(int frame, double& dx, double& dy) const {
    const int k = frame - config_.occlusion_start, n = config_.occlusion_frames;
    if (k < 0 || k >= n) return false;
    const double drift = n > 1 ? kFlareDriftPx * (static_cast<double>(k) / (n - 1) - 0.5) : 0;
    dx = drift * flare_dx_;
    dy = drift * flare_dy_;
    return true;
}

GroundTruth GroundSequence::truth(int frame) const {
    if (frame < 0 || frame >= config_.frames)
        throw std::out_of_range("GroundSequence::truth: frame");
    const GroundSequenceConfig& c = config_;
    const State s = state_at(frame);
    GroundTruth gt;
    std::copy(s.g, s.g + 9, gt.h_ground_to_image);
    apply(s.g, s.tx, s.ty, gt.target_x, gt.target_y);
    const Box b =
        vehicle_box(s.g, s.tx, s.ty, s.along_x, s.along_y, c.target_length_m, c.target_width_m);
    gt.target_w = static_cast<int>(std::floor(b.x1 - b.x0 + 0.5));
    gt.target_h = static_cast<int>(std::floor(b.y1 - b.y0 + 0.5));
    gt.in_view = box_excess(frame) <= 0;
    double fx = 0, fy = 0;  // flare centre − vehicle centre
    gt.occluded = flare_offset(frame, fx, fy) && fx * fx + fy * fy <= kFlareCorePx * kFlareCorePx;
    if (frame == 0) {
        for (int i = 0; i < 9; ++i) gt.h_from_previous[i] = i % 4 == 0 ? 1 : 0;
    } else {
        double prev_inv[9], h[9];
        invert(state_at(frame - 1).g, prev_inv);
        multiply(s.g, prev_inv, h);
        for (int i = 0; i < 9; ++i) gt.h_from_previous[i] = h[i] / h[8];
        gt.h_from_previous[8] = 1;
    }
    return gt;
}

io::GreyImage GroundSequence::render(int frame) const {
    if (frame < 0 || frame >= config_.frames)
        throw std::out_of_range("GroundSequence::render: frame");
    const GroundSequenceConfig& c = config_;
    const State s = state_at(frame);
    double inv[9];
    invert(s.g, inv);
    Terrain terrain(c.seed);
    const double half_len = c.target_length_m / 2, half_wid = c.target_width_m / 2;
    const double roof_len = half_len * kRoofLengthShare, roof_wid = half_wid * kRoofWidthShare;

    // Flare: the truth's occlusion spell, centred near the vehicle's image position.
    double flare_x = 0, flare_y = 0, target_x = 0, target_y = 0;
    const bool flare = flare_offset(frame, flare_x, flare_y);
    apply(s.g, s.tx, s.ty, target_x, target_y);
    flare_x += target_x;
    flare_y += target_y;

    // Pixels whose samples may hit the vehicle: its image box and a pixel around it.
    const Box vb =
        vehicle_box(s.g, s.tx, s.ty, s.along_x, s.along_y, c.target_length_m, c.target_width_m);
    const auto pixel = [](double v, int size) {
        return static_cast<int>(std::clamp(std::floor(v + 0.5), -2.0, size + 1.0));
    };
    const int vx0 = pixel(vb.x0, c.width) - 1, vx1 = pixel(vb.x1, c.width) + 1;
    const int vy0 = pixel(vb.y0, c.height) - 1, vy1 = pixel(vb.y1, c.height) + 1;

    Gaussian noise(
        Pcg32(mix64(c.seed) ^ static_cast<uint64_t>(frame), 0x6E6F697365ULL));  // stream "noise"
    io::GreyImage img(c.width, c.height);
    constexpr double kSub[3] = {-1.0 / 3, 0, 1.0 / 3};  // 3×3 samples per pixel
    for (int y = 0; y < c.height; ++y) {
        for (int x = 0; x < c.width; ++x) {
            const bool near_vehicle = c.draw_target && x >= vx0 && x <= vx1 && y >= vy0 && y <= vy1;
            int sum = 0;
            for (double oy : kSub) {
                for (double ox : kSub) {
                    const double u = x + ox, v = y + oy;
                    const double w = 1 / (inv[6] * u + inv[7] * v + inv[8]);
                    const double gx = (inv[0] * u + inv[1] * v + inv[2]) * w;
                    const double gy = (inv[3] * u + inv[4] * v + inv[5]) * w;
                    if (near_vehicle) {
                        const double dx = gx - s.tx, dy = gy - s.ty;
                        const double along = dx * s.along_x + dy * s.along_y,
                                     side = dy * s.along_x - dx * s.along_y;
                        if (std::fabs(along) <= half_len && std::fabs(side) <= half_wid) {
                            sum += std::fabs(along) <= roof_len && std::fabs(side) <= roof_wid
                                       ? kRoofLevel
                                       : kBodyLevel;
                            continue;
                        }
                    }
                    sum += terrain.level(gx, gy);
                }
            }
            double value = sum / 9.0;
            if (flare) {
                const double fx = x - flare_x, fy = y - flare_y, r2 = fx * fx + fy * fy;
                if (r2 <= kFlareCorePx * kFlareCorePx) {
                    value = kFlareCoreLevel;  // exactly: nothing beneath shows through
                } else if (r2 < kFlareHaloPx * kFlareHaloPx) {
                    const double q = (kFlareHaloPx - std::sqrt(r2)) / (kFlareHaloPx - kFlareCorePx);
                    value += (kFlareCoreLevel - value) * q * q;
                }
            }
            value += c.noise_sigma * noise.next();
            img.at(x, y) = static_cast<uint8_t>(std::clamp(std::floor(value + 0.5), 0.0, 255.0));
        }
    }
    return img;
}

GroundSequenceConfig short_ground_sequence() {
    GroundSequenceConfig c;
    c.frames = 72;
    c.occlusion_start = 8;
    c.occlusion_frames = 8;
    c.out_of_view_start = 36;
    c.out_of_view_frames = 20;
    return c;
}

GroundSequenceConfig long_ground_sequence() { return GroundSequenceConfig{}; }

}  // namespace qt::scene
