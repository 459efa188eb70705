#include "scene/line_motion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/prng.h"
#include "scene/det_math.h"
#include "scene/random.h"

namespace qt::scene {

namespace {

// One PCG stream per purpose, so that e.g. adding noise does not change the segments.
constexpr uint64_t kStreamSegments = 0x5e6u, kStreamAngles = 0xa9137u, kStreamNoise = 0x90153u;

constexpr double kQ16 = 65536.0;        // q16_16 raw units per pixel
constexpr double kTurn = 4294967296.0;  // binary-angle units per turn

q16_16 to_q16(double px) { return q16_16::from_raw(std::llround(px * kQ16)); }

// Squared distance, px², from (x, y) to the segment s (its nearest point, ends included).
double dist2_to_segment(const GtSegment& s, double x, double y) {
    const double dx = s.x2 - s.x1, dy = s.y2 - s.y1, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((x - s.x1) * dx + (y - s.y1) * dy) / len2 : 0;
    t = std::min(1.0, std::max(0.0, t));
    const double ex = s.x1 + t * dx - x, ey = s.y1 + t * dy - y;
    return ex * ex + ey * ey;
}

// Nearest integer, ties towards +inf: the pixel whose centre is closest.
long round_half_up(double v) { return static_cast<long>(std::floor(v + 0.5)); }

GtSegment moved(const GtSegment& s, double dx, double dy) {
    return {s.x1 + dx, s.y1 + dy, s.x2 + dx, s.y2 + dy};
}

}  // namespace

Segment measured_segment(const GtSegment& s) {
    const double dx = s.x2 - s.x1, dy = s.y2 - s.y1, len = std::sqrt(dx * dx + dy * dy);
    if (!(len > 0)) throw std::invalid_argument("measured_segment: end points coincide");
    double nx = -dy / len, ny = dx / len;  // unit normal
    double rho = nx * s.x1 + ny * s.y1;
    if (rho < 0) {  // turn the normal towards the line: rho >= 0
        rho = -rho;
        nx = -nx;
        ny = -ny;
    }
    double turns = std::atan2(ny, nx) / (2 * kPi);
    turns -= std::floor(turns);  // [0, 1]
    Segment m{};
    m.x1 = to_q16(s.x1);
    m.y1 = to_q16(s.y1);
    m.x2 = to_q16(s.x2);
    m.y2 = to_q16(s.y2);
    m.rho = to_q16(rho);
    // llround(1.0 · 2^32) wraps to 0 under the mask: one turn is angle 0.
    m.theta =
        static_cast<angle_t>(static_cast<uint64_t>(std::llround(turns * kTurn)) & 0xFFFFFFFFu);
    m.cx = to_q16(rho * nx);
    m.cy = to_q16(rho * ny);
    m.points = 0;
    m.bright_side = 0;
    return m;
}

double overlap_ratio(const GtSegment& truth, const Segment& tracked, double band_px) {
    if (!(band_px > 0)) throw std::invalid_argument("overlap_ratio: band_px must be positive");
    const double rho = tracked.rho.raw / kQ16;
    double sn, cs;
    det_sincos(tracked.theta * (2 * kPi / kTurn), sn, cs);
    // The truth's end points projected onto the tracked line n·p = rho: the piece to draw.
    const double off1 = cs * truth.x1 + sn * truth.y1 - rho;
    const double off2 = cs * truth.x2 + sn * truth.y2 - rho;
    const double ax = truth.x1 - off1 * cs, ay = truth.y1 - off1 * sn;
    const double bx = truth.x2 - off2 * cs, by = truth.y2 - off2 * sn;
    // DDA along the major axis u (x or y); v is the minor axis.
    const bool x_major = std::fabs(bx - ax) >= std::fabs(by - ay);
    const double u0 = x_major ? ax : ay, u1 = x_major ? bx : by;
    const double v0 = x_major ? ay : ax, v1 = x_major ? by : bx;
    const long i0 = round_half_up(u0), i1 = round_half_up(u1);
    const long step = i1 >= i0 ? 1 : -1;
    const double half2 = (band_px / 2) * (band_px / 2);
    long drawn = 0, inside = 0;
    for (long i = i0;; i += step) {
        // The line at u = i (a lone point when the piece has no extent).
        const double v = u1 == u0 ? v0 : v0 + (static_cast<double>(i) - u0) * (v1 - v0) / (u1 - u0);
        const long j = round_half_up(v);
        const double px = static_cast<double>(x_major ? i : j);
        const double py = static_cast<double>(x_major ? j : i);
        ++drawn;
        if (dist2_to_segment(truth, px, py) <= half2) ++inside;
        if (i == i1) break;
    }
    return static_cast<double>(inside) / static_cast<double>(drawn);
}

std::vector<GtSegment> random_segments(uint64_t seed, int count, int width, int height) {
    Pcg32 rng(seed, kStreamSegments);
    std::vector<GtSegment> out;
    for (int i = 0; i < count; ++i) {
        const double cx = uniform(rng, 0, width - 1), cy = uniform(rng, 0, height - 1);
        const double dir = uniform(rng, 0, 180), len = uniform(rng, 40, 160);
        double s, c;
        det_sincos(det_radians(dir), s, c);
        const double hx = c * len / 2, hy = s * len / 2;  // half the segment, px
        out.push_back({cx - hx, cy - hy, cx + hx, cy + hy});
    }
    return out;
}

GtTrack translation_track(const GtSegment& base, double direction_deg, double speed_px,
                          int frames) {
    double s, c;
    det_sincos(det_radians(direction_deg), s, c);
    GtTrack track;
    for (int k = 0; k < frames; ++k)
        track.push_back(moved(base, k * speed_px * c, k * speed_px * s));
    return track;
}

GtTrack rotation_track(Point2 centre, double r_px, double theta0_deg, double omega_deg, int frames,
                       double length_px) {
    GtTrack track;
    for (int k = 0; k < frames; ++k) {
        double s, c;
        det_sincos(det_radians(theta0_deg + k * omega_deg), s, c);
        const double tx = centre.x + r_px * c, ty = centre.y + r_px * s;  // tangent point
        const double hx = -s * length_px / 2, hy = c * length_px / 2;     // along the line
        track.push_back({tx - hx, ty - hy, tx + hx, ty + hy});
    }
    return track;
}

std::vector<double> random_start_angles(uint64_t seed, int count) {
    Pcg32 rng(seed, kStreamAngles);
    std::vector<double> out;
    for (int i = 0; i < count; ++i) out.push_back(uniform(rng, 0, 360));
    return out;
}

double track_mean_overlap(const GtTrack& track, const LineTrackerParams& params,
                          const MotionOptions& options, uint64_t noise_stream) {
    if (track.size() < 2) throw std::invalid_argument("track_mean_overlap: fewer than 2 frames");
    Gaussian noise(Pcg32(options.seed, kStreamNoise + 2 * noise_stream));  // a stream per track
    Pcg32 pieces(options.seed, kStreamNoise + 2 * noise_stream + 1);
    const double sigma = options.noise_sigma;
    const double min_share = options.min_length_share;
    auto uniform = [&] { return pieces.below(1u << 24) / static_cast<double>(1u << 24); };
    // The frame's segment: the whole one, or a random piece of it.
    auto frame_segment = [&](const GtSegment& s) {
        if (!(min_share < 1)) return s;
        const double share = min_share + (1 - min_share) * uniform();
        const double a = (1 - share) * uniform(), b = a + share;
        const double dx = s.x2 - s.x1, dy = s.y2 - s.y1;
        return GtSegment{s.x1 + a * dx, s.y1 + a * dy, s.x1 + b * dx, s.y1 + b * dy};
    };
    auto measure = [&](const GtSegment& t) {
        if (sigma <= 0) return measured_segment(t);
        GtSegment n = t;
        n.x1 += sigma * noise.next();
        n.y1 += sigma * noise.next();
        n.x2 += sigma * noise.next();
        n.y2 += sigma * noise.next();
        return measured_segment(n);
    };
    LineTracker tracker;
    tracker.init(measure(frame_segment(track[0])), params);
    double sum = 0;
    for (std::size_t k = 1; k < track.size(); ++k) {
        tracker.predict();
        const GtSegment truth = frame_segment(track[k]);
        sum += overlap_ratio(truth, tracker.line(), options.band_px);
        tracker.update(measure(truth));
    }
    return sum / static_cast<double>(track.size() - 1);
}

TranslationTable translation_experiment(const LineTrackerParams& params,
                                        const MotionOptions& options) {
    TranslationTable t;
    t.speeds = {1, 2, 3};
    for (int d = 0; d < 360; d += 15) t.directions_deg.push_back(d);
    const std::vector<GtSegment> segments = random_segments(options.seed);
    uint64_t stream = 0;  // one noise stream per track, the same for every tracker
    for (double speed : t.speeds) {
        std::vector<double> row;
        for (double dir : t.directions_deg) {
            double sum = 0;
            for (const GtSegment& s : segments)
                sum +=
                    track_mean_overlap(translation_track(s, dir, speed), params, options, stream++);
            row.push_back(sum / static_cast<double>(segments.size()));
        }
        t.overlap.push_back(row);
    }
    return t;
}

RotationTable rotation_experiment(const LineTrackerParams& params, Point2 centre,
                                  const MotionOptions& options) {
    RotationTable t;
    t.centre = centre;
    t.radii = {10, 50, 100};
    t.omegas_deg = {1, 2, 4, 8, 16};
    const std::vector<double> starts = random_start_angles(options.seed);
    uint64_t stream = 1u << 20;  // apart from Experiment 1's streams
    for (double r : t.radii) {
        std::vector<double> row;
        for (double w : t.omegas_deg) {
            double sum = 0;
            for (double th0 : starts)
                sum += track_mean_overlap(rotation_track(centre, r, th0, w), params, options,
                                          stream++);
            row.push_back(sum / static_cast<double>(starts.size()));
        }
        t.overlap.push_back(row);
    }
    return t;
}

double mean_of(const std::vector<double>& values) {
    double sum = 0;
    for (double v : values) sum += v;
    return values.empty() ? 0 : sum / static_cast<double>(values.size());
}

}  // namespace qt::scene
