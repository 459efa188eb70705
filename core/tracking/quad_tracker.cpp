#include "tracking/quad_tracker.h"

#include "base/isqrt.h"

namespace qt {

namespace {

// Angle between two lines' orientations, modulo 180°: [0°, 90°] as a binary angle.
angle_t orientation_diff(angle_t a, angle_t b) {
    const angle_t d = (a - b) & (kAngleHalfTurn - 1u);
    return d > kAngleQuarterTurn ? kAngleHalfTurn - d : d;
}

// The contrast polarities of two lines agree (either unknown passes). bright_side is relative
// to each line's own normal, so it flips when the normals point opposite ways.
bool same_polarity(const Segment& a, const Segment& b) {
    if (a.bright_side == 0 || b.bright_side == 0) return true;
    const angle_t d = a.theta - b.theta;
    const bool opposite = d > kAngleQuarterTurn && d < 3u * kAngleQuarterTurn;
    return opposite ? a.bright_side == -b.bright_side : a.bright_side == b.bright_side;
}

// Corners of the quadrangle whose side i lies on sides[i]: corner i = sides[i − 1] × sides[i].
// True when all four exist and make a strictly convex quadrangle, anti-clockwise as seen (the
// winding a track starts with: a flip means the lines crossed over), sides within the limits.
bool corners_of(const Segment sides[4], const QuadParams& shape, Point16 corners[4]) {
    for (int i = 0; i < 4; ++i)
        if (!intersect_lines(sides[(i + 3) % 4], sides[i], corners[i])) return false;
    if (!is_convex(corners) || shoelace2(corners) >= 0) return false;
    q16_16 lengths[4];
    for (int i = 0; i < 4; ++i) lengths[i] = distance(corners[i], corners[(i + 1) % 4]);
    return rule_side_lengths(lengths, shape);
}

// Side i as the segment from corner i to corner i + 1 on its line.
Segment side_segment(const Segment& line, Point16 a, Point16 b) {
    Segment s = line;
    s.x1 = a.x;
    s.y1 = a.y;
    s.x2 = b.x;
    s.y2 = b.y;
    return s;
}

// Side bits in the tracker's order -> the same bits in detect's order, whose side 0 is the
// tracker's side `first`.
uint8_t turn_bits(uint8_t bits, int first) {
    uint8_t out = 0;
    for (int i = 0; i < 4; ++i)
        if (bits & (1u << ((first + i) % 4))) out = static_cast<uint8_t>(out | (1u << i));
    return out;
}

// Fills out's corners, sides and detected bits from the tracker's side order, turned so that
// corner 0 has the smallest x + y (detect's contract). Returns the tracker's side that became
// side 0.
int emit(const Segment lines[4], const Point16 corners[4], uint8_t detected, TrackedQuad& out) {
    int first = 0;
    for (int i = 1; i < 4; ++i) {
        const int64_t s = static_cast<int64_t>(corners[i].x.raw) + corners[i].y.raw;
        const int64_t f = static_cast<int64_t>(corners[first].x.raw) + corners[first].y.raw;
        if (s < f) first = i;
    }
    for (int i = 0; i < 4; ++i) {
        const int k = (first + i) % 4;
        out.corners[i] = corners[k];
        out.sides[i] = side_segment(lines[k], corners[k], corners[(k + 1) % 4]);
    }
    out.detected = turn_bits(detected, first);
    return first;
}

// |a − b| <= tolerance · b for lengths a, b >= 0 (px) and a fraction tolerance.
bool length_within(q16_16 a, q16_16 b, q16_16 tolerance) {
    // |a − b| < 2^32 and b < 2^31 raw, tolerance <= 2^16 raw (one): both sides below 2^48.
    const int64_t diff = abs64(static_cast<int64_t>(a.raw) - b.raw);
    return diff * q16_16::one_raw <= static_cast<int64_t>(tolerance.raw) * b.raw;
}

// The side lengths of a quadrangle: side i from corner i to corner i + 1, px.
void side_lengths(const Point16 corners[4], q16_16 lengths[4]) {
    for (int i = 0; i < 4; ++i) lengths[i] = distance(corners[i], corners[(i + 1) % 4]);
}

}  // namespace

bool QuadTracker::agrees(const TrackedQuad& tracked, const Quad& detected) const {
    // Both in detect's corner order; a detection whose corner 0 is another corner (two corners
    // with almost the same x + y) counts as disagreeing, and restarting from it costs nothing.
    const int64_t gate = params_.gate_distance.raw;
    for (int i = 0; i < 4; ++i)
        if (distance(tracked.corners[i], detected.corners[i]).raw > gate) return false;
    return true;
}

const char* quad_track_lost_name(QuadTrackLost reason) {
    switch (reason) {
        case QuadTrackLost::side_unseen: return "side_unseen";
        case QuadTrackLost::shape: return "shape";
        case QuadTrackLost::saturated: return "saturated";
        case QuadTrackLost::detection_disagrees: return "detection_disagrees";
        default: return nullptr;
    }
}

const char* track_state_name(TrackState state) {
    switch (state) {
        case TrackState::started: return "started";
        case TrackState::tracking: return "tracking";
        case TrackState::none: break;
    }
    return "none";
}

QuadTrackerParams default_quad_tracker_params(uint16_t width, uint16_t height) {
    QuadTrackerParams p;
    p.lines = default_line_tracker_params(width, height);
    p.shape = sized_quad_params(p.shape, height);
    return p;
}

void QuadTracker::reset() {
    active_ = false;
    age_ = 0;
    for (uint8_t& m : missed_) m = 0;
    stats_ = QuadTrackStats{};
}

bool QuadTracker::gated(const Segment& s, const Segment& predicted) const {
    if (orientation_diff(s.theta, predicted.theta) > params_.gate_angle) return false;
    const SinCos normal = sin_cos(predicted.theta);
    const int64_t gate = params_.gate_distance.raw;
    if (abs64(signed_distance(predicted, normal, s.x1.raw, s.y1.raw)) > gate ||
        abs64(signed_distance(predicted, normal, s.x2.raw, s.y2.raw)) > gate)
        return false;
    return same_polarity(s, predicted);
}

bool QuadTracker::within_reach(int side, const Segment& predicted, const Segment& s) const {
    const SinCos normal = sin_cos(predicted.theta);
    const int64_t k = params_.take_back_sigmas < 1   ? 1
                      : params_.take_back_sigmas > 8 ? 8
                                                     : params_.take_back_sigmas;
    const Point16 ends[2] = {{s.x1, s.y1}, {s.x2, s.y2}};
    for (const Point16& e : ends) {
        // d² <= k²·S, both px² with 32 fraction bits: d held to 4096 px (d² <= 2^56) and S to
        // 2^24 px² (2^56 raw), so k²·S <= 2^62 for k <= 8.
        const int64_t d =
            clamp64(abs64(signed_distance(predicted, normal, e.x.raw, e.y.raw)), 0, pow2(28));
        const int64_t var = clamp64(sides_[side].innovation_variance(e), 0, pow2(56));
        if (d * d > k * k * var) return false;
    }
    return true;
}

int QuadTracker::whole_match(const Segment* lines, uint16_t n, const Quad& quad,
                             const Segment predicted[4], const Point16 corners[4]) const {
    // The detection's side i + shift is the track's side i (both wind anti-clockwise).
    for (int shift = 0; shift < 4; ++shift) {
        bool agrees = true;
        for (int i = 0; i < 4 && agrees; ++i) {
            const uint8_t j = quad.lines[(i + shift) % 4];
            agrees = j < n && gated(lines[j], predicted[i]) &&
                     side_overlap(corners[i], corners[(i + 1) % 4], lines[j]).raw > 0;
        }
        if (agrees) return shift;
    }
    return -1;
}

uint8_t QuadTracker::take_back(const Segment* lines, uint16_t n, const Quad& quad,
                               const Segment predicted[4], uint8_t detected, uint32_t used[8]) {
    q16_16 lengths[4];
    side_lengths(quad.corners, lengths);
    // The detection's side i + shift is the track's side i (both wind anti-clockwise): every
    // matched side's counterpart passes that side's gate, and every side of the detection has
    // the length the track had when it last saw all four sides.
    for (int shift = 0; shift < 4; ++shift) {
        bool agrees = true;
        for (int i = 0; i < 4 && agrees; ++i) {
            const int k = (i + shift) % 4;
            agrees = quad.lines[k] < n &&
                     length_within(lengths[k], whole_lengths_[i], params_.take_back_length) &&
                     (!(detected & (1u << i)) || gated(lines[quad.lines[k]], predicted[i]));
        }
        if (!agrees) continue;
        // Each unmatched side's counterpart within its filters' reach, and a line no side took.
        for (int i = 0; i < 4 && agrees; ++i) {
            const uint8_t j = quad.lines[(i + shift) % 4];
            agrees = (detected & (1u << i)) || (!(used[j / 32] & (1u << (j % 32))) &&
                                                within_reach(i, predicted[i], lines[j]));
        }
        if (!agrees) return 0;
        uint8_t taken = 0;
        for (int i = 0; i < 4; ++i) {
            const uint8_t j = quad.lines[(i + shift) % 4];
            if (detected & (1u << i)) continue;
            used[j / 32] |= 1u << (j % 32);
            sides_[i].update(lines[j]);
            missed_[i] = 0;
            taken = static_cast<uint8_t>(taken | (1u << i));
        }
        return taken;
    }
    return 0;
}

TrackedQuad QuadTracker::start(const Segment* lines, const Quad& quad) {
    Segment sides[4];
    for (int i = 0; i < 4; ++i) {
        sides[i] = lines[quad.lines[i]];
        sides_[i].init(sides[i], params_.lines);
        missed_[i] = 0;
    }
    side_lengths(quad.corners, whole_lengths_);
    active_ = true;
    age_ = 0;
    ++track_id_;
    TrackedQuad out;
    out.state = TrackState::started;
    out.track_id = track_id_;
    emit(sides, quad.corners, 0x0F, out);
    return out;
}

TrackedQuad QuadTracker::step(const Segment* lines, uint16_t n, const Quad* quads,
                              uint16_t quad_count) {
    stats_ = QuadTrackStats{};
    if (active_) {
        Segment predicted[4];
        for (int i = 0; i < 4; ++i) {
            sides_[i].predict();
            predicted[i] = sides_[i].line();
        }
        Point16 corners[4];
        uint8_t detected = 0;
        QuadTrackLost lost = QuadTrackLost::none;
        if (!corners_of(predicted, params_.shape, corners)) {
            lost = QuadTrackLost::shape;
        } else {
            // Association: this frame's best detection when each of its sides passes the gate
            // of one of the track's (its sides are refitted to the edge evidence between its
            // corners); otherwise each side takes the longest gated line. A line serves one side.
            // A frame without lines leaves every side unmatched (and counted in missed_).
            uint32_t used[8] = {};  // bit set of line indices < 256
            const int shift =
                quad_count > 0 ? whole_match(lines, n, quads[0], predicted, corners) : -1;
            for (int i = 0; i < 4; ++i) {
                const Point16 a = corners[i], b = corners[(i + 1) % 4];
                int best = shift >= 0 ? quads[0].lines[(i + shift) % 4] : -1;
                uint64_t best_len2 = 0;  // its squared length; the length is compared below
                for (uint16_t j = 0; shift < 0 && j < n && j < 256; ++j) {
                    if (used[j / 32] & (1u << (j % 32))) continue;
                    const Segment& s = lines[j];
                    if (!gated(s, predicted[i])) continue;
                    if (side_overlap(a, b, s).raw <= 0) continue;
                    // Longer to 2^-16 px (distance()): a longer square first, then its root.
                    const uint64_t len2 = distance2(Point16{s.x1, s.y1}, Point16{s.x2, s.y2});
                    if (best < 0 || (len2 > best_len2 && isqrt64(len2) > isqrt64(best_len2))) {
                        best = j;
                        best_len2 = len2;
                    }
                }
                if (best >= 0) {
                    used[best / 32] |= 1u << (best % 32);
                    sides_[i].update(lines[best]);
                    detected = static_cast<uint8_t>(detected | (1u << i));
                    missed_[i] = 0;
                } else if (missed_[i] < 255) {
                    ++missed_[i];
                }
            }
            // A side predicted off the line the detector sees is taken back from a whole
            // detection that agrees with the matched sides (see the top of quad_tracker.h).
            const uint8_t matched = detected;
            uint8_t taken = 0;
            if (params_.take_back && matched != 0 && matched != 0x0F && quad_count > 0 && n > 0) {
                taken = take_back(lines, n, quads[0], predicted, matched, used);
                detected = static_cast<uint8_t>(matched | taken);
            }
            Segment current[4];
            for (int i = 0; i < 4; ++i) {
                current[i] = sides_[i].line();
                if (missed_[i] > params_.max_predicted) lost = QuadTrackLost::side_unseen;
                if (sides_[i].flags() != 0) lost = QuadTrackLost::saturated;
            }
            if (lost == QuadTrackLost::none && !corners_of(current, params_.shape, corners))
                lost = QuadTrackLost::shape;
            if (lost == QuadTrackLost::none) {
                TrackedQuad out;
                out.state = TrackState::tracking;
                out.track_id = track_id_;
                out.age = age_ + 1;
                const int first = emit(current, corners, detected, out);
                stats_.taken_back = turn_bits(taken, first);
                if (matched == 0x0F) side_lengths(corners, whole_lengths_);
                // No side found near its prediction while the detector sees a whole quadrangle
                // elsewhere: the board moved past the gate; trust the detection. With some
                // sides matched the track is anchored, and a disagreeing detection is more
                // likely those sides plus an occluder's edges (the demo's bars) than the board.
                if (detected != 0 || quad_count == 0 || agrees(out, quads[0])) {
                    ++age_;
                    return out;
                }
                lost = QuadTrackLost::detection_disagrees;
            }
        }
        // Lost: start again from this frame's detection, if there is one.
        stats_.lost_reason = lost;
        active_ = false;
    }
    if (quad_count > 0 && n > 0) return start(lines, quads[0]);
    return TrackedQuad{};
}

}  // namespace qt
