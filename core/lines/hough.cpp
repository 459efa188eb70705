#include "lines/hough.h"

#include <string.h>

#if defined(__ARM_FEATURE_SIMD32)
#include <arm_acle.h>
#endif

#include "lines/line_fit.h"
#include "lines/visit_order.h"

namespace qt {

namespace {

int rho_shift_of(uint16_t rho_step) {
    return rho_step == 1 ? 0 : rho_step == 2 ? 1 : rho_step == 4 ? 2 : -1;
}

// The voting arithmetic, one instruction each where the Cortex-M4's SIMD extension has it, the
// same values in plain C elsewhere (bit for bit: the tests compare the two).
#if defined(__ARM_FEATURE_SIMD32)
// x·cos θ + y·sin θ + bias for a point packed as x in the low 16 bits and y in the high
// (signed) and a cos_sin_q14 entry (|x|, |y| <= 1024, |cos|, |sin| <= 2^14 and |bias| < 2^28:
// no overflow).
inline int32_t dot_q14_plus(uint32_t xy, uint32_t cs, int32_t bias) {
    return __smlad(static_cast<int16x2_t>(xy), static_cast<int16x2_t>(cs), bias);
}
inline uint32_t saturating_inc(uint32_t bin) { return __uqadd8(bin, 1u); }  // bin <= 255
inline uint32_t saturating_dec(uint32_t bin) { return __uqsub8(bin, 1u); }
// v − floor, or 0 when v <= floor (v, floor <= 255)
inline uint32_t excess(uint32_t v, uint32_t floor) { return __uqsub8(v, floor); }
// acc + (raised − bin), raised >= bin
inline uint32_t add_increase(uint32_t raised, uint32_t bin, uint32_t acc) {
    return __usada8(raised, bin, acc);
}
#else
inline int32_t dot_q14_plus(uint32_t xy, uint32_t cs, int32_t bias) {
    return static_cast<int16_t>(xy & 0xFFFFu) * static_cast<int16_t>(cs & 0xFFFFu) +
           static_cast<int16_t>(xy >> 16) * static_cast<int16_t>(cs >> 16) + bias;
}
inline uint32_t saturating_inc(uint32_t bin) { return bin + (bin < 255u); }
inline uint32_t saturating_dec(uint32_t bin) { return bin - (bin > 0u); }
inline uint32_t excess(uint32_t v, uint32_t floor) { return v > floor ? v - floor : 0u; }
inline uint32_t add_increase(uint32_t raised, uint32_t bin, uint32_t acc) {
    return acc + raised - bin;
}
#endif

inline int32_t cos_of(uint32_t cs) { return static_cast<int16_t>(cs & 0xFFFFu); }
inline int32_t sin_of(uint32_t cs) { return static_cast<int16_t>(cs >> 16); }

// The arithmetic of a point's votes. The loops over them are kept out of line with a copy of
// it in locals: inside the large PPHT loop the compiler keeps its values on the stack, and a
// store through the uint8_t bins may alias any of them (reloaded every vote).
struct VoteRun {
    uint8_t* bins;
    const uint32_t* cos_sin_q14;
    uint32_t n_rho;
    uint32_t xy;    // the point, pixels from the frame centre: x low 16 bits, y high, signed
    int32_t bias;   // rounding plus the rho offset, in rho units << shift
    int32_t shift;  // 14 + log2(rho_step): rho = (x·cos + y·sin + bias) >> shift
    uint32_t below_threshold;  // the vote threshold − 1
};

// A point's votes: the θ indices within the window about its gradient direction, as up to two
// runs [first, last] that do not wrap past 0° or 180° (the second empty, {1, 0}, unless the
// window wraps), and the runs' arithmetic.
struct Votes {
    int32_t runs[2][2];
    VoteRun run;
};

// How many bins the votes touch.
inline uint32_t vote_count(const Votes& v) {
    return static_cast<uint32_t>(v.runs[0][1] - v.runs[0][0] + 1) +
           static_cast<uint32_t>(v.runs[1][1] - v.runs[1][0] + 1);
}

// Calls visit(index) for each of the votes' bins in θ order; r: a copy of v.run in locals. The
// bins of θ index t start at t·n_rho.
template <class Visit>
inline void for_each_bin(const Votes& v, const VoteRun& r, Visit&& visit) {
    for (int32_t k = 0; k < 2; ++k) {
        const uint32_t* cs = r.cos_sin_q14 + v.runs[k][0];
        const uint32_t* const cs_end = r.cos_sin_q14 + v.runs[k][1] + 1;
        for (uint32_t row = static_cast<uint32_t>(v.runs[k][0]) * r.n_rho; cs < cs_end;
             ++cs, row += r.n_rho)
            visit(row + static_cast<uint32_t>(dot_q14_plus(r.xy, *cs, r.bias) >> r.shift));
    }
}

// +1 on each bin (saturating at 255), counted in stats (votes, and the votes a bin at 255 lost);
// returns whether a bin reached the threshold. Out of line, both runs in one call.
__attribute__((noinline)) bool cast_votes(const Votes& v, HoughStats* stats) {
    const VoteRun r = v.run;
    uint32_t gained = 0, reached = 0;
    for_each_bin(v, r, [&](uint32_t index) {
        const uint32_t bin = r.bins[index];
        const uint32_t raised = saturating_inc(bin);
        r.bins[index] = static_cast<uint8_t>(raised);
        gained = add_increase(raised, bin, gained);
        reached |= excess(raised, r.below_threshold);
    });
    const uint32_t votes = vote_count(v);
    stats->votes += votes;
    stats->saturated_votes += votes - gained;
    return reached != 0;
}

// The highest bin of the votes and its first index in *best_index (only read).
uint32_t best_of_votes(const Votes& v, uint32_t* best_index) {
    uint32_t best = 0;
    for_each_bin(v, v.run, [&](uint32_t index) {
        if (v.run.bins[index] > best) {
            best = v.run.bins[index];
            *best_index = index;
        }
    });
    return best;
}

// −1 on each bin (not below 0).
__attribute__((noinline)) void withdraw_votes(const Votes& v) {
    const VoteRun r = v.run;
    for_each_bin(v, r, [&](uint32_t index) {
        r.bins[index] = static_cast<uint8_t>(saturating_dec(r.bins[index]));
    });
}

class Ppht {
public:
    Ppht(EdgeList& edges, uint16_t width, uint16_t height, const HoughParams& p,
         const HoughWorkspace& ws, HoughStats& stats)
        : edges_(edges),
          p_(p),
          ws_(ws),
          stats_(stats),
          width_(width),
          height_(height),
          cx_(width / 2),
          cy_(height / 2),
          rho_shift_(rho_shift_of(p.rho_step)),
          rho_half_(static_cast<int32_t>(hough_rho_half_bins(width, height, p.rho_step))),
          n_rho_(static_cast<uint32_t>(2 * rho_half_ + 1)),
          held_(edges.spare_words()),
          held_capacity_(edges.capacity() / 2u) {
        const uint32_t n = p.theta_bins;
        window_ = p.vote_window_deg >= 90
                      ? -1
                      : static_cast<int32_t>((p.vote_window_deg * n + 179u) / 180u);
        if (2 * window_ + 1 >= static_cast<int32_t>(n)) window_ = -1;  // the window covers all θ
        if (*ws.table_bins != n) {
            for (uint32_t t = 0; t < n; ++t) {
                // θ_t = t·180°/n as a binary angle: t·2^31/n.
                const SinCos sc =
                    sin_cos(static_cast<angle_t>((static_cast<uint64_t>(t) << 31) / n));
                const int32_t c = static_cast<int32_t>(shr_round_half_away(sc.cos.raw, 16));
                const int32_t s = static_cast<int32_t>(shr_round_half_away(sc.sin.raw, 16));
                ws.cos_sin_q14[t] =
                    (static_cast<uint32_t>(c) & 0xFFFFu) | (static_cast<uint32_t>(s) << 16);
            }
            *ws.table_bins = static_cast<uint16_t>(n);
        }
        memset(ws.bins, 0, n * n_rho_);
    }

    void run(Segment* out, uint16_t capacity, uint16_t* count) {
        *count = 0;
        VisitOrder order(edges_.size(), p_.seed);
        const uint32_t voters = p_.max_voters ? p_.max_voters : edges_.capacity() / 2u;
        for (uint32_t k = 0; k < edges_.size() && !stats_.budget_exhausted; ++k) {
            const uint16_t i = static_cast<uint16_t>(order.next());
            const edge_point pt = edges_[i];
            if (ep::state(pt) != ep::kFresh) continue;
            if (stats_.points_visited == voters) {
                stats_.voters_exhausted = true;
                break;
            }
            edges_[i] = ep::with_state(pt, ep::kVoted);
            ++stats_.points_visited;
            uint32_t best_bin = 0;
            const uint32_t top = cast(pt, &best_bin);
            if (top == 0) continue;
            if (!stands_out(best_bin, top)) {
                ++stats_.flat_bins;
                continue;
            }
            ++stats_.lines_followed;
            Segment s;
            if (!follow(i, best_bin / n_rho_, s)) {
                // No segment along this bin's line here (a curve or scattered points voted
                // for it): empty the bin, so that the next vote does not follow it again.
                ws_.bins[best_bin] = 0;
            } else if (*count < capacity) {
                out[(*count)++] = s;
                ++stats_.segments;
            } else {
                keep_longest(out, capacity, s);
                ++stats_.segments_dropped;
            }
        }
    }

private:
    // Squared length in (1/256 px)²: |dx|, |dy| < 2^12 px = 2^20 units, so the sum < 2^41.
    static int64_t length2(const Segment& s) {
        int64_t dx = static_cast<int64_t>(s.x2.raw) - s.x1.raw,
                dy = static_cast<int64_t>(s.y2.raw) - s.y1.raw;
        dx = (dx < 0 ? -dx : dx) >> 8;
        dy = (dy < 0 ? -dy : dy) >> 8;
        return dx * dx + dy * dy;
    }

    // The output is full: s replaces the shortest segment found so far when it is longer (the
    // weakest evidence goes, whatever the visiting order); otherwise s is the one dropped.
    static void keep_longest(Segment* out, uint16_t capacity, const Segment& s) {
        uint16_t shortest = 0;
        for (uint16_t k = 1; k < capacity; ++k)
            if (length2(out[k]) < length2(out[shortest])) shortest = k;
        if (length2(s) > length2(out[shortest])) out[shortest] = s;
    }

    Votes votes_of(edge_point pt) const {
        const int32_t n = p_.theta_bins;
        const int32_t x = static_cast<int32_t>(ep::x(pt)) - cx_,
                      y = static_cast<int32_t>(ep::y(pt)) - cy_;
        int32_t first = 0, last = n - 1;
        if (window_ >= 0) {
            // Normal orientation of direction bin d: (d mod 8)·22.5°, as a θ index, rounded.
            const int32_t centre = (static_cast<int32_t>(ep::dir(pt) & 7u) * n * 2 + 8) / 16;
            first = centre - window_;
            last = centre + window_;
        }
        Votes v;
        v.runs[0][0] = first;
        v.runs[0][1] = last;
        v.runs[1][0] = 1;  // the second run empty unless the window wraps
        v.runs[1][1] = 0;
        if (first < 0) {
            v.runs[0][0] = first + n;
            v.runs[0][1] = n - 1;
            v.runs[1][0] = 0;
            v.runs[1][1] = last;
        } else if (last >= n) {
            v.runs[0][1] = n - 1;
            v.runs[1][0] = 0;
            v.runs[1][1] = last - n;
        }
        const int32_t shift = 14 + rho_shift_;
        const int32_t bias = (1 << (13 + rho_shift_)) + (rho_half_ << shift);  // rounding, offset
        const uint32_t xy = (static_cast<uint32_t>(x) & 0xFFFFu) | (static_cast<uint32_t>(y) << 16);
        v.run.bins = ws_.bins;
        v.run.cos_sin_q14 = ws_.cos_sin_q14;
        v.run.n_rho = n_rho_;
        v.run.xy = xy;
        v.run.bias = bias;
        v.run.shift = shift;
        v.run.below_threshold = static_cast<uint32_t>(p_.threshold - 1u);
        return v;
    }

    // Casts the point's votes; when a bin reaches the threshold, returns the highest bin's count
    // with its index (θ index · rho bins + rho index; the first of equals) in *best_bin, else 0.
    uint32_t cast(edge_point pt, uint32_t* best_bin) {
        const Votes v = votes_of(pt);
        return cast_votes(v, &stats_) ? best_of_votes(v, best_bin) : 0;
    }

    // Whether bin `index` (count `top`) stands out in its θ row: top at least min_peak_percent %
    // of its flank's count on one side at least, a flank's count being the larger of the bins
    // kPeakFlank and kPeakFlank + 1 bins that way (0 beyond the row's ends). A lone line has
    // both flanks low, either line of a pair (a bar's two edges) one; texture neither.
    bool stands_out(uint32_t index, uint32_t top) const {
        if (p_.min_peak_percent == 0) return true;
        const uint32_t r = index % n_rho_;
        uint32_t below = 0, above = 0;
        for (uint32_t d = kPeakFlank; d <= kPeakFlank + 1u; ++d) {
            if (r >= d && ws_.bins[index - d] > below) below = ws_.bins[index - d];
            if (r + d < n_rho_ && ws_.bins[index + d] > above) above = ws_.bins[index + d];
        }
        return top * 100u >= (below < above ? below : above) * p_.min_peak_percent;
    }

    // Withdraws the point's votes.
    void withdraw(edge_point pt) { withdraw_votes(votes_of(pt)); }

    // The line being followed: minor = anchor_minor + (major - anchor_major)·slope, in 1/32 px.
    struct Track {
        bool major_is_y;
        uint32_t normal_axis;  // the line normal as a direction bin modulo 8 (22.5° steps)
        int32_t anchor_major32, anchor_minor32;
        int32_t slope_q16;  // d minor / d major
        bool forward;       // the walk goes to larger major coordinates
    };

    static int32_t major_of(const Track& tr, int32_t x, int32_t y) { return tr.major_is_y ? y : x; }
    static int32_t minor_of(const Track& tr, int32_t x, int32_t y) { return tr.major_is_y ? x : y; }

    static void set_direction(Track& tr, int32_t dx, int32_t dy) {
        const int64_t dmaj = tr.major_is_y ? dy : dx, dmin = tr.major_is_y ? dx : dy;
        // |slope| <= 2: beyond that the other axis would be the major one; the walk keeps its
        // axis for the whole line, and a line turning past 63° is not one line.
        const int64_t limit = int64_t{2} << 16;
        int64_t s = dmaj == 0 ? limit : dmin * 65536 / dmaj;
        s = s > limit ? limit : s < -limit ? -limit : s;
        tr.slope_q16 = static_cast<int32_t>(s);
    }

    // Points the track along a fitted line.
    static void aim(Track& tr, const FittedLine& line) {
        const int32_t mx32 = static_cast<int32_t>(shr_round_half_away(line.mx.raw, 11));
        const int32_t my32 = static_cast<int32_t>(shr_round_half_away(line.my.raw, 11));
        tr.anchor_major32 = major_of(tr, mx32, my32);
        tr.anchor_minor32 = minor_of(tr, mx32, my32);
        set_direction(tr, line.dx.raw, line.dy.raw);
    }

    static void refit(Track& tr, const Moments& m, int32_t ax32, int32_t ay32) {
        FittedLine line;
        if (fit_line(m, ax32, ay32, line)) aim(tr, line);
    }

    // Predicted minor coordinate (whole pixels) at whole-pixel major coordinate `major`.
    static int32_t predict(const Track& tr, int32_t major) {
        // |d| < 2^17 (both terms are 1/32 px within a 2048 px frame) and |slope| <= 2^17: a
        // 32 x 32 -> 64-bit product (one SMULL on a Cortex-M), below 2^18 once shifted back,
        // so with the anchor (below 2^17) the rest is 32-bit.
        const int32_t d = major * 32 - tr.anchor_major32;
        const int32_t step32 = static_cast<int32_t>((static_cast<int64_t>(d) * tr.slope_q16) >> 16);
        return (tr.anchor_minor32 + step32 + 16) >> 5;
    }

    // Calls visit(i, off) for each edge point i at (major, minor + off), |off| <= corridor,
    // whose gradient runs across the line.
    template <class Visit>
    void in_corridor(const Track& tr, int32_t major, int32_t minor, Visit&& visit) const {
        const int32_t corridor = static_cast<int32_t>(p_.corridor);
        if (tr.major_is_y) {  // the corridor lies along row `major`: one search
            uint32_t first = 0, end = 0;
            edges_.span(minor - corridor, minor + corridor, major, &first, &end);
            for (uint32_t i = first; i < end; ++i) {
                const edge_point e = edges_[static_cast<uint16_t>(i)];
                if (across(tr, e))
                    visit(static_cast<uint16_t>(i), static_cast<int32_t>(ep::x(e)) - minor);
            }
            return;
        }
        for (int32_t off = -corridor; off <= corridor; ++off) {
            const int32_t y = minor + off;
            const int32_t i =
                edges_.find_near(major, y, row_probe_[static_cast<uint32_t>(y) & 7u], tr.forward);
            if (i >= 0 && across(tr, edges_[static_cast<uint16_t>(i)]))
                visit(static_cast<uint16_t>(i), off);
        }
    }

    // The corridor's points at `major`: calls fresh_point(i) for each one not yet consumed and
    // returns the nearest to `minor` of all (0, -1, +1, -2, ... in that order), or -1. Points
    // consumed by an earlier segment still mark where the edge runs (at a corner two lines
    // share pixels), so they extend a segment but are not fitted again. Every fresh point is
    // fitted, not only the nearest: a diagonal edge is a staircase with two points in most
    // columns, and taking the one nearer a slightly wrong prediction pulls the fit further
    // that way (2° on a clean 42° edge).
    template <class Fresh>
    int32_t corridor_points(const Track& tr, int32_t major, int32_t minor,
                            Fresh&& fresh_point) const {
        int32_t nearest = -1;
        uint32_t nearest_rank = ~0u;
        in_corridor(tr, major, minor, [&](uint16_t i, int32_t off) {
            const uint32_t rank = static_cast<uint32_t>(off < 0 ? -2 * off - 1 : 2 * off);
            if (rank < nearest_rank) {
                nearest_rank = rank;
                nearest = i;
            }
            if (ep::state(edges_[i]) != ep::kConsumed) fresh_point(i);
        });
        return nearest;
    }

    // Polarity from the points' gradient directions (which point from dark to bright): +1 when
    // more of them lie within ±67.5° of the normal θ than of its opposite, else −1.
    static int8_t bright_side(angle_t theta, const uint16_t (&dir_count)[16]) {
        const uint32_t normal_bin = ((theta >> 27) + 1u) / 2u & 15u;  // round(θ / 22.5°) mod 16
        uint32_t along = 0, against = 0;
        for (uint32_t k = 0; k < 16; ++k) {
            const uint32_t d = (k - normal_bin) & 15u;
            if (d <= 3u || d >= 13u) along += dir_count[k];
            if (d >= 5u && d <= 11u) against += dir_count[k];
        }
        return along >= against ? int8_t{1} : int8_t{-1};
    }

    // Whether a point's gradient runs across the line (within 2 bins, ±45°, of its normal):
    // beyond a sharp corner the other side's pixels lie within the corridor for a while, and
    // without this test a line would run on along them.
    static bool across(const Track& tr, edge_point p) {
        const uint32_t d = (ep::dir(p) - tr.normal_axis) & 7u;
        return d <= 2u || d >= 6u;
    }

    // Whether such a point is fitted: within one bin (±22.5°) of the normal. A point 45° off
    // (a corner's pixel, whose gradient is half each side's) belongs to the segment but not to
    // its fit: its sub-pixel offset runs along the 45° axis, so its place across the line is
    // off by up to half a pixel, enough to tilt a clean side.
    static bool fitted_to(const Track& tr, edge_point p) {
        const uint32_t d = (ep::dir(p) - tr.normal_axis) & 7u;
        return d <= 1u || d >= 7u;
    }

    // Notes point i, found by the walk and not consumed, in the held list (in the edge list's
    // spare words); a list too long for them is marked incomplete.
    void hold(uint16_t i) {
        if (held_count_ >= held_capacity_) {
            held_complete_ = false;
            return;
        }
        held_[held_count_] = i;
        ++held_count_;
    }

    // Consumes point i, withdrawing its votes if it voted.
    void consume_point(uint16_t i) {
        edge_point& e = edges_[i];
        if (ep::state(e) == ep::kVoted) withdraw(e);
        e = ep::with_state(e, ep::kConsumed);
    }

    // Columns lo..hi of the walk's budget, one step each as the walk spends them; returns the
    // last column the budget pays for (below lo when none).
    int32_t pay_columns(int32_t lo, int32_t hi) {
        const uint32_t columns = static_cast<uint32_t>(hi - lo + 1);
        const uint32_t left = p_.max_walk_steps - stats_.walk_steps;
        if (columns <= left) {
            stats_.walk_steps += columns;
            return hi;
        }
        stats_.walk_steps += left;
        stats_.budget_exhausted = true;
        return lo + static_cast<int32_t>(left) - 1;
    }

    // Consumes the corridor points of the track's columns lo..hi from the held list: every
    // point the walk found there (the corridor's points off the walked line stay). One step of
    // the budget per column, as consume_corridor.
    void consume_held(const Track& tr, int32_t lo, int32_t hi) {
        hi = pay_columns(lo, hi);
        const int32_t corridor = static_cast<int32_t>(p_.corridor);
        for (uint32_t k = 0; k < held_count_; ++k) {
            const uint16_t i = held_[k];
            const edge_point e = edges_[i];
            if (ep::state(e) == ep::kConsumed) continue;
            const int32_t x = static_cast<int32_t>(ep::x(e)), y = static_cast<int32_t>(ep::y(e));
            const int32_t major = major_of(tr, x, y);
            if (major < lo || major > hi) continue;
            const int32_t off = minor_of(tr, x, y) - predict(tr, major);
            if (off >= -corridor && off <= corridor) consume_point(i);
        }
    }

    // The same by searching the corridor column by column: for a walk whose list outgrew the
    // spare words.
    void consume_corridor(const Track& tr, int32_t lo, int32_t hi) {
        hi = pay_columns(lo, hi);
        for (int32_t major = lo; major <= hi; ++major)
            in_corridor(tr, major, predict(tr, major), [&](uint16_t i, int32_t) {
                if (ep::state(edges_[i]) != ep::kConsumed) consume_point(i);
            });
    }

    // The run of hits around the seed: the seed and the hits each way before the first gap of
    // 2 px or more. The walk grows the segment outward from the seed, so a seed that is itself
    // noise past a line's end would carry that end with it; this record lets the rule for runs
    // past a gap (see follow()) judge the seed's run from the segment's side as well.
    struct SeedRun {
        bool open[2] = {true, true};  // the way is still within the run (no gap of 2 px yet)
        int32_t columns = 1;          // hit columns of the run, the seed's included
        int32_t end32[2][2];          // its last hit each way, x32 and y32
        int32_t gap[2] = {};          // each way: the gap past the run and the first hit past it
        int32_t beyond32[2][2] = {};
        // Its points besides the seed: held-list entries [begin, end) of each pass.
        uint32_t begin[3] = {}, end[3] = {};
        SeedRun(int32_t sx32, int32_t sy32) {
            end32[0][0] = end32[1][0] = sx32;
            end32[0][1] = end32[1][1] = sy32;
        }
    };

    // When the segment goes on past a gap g on one side of the seed's run only and the run has
    // fewer than g hit columns, the run is noise past the segment's end (the rule for runs past
    // a gap, seen from the segment's side): its points leave the fit and that end moves to the
    // segment's first hit past the gap.
    void drop_lone_seed_run(const SeedRun& run, const Track& tr, uint16_t seed,
                            int32_t (&end32)[2][2], Moments& m, uint16_t (&dir_count)[16]) const {
        if (!held_complete_) return;  // the run's points are not all in the list
        for (int way = 0; way < 2; ++way) {
            const int other = 1 - way;
            const bool segment_past_gap = !run.open[way] && (end32[way][0] != run.end32[way][0] ||
                                                             end32[way][1] != run.end32[way][1]);
            if (!segment_past_gap || !run.open[other] || run.columns >= run.gap[way]) continue;
            const edge_point sp = edges_[seed];
            const int32_t sx32 = ep::x32(sp), sy32 = ep::y32(sp);
            m.add(0, 0, -1);
            --dir_count[ep::dir(sp)];
            for (int pass = 0; pass < 3; ++pass)
                for (uint32_t k = run.begin[pass]; k < run.end[pass]; ++k) {
                    const edge_point e = edges_[held_[k]];
                    if (dir_count[ep::dir(e)] > 0) --dir_count[ep::dir(e)];
                    if (fitted_to(tr, e)) m.add(ep::x32(e) - sx32, ep::y32(e) - sy32, -1);
                }
            memcpy(end32[other], run.beyond32[way], sizeof end32[other]);
            return;
        }
    }

    // One follow() under way: the track, the fit's moments about the seed (sx32, sy32), the
    // fitted points per gradient direction bin (the polarity), each way's last hit (end32: x32
    // and y32 of the segment's end; last_major: the hit's major coordinate, px), the refits so
    // far, the steps taken against steps_left (a frame's budget), and the seed's own run.
    struct Following {
        Track tr;
        int32_t sx32, sy32;
        Moments m;
        uint16_t dir_count[16] = {};
        int32_t end32[2][2];
        int32_t last_major[2];
        uint32_t refits = 0;
        uint32_t steps = 0, steps_left;
        SeedRun seed_run;
        Following(int32_t x32, int32_t y32, uint32_t budget)
            : sx32(x32), sy32(y32), steps_left(budget), seed_run(x32, y32) {
            end32[0][0] = end32[1][0] = x32;
            end32[0][1] = end32[1][1] = y32;
        }
    };

    // Follows the line of θ bin `t` through seed point `seed`; true with the segment when it
    // is long enough (its points are then consumed and their votes withdrawn).
    bool follow(uint16_t seed, uint32_t t, Segment& out) {
        const edge_point sp = edges_[seed];
        Following f(ep::x32(sp), ep::y32(sp), p_.max_walk_steps - stats_.walk_steps);
        // Normal (cos θ, sin θ); the line runs along (−sin θ, cos θ).
        const int32_t c = cos_of(ws_.cos_sin_q14[t]), s = sin_of(ws_.cos_sin_q14[t]);
        f.tr.major_is_y = (c < 0 ? -c : c) > (s < 0 ? -s : s);
        f.tr.normal_axis = ((t * 16u / p_.theta_bins) + 1u) / 2u & 7u;  // round(θ / 22.5°) mod 8
        f.tr.anchor_major32 = major_of(f.tr, f.sx32, f.sy32);
        f.tr.anchor_minor32 = minor_of(f.tr, f.sx32, f.sy32);
        set_direction(f.tr, -s, c);
        held_count_ = 0;
        held_complete_ = true;
        hold(seed);
        f.m.add(0, 0);
        ++f.dir_count[ep::dir(sp)];
        f.last_major[0] = f.last_major[1] =
            major_of(f.tr, static_cast<int32_t>(ep::x(sp)), static_cast<int32_t>(ep::y(sp)));
        // Way 0, way 1, then way 0 again: way 0 starts along the seed bin's direction, which
        // may be a few degrees off (a bin of 2° that noise helped to the top), and until the
        // 8th point's refit it can leave the line after a few pixels. When it ended before any
        // refit and way 1 refitted, way 0 goes on from its last hit along the refitted line.
        uint32_t refits_in_way0 = 0;
        for (int pass = 0; pass < 3; ++pass) {
            if (pass == 1) refits_in_way0 = f.refits;
            if (pass == 2) {
                if (refits_in_way0 > 0 || f.refits == 0) break;
                refit(f.tr, f.m, f.sx32, f.sy32);
            }
            if (!walk(f, pass)) {
                stats_.walk_steps += f.steps;
                stats_.budget_exhausted = true;
                return false;
            }
        }
        stats_.walk_steps += f.steps;
        drop_lone_seed_run(f.seed_run, f.tr, seed, f.end32, f.m, f.dir_count);
        return keep_segment(f, out);
    }

    // One pass of follow(): along way pass & 1 from that way's last hit until a gap longer than
    // max_line_gap or the frame's edge. Hits join the fit (refitted at 8, 16, 32, ... points);
    // a run of hits after a gap of g >= 2 px becomes part of the segment once it has g hits or
    // a later run follows it: a noise pixel or two beyond a corner would otherwise carry the end
    // up to max_line_gap past it. False when the frame's step budget ran out.
    bool walk(Following& f, int pass) {
        const int way = pass & 1;
        const int32_t step = way == 0 ? 1 : -1;
        const int32_t extent = f.tr.major_is_y ? height_ : width_;
        f.tr.forward = way == 0;
        f.seed_run.begin[pass] = f.seed_run.end[pass] = held_count_;
        int32_t gap = 0;
        int32_t run = 0, run_gap = 0;  // hits of the run not yet in the segment, its gap
        int32_t run32[2] = {0, 0};     // that run's last hit, x32 and y32
        for (int32_t major = f.last_major[way] + step; major >= 0 && major < extent;
             major += step) {
            if (f.steps == f.steps_left) return false;
            ++f.steps;
            const int32_t i = corridor_points(f.tr, major, predict(f.tr, major), [&](uint16_t k) {
                hold(k);
                const edge_point fp = edges_[k];
                if (f.dir_count[ep::dir(fp)] < 0xFFFFu) ++f.dir_count[ep::dir(fp)];
                if (!fitted_to(f.tr, fp)) return;
                f.m.add(ep::x32(fp) - f.sx32, ep::y32(fp) - f.sy32);
                // Refit at 8, 16, 32, ... points: the direction settles quickly, and each
                // fit costs two CORDIC runs.
                if (f.m.n >= 8 && (f.m.n & (f.m.n - 1)) == 0) {
                    refit(f.tr, f.m, f.sx32, f.sy32);
                    ++f.refits;
                }
            });
            if (i < 0) {
                if (++gap > p_.max_line_gap) break;
                continue;
            }
            f.last_major[way] = major;
            const edge_point hp = edges_[static_cast<uint16_t>(i)];
            const int32_t here[2] = {ep::x32(hp), ep::y32(hp)};
            SeedRun& sr = f.seed_run;
            if (sr.open[way]) {
                if (gap < 2) {
                    ++sr.columns;
                    memcpy(sr.end32[way], here, sizeof here);
                    sr.end[pass] = held_count_;
                } else {  // the first hit past a gap of 2 px or more
                    sr.open[way] = false;
                    sr.gap[way] = gap;
                    memcpy(sr.beyond32[way], here, sizeof here);
                }
            }
            if (gap >= 2) {
                if (run > 0) memcpy(f.end32[way], run32, sizeof run32);
                run = 1;
                run_gap = gap;
            } else if (run > 0) {
                ++run;
            }
            memcpy(run > 0 ? run32 : f.end32[way], here, sizeof here);
            if (run > 0 && run >= run_gap) {
                memcpy(f.end32[way], run32, sizeof run32);
                run = 0;
            }
            gap = 0;
        }
        return true;
    }

    // The end of follow(): the final fit between the two ends, kept when long enough and
    // carried by enough points; its points are then consumed.
    bool keep_segment(Following& f, Segment& out) {
        const Track& tr = f.tr;
        int32_t(&end32)[2][2] = f.end32;
        // Too few points, or a run too short along its major axis (the line is at most √5 times
        // longer, |slope| <= 2): rejected before the final fit.
        const int32_t major_extent =
            (major_of(tr, end32[0][0], end32[0][1]) - major_of(tr, end32[1][0], end32[1][1])) / 32;
        if (f.m.n < p_.threshold || (major_extent < 0 ? -major_extent : major_extent) * 9 <
                                        4 * static_cast<int32_t>(p_.min_line_length))
            return false;
        FittedLine line;
        const bool fitted = fit_line(f.m, f.sx32, f.sy32, line);
        q16_16 t1 = along(line, q16_16::from_raw(int64_t{end32[1][0]} * 2048),
                          q16_16::from_raw(int64_t{end32[1][1]} * 2048));
        q16_16 t2 = along(line, q16_16::from_raw(int64_t{end32[0][0]} * 2048),
                          q16_16::from_raw(int64_t{end32[0][1]} * 2048));
        if (t2 < t1) {
            const q16_16 tmp = t1;
            t1 = t2;
            t2 = tmp;
        }
        // Long enough, and carried by enough points of its own: a run along points consumed by
        // an earlier segment with a few new ones is that segment again, not a new line.
        if (static_cast<int64_t>(t2.raw) - t1.raw < static_cast<int64_t>(p_.min_line_length)
                                                        << 16 ||
            f.m.n < p_.threshold)
            return false;

        // Consume every point in the corridor of the final line between the two ends.
        if (fitted) aim(f.tr, line);
        const int32_t a = (major_of(tr, end32[1][0], end32[1][1]) + 16) >> 5;
        const int32_t b = (major_of(tr, end32[0][0], end32[0][1]) + 16) >> 5;
        if (held_complete_)
            consume_held(tr, a < b ? a : b, a < b ? b : a);
        else
            consume_corridor(tr, a < b ? a : b, a < b ? b : a);
        out = make_segment(line, t1, t2, static_cast<uint16_t>(f.m.n > 65535 ? 65535 : f.m.n));
        out.bright_side = bright_side(out.theta, f.dir_count);
        return true;
    }

    EdgeList& edges_;
    const HoughParams& p_;
    const HoughWorkspace& ws_;
    HoughStats& stats_;
    int32_t width_, height_, cx_, cy_;
    int rho_shift_;
    int32_t rho_half_;
    uint32_t n_rho_;
    int32_t window_ = -1;  // θ bins either side of the gradient's; -1 = vote every θ
    // What the last search in row y (keyed y mod 8) found: a walk along x asks the same few
    // rows for consecutive columns (see EdgeList::find_near).
    mutable RowProbe row_probe_[8];
    // The points the current walk found and did not find consumed, to consume them when the
    // segment is kept (see hold()).
    uint16_t* held_;
    uint32_t held_capacity_;  // indices the spare words hold
    uint32_t held_count_ = 0;
    bool held_complete_ = true;
};

}  // namespace

Status hough_segments(EdgeList& edges, uint16_t width, uint16_t height, const HoughParams& params,
                      const HoughWorkspace& ws, Segment* out, uint16_t out_capacity,
                      uint16_t* count, HoughStats* stats) {
    *count = 0;
    *stats = HoughStats{};
    if (width == 0 || height == 0 || width > ep::kMaxCoordinate + 1 ||
        height > ep::kMaxCoordinate + 1 || edges.height() != height ||
        rho_shift_of(params.rho_step) < 0 || params.theta_bins < 2 ||
        params.theta_bins > ws.theta_capacity || params.threshold == 0 || params.threshold > 255 ||
        hough_bins_for(width, height, params.theta_bins, params.rho_step) > ws.bin_capacity)
        return Status::bad_size;
    Ppht ppht(edges, width, height, params, ws, *stats);
    ppht.run(out, out_capacity, count);
    return Status::ok;
}

}  // namespace qt
