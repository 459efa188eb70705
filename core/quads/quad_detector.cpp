#include "quads/quad_detector.h"

#include "lines/line_fit.h"

namespace qt {

namespace {

// Distance of the middle of segment s from line l with normal n, pixels, q16_16.
int64_t separation(const Segment& l, SinCos n, const Segment& s) {
    const int64_t d = signed_distance(l, n, (static_cast<int64_t>(s.x1.raw) + s.x2.raw) / 2,
                                      (static_cast<int64_t>(s.y1.raw) + s.y2.raw) / 2);
    return d < 0 ? -d : d;
}

int64_t perimeter(const Quad& q) {
    int64_t sum = 0;
    for (int i = 0; i < 4; ++i) sum += distance(q.corners[i], q.corners[(i + 1) & 3]).raw;
    return sum;
}

// Whether both ends of segment s lie within collinear_distance of line l (normal nl).
bool lies_along(const Segment& l, SinCos nl, const Segment& s, const QuadParams& p) {
    auto off_line = [&](q16_16 x, q16_16 y) {  // pixels, q16_16
        const int64_t d = signed_distance(l, nl, x.raw, y.raw);
        return d < 0 ? -d : d;
    };
    return off_line(s.x1, s.y1) <= p.collinear_distance.raw &&
           off_line(s.x2, s.y2) <= p.collinear_distance.raw;
}

// Length of side a -> b (on line `l`, normal `nl`) covered by the lines lying along it: `l`
// itself when it is one of them (index `on_index`; geometry[on_index].collinear then names the
// others below 32), and every line with both ends within collinear_distance of it; at most
// the side's length.
int64_t side_support(Point16 a, Point16 b, const Segment& l, SinCos nl, const Segment* lines,
                     const QuadLine* geometry, uint16_t n, uint8_t on_index, int64_t side_length,
                     const QuadParams& p) {
    int64_t covered = 0;
    uint16_t tested_from = 0;
    if (on_index != kCompletedSide) {
        for (uint32_t along = geometry[on_index].collinear; along != 0; along &= along - 1)
            covered += side_overlap(a, b, lines[__builtin_ctz(along)]).raw;
        tested_from = 32;
    }
    for (uint16_t j = tested_from; j < n; ++j)
        if (j == on_index || lies_along(l, nl, lines[j], p))
            covered += side_overlap(a, b, lines[j]).raw;
    return covered < side_length ? covered : side_length;
}

// Whether every corner of a lies within `tolerance` (per axis) of the same corner of b.
bool same_quad(const Quad& a, const Quad& b, q16_16 tolerance) {
    for (int i = 0; i < 4; ++i) {
        const int64_t dx = static_cast<int64_t>(a.corners[i].x.raw) - b.corners[i].x.raw;
        const int64_t dy = static_cast<int64_t>(a.corners[i].y.raw) - b.corners[i].y.raw;
        if (dx > tolerance.raw || dx < -tolerance.raw || dy > tolerance.raw || dy < -tolerance.raw)
            return false;
    }
    return true;
}

int completed_sides(const Quad& q) {
    int n = 0;
    for (int i = 0; i < 4; ++i) n += q.lines[i] == kCompletedSide;
    return n;
}

// Strict "a ranks before b": score, then found sides over completed ones, then perimeter
// (b's computed only when the rest ties: each costs four square roots), then line indices.
bool ranks_before(const Quad& a, int64_t perim_a, const Quad& b) {
    if (a.score != b.score) return a.score > b.score;
    if (completed_sides(a) != completed_sides(b)) return completed_sides(a) < completed_sides(b);
    const int64_t perim_b = perimeter(b);
    if (perim_a != perim_b) return perim_a > perim_b;
    for (int i = 0; i < 4; ++i)
        if (a.lines[i] != b.lines[i]) return a.lines[i] < b.lines[i];
    return false;
}

// One candidate's sides going round: side i on line[i] (normal normal[i], index id[i] into the
// lines, kCompletedSide for a completed one); corner i is where side i − 1 meets side i.
struct Sides {
    const Segment* line[4];
    SinCos normal[4];
    uint8_t id[4];
};

// Corners of the candidate, put in the canonical order of quad_rules.h, with `order` saying
// which entry of `sides` each output side came from. False when two lines do not cross or the
// shape is not convex.
bool build_candidate(const Sides& sides, Quad& out, uint8_t order[4]) {
    Point16 c[4];
    for (int i = 0; i < 4; ++i) {
        const int before = (i + 3) & 3;
        if (!intersect_lines(*sides.line[before], sides.normal[before], *sides.line[i],
                             sides.normal[i], c[i]))
            return false;
    }
    if (!is_convex(c)) return false;

    // Anti-clockwise as seen (negative shoelace in y-down); reversing the corner order
    // c0 c3 c2 c1 reverses the sides too: L3 L2 L1 L0.
    Point16 ordered[4];
    uint8_t ordered_side[4];
    const bool reverse = shoelace2(c) > 0;
    for (int i = 0; i < 4; ++i) {
        ordered[i] = reverse ? c[(4 - i) & 3] : c[i];
        ordered_side[i] = static_cast<uint8_t>(reverse ? 3 - i : i);
    }
    int first = 0;
    for (int i = 1; i < 4; ++i) {
        const int64_t s = static_cast<int64_t>(ordered[i].x.raw) + ordered[i].y.raw;
        const int64_t best = static_cast<int64_t>(ordered[first].x.raw) + ordered[first].y.raw;
        if (s < best) first = i;
    }
    for (int i = 0; i < 4; ++i) {
        out.corners[i] = ordered[(i + first) & 3];
        order[i] = ordered_side[(i + first) & 3];
        out.lines[i] = sides.id[order[i]];
    }
    return true;
}

// The end of segment s farther from line l (normal n) and its distance, q16_16 raw.
Point16 far_end(const Segment& s, const Segment& l, SinCos n, int64_t* d) {
    const int64_t d1 = signed_distance(l, n, s.x1.raw, s.y1.raw),
                  d2 = signed_distance(l, n, s.x2.raw, s.y2.raw);
    const int64_t a1 = d1 < 0 ? -d1 : d1, a2 = d2 < 0 ? -d2 : d2;
    *d = a1 > a2 ? d1 : d2;
    return a1 > a2 ? Point16{s.x1, s.y1} : Point16{s.x2, s.y2};
}

// The candidate tests after rules 1 and 2, shared by the search over four lines and by
// completion: shape, contrast, rules 3, 4, 5 and support, then the ranked, de-duplicated
// insertion into out[0 .. *count) (completed sides move with their quadrangles).
class Candidates {
public:
    Candidates(const Segment* lines, const QuadLine* geometry, uint16_t n, uint16_t width,
               uint16_t height, const QuadParams& p, Quad* out, Segment* completed,
               uint16_t capacity, uint16_t* count, QuadStats* stats)
        : lines_(lines),
          geometry_(geometry),
          n_(n),
          width_(width),
          height_(height),
          p_(p),
          out_(out),
          completed_(completed),
          capacity_(capacity),
          count_(count),
          stats_(stats) {}

    void consider(const Sides& sides) {
        Quad cand;
        uint8_t order[4];
        if (!build_candidate(sides, cand, order)) {
            ++stats_->rejected_shape;
            return;
        }
        const Segment* side_lines[4];
        SinCos side_normals[4];
        int completed_side = -1;
        for (int k = 0; k < 4; ++k) {
            side_lines[k] = sides.line[order[k]];
            side_normals[k] = sides.normal[order[k]];
            if (cand.lines[k] == kCompletedSide) completed_side = k;
        }
        if (!rule_contrast(cand.corners, side_lines, side_normals, p_)) {
            ++stats_->rejected_contrast;
            return;
        }
        if (!rule_corners_inside(cand.corners, width_, height_, p_)) {
            ++stats_->rejected_inside;
            return;
        }
        q16_16 lengths[4];
        for (int k = 0; k < 4; ++k)
            lengths[k] = distance(cand.corners[k], cand.corners[(k + 1) & 3]);
        if (!rule_side_lengths(lengths, p_)) {
            ++stats_->rejected_sides;
            return;
        }
        if (!rule_aspect(lengths, opposite_convergence(side_lines), p_)) {
            ++stats_->rejected_aspect;
            return;
        }
        // Support: each side found by the lines stage covered at least min_side_coverage (a
        // completed side: whatever pieces of it were found); score = covered share of the
        // perimeter. Sides <= 2048 px, so the q16_16 sums stay below 2^31.
        int64_t covered = 0, perim = 0;
        bool supported = true;
        for (int k = 0; k < 4; ++k) {
            const int64_t o = side_support(cand.corners[k], cand.corners[(k + 1) & 3],
                                           *side_lines[k], side_normals[k], lines_, geometry_, n_,
                                           cand.lines[k], lengths[k].raw, p_);
            if (k != completed_side &&
                o * 65536 < static_cast<int64_t>(lengths[k].raw) * p_.min_side_coverage.raw)
                supported = false;
            covered += o;
            perim += lengths[k].raw;
        }
        cand.score = q16_16::from_raw(perim > 0 ? (covered << 16) / perim : 0);  // rounded down
        if (!supported || cand.score < p_.min_score) {
            ++stats_->rejected_support;
            return;
        }
        ++stats_->accepted;
        insert(cand, perim, completed_side >= 0 ? side_lines[completed_side] : nullptr);
    }

private:
    // One quadrangle found twice (a side on two collinear lines, say) is reported once, as its
    // better-ranked candidate; the best `capacity` are kept, in rank order.
    void insert(const Quad& cand, int64_t perim, const Segment* completed) {
        if (capacity_ == 0) return;
        uint16_t& count = *count_;
        uint16_t dup = 0;
        while (dup < count && !same_quad(out_[dup], cand, p_.collinear_distance)) ++dup;
        if (dup < count) {
            if (!ranks_before(cand, perim, out_[dup])) return;
            for (uint16_t k = dup; k + 1u < count; ++k) move(k + 1, k);
            --count;
        }
        if (count == capacity_ && !ranks_before(cand, perim, out_[capacity_ - 1])) return;
        uint16_t at = count < capacity_ ? count : static_cast<uint16_t>(capacity_ - 1);
        while (at > 0 && ranks_before(cand, perim, out_[at - 1])) {
            move(at - 1, at);
            --at;
        }
        out_[at] = cand;
        if (completed && completed_) completed_[at] = *completed;
        if (count < capacity_) ++count;
    }
    void move(uint16_t from, uint16_t to) {
        out_[to] = out_[from];
        if (completed_) completed_[to] = completed_[from];
    }

    const Segment* lines_;
    const QuadLine* geometry_;
    uint16_t n_, width_, height_;
    const QuadParams& p_;
    Quad* out_;
    Segment* completed_;
    uint16_t capacity_;
    uint16_t* count_;
    QuadStats* stats_;
};

// Whether each line of a parallel pair has the side the board's inside needs (bright for a
// bright board) towards the other line: opposite sides of a board face each other. Lines of
// unknown polarity pass; so does everything with Contrast::any.
// Whether line l has the side the board's inside needs towards the middle of segment `other`
// (lines of unknown polarity, and Contrast::any, always do).
bool faces(const Segment& l, SinCos n, const Segment& other, const QuadParams& p) {
    if (p.contrast == Contrast::any || l.bright_side == 0) return true;
    const int8_t want = p.contrast == Contrast::bright_board ? 1 : -1;
    const int64_t d = signed_distance(l, n, (static_cast<int64_t>(other.x1.raw) + other.x2.raw) / 2,
                                      (static_cast<int64_t>(other.y1.raw) + other.y2.raw) / 2);
    return (d > 0) == (l.bright_side * want > 0);
}

bool facing(const Segment& a, SinCos na, const Segment& b, SinCos nb, const QuadParams& p) {
    return faces(a, na, b, p) && faces(b, nb, a, p);
}

bool perpendicular_to_pair(const Segment* lines, uint8_t c, LinePair p, const QuadParams& params) {
    return rule_perpendicular(lines[c].theta, lines[p.a].theta, params) &&
           rule_perpendicular(lines[c].theta, lines[p.b].theta, params);
}

// Each line's normal, and which of the first 32 lines lie along it (the support rule counts
// their segments).
void line_geometry(const Segment* lines, uint16_t n, const QuadParams& rules, QuadLine* geometry) {
    for (uint16_t i = 0; i < n; ++i) geometry[i].normal = sin_cos(lines[i].theta);
    for (uint16_t i = 0; i < n; ++i) {
        uint32_t along = 0;
        for (uint16_t j = 0; j < n && j < 32; ++j)
            if (j == i || lies_along(lines[i], geometry[i].normal, lines[j], rules))
                along |= uint32_t{1} << j;
        geometry[i].collinear = along;
    }
}

// Parallel pairs (rule 1) whose lines are at least half the shortest side apart (a side meets
// its parallel pair at more than 90° − perpendicular_tolerance, so it is at most ~1/sin(55°)
// times their separation; half is a safe prefilter, rule 4 decides later) and face each other
// with the contrast asked for (the contrast test, early: in texture half the parallel lines or
// more look away from each other). Lines come strongest first (clustering seeds clusters by
// points): every pair of lines 0..j is formed before any pair with line j + 1, so a full pair
// capacity drops the pairs of the weakest lines. Returns the pairs written.
uint16_t parallel_pairs(const Segment* lines, uint16_t n, const QuadLine* geometry,
                        const QuadParams& rules, LinePair* pairs, uint16_t pair_capacity,
                        QuadStats* stats) {
    uint16_t npairs = 0;
    const int64_t min_sep = rules.min_side_length.raw / 2, max_sep = rules.max_side_length.raw;
    for (uint16_t j = 1; j < n; ++j) {
        for (uint16_t i = 0; i < j; ++i) {
            if (!rule_parallel(lines[i].theta, lines[j].theta, rules)) continue;
            const int64_t sep = separation(lines[i], geometry[i].normal, lines[j]);
            if (sep < min_sep || sep > max_sep ||
                !facing(lines[i], geometry[i].normal, lines[j], geometry[j].normal, rules))
                continue;
            if (npairs == pair_capacity) {
                ++stats->pairs_dropped;
                continue;
            }
            pairs[npairs++] = {static_cast<uint8_t>(i), static_cast<uint8_t>(j)};
        }
    }
    return npairs;
}

void set_side(Sides& s, int k, const Segment* lines, const QuadLine* geometry, uint8_t line) {
    s.line[k] = &lines[line];
    s.normal[k] = geometry[line].normal;
    s.id[k] = line;
}

// Two parallel pairs, each line of one almost perpendicular to both of the other (rule 2) and
// facing them: four sides, handed to the candidates.
void pairs_of_pairs(const Segment* lines, const QuadLine* geometry, const LinePair* pairs,
                    uint16_t npairs, const QuadParams& rules, Candidates& candidates,
                    QuadStats* stats) {
    for (uint16_t i = 0; i < npairs; ++i) {
        for (uint16_t j = static_cast<uint16_t>(i + 1); j < npairs; ++j) {
            const LinePair p = pairs[i], q = pairs[j];
            if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b) continue;
            ++stats->combinations;
            if (!perpendicular_to_pair(lines, q.a, p, rules) ||
                !perpendicular_to_pair(lines, q.b, p, rules)) {
                ++stats->rejected_perpendicular;
                continue;
            }
            // Each line of one pair has the inside's side towards the other pair's segments (a
            // side's segment lies between the corners, so its middle is inside the adjacent
            // sides' lines): cheap, and most combinations of clutter lines fail it.
            if (!facing(lines[p.a], geometry[p.a].normal, lines[q.a], geometry[q.a].normal,
                        rules) ||
                !facing(lines[p.a], geometry[p.a].normal, lines[q.b], geometry[q.b].normal,
                        rules) ||
                !facing(lines[p.b], geometry[p.b].normal, lines[q.a], geometry[q.a].normal,
                        rules) ||
                !facing(lines[p.b], geometry[p.b].normal, lines[q.b], geometry[q.b].normal,
                        rules)) {
                ++stats->rejected_contrast;
                continue;
            }
            // Going round: p.a ∩ q.a, q.a ∩ p.b, p.b ∩ q.b, q.b ∩ p.a.
            Sides s;
            set_side(s, 0, lines, geometry, q.a);
            set_side(s, 1, lines, geometry, p.b);
            set_side(s, 2, lines, geometry, q.b);
            set_side(s, 3, lines, geometry, p.a);
            candidates.consider(s);
        }
    }
}

// Completion: a side hidden along most of its length (an arm across it) but whose corners
// show: the two sides next to it run up to those corners. For a parallel pair (a, b) and a
// line c almost perpendicular to both, the fourth side joins the ends of a and b farther from
// c, on the same side of c.
void complete_hidden_sides(const Segment* lines, uint16_t n, const QuadLine* geometry,
                           const LinePair* pairs, uint16_t npairs, const QuadParams& rules,
                           Candidates& candidates, QuadStats* stats) {
    for (uint16_t i = 0; i < npairs; ++i) {
        const LinePair p = pairs[i];
        for (uint16_t c = 0; c < n; ++c) {
            if (c == p.a || c == p.b ||
                !perpendicular_to_pair(lines, static_cast<uint8_t>(c), p, rules))
                continue;
            ++stats->completions;
            int64_t da = 0, db = 0;
            const Point16 fa = far_end(lines[p.a], lines[c], geometry[c].normal, &da);
            const Point16 fb = far_end(lines[p.b], lines[c], geometry[c].normal, &db);
            // Both legs on one side of c, long enough for rule 4, and c's bright (or dark)
            // side towards them: cheap tests before the fourth side is built.
            const int64_t min_leg = rules.min_side_length.raw;
            if ((da < 0) != (db < 0) || (da < 0 ? -da : da) < min_leg ||
                (db < 0 ? -db : db) < min_leg)
                continue;
            if (rules.contrast != Contrast::any && lines[c].bright_side != 0 &&
                ((da > 0) != (lines[c].bright_side > 0)) !=
                    (rules.contrast == Contrast::dark_board))
                continue;
            if (distance(fa, fb).raw < min_leg) continue;
            Segment hidden = line_through(fa, fb);
            if (!rule_parallel(hidden.theta, lines[c].theta, rules)) continue;
            // Its polarity: the board's inside (c's side of it) bright or dark as asked.
            const SinCos nh = sin_cos(hidden.theta);
            const bool c_on_plus =
                signed_distance(hidden, nh,
                                (static_cast<int64_t>(lines[c].x1.raw) + lines[c].x2.raw) / 2,
                                (static_cast<int64_t>(lines[c].y1.raw) + lines[c].y2.raw) / 2) > 0;
            const int8_t inside = c_on_plus ? int8_t{1} : int8_t{-1};
            hidden.bright_side = rules.contrast == Contrast::bright_board ? inside
                                 : rules.contrast == Contrast::dark_board
                                     ? static_cast<int8_t>(-inside)
                                     : int8_t{0};
            Sides s;
            set_side(s, 0, lines, geometry, static_cast<uint8_t>(c));
            set_side(s, 1, lines, geometry, p.b);
            s.line[2] = &hidden;
            s.normal[2] = nh;
            s.id[2] = kCompletedSide;
            set_side(s, 3, lines, geometry, p.a);
            candidates.consider(s);
        }
    }
}

}  // namespace

Segment line_through(Point16 p, Point16 q) {
    const int64_t ux = static_cast<int64_t>(q.x.raw) - p.x.raw,
                  uy = static_cast<int64_t>(q.y.raw) - p.y.raw;
    const int64_t len = distance(p, q).raw;
    FittedLine l;
    l.mx = q16_16::from_raw(static_cast<int32_t>((static_cast<int64_t>(p.x.raw) + q.x.raw) / 2));
    l.my = q16_16::from_raw(static_cast<int32_t>((static_cast<int64_t>(p.y.raw) + q.y.raw) / 2));
    int64_t dx = (ux * (int64_t{1} << 30)) / len, dy = (uy * (int64_t{1} << 30)) / len;
    if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy;
    l.dx = q2_30::from_raw(static_cast<int32_t>(dx));
    l.dy = q2_30::from_raw(static_cast<int32_t>(dy));
    const q16_16 half = q16_16::from_raw(static_cast<int32_t>(len / 2));
    return make_segment(l, q16_16::from_raw(-half.raw), half, 0);
}

Status detect_quads(const Segment* lines, uint16_t n, uint16_t width, uint16_t height,
                    const QuadParams& params, const QuadSearchMemory& memory, QuadStats* stats) {
    *stats = QuadStats{};
    uint16_t count = 0;
    QuadLine* geometry = memory.geometry;
    if (n >= kCompletedSide || width == 0 || height == 0) return Status::bad_size;
    // Rule 4's shortest side by default a tenth of the frame height: the board is held at a
    // working distance, smaller bright quadrangles are other things.
    const QuadParams rules = sized_quad_params(params, height);
    line_geometry(lines, n, rules, geometry);
    const uint16_t npairs =
        parallel_pairs(lines, n, geometry, rules, memory.pairs, memory.pair_capacity, stats);
    stats->parallel_pairs = npairs;
    Candidates candidates(lines, geometry, n, width, height, rules, memory.out, memory.completed,
                          memory.capacity, &count, stats);
    pairs_of_pairs(lines, geometry, memory.pairs, npairs, rules, candidates, stats);
    if (memory.completed != nullptr && rules.complete_hidden_side)
        complete_hidden_sides(lines, n, geometry, memory.pairs, npairs, rules, candidates, stats);
    stats->quads = count;
    return stats->pairs_dropped > 0 ? Status::capacity_exceeded : Status::ok;
}

}  // namespace qt
