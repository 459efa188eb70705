// The tracker benchmark's synthetic motion and checksums (platform/firmware/track_sequence.h) on
// the host. The Cortex-M4 image track_bench computes the same checksums on the target and
// compares them with the host's (the ctest m4_track_lines); here: the checksum is FNV-1a, the
// sequence is the motion it claims to be, every model follows it, and the checksum does not
// depend on the order the image uses (measurements generated first, line() results folded
// after the timed loop).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "track_sequence.h"

using namespace qt;

namespace {

constexpr double kQ16 = 65536.0;
constexpr double kPi = 3.14159265358979323846;
constexpr double kCentreX = (kTrackWidth - 1) / 2.0, kCentreY = (kTrackHeight - 1) / 2.0;

double px(q16_16 v) { return v.raw / kQ16; }
double rad(angle_t a) { return a * (2 * kPi / 4294967296.0); }
double deg(double r) { return r * 180 / kPi; }

// Angle difference wrapped into [-π, π).
double wrap(double r) { return r - 2 * kPi * std::floor((r + kPi) / (2 * kPi)); }

// Signed distance of the segment's line from the frame's centre along its normal θ.
double rho_from_centre(const Segment& s) {
    return px(s.rho) - (std::cos(rad(s.theta)) * kCentreX + std::sin(rad(s.theta)) * kCentreY);
}

uint32_t fnv1a(const char* text) {
    Fnv1a h;
    while (*text != 0) h.add_byte(static_cast<uint8_t>(*text++));
    return h.hash;
}

// How far line() (the prediction) is from the true line of its frame: worst angle (degrees) and
// offset from the centre (px) over frames first..last.
struct TrackError {
    double angle = 0, offset = 0;
};

TrackError track_error(const TrackCase& c, int first, int last, uint8_t& flags) {
    TrackSequence seq;
    LineTracker tracker;
    REQUIRE(tracker.init(seq.next(), track_params(c)));
    TrackError worst;
    for (int k = 1; k <= kTrackFrames; ++k) {
        const Segment line = track_step(tracker, seq.next());
        if (k < first || k > last) continue;
        const TrackTruth t = track_truth(k);
        double dtheta = wrap(rad(line.theta) - rad(t.theta)), rho_c = rho_from_centre(line);
        if (std::abs(dtheta) > kPi / 2) {
            dtheta = wrap(dtheta + kPi);
            rho_c = -rho_c;
        }
        worst.angle = std::max(worst.angle, std::abs(deg(dtheta)));
        worst.offset = std::max(worst.offset, std::abs(rho_c - t.rho_centre_raw / kQ16));
    }
    flags = tracker.flags();
    return worst;
}

}  // namespace

TEST_CASE("track checksum is 32-bit FNV-1a, little-endian words", "[track]") {
    // The published FNV-1a 32-bit test values.
    CHECK(fnv1a("") == 0x811c9dc5u);
    CHECK(fnv1a("a") == 0xe40c292cu);
    CHECK(fnv1a("foobar") == 0xbf9cf968u);
    Fnv1a word, bytes;
    word.add_u32(0x64636261u);  // "abcd", least significant byte first
    for (const char c : {'a', 'b', 'c', 'd'}) bytes.add_byte(static_cast<uint8_t>(c));
    CHECK(word.hash == bytes.hash);
    CHECK(word.hash == fnv1a("abcd"));
}

TEST_CASE("track sequence: a line turning 2 deg/frame, 0.5 px/frame off centre, noisy", "[track]") {
    TrackSequence seq, again;
    for (int k = 0; k <= kTrackFrames; ++k) {
        INFO("frame " << k);
        REQUIRE(seq.frame() == k);
        const Segment m = seq.next();
        const Segment r = again.next();
        REQUIRE(m.rho.raw == r.rho.raw);  // deterministic
        REQUIRE(m.theta == r.theta);

        // A Segment as the detector reports it: rho >= 0, C = rho·n, both ends on the line and
        // inside the frame, 80 px apart.
        const double th = rad(m.theta), nx = std::cos(th), ny = std::sin(th);
        CHECK(m.rho.raw >= 0);
        CHECK(std::abs(px(m.cx) - px(m.rho) * nx) < 1e-3);
        CHECK(std::abs(px(m.cy) - px(m.rho) * ny) < 1e-3);
        for (const auto& [x, y] : {std::pair{m.x1, m.y1}, std::pair{m.x2, m.y2}}) {
            CHECK(std::abs(px(x) * nx + px(y) * ny - px(m.rho)) < 1e-3);
            CHECK(px(x) >= 0);
            CHECK(px(x) <= kTrackWidth - 1);
            CHECK(px(y) >= 0);
            CHECK(px(y) <= kTrackHeight - 1);
        }
        CHECK(std::hypot(px(m.x2) - px(m.x1), px(m.y2) - px(m.y1)) == Approx(80).margin(1e-3));
        CHECK(m.points == 80);

        // The motion, within the noise: θ = 30° + 2°·k (or opposite, with ρc negated),
        // ρc = 10 + 0.5·k px; |noise| <= 0.1° and 1/4 px.
        const double truth_theta = rad(angle_from_deg(30)) + k * rad(angle_from_deg(2));
        double dtheta = wrap(th - truth_theta), rho_c = rho_from_centre(m);
        if (std::abs(dtheta) > kPi / 2) {
            dtheta = wrap(dtheta + kPi);
            rho_c = -rho_c;
        }
        CHECK(std::abs(deg(dtheta)) <= 0.1 + 1e-6);
        CHECK(std::abs(rho_c - (10 + 0.5 * k)) <= 0.25 + 1e-3);
        // The bright side lies away from the centre.
        CHECK(m.bright_side == (rho_from_centre(m) > 0 ? 1 : -1));
    }
}

TEST_CASE("track sequence: the models follow the line", "[track]") {
    // 3KF and turn follow the whole run once settled (20 frames). 1KF and 2KF do not: the line
    // passes within 2-3 px of the image origin, 1KF's only origin, at frames 54 and 128
    // (θ ≈ 138° and 286°), where its closest point swings round that origin faster than a
    // constant-velocity filter follows (errors up to ~20° and ~70 px), and 2KF falls back to one
    // filter while the line stands perpendicular to O1O2 (θ ≈ 0° and 180°): the weaknesses the
    // paper's third filter removes. Both recover: in the last 20 frames (θ = 30°..70°, past
    // both) they are within 1° and 2 px (the lag of a constant-velocity point on a turning line).
    for (const TrackCase& c : kTrackCases) {
        INFO("model " << c.name);
        uint8_t flags = 0;
        const bool whole = c.model == LineModel::turn || c.filters == 3;
        const TrackError e = whole ? track_error(c, 20, kTrackFrames, flags)
                                   : track_error(c, kTrackFrames - 19, kTrackFrames, flags);
        INFO("worst angle error " << e.angle << " deg, offset error " << e.offset << " px");
        CHECK(flags == 0);
        CHECK(e.angle < 1.0);
        CHECK(e.offset < (whole ? 1.0 : 2.0));
    }
}

TEST_CASE("track checksums: deterministic, distinct per model, same in the image's order",
          "[track]") {
    uint32_t sums[kTrackCaseCount];
    for (int i = 0; i < kTrackCaseCount; ++i) {
        const TrackCase& c = kTrackCases[i];
        sums[i] = track_checksum(c);
        INFO("model " << c.name << " checksum 0x" << std::hex << sums[i]);
        CHECK(track_checksum(c) == sums[i]);

        // track_bench.cpp's order: all measurements first, the timed loop storing rho and
        // theta, the checksum folded afterwards.
        static Segment measured[kTrackFrames + 1];
        static int32_t rho[kTrackFrames];
        static angle_t theta[kTrackFrames];
        TrackSequence seq;
        for (Segment& m : measured) m = seq.next();
        LineTracker tracker;
        tracker.init(measured[0], track_params(c));
        for (int k = 0; k < kTrackFrames; ++k) {
            const Segment line = track_step(tracker, measured[k + 1]);
            rho[k] = line.rho.raw;
            theta[k] = line.theta;
        }
        Fnv1a h;
        for (int k = 0; k < kTrackFrames; ++k) track_fold(h, rho[k], theta[k]);
        CHECK(h.hash == sums[i]);
        for (int j = 0; j < i; ++j) CHECK(sums[j] != sums[i]);
    }
}
