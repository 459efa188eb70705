// The detection chain of one frame: the lines stage (line_detector.h), then the quadrangle
// rules (quad_detector.h) on its clustered lines. All memory inside, fixed at compile time.
//
//   static qt::BoardDetectorQvga det;
//   det.begin_frame(320, 240, params);
//   for each camera row: det.push_row(row, 320);        // or push_gradient_row(words, 320)
//   (or the FPGA's edge beats: det.push_edge_beats(beats, n, &used), line_detector.h)
//   det.finish();                              // lines, then quadrangles
//   det.quads()[0 .. det.quad_count()), best first; det.lines() for the lines stage
#pragma once
#include <stdint.h>

#include "lines/line_detector.h"
#include "quads/quad_detector.h"
#include "quads/quad_interior.h"
#include "quads/quad_refine.h"

namespace qt {

struct BoardParams {
    LineParams lines;
    QuadParams quads;
    RefineParams refine;
};

// Capacity: a base/capacity.h configuration (the lines stage's, parallel_pairs, quads).
template <class Capacity>
class BoardDetector {
    using Lines = LineDetector<Capacity>;
    static constexpr uint16_t PairCapacity = Capacity::parallel_pairs, MaxQuads = Capacity::quads;
    static constexpr uint16_t MaxCandidates = Capacity::quad_candidates;
    static_assert(MaxCandidates >= MaxQuads, "candidates: at least the quadrangles kept");
    static_assert(Lines::max_lines() > 4 * MaxQuads,
                  "room for the completed sides beside the kept quadrangles' lines");

public:
    static constexpr uint32_t ram_bytes() { return sizeof(BoardDetector); }
    static constexpr uint32_t quad_bytes() {
        return sizeof(LinePair) * PairCapacity + sizeof(QuadLine) * Lines::max_lines() +
               (sizeof(Quad) + sizeof(Segment)) * MaxCandidates + 4 * sizeof(Segment) * MaxQuads;
    }
    static constexpr uint16_t max_quads() { return MaxQuads; }
    // Quadrangles a caller may ask for, best first (base/setting_range.h).
    static constexpr SettingRange quads_range{"", 1, MaxQuads};

    // window: tracking mode's bands (LineDetector::begin_frame); null: the whole frame.
    Status begin_frame(uint16_t width, uint16_t height, const BoardParams& params,
                       BandWindow* window = nullptr) {
        params_ = params;
        quad_count_ = 0;
        quad_stats_ = QuadStats{};
        return lines_.begin_frame(width, height, params.lines, window);
    }
    Status push_row(const uint8_t* pixels, uint16_t length) {
        return lines_.push_row(pixels, length);
    }
    Status push_gradient_row(const gradient_word* words, uint16_t width) {
        return lines_.push_gradient_row(words, width);
    }
    // The frame's edge beats from the FPGA front end instead of rows (line_detector.h).
    Status push_edge_beats(const uint8_t* beats, uint32_t count, uint32_t* used) {
        return lines_.push_edge_beats(beats, count, used);
    }
    bool edge_beats_done() const { return lines_.edge_beats_done(); }

    // After the last row. Errors of the lines stage are returned as they are; otherwise the
    // quadrangles are searched and capacity_exceeded reports a capacity that filled in either
    // stage (the results are valid, the stats say what was cut).
    Status finish() {
        return finish([](FinishStage) {});
    }
    // The same, calling mark(stage) as each stage ends (line_detector.h's FinishStage).
    template <class Mark>
    Status finish(Mark&& mark) {
        const BandWindow* bands = lines_.window();
        if (bands != nullptr && bands->fits_sides()) return fit_sides(*bands, mark);
        const Status l = lines_.finish(mark);
        if (l != Status::ok && l != Status::capacity_exceeded) return l;
        // Tracking mode: only the lines along a band's side can be the board's sides; the
        // others are background edges the bands cut short across them.
        if (const BandWindow* w = lines_.window())
            lines_.keep_lines([w](const Segment& s) { return w->along_a_side(s); });
        const QuadSearchMemory memory{pairs_, PairCapacity,  geometry_,
                                      quads_, MaxCandidates, completed_};
        const Status q = detect_quads(lines_.lines(), lines_.line_count(), lines_.width(),
                                      lines_.height(), params_.quads, memory, &quad_stats_);
        quad_count_ = quad_stats_.quads;
        // Each candidate's sides refitted to the edge points between its corners and verified
        // by that evidence, which also becomes its score; in rank order until MaxQuads are
        // kept (a pattern's own quadrangles can outrank the board and fail).
        uint16_t kept = 0;
        for (uint16_t k = 0; k < quad_count_ && kept < MaxQuads; ++k) {
            Quad quad = quads_[k];
            bool seen = false;
            for (uint16_t j = 0; j < kept && !seen; ++j)
                seen = same_corners(quads_[j], quad, params_.refine.duplicate_distance);
            if (seen) continue;
            Segment sides[4];
            if (passes_checks(k, quad, sides)) kept = keep(quad, sides, kept);
        }
        quad_count_ = kept;
        quad_stats_.quads = kept;
        place_sides();
        mark(FinishStage::quads);
        if (q != Status::ok && q != Status::capacity_exceeded) return q;
        return l == Status::ok && q == Status::ok ? Status::ok : Status::capacity_exceeded;
    }

    const Lines& lines() const { return lines_; }
    const Quad* quads() const { return quads_; }
    uint16_t quad_count() const { return quad_count_; }
    const QuadStats& quad_stats() const { return quad_stats_; }

private:
    // Tracking mode's side fitting: each predicted side refitted to the edge points of its band
    // (refine_quad), the refitted sides the frame's lines, and the quadrangle they make kept
    // when it passes the evidence checks and rule 3 (the checks of what the bands cannot see
    // are not made).
    template <class Mark>
    Status fit_sides(const BandWindow& bands, Mark&& mark) {
        const Status l = lines_.finish_edges();
        if (l != Status::ok && l != Status::capacity_exceeded) return l;
        mark(FinishStage::hough);
        mark(FinishStage::cluster);
        quad_count_ = 0;
        Quad quad{};
        Segment predicted[4];
        for (int i = 0; i < 4; ++i) quad.corners[i] = Point16{bands.corner_x(i), bands.corner_y(i)};
        const Segment* lines[4];
        for (int i = 0; i < 4; ++i) {
            const Point16 a = quad.corners[i], b = quad.corners[(i + 1) & 3];
            predicted[i] = line_through(a, b);
            // The polarity along the side, turned into the line's own: +1 when the brighter
            // side lies on its +normal, the right of a -> b (as seen, y down) being (-dy, dx).
            const SinCos n = sin_cos(predicted[i].theta);
            const int64_t dot = (int64_t{n.cos.raw} * -(int64_t{b.y.raw} - a.y.raw) +
                                 int64_t{n.sin.raw} * (int64_t{b.x.raw} - a.x.raw));
            predicted[i].bright_side =
                static_cast<int8_t>(dot >= 0 ? bands.bright_right(i) : -bands.bright_right(i));
            quad.lines[i] = static_cast<uint8_t>(i);
            lines[i] = &predicted[i];
        }
        // Refitted as detect's quadrangles are; a side the first pass does not find there (a
        // prediction off by more than the refinement's band) is sought again across the whole
        // band, only then: the wider first pass lets clutter near a side pull its fit.
        RefineParams refine = params_.refine;
        Segment sides[4];
        SideEvidence evidence;
        const Quad predicted_quad = quad;
        uint8_t refitted = refine_quad(lines_.edges(), lines, refine, quad, sides, &evidence);
        if (refitted != 0xFu && refine.band.raw < bands.half_width().raw) {
            refine.band = bands.half_width();
            quad = predicted_quad;
            refitted = refine_quad(lines_.edges(), lines, refine, quad, sides, &evidence);
        }
        uint8_t index[4] = {};
        for (int i = 0; i < 4; ++i)
            if (((static_cast<uint32_t>(refitted) >> i) & 1u) != 0) {
                index[i] = static_cast<uint8_t>(lines_.line_count());
                lines_.append_line(sides[i]);
            }
        q16_16 score = q16_16::from_int(0);
        if (refitted == 0xFu && verify_evidence(evidence, 0, refine, &score) &&
            rule_corners_inside(quad.corners, lines_.width(), lines_.height(), params_.quads)) {
            for (int i = 0; i < 4; ++i) quad.lines[i] = index[i];
            quad.score = score;
            quads_[0] = quad;
            for (int i = 0; i < 4; ++i) sides_[0][i] = sides[i];
            quad_count_ = 1;
        }
        quad_stats_.quads = quad_count_;
        mark(FinishStage::quads);
        return l;
    }

    // Candidate k (quad, as detect_quads ranked it) refined and checked as finish() keeps one:
    // edge evidence on its refitted sides (quad and sides then refined, quad.score the
    // evidence), rule 3 again for the refitted corners, no sides running on past its corners,
    // a clear inside, few lines across. False at the first check it fails, counted in the stats.
    // A banded frame (tracking mode) makes no check of what its bands do not see: the inside
    // and the sides' lines beyond the corners.
    bool passes_checks(uint16_t k, Quad& quad, Segment (&sides)[4]) {
        const bool whole = lines_.window() == nullptr;
        const Segment* side_lines[4];
        for (int i = 0; i < 4; ++i)
            side_lines[i] =
                quad.lines[i] == kCompletedSide ? &completed_[k] : &lines_.lines()[quad.lines[i]];
        if (!refine_verified(lines_.edges(), side_lines, params_.refine, quad, sides,
                             &quad.score)) {
            ++quad_stats_.rejected_evidence;
            return false;
        }
        // Refitted sides can move a corner a pixel or two: rule 3 holds for what is kept.
        if (!rule_corners_inside(quad.corners, lines_.width(), lines_.height(), params_.quads)) {
            ++quad_stats_.rejected_inside;
            return false;
        }
        if (whole && params_.refine.max_junction_corners != kCheckOff &&
            junction_corners(lines_.edges(), quad.corners, params_.refine) >
                params_.refine.max_junction_corners) {
            ++quad_stats_.rejected_junctions;
            return false;
        }
        const uint8_t inside_limit = params_.refine.max_inside_edge_cells_percent;
        if (whole && inside_limit != kCheckOff &&  // off: nothing is counted
            !interior_clear(
                count_inside_edges(lines_.edges(), quad.corners, params_.refine.inside_margin),
                lines_.height(), inside_limit)) {
            ++quad_stats_.rejected_interior;
            return false;
        }
        if (params_.refine.max_lines_across != kCheckOff &&
            count_lines_across(lines_.lines(), lines_.line_count(), quad.corners,
                               params_.refine.inside_margin,
                               half_shortest_side(quad)) > params_.refine.max_lines_across) {
            ++quad_stats_.rejected_across;
            return false;
        }
        return true;
    }

    // Puts a checked quadrangle among the `kept` first of quads_ (and its sides in sides_) by
    // score, earlier rank first among equals; returns the new count. Two candidates that refit
    // to one quadrangle (corners within collinear_distance) are one: the better scored stays.
    uint16_t keep(const Quad& quad, const Segment (&sides)[4], uint16_t kept) {
        uint16_t dup = 0;
        while (dup < kept && !same_corners(quads_[dup], quad, params_.quads.collinear_distance))
            ++dup;
        if (dup < kept) {
            if (quads_[dup].score >= quad.score) return kept;
            for (uint16_t j = dup; j + 1u < kept; ++j) {
                quads_[j] = quads_[j + 1];
                for (int i = 0; i < 4; ++i) sides_[j][i] = sides_[j + 1][i];
            }
            --kept;
        }
        uint16_t at = kept;
        while (at > 0 && quad.score > quads_[at - 1].score) {
            quads_[at] = quads_[at - 1];
            for (int i = 0; i < 4; ++i) sides_[at][i] = sides_[at - 1][i];
            --at;
        }
        quads_[at] = quad;
        for (int i = 0; i < 4; ++i) sides_[at][i] = sides[i];
        return static_cast<uint16_t>(kept + 1);
    }

    // Every kept quadrangle's completed sides join the line list (so that Quad::lines index it
    // for every quadrangle), replacing the weakest lines no kept quadrangle uses when it is
    // full; then the best quadrangle's refitted sides replace its lines (what a tracker takes).
    void place_sides() {
        for (uint16_t k = 0; k < quad_count_; ++k)
            for (int i = 0; i < 4; ++i) {
                if (quads_[k].lines[i] != kCompletedSide) continue;
                uint16_t slot = lines_.line_count();
                if (!lines_.append_line(sides_[k][i])) {
                    while (slot-- > 0 && used(slot)) {
                    }
                    lines_.replace_line(slot,
                                        sides_[k][i]);  // slot < line_count: some line is unused
                }
                quads_[k].lines[i] = static_cast<uint8_t>(slot);
            }
        if (quad_count_ > 0)
            for (int i = 0; i < 4; ++i) lines_.replace_line(quads_[0].lines[i], sides_[0][i]);
    }
    bool used(uint16_t line) const {
        for (uint16_t k = 0; k < quad_count_; ++k)
            for (int i = 0; i < 4; ++i)
                if (quads_[k].lines[i] == line) return true;
        return false;
    }

    static q16_16 half_shortest_side(const Quad& quad) {
        q16_16 shortest = distance(quad.corners[0], quad.corners[1]);
        for (int i = 1; i < 4; ++i) {
            const q16_16 d = distance(quad.corners[i], quad.corners[(i + 1) & 3]);
            shortest = d < shortest ? d : shortest;
        }
        return q16_16::from_raw(shortest.raw / 2);
    }

    static bool same_corners(const Quad& a, const Quad& b, q16_16 tolerance) {
        for (int i = 0; i < 4; ++i) {
            const int64_t dx = static_cast<int64_t>(a.corners[i].x.raw) - b.corners[i].x.raw;
            const int64_t dy = static_cast<int64_t>(a.corners[i].y.raw) - b.corners[i].y.raw;
            if (dx > tolerance.raw || dx < -tolerance.raw || dy > tolerance.raw ||
                dy < -tolerance.raw)
                return false;
        }
        return true;
    }

    Lines lines_;
    LinePair pairs_[PairCapacity] = {};
    QuadLine geometry_[Lines::max_lines()] = {};
    Quad quads_[MaxCandidates] = {};         // the candidates, then the kept ones first
    Segment sides_[MaxQuads][4] = {};        // each kept quadrangle's refitted sides
    Segment completed_[MaxCandidates] = {};  // detect_quads' completed sides
    BoardParams params_;
    QuadStats quad_stats_;
    uint16_t quad_count_ = 0;
};

// QVGA: the QVGA lines stage, 128 parallel pairs, the best 4 quadrangles.
using BoardDetectorQvga = BoardDetector<Qvga>;
// VGA: the VGA lines stage, 256 parallel pairs, the best 4 quadrangles.
using BoardDetectorVga = BoardDetector<Vga>;

}  // namespace qt
