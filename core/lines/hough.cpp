#include "lines/hough.h"

#include <string.h>

#include "lines/line_fit.h"
#include "lines/visit_order.h"

namespace qt {

namespace {

int rho_shift_of(uint16_t rho_step) {
    return rho_step == 1 ? 0 : rho_step == 2 ? 1 : rho_step == 4 ? 2 : -1;
}

// One run of consecutive θ indices [t_first, t_last] of a point's votes. Kept out of line, with
// everything in arguments: inside the large PPHT loop the compiler keeps its values on the
// stack, and a store through the uint8_t bins may alias any of them (reloaded every vote).
struct VoteRun {
    uint8_t* bins;
    const int16_t* cos_q14;
    const int16_t* sin_q14;
    uint32_t n_rho;
    int32_t x, y;   // the point, pixels from the frame centre
    int32_t bias;   // rounding plus the rho offset, in rho units << shift
    int32_t shift;  // 14 + log2(rho_step): rho = (x·cos + y·sin + bias) >> shift
};

uint32_t rho_index(const VoteRun& r, int32_t t) {
    const int32_t v = r.x * r.cos_q14[t] + r.y * r.sin_q14[t];  // rho, 1.0 = 2^14
    return static_cast<uint32_t>(t) * r.n_rho + static_cast<uint32_t>((v + r.bias) >> r.shift);
}

// +1 on each bin (saturating at 255, counted in *saturated); returns the highest count, from
// `best` up, with its bin in *best_index.
__attribute__((noinline)) uint32_t cast_run(const VoteRun r, int32_t t_first, int32_t t_last,
                                            uint32_t best, uint32_t* best_index,
                                            uint32_t* saturated) {
    uint32_t lost = 0, index_of_best = *best_index;
    for (int32_t t = t_first; t <= t_last; ++t) {
        const uint32_t index = rho_index(r, t);
        const uint32_t bin = r.bins[index];
        lost += bin == 255;
        const uint32_t raised = bin + (bin < 255);
        r.bins[index] = static_cast<uint8_t>(raised);
        if (raised > best) {
            best = raised;
            index_of_best = index;
        }
    }
    *best_index = index_of_best;
    *saturated += lost;
    return best;
}

// −1 on each bin (not below 0).
__attribute__((noinline)) void withdraw_run(const VoteRun r, int32_t t_first, int32_t t_last) {
    for (int32_t t = t_first; t <= t_last; ++t) {
        const uint32_t index = rho_index(r, t);
        const uint32_t bin = r.bins[index];
        r.bins[index] = static_cast<uint8_t>(bin - (bin > 0));
    }
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
          n_rho_(static_cast<uint32_t>(2 * rho_half_ + 1)) {
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
                ws.cos_q14[t] = static_cast<int16_t>(shr_round_half_away(sc.cos.raw, 16));
                ws.sin_q14[t] = static_cast<int16_t>(shr_round_half_away(sc.sin.raw, 16));
            }
            *ws.table_bins = static_cast<uint16_t>(n);
        }
        memset(ws.bins, 0, n * n_rho_);
    }

    void run(Segment* out, uint16_t capacity, uint16_t* count) {
        *count = 0;
        const VisitOrder order(edges_.size(), p_.seed);
        for (uint32_t k = 0; k < edges_.size() && !stats_.budget_exhausted; ++k) {
            const uint16_t i = static_cast<uint16_t>(order.at(k));
            const edge_point pt = edges_[i];
            if (ep::state(pt) != ep::kFresh) continue;
            edges_[i] = ep::with_state(pt, ep::kVoted);
            ++stats_.points_visited;
            uint32_t best_bin = 0;
            const uint32_t best = vote(pt, +1, &best_bin);
            if (best < p_.threshold) continue;
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

    // Casts (+1) or withdraws (-1) the point's votes; returns the highest count among its bins
    // and that bin's index (θ index · rho bins + rho index).
    uint32_t vote(edge_point pt, int delta, uint32_t* best_bin) {
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
        // The window may wrap past 0° or 180°: at most two runs of consecutive θ indices.
        uint32_t best = 0;
        int32_t runs[2][2] = {{first, last}, {1, 0}};  // the second run empty unless it wraps
        if (first < 0) {
            runs[0][0] = first + n;
            runs[0][1] = n - 1;
            runs[1][0] = 0;
            runs[1][1] = last;
        } else if (last >= n) {
            runs[0][1] = n - 1;
            runs[1][0] = 0;
            runs[1][1] = last - n;
        }
        const int32_t shift = 14 + rho_shift_;
        const int32_t bias = (1 << (13 + rho_shift_)) + (rho_half_ << shift);  // rounding, offset
        const VoteRun run{ws_.bins, ws_.cos_q14, ws_.sin_q14, n_rho_, x, y, bias, shift};
        uint32_t best_index = 0;
        for (int32_t k = 0; k < 2; ++k) {
            if (delta < 0)
                withdraw_run(run, runs[k][0], runs[k][1]);
            else
                best = cast_run(run, runs[k][0], runs[k][1], best, &best_index,
                                &stats_.saturated_votes);
        }
        if (best > 0) *best_bin = best_index;
        if (delta > 0) stats_.votes += static_cast<uint32_t>(last - first + 1);
        return best;
    }

    // The line being followed: minor = anchor_minor + (major - anchor_major)·slope, in 1/32 px.
    struct Track {
        bool major_is_y;
        uint32_t normal_axis;  // the line normal as a direction bin modulo 8 (22.5° steps)
        int32_t anchor_major32, anchor_minor32;
        int32_t slope_q16;  // d minor / d major
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
        // 32 x 32 -> 64-bit product (one SMULL on a Cortex-M).
        const int32_t d = major * 32 - tr.anchor_major32;
        const int64_t minor32 =
            tr.anchor_minor32 + ((static_cast<int64_t>(d) * tr.slope_q16) >> 16);
        return static_cast<int32_t>((minor32 + 16) >> 5);
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
            const int32_t i = edges_.find_near(major, y, &row_hint_[static_cast<uint32_t>(y) & 7u]);
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

    bool spend_step() {
        if (stats_.walk_steps >= p_.max_walk_steps) {
            stats_.budget_exhausted = true;
            return false;
        }
        ++stats_.walk_steps;
        return true;
    }

    // Follows the line of θ bin `t` through seed point `seed`; true with the segment when it
    // is long enough (its points are then consumed and their votes withdrawn).
    bool follow(uint16_t seed, uint32_t t, Segment& out) {
        const edge_point sp = edges_[seed];
        const int32_t sx32 = ep::x32(sp), sy32 = ep::y32(sp);
        Track tr{};
        // Normal (cos θ, sin θ); the line runs along (−sin θ, cos θ).
        const int32_t c = ws_.cos_q14[t], s = ws_.sin_q14[t];
        tr.major_is_y = (c < 0 ? -c : c) > (s < 0 ? -s : s);
        tr.normal_axis = ((t * 16u / p_.theta_bins) + 1u) / 2u & 7u;  // round(θ / 22.5°) mod 8
        tr.anchor_major32 = major_of(tr, sx32, sy32);
        tr.anchor_minor32 = minor_of(tr, sx32, sy32);
        set_direction(tr, -s, c);

        Moments m;
        m.add(0, 0);
        uint16_t dir_count[16] = {};  // fitted points per gradient direction bin (polarity)
        ++dir_count[ep::dir(sp)];
        int32_t end32[2][2] = {{sx32, sy32}, {sx32, sy32}};  // last hit each way: x32, y32
        const int32_t extent = tr.major_is_y ? height_ : width_;
        const int32_t seed_major =
            major_of(tr, static_cast<int32_t>(ep::x(sp)), static_cast<int32_t>(ep::y(sp)));
        int32_t last_major[2] = {seed_major, seed_major};  // of the last hit each way, pixels
        uint32_t refits = 0, refits_in_way0 = 0;
        // Way 0, way 1, then way 0 again: way 0 starts along the seed bin's direction, which
        // may be a few degrees off (a bin of 2° that noise helped to the top), and until the
        // 8th point's refit it can leave the line after a few pixels. When it ended before any
        // refit and way 1 refitted, way 0 goes on from its last hit along the refitted line.
        for (int pass = 0; pass < 3; ++pass) {
            const int way = pass & 1;
            if (pass == 1) refits_in_way0 = refits;
            if (pass == 2) {
                if (refits_in_way0 > 0 || refits == 0) break;
                refit(tr, m, sx32, sy32);
            }
            const int32_t step = way == 0 ? 1 : -1;
            int32_t gap = 0;
            int32_t run = 0, run_gap = 0;  // hits of the run not yet in the segment, its gap
            int32_t run32[2] = {0, 0};     // that run's last hit, x32 and y32
            for (int32_t major = last_major[way] + step; major >= 0 && major < extent;
                 major += step) {
                if (!spend_step()) return false;
                const int32_t i = corridor_points(tr, major, predict(tr, major), [&](uint16_t f) {
                    const edge_point fp = edges_[f];
                    m.add(ep::x32(fp) - sx32, ep::y32(fp) - sy32);
                    if (dir_count[ep::dir(fp)] < 0xFFFFu) ++dir_count[ep::dir(fp)];
                    // Refit at 8, 16, 32, ... points: the direction settles quickly, and each
                    // fit costs two CORDIC runs.
                    if (m.n >= 8 && (m.n & (m.n - 1)) == 0) {
                        refit(tr, m, sx32, sy32);
                        ++refits;
                    }
                });
                if (i < 0) {
                    if (++gap > p_.max_line_gap) break;
                    continue;
                }
                last_major[way] = major;
                const edge_point hp = edges_[static_cast<uint16_t>(i)];
                // A run of hits after a gap of g >= 2 px becomes part of the segment once it
                // has g hits or a later run follows it: a noise pixel or two beyond a corner
                // would otherwise carry the end up to max_line_gap past it.
                const int32_t here[2] = {ep::x32(hp), ep::y32(hp)};
                if (gap >= 2) {
                    if (run > 0) memcpy(end32[way], run32, sizeof run32);
                    run = 1;
                    run_gap = gap;
                } else if (run > 0) {
                    ++run;
                }
                memcpy(run > 0 ? run32 : end32[way], here, sizeof here);
                if (run > 0 && run >= run_gap) {
                    memcpy(end32[way], run32, sizeof run32);
                    run = 0;
                }
                gap = 0;
            }
        }
        // Too few points, or a run too short along its major axis (the line is at most √5 times
        // longer, |slope| <= 2): rejected before the final fit.
        const int32_t major_extent =
            (major_of(tr, end32[0][0], end32[0][1]) - major_of(tr, end32[1][0], end32[1][1])) / 32;
        if (m.n < p_.threshold || (major_extent < 0 ? -major_extent : major_extent) * 9 <
                                      4 * static_cast<int32_t>(p_.min_line_length))
            return false;
        FittedLine line;
        const bool fitted = fit_line(m, sx32, sy32, line);
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
            m.n < p_.threshold)
            return false;

        // Consume every point in the corridor of the final line between the two ends.
        if (fitted) aim(tr, line);
        const int32_t a = (major_of(tr, end32[1][0], end32[1][1]) + 16) >> 5;
        const int32_t b = (major_of(tr, end32[0][0], end32[0][1]) + 16) >> 5;
        for (int32_t major = a < b ? a : b; major <= (a < b ? b : a); ++major) {
            if (!spend_step()) break;
            in_corridor(tr, major, predict(tr, major), [&](uint16_t i, int32_t) {
                edge_point& e = edges_[i];
                if (ep::state(e) == ep::kVoted) {
                    uint32_t unused = 0;
                    vote(e, -1, &unused);
                }
                e = ep::with_state(e, ep::kConsumed);
            });
        }
        out = make_segment(line, t1, t2, static_cast<uint16_t>(m.n > 65535 ? 65535 : m.n));
        out.bright_side = bright_side(out.theta, dir_count);
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
    // Where the last search in row y (keyed y mod 8) ended: a walk along x asks the same few
    // rows for consecutive columns (see EdgeList::find_near). Any value is safe.
    mutable uint32_t row_hint_[8] = {};
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
