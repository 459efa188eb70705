#include "bench/soak_runs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "base/prng.h"
#include "quads/quad_detector.h"
#include "scene/det_math.h"
#include "scene/line_motion.h"
#include "scene/random.h"
#include "target/float/homography.h"
#include "tracking/quad_tracker.h"

namespace qt::soak {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Σ_{i=0}^{m−1} (i + ½)²: the position variance m frames of random acceleration (variance 1 a
// frame) add to a constant-velocity prediction.
double drift_sum(int m) {
    double s = 0;
    for (int i = 0; i < m; ++i) s += (i + 0.5) * (i + 0.5);
    return s;
}

template <class... Args>
std::string words(const char* format, Args... args) {
    char buf[256];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

}  // namespace

VarianceBound cv_variance_bound(double q, double r, double p0_pos, double p0_vel, int max_gap,
                                int age) {
    VarianceBound b;
    const int last = max_gap - 1;  // predictions since the last update while the track lives
    // Before the first update: the initial position, velocity 0 (its prior), m predictions.
    if (age < max_gap) {
        const int m = age < 0 ? last : age;
        b.pos = p0_pos + p0_vel * m * m + q * drift_sum(m);
        b.vel = p0_vel + q * m;
    }
    // After it: the line through the last two (init or updates) g frames apart, extrapolated m
    // frames. Position error = n2·(1 + m/g) − n1·m/g + the accelerations' share; velocity error
    // = (n2 − n1)/g + theirs (n1 has variance p0_pos at the init, r at an update).
    const double v1 = std::max(r, p0_pos);
    for (int g = 1; g <= max_gap; ++g)
        for (int m = 0; m <= last; ++m) {
            const double k = static_cast<double>(m) / g;
            double acc_pos = drift_sum(m), acc_vel = m;
            for (int i = 0; i < g; ++i) {
                acc_pos += (k * (i + 0.5) - m) * (k * (i + 0.5) - m);
                acc_vel += ((i + 0.5) / g - 1) * ((i + 0.5) / g - 1);
            }
            b.pos = std::max(b.pos, v1 * k * k + r * (1 + k) * (1 + k) + q * acc_pos);
            b.vel = std::max(b.vel, (r + v1) / (g * g) + q * acc_vel);
        }
    return b;
}

// ---- quadrangle tracker ---------------------------------------------------------------------

namespace {

constexpr int kW = 640, kH = 480;

struct P {
    double x, y;
};

double val(q16_16 v) { return v.raw / 65536.0; }

// The segment from a to b as the lines stage reports it (scene::measured_segment), with 50
// points and the bright side of a board brighter than its surroundings whose centre is `inside`.
Segment segment(P a, P b, P inside) {
    Segment s = scene::measured_segment({a.x, a.y, b.x, b.y});
    double sn, cs;
    scene::det_sincos(s.theta * (2 * kPi / 4294967296.0), sn, cs);
    s.points = 50;
    s.bright_side = static_cast<int8_t>(cs * inside.x + sn * inside.y - val(s.rho) > 0 ? 1 : -1);
    return s;
}

// The board's smooth motion: centre on a Lissajous path, turning back and forth by up to 30°,
// size breathing by ±15 %: up to ~2 px and ~0.4° a frame.
struct BoardMotion {
    double px, py, pa, ps;  // periods, frames
    double fx, fy, fa, fs;  // phases
    explicit BoardMotion(Pcg32& rng) {
        px = scene::uniform(rng, 500, 900);
        py = scene::uniform(rng, 400, 800);
        pa = scene::uniform(rng, 500, 1000);
        ps = scene::uniform(rng, 700, 1400);
        fx = scene::uniform(rng, 0, 2 * kPi);
        fy = scene::uniform(rng, 0, 2 * kPi);
        fa = scene::uniform(rng, 0, 2 * kPi);
        fs = scene::uniform(rng, 0, 2 * kPi);
    }
    // Corners anti-clockwise as seen: top-left, bottom-left, bottom-right, top-right.
    void corners(uint32_t k, P c[4]) const {
        const double t = k;
        const double cx = kW / 2.0 + 150 * std::sin(2 * kPi * t / px + fx);
        const double cy = kH / 2.0 + 100 * std::sin(2 * kPi * t / py + fy);
        const double a = 30 * kPi / 180 * std::sin(2 * kPi * t / pa + fa);
        const double s = 1 + 0.15 * std::sin(2 * kPi * t / ps + fs);
        const P local[4] = {{-80, -60}, {-80, 60}, {80, 60}, {80, -60}};
        for (int i = 0; i < 4; ++i)
            c[i] = P{cx + s * (local[i].x * std::cos(a) - local[i].y * std::sin(a)),
                     cy + s * (local[i].x * std::sin(a) + local[i].y * std::cos(a))};
    }
};

// Worst corner distance between the tracked quadrangle and the truth, the truth's corners taken
// in the cyclic order that fits best (corner order is detect's business, tested elsewhere).
double corner_error(const TrackedQuad& t, const P truth[4]) {
    double best = 1e30;
    for (int r = 0; r < 4; ++r) {
        double worst = 0;
        for (int i = 0; i < 4; ++i) {
            const P& c = truth[(i + r) % 4];
            worst =
                std::max(worst, std::hypot(val(t.corners[i].x) - c.x, val(t.corners[i].y) - c.y));
        }
        best = std::min(best, worst);
    }
    return best;
}

struct Burst {
    uint32_t start = 0, end = 0;  // first frame without lines, first frame with lines again
};

}  // namespace

QuadSoakResult run_quad_soak(const QuadSoakConfig& cfg) {
    QuadSoakResult res;
    Pcg32 rng(cfg.seed, 0x736F616B71756164ULL);  // stream "soakquad"
    const BoardMotion motion(rng);
    scene::Gaussian noise(Pcg32(cfg.seed, 0x6E6F697365ULL));

    const QuadTrackerParams params = [&] {
        QuadTrackerParams p = default_quad_tracker_params(kW, kH);
        p.lines.model = cfg.model;
        return p;
    }();
    QuadTracker tracker(params);
    const int max_gap = params.max_predicted + 1;  // predictions after which a side is given up
    const bool turn = cfg.model == LineModel::turn;
    const double q = turn ? val(params.lines.turn.q_angle) : val(params.lines.kalman.q);
    const double r = turn ? val(params.lines.turn.r_angle) : val(params.lines.kalman.r);
    const double p0_pos = turn ? val(params.lines.turn.r_angle) : val(params.lines.kalman.p0_pos);
    const double p0_vel = turn ? val(params.lines.turn.p0_turn) : val(params.lines.kalman.p0_vel);
    std::vector<VarianceBound> by_age(static_cast<size_t>(max_gap) +
                                      1);  // ages >= max_gap share one
    for (int a = 0; a <= max_gap; ++a)
        by_age[static_cast<size_t>(a)] = cv_variance_bound(q, r, p0_pos, p0_vel, max_gap, a);
    const VarianceBound settled = by_age[static_cast<size_t>(max_gap)];
    res.pos_variance_bound = settled.pos;
    res.vel_variance_bound = settled.vel;
    res.settled_age = static_cast<uint32_t>(max_gap);
    res.pos_variance_bound_young =
        by_age[static_cast<size_t>(max_gap) - 1].pos;  // the largest before max_gap
    res.vel_variance_bound_young = by_age[static_cast<size_t>(max_gap) - 1].vel;

    auto fail = [&](uint32_t k, const std::string& what) {
        ++res.breaks;
        if (res.first_break.empty()) res.first_break = words("frame %u: ", k) + what;
    };

    // The schedule of bursts.
    std::vector<Burst> bursts;
    for (uint32_t k = cfg.gap_min + rng.below(cfg.gap_max - cfg.gap_min + 1);;) {
        Burst b;
        b.start = k;
        b.end = k + cfg.burst_min + rng.below(cfg.burst_max - cfg.burst_min + 1);
        if (b.end + cfg.gap_min >= cfg.frames) break;
        bursts.push_back(b);
        k = b.end + cfg.gap_min + rng.below(cfg.gap_max - cfg.gap_min + 1);
    }

    // Per burst: the first frame at or after its end showing all four sides, the first such
    // frame at or after max(end, start + max_predicted), and the recovery frame.
    struct BurstLog {
        int64_t first_full = -1, first_full_late = -1, recovered = -1;
    };
    std::vector<BurstLog> log(bursts.size());
    size_t next_burst = 0;  // the first burst whose start is still ahead or under way
    int64_t current = -1;   // the burst being recovered from (index), -1 if none
    uint32_t last_loss_window_end = 0;
    uint32_t last_age = 0;  // the age of the previous frame's track

    Segment lines[4];
    LinePair pairs[64];
    QuadLine geometry[4];
    Quad quads[4];
    P truth[4];
    for (uint32_t k = 0; k < cfg.frames; ++k) {
        while (next_burst < bursts.size() && bursts[next_burst].end <= k) {
            current = static_cast<int64_t>(next_burst);
            ++next_burst;
        }
        const bool in_burst = next_burst < bursts.size() && bursts[next_burst].start <= k;
        if (in_burst && current >= 0) {
            fail(k, "a burst's recovery still open when the next burst began");
            current = -1;
        }
        motion.corners(k, truth);

        // The lines of this frame.
        uint16_t n = 0;
        if (!in_burst) {
            const P mid{(truth[0].x + truth[2].x) / 2, (truth[0].y + truth[2].y) / 2};
            for (int i = 0; i < 4; ++i) {
                const bool missed = scene::uniform01(rng) < cfg.miss_rate;
                if (missed) continue;
                const P a = truth[i], b = truth[(i + 1) % 4];
                P e1{a.x + 0.1 * (b.x - a.x), a.y + 0.1 * (b.y - a.y)};
                P e2{b.x - 0.1 * (b.x - a.x), b.y - 0.1 * (b.y - a.y)};
                e1.x += cfg.end_noise_px * noise.next();
                e1.y += cfg.end_noise_px * noise.next();
                e2.x += cfg.end_noise_px * noise.next();
                e2.y += cfg.end_noise_px * noise.next();
                lines[n++] = segment(e1, e2, mid);
            }
            for (uint16_t i = n; i > 1; --i) std::swap(lines[i - 1], lines[rng.below(i)]);
        }
        const bool full = n == 4;
        res.full_frames += full;
        QuadStats qs;
        detect_quads(lines, n, kW, kH, QuadParams{}, {pairs, 64, geometry, quads, 4}, &qs);
        const uint16_t count = qs.quads;
        const TrackedQuad out = tracker.step(n > 0 ? lines : nullptr, n, quads, count);
        const QuadTrackLost lost = tracker.stats().lost_reason;
        // missed_ counts restart with a track: side_unseen needs max_predicted + 1 frames of it.
        if (lost == QuadTrackLost::side_unseen && last_age + 1 < static_cast<uint32_t>(max_gap))
            fail(k, words("track lost for a side unseen at age %u", last_age + 1));
        if (lost != QuadTrackLost::none) {
            ++res.lost[static_cast<uint8_t>(lost) < 5 ? static_cast<uint8_t>(lost) : 0];
            if (k > last_loss_window_end && !in_burst && current < 0) ++res.lost_outside_bursts;
        }
        res.tracks_started += out.state == TrackState::started;
        last_age = out.age;
        const double err = out.state == TrackState::none ? 1e30 : corner_error(out, truth);

        // Covariances of every constant-velocity filter axis, against the bound for the track's
        // age.
        if (out.state != TrackState::none) {
            const VarianceBound& bound =
                by_age[std::min<size_t>(out.age, static_cast<size_t>(max_gap))];
            for (int s = 0; s < 4; ++s) {
                const LineTracker& lt = tracker.side(s);
                if (lt.flags() != 0) fail(k, words("side %d saturated", s));
                const KalmanAxis* axes[6];
                int na = 0;
                if (turn) {
                    axes[na++] = &lt.angle_filter();
                    res.max_offset_variance =
                        std::max(res.max_offset_variance,
                                 static_cast<double>(lt.offset_filter().cov()[0]) / 4294967296.0);
                } else {
                    for (int f = 0; f < lt.params().filters; ++f) {
                        axes[na++] = &lt.point_filter(f).axis_x();
                        axes[na++] = &lt.point_filter(f).axis_y();
                    }
                }
                for (int i = 0; i < na; ++i) {
                    const double pp = static_cast<double>(axes[i]->pp) / 4294967296.0;
                    const double vv = static_cast<double>(axes[i]->vv) / 4294967296.0;
                    const bool young = out.age < static_cast<uint32_t>(max_gap);
                    double& mp = young ? res.max_pos_variance_young : res.max_pos_variance;
                    double& mv = young ? res.max_vel_variance_young : res.max_vel_variance;
                    mp = std::max(mp, pp);
                    mv = std::max(mv, vv);
                    if (pp > bound.pos || vv > bound.vel)
                        fail(k, words("side %d axis %d: Ppp %.3f (bound %.3f), Pvv %.3f (bound "
                                      "%.3f) at age %u",
                                      s, i, pp, bound.pos, vv, bound.vel, out.age));
                }
            }
        }

        // Bursts: the rule for long ones, the recovery of every one.
        if (in_burst) {
            const Burst& b = bursts[next_burst];
            const uint32_t gone =
                b.start + params.max_predicted;  // the burst's (max_predicted + 1)-th frame
            if (k >= gone && out.state != TrackState::none)
                fail(k, words("a track still carried %u frames into a burst of total loss",
                              k - b.start + 1));
        } else if (current >= 0) {
            const Burst& b = bursts[static_cast<size_t>(current)];
            BurstLog& l = log[static_cast<size_t>(current)];
            const bool is_long = b.end - b.start > params.max_predicted;
            if (full && l.first_full < 0) l.first_full = k;
            if (full && l.first_full_late < 0 && k >= b.start + params.max_predicted)
                l.first_full_late = k;
            if (l.recovered < 0 && err <= cfg.recovery_tolerance_px) l.recovered = k;
            if (is_long) {
                // Gone until the first frame with all four sides, started there.
                if (l.first_full < 0 && out.state != TrackState::none)
                    fail(
                        k,
                        words("a track after a burst of %u frames before the board was whole again",
                              b.end - b.start));
                if (l.first_full == k &&
                    (out.state != TrackState::started || err > cfg.recovery_tolerance_px))
                    fail(k, words("no new track (state %s, error %.2f px) in the first whole frame "
                                  "after a long burst",
                                  track_state_name(out.state), err < 1e29 ? err : -1.0));
            }
            if (l.first_full_late >= 0 && l.recovered < 0)
                fail(k, words("not recovered by the first whole frame at or after the burst's end "
                              "and its frame %u",
                              params.max_predicted + 1));
            if (l.recovered >= 0 && l.first_full >= 0 && l.first_full_late >= 0) {
                // Closed: recovered and the rule's frame is past.
                const uint32_t rec = static_cast<uint32_t>(l.recovered) - b.end;
                res.worst_recovery = std::max(res.worst_recovery, rec);
                res.worst_wait_full =
                    std::max(res.worst_wait_full, static_cast<uint32_t>(l.first_full) - b.end);
                res.recovered_at_burst_end += rec == 0;
                res.recovered_after_whole += l.recovered > l.first_full;
                ++res.bursts;
                res.long_bursts += is_long;
                last_loss_window_end =
                    std::max(b.start + params.max_predicted, static_cast<uint32_t>(l.recovered));
                current = -1;
            } else if (l.recovered >= 0) {
                last_loss_window_end =
                    std::max(last_loss_window_end, static_cast<uint32_t>(l.recovered));
            }
        } else if (out.state != TrackState::none) {
            res.worst_error_tracking = std::max(res.worst_error_tracking, err);
        }
        if (!in_burst && current < 0 && out.state == TrackState::none && res.tracks_started > 0)
            ++res.untracked_outside_bursts;
        res.frames = k + 1;
    }
    return res;
}

// ---- target tracker -------------------------------------------------------------------------

namespace {

// 3×3 matrices in double, row-major.
struct M3 {
    double m[9];
};

M3 mul(const M3& a, const M3& b) {
    M3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c.m[3 * i + j] += a.m[3 * i + k] * b.m[3 * k + j];
    return c;
}

// The camera: ground (m) → image (px) is the similarity g ↦ aim + s·R(ψ)·(g − p), which puts
// the ground point p (the vehicle) at the image point `aim`.
struct Camera {
    double s, psi;  // px per metre, heading (rad)
    P aim;          // where the vehicle appears, px
    P vehicle;      // the vehicle on the ground, m
    M3 ground_to_image() const {
        const double c = s * std::cos(psi), n = s * std::sin(psi);
        return M3{{c, -n, aim.x - (c * vehicle.x - n * vehicle.y), n, c,
                   aim.y - (n * vehicle.x + c * vehicle.y), 0, 0, 1}};
    }
};

enum SpellKind { drift = 0, unseen_kind = 1, bad_geometry_kind = 2, scale_kind = 3 };

}  // namespace

TargetSoakResult run_target_soak(const TargetSoakConfig& cfg) {
    TargetSoakResult res;
    Pcg32 rng(cfg.seed, 0x736F616B74677421ULL);  // stream "soaktgt!"
    const TargetTrackerParams& tp = cfg.params;
    const double w = cfg.width, h = cfg.height;
    const P centre{(w - 1) / 2, (h - 1) / 2};
    auto in_image = [&](P a) {
        return a.x >= -0.5 && a.y >= -0.5 && a.x < w - 0.5 && a.y < h - 0.5;
    };
    auto fail = [&](uint32_t k, const std::string& what) {
        ++res.breaks;
        if (res.first_break.empty()) res.first_break = words("frame %u: ", k) + what;
    };

    // The world: a vehicle driving straight at 0.2 m a frame; the camera at 2.5 px/m (±10 %
    // over 240 frames) turning 0.2° a frame; a scale spell multiplies the scale by `zoom` a frame.
    const double heading = scene::uniform(rng, -kPi, kPi);
    const P velocity{0.2 * std::cos(heading), 0.2 * std::sin(heading)};
    const double phase = scene::uniform(rng, 0, 2 * kPi);
    Camera cam{2.5,
               scene::uniform(rng, -kPi, kPi),
               centre,
               {scene::uniform(rng, -500, 500), scene::uniform(rng, -500, 500)}};
    double zoom_factor = 1;  // product of the scale spells' zooms so far

    TargetTracker tracker;
    M3 prev_g2i = cam.ground_to_image();
    tracker.init(static_cast<float>(cam.aim.x), static_cast<float>(cam.aim.y), cfg.width,
                 cfg.height, tp);
    // The rule's inputs, kept from the inputs alone.
    uint32_t unseen = 0, bad_run = 0;
    double ref_scale = cam.s;  // scale at the tracker's reference frame (init or last reset)
    bool lost = false, trusted = true;
    uint32_t frame = 0;

    // One frame: move the world, tell the tracker, check. `measure`: the vehicle is offered
    // (when in view); `geometry`: 0 trusted, 1 failed (a flat frame), 2 untrustworthy (noise).
    auto step = [&](P aim, double zoom, bool measure, int geometry) {
        const uint32_t k = frame++;
        cam.vehicle.x += velocity.x;
        cam.vehicle.y += velocity.y;
        cam.psi += 0.2 * kPi / 180;
        zoom_factor *= zoom;
        cam.s = 2.5 * (1 + 0.1 * std::sin(2 * kPi * k / 240 + phase)) * zoom_factor;
        cam.aim = aim;
        const M3 g2i = cam.ground_to_image();
        // Previous image → this image: G_k · G_{k−1}⁻¹; the inverse of the previous similarity
        // [A t; 0 1] is [A⁻¹, −A⁻¹t; 0 1].
        const double a = prev_g2i.m[0], b = prev_g2i.m[1], c = prev_g2i.m[3], d = prev_g2i.m[4];
        const double det = a * d - b * c;
        const double ia = d / det, ib = -b / det, ic = -c / det, id = a / det;
        const M3 inv{{ia, ib, -(ia * prev_g2i.m[2] + ib * prev_g2i.m[5]), ic, id,
                      -(ic * prev_g2i.m[2] + id * prev_g2i.m[5]), 0, 0, 1}};
        const M3 hd = mul(g2i, inv);
        prev_g2i = g2i;
        FrameGeometry g;
        for (int i = 0; i < 9; ++i) g.h.m[i] = static_cast<float>(hd.m[i] / hd.m[8]);
        g.valid = geometry != 1;
        g.reprojection_px = g.d_rep_capped_px = geometry == 2 ? 3.0f : 0.3f;
        g.d_rep = geometry == 2 ? 1.0e4f : 9.0f;
        const bool geometry_ok = geometry == 0;
        const bool visible = in_image(aim);
        const bool offered = measure && visible;
        TargetMeasurement m;
        if (offered) {
            m.found = true;
            m.x = static_cast<float>(aim.x);
            m.y = static_cast<float>(aim.y);
            m.score = 1.0f;
        }
        tracker.predict(g);
        const TargetEstimate e = tracker.update(m);

        // The rule, from the inputs: a measurement is accepted exactly when offered with a
        // trusted homography (the estimate is exact, so it passes the gate) and not lost.
        const bool accepted = !lost && offered && geometry_ok;
        bad_run = geometry_ok ? 0 : bad_run + 1;
        const bool was_lost = lost;
        int rule = -1;
        if (!lost && !accepted) {
            ++unseen;
            // A's area factor at the estimate: A maps the reference image (init or the last
            // reset) into this one, a similarity scaling lengths by s_now / s_ref.
            const double area = (cam.s / ref_scale) * (cam.s / ref_scale);
            const double s2 = static_cast<double>(tp.max_scale) * tp.max_scale;
            if (unseen > tp.max_unseen) {
                rule = rule_unseen;
            } else if (bad_run > tp.max_bad_geometry) {
                rule = rule_bad_geometry;
            } else {
                // So near the threshold that float rounding decides: either frame is right.
                const bool borderline =
                    std::fabs(area * s2 - 1) < 1e-4 || std::fabs(area / s2 - 1) < 1e-4;
                if (borderline ? e.state == TargetState::lost : area < 1 / s2 || area > s2)
                    rule = rule_scale;
            }
            if (rule >= 0) lost = true;
        }
        if (!geometry_ok) trusted = false;
        if (accepted) {
            if (unseen > 0) {
                if (e.state != TargetState::reacquired)
                    fail(k, words("not reacquired (%s) on the first frame back",
                                  target_state_name(e.state)));
                ++res.reacquired;
                res.longest_unseen = std::max(res.longest_unseen, unseen);
            } else if (e.state != TargetState::measured) {
                fail(k, words("measurement refused (%s, D_nds %.3f)", target_state_name(e.state),
                              static_cast<double>(e.nds)));
            }
            unseen = 0;
            if (e.reset) ref_scale = cam.s;
        }
        if (lost && !was_lost) {
            ++res.lost_events;
            ++res.lost_by_rule[rule];
            if (e.state == TargetState::lost)
                ++res.lost_on_time;
            else
                fail(k, words("not lost (%s) in the frame the rule names (unseen %u, bad run %u)",
                              target_state_name(e.state), unseen, bad_run));
        } else if (lost && e.state != TargetState::lost) {
            fail(k, words("came back (%s) from lost without init", target_state_name(e.state)));
        } else if (!lost && e.state == TargetState::lost) {
            fail(k, words("lost early (unseen %u, bad run %u, area %.4f)", unseen, bad_run,
                          (cam.s / ref_scale) * (cam.s / ref_scale)));
            lost = true;
        }
        if (!lost && trusted) {
            const double err =
                std::hypot(static_cast<double>(e.x) - aim.x, static_cast<double>(e.y) - aim.y);
            res.worst_error_px = std::max(res.worst_error_px, err);
            if (!visible) res.worst_error_outside_px = std::max(res.worst_error_outside_px, err);
            if (err > cfg.error_tolerance_px)
                fail(k, words("estimate %.3f px from the truth", err));
        }
        if (!visible) {
            const double out =
                std::max({-0.5 - aim.x, aim.x - (w - 0.5), -0.5 - aim.y, aim.y - (h - 0.5)});
            res.farthest_outside_px = std::max(res.farthest_outside_px, out);
        }
        res.frames = frame;
    };

    int kind = 0;
    while (frame < cfg.frames) {
        // Start (again) on the vehicle where it is.
        tracker.init(static_cast<float>(cam.aim.x), static_cast<float>(cam.aim.y), cfg.width,
                     cfg.height, tp);
        unseen = bad_run = 0;
        ref_scale = cam.s;
        lost = false;
        trusted = true;
        ++res.cycles;
        // In view, wandering about the centre, measured.
        const double wx = scene::uniform(rng, 0, 2 * kPi), wy = scene::uniform(rng, 0, 2 * kPi);
        auto wander = [&](uint32_t i) {
            return P{centre.x + 15 * std::sin(i / 40.0 + wx),
                     centre.y + 10 * std::sin(i / 50.0 + wy)};
        };
        const uint32_t view = 40 + rng.below(120);
        for (uint32_t i = 0; i < view && frame < cfg.frames; ++i) step(wander(i), 1, true, 0);
        // The spell: out through a random side to `depth` px beyond the border, held, back.
        const double dir = scene::uniform(rng, -kPi, kPi);
        const P d{std::cos(dir), std::sin(dir)};
        const double reach = std::min(std::fabs(d.x) > 1e-9 ? (w / 2) / std::fabs(d.x) : 1e9,
                                      std::fabs(d.y) > 1e-9 ? (h / 2) / std::fabs(d.y) : 1e9);
        const double depth = scene::uniform(rng, 20, 100);
        const P start = wander(view),
                far{centre.x + d.x * (reach + depth), centre.y + d.y * (reach + depth)};
        const uint32_t ramp = 60;
        const SpellKind sk = static_cast<SpellKind>(kind++ % 4);
        ++res.spells[sk];
        uint32_t hold = 0;
        switch (sk) {
            case drift:
                hold = 1 + rng.below(tp.max_unseen > ramp + 11 ? tp.max_unseen - ramp - 10 : 1u);
                break;
            case unseen_kind: hold = tp.max_unseen + rng.below(100); break;
            case bad_geometry_kind: hold = 150; break;
            case scale_kind: hold = 150; break;
        }
        const double zoom = sk == scale_kind ? (rng.below(2) ? 0.97 : 1 / 0.97) : 1;  // a frame
        // Bad geometry: runs of 1..max_bad_geometry untrustworthy frames between trusted ones,
        // then, from the hold's middle, one run that does not end.
        uint32_t run_left = 0, good_left = 10;
        auto smooth = [](double t) { return t * t * (3 - 2 * t); };
        for (uint32_t i = 0; i < 2 * ramp + hold && frame < cfg.frames; ++i) {
            const double t = i < ramp ? smooth(i / static_cast<double>(ramp))
                             : i < ramp + hold
                                 ? 1.0
                                 : smooth(1 - (i - ramp - hold) / static_cast<double>(ramp));
            const P home = i < ramp + hold ? start : wander(view + i);
            const P aim{home.x + t * (far.x - home.x), home.y + t * (far.y - home.y)};
            const bool holding = i >= ramp && i < ramp + hold;
            int geometry = 0;
            if (sk == bad_geometry_kind && holding) {
                if (i >= ramp + hold / 2) {
                    geometry = 1 + static_cast<int>(rng.below(2));
                } else if (run_left > 0) {
                    --run_left;
                    geometry = 1 + static_cast<int>(rng.below(2));
                } else if (good_left > 0) {
                    --good_left;
                } else {
                    run_left = 1 + rng.below(tp.max_bad_geometry);
                    good_left = 1 + rng.below(3);
                }
            }
            // A scale spell zooms for 60 frames (lost after about 46) and back for 60: the
            // camera ends at the scale it started from.
            const uint32_t j = i - ramp;
            const double z = !holding ? 1 : j < 60 ? zoom : j < 120 ? 1 / zoom : 1;
            // Measured only outside the hold (and while in view): the spell is "no measurement".
            step(aim, z, !holding, geometry);
        }
        // Back in view and offered: lost stays lost; a live track is reacquired.
        for (uint32_t i = 0; i < 20 && frame < cfg.frames; ++i)
            step(wander(view + 2 * ramp + hold + i), 1, true, 0);
    }
    return res;
}

}  // namespace qt::soak
