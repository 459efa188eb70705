// The synthetic line motion and checksum of the tracker benchmark, shared by the Cortex-M4 image
// (platform/firmware/track_bench.cpp), the host tool that computes its expected checksums at build
// time (platform/firmware/CMakeLists.txt) and the host test
// (tests/tracking/test_track_checksum.cpp). Header-only, core types only, integer arithmetic only:
// the same source must give bit-identical results on every target.
//
// Motion. One line in a 320 × 240 frame, given by its normal direction θ and its signed
// distance ρc from the frame's centre c = (159.5, 119.5) (pixel centres, y down):
//   θ_k = 30° + 2°·k,   ρc_k = 10 px + 0.5 px·k,   frames k = 0 .. kTrackFrames,
// so over the run the line turns 400° while drifting from 10 px to 110 px off centre: it
// crosses the frame in every frame (ρc < 119.5, the centre's distance to the nearest border).
// On the way it passes within 2 px of each origin of default_line_tracker_params()' filters,
// the trackers' near-origin cases: (0, 0) at frame 54, (319, 0) at 111 and 177,
// (159.5, 239) at 197–198.
// 2° is the binary angle angle_from_deg(2) (rounded), so θ_k is exact modulo one turn.
//
// Measurement of frame k: (θ_k, ρc_k) plus noise, uniform in ±0.1° and ±1/4 px, drawn from the
// project's PCG32 with a fixed seed, then turned into a Segment as the detector reports one:
// an 80 px segment centred on the foot of the perpendicular from c (both ends inside the
// frame: √(110.25² + 40²) < 119.5), rho >= 0 and theta relative to the image origin, C =
// rho·(cos θ, sin θ), points = 80, bright side = the side away from the frame's centre.
//
// Protocol (track_checksum): init() on frame 0's measurement; then for each frame
// k = 1 .. kTrackFrames, predict(), line(), update(measurement k) — track_step(). The checksum
// is 32-bit FNV-1a over the raw rho (int32, as uint32) and theta (uint32) of every line()
// result, each fed as 4 bytes, least significant first (so it does not depend on the byte
// order of the machine).
#pragma once
#include <stdint.h>

#include "base/angle.h"
#include "base/fixed.h"
#include "base/prng.h"
#include "lines/segment.h"
#include "tracking/line_tracker.h"

namespace qt {

constexpr uint16_t kTrackWidth = 320, kTrackHeight = 240;
constexpr int kTrackFrames = 200;  // tracked frames, after the one init() takes
constexpr uint64_t kTrackSeed = 0x7472616B;

// The motion's parameters.
constexpr angle_t kTrackTheta0 = angle_from_deg(30);
constexpr angle_t kTrackThetaStep = angle_from_deg(2);
constexpr int32_t kTrackRho0Raw = 10 * 65536;    // 10 px, q16_16 raw
constexpr int32_t kTrackRhoStepRaw = 65536 / 2;  // 0.5 px per frame
// The measurement noise bounds: 0.1° as a binary angle, 1/4 px as q16_16 raw.
constexpr uint32_t kTrackThetaNoise = static_cast<uint32_t>(div_round_half_away(pow2(32), 3600));
constexpr uint32_t kTrackRhoNoiseRaw = 65536 / 4;
constexpr int32_t kTrackHalfLengthRaw = 40 * 65536;  // half the segment's length, px

// The frame's centre, q16_16 raw: ((W − 1)/2, (H − 1)/2).
constexpr int32_t kTrackCentreXRaw = (kTrackWidth - 1) * 65536 / 2;
constexpr int32_t kTrackCentreYRaw = (kTrackHeight - 1) * 65536 / 2;

// The true line of frame k: normal direction and signed distance from the centre (q16_16 raw).
struct TrackTruth {
    angle_t theta;
    int32_t rho_centre_raw;
};

constexpr TrackTruth track_truth(int k) {
    return TrackTruth{kTrackTheta0 + static_cast<uint32_t>(k) * kTrackThetaStep,
                      kTrackRho0Raw + k * kTrackRhoStepRaw};
}

// The Segment of the line with normal `theta` at signed distance rho_centre_raw (q16_16 raw)
// from the frame's centre, as described at the top of this file.
inline Segment track_segment(angle_t theta, int32_t rho_centre_raw) {
    const SinCos n = sin_cos(theta);
    // Foot of the perpendicular from the centre, F = c + ρc·n, and half the segment along the
    // line's direction d = (−sin θ, cos θ).
    const int64_t fx = kTrackCentreXRaw +
                       shr_round_half_away(static_cast<int64_t>(rho_centre_raw) * n.cos.raw, 30);
    const int64_t fy = kTrackCentreYRaw +
                       shr_round_half_away(static_cast<int64_t>(rho_centre_raw) * n.sin.raw, 30);
    const int64_t hx =
        shr_round_half_away(-static_cast<int64_t>(kTrackHalfLengthRaw) * n.sin.raw, 30);
    const int64_t hy =
        shr_round_half_away(static_cast<int64_t>(kTrackHalfLengthRaw) * n.cos.raw, 30);
    Segment s{};
    s.x1 = q16_16::from_raw(fx - hx);
    s.y1 = q16_16::from_raw(fy - hy);
    s.x2 = q16_16::from_raw(fx + hx);
    s.y2 = q16_16::from_raw(fy + hy);
    // Distance from the image origin along n: n·F. Negative: the normal turns half a turn.
    int64_t rho = shr_round_half_away(fx * n.cos.raw + fy * n.sin.raw, 30);
    int64_t sign = 1;
    if (rho < 0) {
        rho = -rho;
        sign = -1;
        theta += kAngleHalfTurn;
    }
    s.rho = q16_16::from_raw(rho);
    s.theta = theta;
    s.cx = q16_16::from_raw(shr_round_half_away(rho * sign * n.cos.raw, 30));
    s.cy = q16_16::from_raw(shr_round_half_away(rho * sign * n.sin.raw, 30));
    s.points = 80;
    // Brighter away from the centre, i.e. along n; along the reported normal unless it turned.
    s.bright_side = static_cast<int8_t>(sign);
    return s;
}

// The noisy measurements of frames 0, 1, 2, ... in order.
class TrackSequence {
public:
    int frame() const { return frame_; }  // the frame next() measures next

    Segment next() {
        const TrackTruth t = track_truth(frame_++);
        const uint32_t dtheta = rng_.below(2 * kTrackThetaNoise + 1);  // [0, 2·bound]
        const int32_t drho = static_cast<int32_t>(rng_.below(2 * kTrackRhoNoiseRaw + 1)) -
                             static_cast<int32_t>(kTrackRhoNoiseRaw);
        return track_segment(t.theta + dtheta - kTrackThetaNoise, t.rho_centre_raw + drho);
    }

private:
    Pcg32 rng_{kTrackSeed};
    int frame_ = 0;
};

// The tracker configurations measured: the paper's closest-point model with 1, 2 and 3
// filters, and the turn model.
struct TrackCase {
    const char* name;
    LineModel model;
    uint8_t filters;
};

inline constexpr TrackCase kTrackCases[] = {
    {"1KF", LineModel::closest_points, 1},
    {"2KF", LineModel::closest_points, 2},
    {"3KF", LineModel::closest_points, 3},
    {"turn", LineModel::turn, 3},
};
constexpr int kTrackCaseCount = static_cast<int>(sizeof kTrackCases / sizeof kTrackCases[0]);

inline LineTrackerParams track_params(const TrackCase& c) {
    LineTrackerParams p = default_line_tracker_params(kTrackWidth, kTrackHeight);
    p.model = c.model;
    p.filters = c.filters;
    return p;
}

// One tracked frame: predict(), line() (returned), update(measured).
inline Segment track_step(LineTracker& tracker, const Segment& measured) {
    tracker.predict();
    const Segment line = tracker.line();
    tracker.update(measured);
    return line;
}

// 32-bit FNV-1a (offset basis 2166136261, prime 16777619).
struct Fnv1a {
    uint32_t hash = 2166136261u;

    void add_byte(uint8_t b) {
        hash ^= b;
        hash *= 16777619u;
    }
    void add_u32(uint32_t v) {  // least significant byte first
        for (int i = 0; i < 4; ++i) add_byte(static_cast<uint8_t>(v >> (8 * i)));
    }
};

// What the checksum covers of one line() result.
inline void track_fold(Fnv1a& h, int32_t rho_raw, angle_t theta) {
    h.add_u32(static_cast<uint32_t>(rho_raw));
    h.add_u32(theta);
}

// The protocol over the whole sequence; the checksum of every line() result.
inline uint32_t track_checksum(const TrackCase& c) {
    TrackSequence seq;
    LineTracker tracker;
    tracker.init(seq.next(), track_params(c));
    Fnv1a h;
    for (int k = 1; k <= kTrackFrames; ++k) {
        const Segment line = track_step(tracker, seq.next());
        track_fold(h, line.rho.raw, line.theta);
    }
    return h.hash;
}

}  // namespace qt
