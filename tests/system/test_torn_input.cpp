// Torn input: every streaming entry point of the core pipeline given a frame
// that ends early, rows of the wrong length and size changes between frames. For each:
// the documented error status, no frame afterwards (rows refused with not_in_frame, finish()
// refused, no results of an earlier frame left standing), and the NEXT good frame processed
// normally: its whole output (gradient words; lines, segments, edge list, stats; quadrangles;
// Harris corners with their patches; the target pipeline's estimate, homography, search window
// and match) identical, field by field and bit by bit for floats, to that of a fresh object
// given the same good frames and never the torn ones. For the stateless stages that is a fresh
// object given only the good frame; the target pipeline carries the previous frame's corners
// and the track from frame to frame, so its reference is a fresh pipeline given the same good
// frames in the same order (a torn or refused frame must leave no trace).
//
// Statuses expected (status.h, gradient_stage.h, harris.h, line_detector.h):
//   begin_frame() while rows are missing         previous_frame_incomplete, the new frame starts
//   a row of the wrong length (shorter, longer, 0) bad_row_length; the frame is abandoned: later
//                                                 rows and finish() get not_in_frame, and the
//                                                 next begin_frame() is ok (nothing left to
//                                                 abandon)
//   finish() before the last row                  not_in_frame, no results; Harris ends the frame
//                                                 there (next begin ok), the line/board detectors
//                                                 and the target pipeline keep it open (next
//                                                 begin: previous_frame_incomplete)
//   a row after the last one                      not_in_frame, the frame's results unharmed
//   begin_frame() with 0 or above capacity        bad_size and no frame at all (also when it
//                                                 arrives in the middle of a frame)
#include <catch2/catch.hpp>

#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gradient/gradient_stage.h"
#include "lines/line_detector.h"
#include "quads/board_detector.h"
#include "scene/board_scene.h"
#include "scene/ground_sequence.h"
#include "target/float/target_pipeline.h"
#include "target/harris.h"

using namespace qt;
using io::GreyImage;

namespace Catch {
template <>
struct StringMaker<qt::Status> {
    static std::string convert(qt::Status s) { return qt::status_name(s); }
};
}  // namespace Catch

namespace {

// ---- frames: pixels and the gradient words of the same frame (for push_gradient_row) ---------

struct Frame {
    int w = 0, h = 0;
    std::vector<uint8_t> pixels;       // w·h
    std::vector<gradient_word> words;  // w·h, from a GradientStage of their own
    const uint8_t* row(int y) const { return pixels.data() + static_cast<size_t>(y) * w; }
    const gradient_word* word_row(int y) const { return words.data() + static_cast<size_t>(y) * w; }
};

Frame make_frame(const GreyImage& img) {
    Frame f;
    f.w = img.width;
    f.h = img.height;
    f.pixels = img.pixels;
    f.words.resize(f.pixels.size());
    const auto stage = std::make_unique<GradientStage<640>>();  // a fresh one: one frame only
    REQUIRE(stage->begin_frame(static_cast<uint16_t>(f.w), static_cast<uint16_t>(f.h)) ==
            Status::ok);
    for (int y = 0; y < f.h; ++y)
        REQUIRE(stage->push_row(f.row(y), static_cast<uint16_t>(f.w),
                                [&](uint16_t gy, const gradient_word* wds, uint16_t n) {
                                    std::memcpy(f.words.data() + static_cast<size_t>(gy) * f.w, wds,
                                                n * sizeof *wds);
                                }) == Status::ok);
    return f;
}

GreyImage crop(const GreyImage& img, int w, int h) {
    GreyImage out(w, h);
    for (int y = 0; y < h; ++y) std::memcpy(&out.at(0, y), img.row(y), static_cast<size_t>(w));
    return out;
}

// A bright board in a w × h frame; `variant` moves it and changes the noise.
GreyImage board_image(int w, int h, int variant) {
    scene::BoardScene s;
    s.width = w;
    s.height = h;
    s.seed = 100 + static_cast<uint64_t>(variant);
    const double at[4][2] = {{0.20, 0.18}, {0.16, 0.80}, {0.82, 0.84}, {0.86, 0.16}};
    for (int i = 0; i < 4; ++i)
        s.corners[i] = {static_cast<int32_t>((at[i][0] * w + 3 * variant) * 256),
                        static_cast<int32_t>((at[i][1] * h + 2 * variant) * 256)};
    return scene::render_board(s);
}

// The frames every case uses: P primes the object, T is torn, B and C follow; S is smaller,
// O an odd size.
struct FrameSet {
    Frame p, t, b, c, s, o;
};

const FrameSet& board_frames() {
    static const FrameSet set = [] {
        FrameSet f;
        f.p = make_frame(board_image(320, 240, 0));
        f.t = make_frame(board_image(320, 240, 1));
        f.b = make_frame(board_image(320, 240, 2));
        f.c = make_frame(board_image(320, 240, 3));
        f.s = make_frame(board_image(160, 120, 4));
        f.o = make_frame(board_image(203, 151, 5));
        return f;
    }();
    return set;
}

// The airborne sequence's first frames (textured ground: many Harris corners, a homography).
const scene::GroundSequence& ground() {
    static const scene::GroundSequence seq(scene::short_ground_sequence());
    return seq;
}

const FrameSet& ground_frames() {
    static const FrameSet set = [] {
        const scene::GroundSequence& seq = ground();
        FrameSet f;
        f.p = make_frame(seq.render(0));
        f.t = make_frame(seq.render(1));
        f.b = make_frame(seq.render(2));
        f.c = make_frame(seq.render(3));
        f.s = make_frame(crop(seq.render(4), 160, 120));
        f.o = make_frame(crop(seq.render(5), 203, 151));
        return f;
    }();
    return set;
}

// ---- outputs, flattened for exact comparison -----------------------------------------------

struct Out {
    std::vector<int64_t> v;
    void add(int64_t x) { v.push_back(x); }
    void add(float f) {
        uint32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        v.push_back(bits);
    }
    void add(const Segment& s) {
        for (q16_16 q : {s.x1, s.y1, s.x2, s.y2, s.rho, s.cx, s.cy}) add(int64_t{q.raw});
        add(int64_t{s.theta});
        add(int64_t{s.points});
        add(int64_t{s.bright_side});
    }
};

template <class Lines>
void add_lines(Out& o, const Lines& d) {
    o.add(int64_t{d.width()});
    o.add(int64_t{d.height()});
    o.add(int64_t{d.segment_count()});
    for (uint16_t i = 0; i < d.segment_count(); ++i) o.add(d.segments()[i]);
    o.add(int64_t{d.line_count()});
    for (uint16_t i = 0; i < d.line_count(); ++i) o.add(d.lines()[i]);
    const LineStats& s = d.stats();
    for (int64_t x :
         {int64_t{s.edges}, int64_t{s.edges_dropped}, int64_t{s.hough.points_visited},
          int64_t{s.hough.votes}, int64_t{s.hough.saturated_votes}, int64_t{s.hough.lines_followed},
          int64_t{s.hough.flat_bins}, int64_t{s.hough.walk_steps}, int64_t{s.hough.segments},
          int64_t{s.hough.segments_dropped}, int64_t{s.hough.budget_exhausted},
          int64_t{s.cluster.clusters}, int64_t{s.cluster.clusters_dropped},
          int64_t{s.cluster.ends_joined}})
        o.add(x);
    const EdgeList& e = d.edges();
    o.add(int64_t{e.size()});
    for (uint16_t i = 0; i < e.size(); ++i) o.add(int64_t{e[i]});
}

// ---- one adapter per entry point: begin / push row y (any length) / finish / output ----------

// Row y of f with `len` entries: the frame's row, cut short or padded with zeros; nullptr for 0.
template <class T>
const T* row_of(const T* row, int w, uint16_t len, std::vector<T>& scratch) {
    if (len == 0) return nullptr;
    if (len == w) return row;
    scratch.assign(len, T{});
    std::memcpy(scratch.data(), row, sizeof(T) * (len < w ? len : static_cast<size_t>(w)));
    return scratch.data();
}

struct GradientAdapter {
    static constexpr const char* name = "GradientStage";
    static constexpr bool stateful = false, has_finish = false;
    static constexpr uint16_t max_w = 320, max_h = 0;         // no height capacity
    static constexpr Status after_early_finish = Status::ok;  // (no finish)
    GradientStage<320> stage;
    std::vector<int64_t> emitted;
    std::vector<uint8_t> scratch;
    Status begin(uint16_t w, uint16_t h) {
        emitted.clear();
        return stage.begin_frame(w, h);
    }
    Status push(const Frame& f, int y, uint16_t len) {
        return stage.push_row(row_of(f.row(y), f.w, len, scratch), len,
                              [&](uint16_t gy, const gradient_word* wds, uint16_t n) {
                                  emitted.push_back(-1 - gy);
                                  for (uint16_t x = 0; x < n; ++x) emitted.push_back(wds[x]);
                              });
    }
    Status finish() { return Status::ok; }
    Out output() const { return Out{emitted}; }
    bool no_results() const { return true; }
    bool meaningful() const { return !emitted.empty(); }
};

// Camera rows (push_row) or gradient words (push_gradient_row) into a LineDetector or a
// BoardDetector: the two share these entry points.
template <class Detector, class Params, bool Words>
struct DetectorFeed {
    static constexpr bool stateful = false, has_finish = true;
    static constexpr uint16_t max_w = 320, max_h = 240;
    static constexpr Status after_early_finish = Status::previous_frame_incomplete;
    std::unique_ptr<Detector> det = std::make_unique<Detector>();
    std::vector<uint8_t> px;
    std::vector<gradient_word> wd;
    Status begin(uint16_t w, uint16_t h) { return det->begin_frame(w, h, Params{}); }
    Status push(const Frame& f, int y, uint16_t len) {
        return Words ? det->push_gradient_row(row_of(f.word_row(y), f.w, len, wd), len)
                     : det->push_row(row_of(f.row(y), f.w, len, px), len);
    }
    Status finish() { return det->finish(); }
};

template <bool Words>
struct LineAdapter : DetectorFeed<LineDetectorQvga, LineParams, Words> {
    static constexpr const char* name =
        Words ? "LineDetectorQvga push_gradient_row" : "LineDetectorQvga push_row";
    using DetectorFeed<LineDetectorQvga, LineParams, Words>::det;
    Out output() const {
        Out o;
        add_lines(o, *det);
        return o;
    }
    bool no_results() const { return det->segment_count() == 0 && det->line_count() == 0; }
    bool meaningful() const { return det->line_count() >= 4; }
};

template <bool Words>
struct BoardAdapter : DetectorFeed<BoardDetectorQvga, BoardParams, Words> {
    static constexpr const char* name =
        Words ? "BoardDetectorQvga push_gradient_row" : "BoardDetectorQvga push_row";
    using DetectorFeed<BoardDetectorQvga, BoardParams, Words>::det;
    Out output() const {
        Out o;
        add_lines(o, det->lines());
        o.add(int64_t{det->quad_count()});
        for (uint16_t i = 0; i < det->quad_count(); ++i) {
            const Quad& q = det->quads()[i];
            for (const Point16& c : q.corners) {
                o.add(int64_t{c.x.raw});
                o.add(int64_t{c.y.raw});
            }
            for (uint8_t l : q.lines) o.add(int64_t{l});
            o.add(int64_t{q.score.raw});
        }
        const QuadStats& s = det->quad_stats();
        for (int64_t x :
             {int64_t{s.parallel_pairs}, int64_t{s.pairs_dropped}, int64_t{s.combinations},
              int64_t{s.rejected_perpendicular}, int64_t{s.rejected_shape},
              int64_t{s.rejected_contrast}, int64_t{s.rejected_inside}, int64_t{s.rejected_sides},
              int64_t{s.rejected_aspect}, int64_t{s.rejected_support}})
            o.add(x);
        return o;
    }
    bool no_results() const {
        return det->quad_count() == 0 && det->lines().segment_count() == 0 &&
               det->lines().line_count() == 0;
    }
    bool meaningful() const { return det->quad_count() >= 1; }
};

// Harris: pixel row y then gradient row y (the order harris.h allows); Words puts the wrong
// length on the gradient row instead of the pixel row.
template <bool Words>
struct HarrisAdapter {
    using Det = HarrisDetector<320, 96, 4, 2>;
    static constexpr const char* name =
        Words ? "HarrisDetector push_gradient_row" : "HarrisDetector push_pixel_row";
    static constexpr bool stateful = false, has_finish = true;
    static constexpr uint16_t max_w = 320, max_h = Det::kMaxHeight;
    static constexpr Status after_early_finish =
        Status::ok;  // harris.h: "the frame ends either way"
    std::unique_ptr<Det> det = std::make_unique<Det>();
    std::vector<uint8_t> px;
    std::vector<gradient_word> wd;
    Status begin(uint16_t w, uint16_t h) { return det->begin_frame(w, h, HarrisParams{}); }
    Status push(const Frame& f, int y, uint16_t len) {
        const uint16_t plen = Words ? static_cast<uint16_t>(f.w) : len;
        const Status s = det->push_pixel_row(row_of(f.row(y), f.w, plen, px), plen);
        if (s != Status::ok) return s;
        // A row beyond the frame's last: nothing to pair it with (the pixel row was refused).
        const uint16_t glen = Words ? len : static_cast<uint16_t>(f.w);
        return det->push_gradient_row(static_cast<uint16_t>(y),
                                      row_of(f.word_row(y), f.w, glen, wd), glen);
    }
    Status finish() { return det->finish(); }
    Out output() const {
        Out o;
        const auto& fs = det->features();
        o.add(int64_t{fs.width});
        o.add(int64_t{fs.height});
        o.add(int64_t{fs.count});
        for (uint16_t i = 0; i < fs.count; ++i) {
            const auto& f = fs.items[i];
            for (int64_t x :
                 {f.response, int64_t{f.x_q8}, int64_t{f.y_q8}, int64_t{f.px}, int64_t{f.py}})
                o.add(x);
            for (uint8_t p : f.patch) o.add(int64_t{p});
        }
        const HarrisStats& s = det->stats();
        for (int64_t x :
             {int64_t{s.candidates}, int64_t{s.replaced}, int64_t{s.dropped}, int64_t{s.weak}})
            o.add(x);
        return o;
    }
    bool no_results() const { return det->features().count == 0; }
    bool meaningful() const { return det->features().count >= 40; }
};

void add_frame(Out& o, const TargetFrame& f) {
    o.add(int64_t{f.started});
    o.add(int64_t{f.tracking});
    const TargetEstimate& e = f.estimate;
    o.add(int64_t{static_cast<int>(e.state)});
    for (float x : {e.x, e.y, e.nds, e.det_s}) o.add(x);
    o.add(int64_t{e.reset});
    o.add(int64_t{e.unseen});
    o.add(int64_t{f.features});
    const FrameHomography& g = f.geometry;
    o.add(int64_t{static_cast<int>(g.ransac.status)});
    for (float m : g.ransac.h.m) o.add(m);
    o.add(int64_t{g.ransac.inliers});
    o.add(int64_t{g.ransac.iterations});
    o.add(g.ransac.reprojection_px);
    o.add(int64_t{g.matches});
    const MatchStats& m = g.match_stats;
    for (int64_t x :
         {int64_t{m.scored}, int64_t{m.flat}, int64_t{m.no_candidate}, int64_t{m.below_min},
          int64_t{m.ambiguous}, int64_t{m.not_mutual}, int64_t{m.dropped_capacity}})
        o.add(x);
    for (float x : {f.window.x, f.window.y, f.window.radius}) o.add(x);
    o.add(int64_t{f.hit.found});
    for (int64_t x : {int64_t{f.hit.x_q8}, int64_t{f.hit.y_q8}, int64_t{f.hit.score_q15},
                      int64_t{f.hit.positions}})
        o.add(x);
}

// The target pipeline; Track: a target set before the first frame (the vehicle of the
// airborne sequence's frame 0, a 15 × 15 box).
template <bool Track>
struct TargetAdapter {
    static constexpr const char* name =
        Track ? "TargetPipelineQvga tracking" : "TargetPipelineQvga";
    static constexpr bool stateful = true, has_finish = true;
    static constexpr uint16_t max_w = 320, max_h = HarrisDetector<320, 96>::kMaxHeight;
    static constexpr Status after_early_finish = Status::previous_frame_incomplete;
    std::unique_ptr<TargetPipelineQvga> pipe = std::make_unique<TargetPipelineQvga>();
    TargetFrame out;
    std::vector<uint8_t> px;
    TargetAdapter() {
        if (Track) {
            const scene::GroundTruth t = ground().truth(0);
            REQUIRE(pipe->set_target(static_cast<int32_t>(t.target_x + 0.5) - 7,
                                     static_cast<int32_t>(t.target_y + 0.5) - 7, 15,
                                     15) == Status::ok);
        }
    }
    Status begin(uint16_t w, uint16_t h) { return pipe->begin_frame(w, h, TargetPipelineParams{}); }
    Status push(const Frame& f, int y, uint16_t len) {
        return pipe->push_row(row_of(f.row(y), f.w, len, px), len);
    }
    Status finish() { return pipe->finish(out); }
    Out output() const {
        Out o;
        add_frame(o, out);
        return o;
    }
    bool no_results() const {
        Out a, b;
        add_frame(a, out);
        add_frame(b, TargetFrame{});
        return a.v == b.v;
    }
    bool meaningful() const { return out.features >= 40 && (!Track || out.tracking); }
};

// ---- the cases ---------------------------------------------------------------------------

uint16_t u16(int v) { return static_cast<uint16_t>(v); }

// Every row of f; returns finish()'s status (CHECKs that begin_frame said `begin`, rows ok).
template <class A>
Status feed(A& a, const Frame& f, Status begin = Status::ok) {
    CHECK(a.begin(u16(f.w), u16(f.h)) == begin);
    for (int y = 0; y < f.h; ++y) {
        const Status s = a.push(f, y, u16(f.w));
        if (s != Status::ok) {
            FAIL_CHECK("row " << y << ": " << status_name(s));
            break;
        }
    }
    return a.finish();
}

// The first `rows` rows of f (begin_frame ok).
template <class A>
void feed_part(A& a, const Frame& f, int rows) {
    CHECK(a.begin(u16(f.w), u16(f.h)) == Status::ok);
    for (int y = 0; y < rows; ++y) CHECK(a.push(f, y, u16(f.w)) == Status::ok);
}

// The torn object `a`, given the good frames `history` (in order) and torn ones, now gets the
// good frame `next`: begin_frame says `begin`, every row is ok, and finish()'s status and the
// whole output equal those of a fresh object given the same good frames (only `next` for
// stateless stages).
template <class A>
void next_is_normal(A& a, const std::vector<const Frame*>& history, const Frame& next,
                    Status begin) {
    const Status got = feed(a, next, begin);
    // The reference, computed once per sequence of good frames (most cases share one).
    struct Reference {
        Status status;
        Out out;
        bool meaningful;
    };
    static std::map<std::vector<const Frame*>, Reference> cache;
    std::vector<const Frame*> key = A::stateful ? history : std::vector<const Frame*>{};
    key.push_back(&next);
    auto it = cache.find(key);
    if (it == cache.end()) {
        A ref;
        for (size_t i = 0; i + 1 < key.size(); ++i) feed(ref, *key[i]);
        const Status want = feed(ref, next);
        it = cache.emplace(key, Reference{want, ref.output(), ref.meaningful()}).first;
    }
    const Reference& ref = it->second;
    CHECK(ref.status == Status::ok);
    CHECK(ref.meaningful);
    CHECK(got == ref.status);
    CHECK(a.output().v == ref.out.v);
}

template <class A>
void torn_cases(const FrameSet& f) {
    INFO(A::name);
    const int h = f.t.h, w = f.t.w;

    // (a) A frame that ends early: the next begin_frame() arrives before its last row.
    for (int cut : {0, 1, h / 2, h - 1}) {
        INFO("(a) begin_frame after " << cut << " rows");
        A a;
        REQUIRE(feed(a, f.p) == Status::ok);
        feed_part(a, f.t, cut);
        next_is_normal(a, {&f.p}, f.b, Status::previous_frame_incomplete);
        if (A::stateful) next_is_normal(a, {&f.p, &f.b}, f.c, Status::ok);
    }
    {
        INFO("(a) the very first frame torn");
        A a;
        feed_part(a, f.t, h / 2);
        next_is_normal(a, {}, f.b, Status::previous_frame_incomplete);
    }
    {
        INFO("(a) a smaller frame torn between two full ones");
        A a;
        REQUIRE(feed(a, f.p) == Status::ok);
        feed_part(a, f.s, f.s.h / 2);
        next_is_normal(a, {&f.p}, f.b, Status::previous_frame_incomplete);
    }
    // (a) finish() before the last row: refused, and no results (none of P's left standing).
    if (A::has_finish) {
        for (int cut : {0, 1, h / 2, h - 1}) {
            INFO("(a) finish after " << cut << " rows");
            A a;
            REQUIRE(feed(a, f.p) == Status::ok);
            feed_part(a, f.t, cut);
            CHECK(a.finish() == Status::not_in_frame);
            CHECK(a.no_results());
            next_is_normal(a, {&f.p}, f.b, A::after_early_finish);
            if (A::stateful) next_is_normal(a, {&f.p, &f.b}, f.c, Status::ok);
        }
    }
    // A row after the last one: refused; the frame's results are those of a fresh object.
    {
        INFO("a row after the last");
        A a;
        REQUIRE(feed(a, f.p) == Status::ok);
        CHECK(a.begin(u16(w), u16(h)) == Status::ok);
        for (int y = 0; y < h; ++y) CHECK(a.push(f.b, y, u16(w)) == Status::ok);
        CHECK(a.push(f.b, h - 1, u16(w)) == Status::not_in_frame);
        const Status got = a.finish();
        A ref;
        if (A::stateful) feed(ref, f.p);
        CHECK(got == feed(ref, f.b));
        CHECK(a.output().v == ref.output().v);
        // And the frame after it is normal.
        next_is_normal(a, {&f.p, &f.b}, f.c, Status::ok);
    }

    // (b) A row of the wrong length: shorter, longer, empty; first, middle and last row.
    for (int row : {0, h / 2, h - 1})
        for (int len : {w - 1, w + 1, 0}) {
            INFO("(b) row " << row << " of length " << len);
            A a;
            REQUIRE(feed(a, f.p) == Status::ok);
            feed_part(a, f.t, row);
            CHECK(a.push(f.t, row, u16(len)) == Status::bad_row_length);
            CHECK(a.push(f.t, row, u16(w)) == Status::not_in_frame);  // the frame was abandoned
            if (row + 1 < h) CHECK(a.push(f.t, row + 1, u16(w)) == Status::not_in_frame);
            if (A::has_finish) {
                CHECK(a.finish() == Status::not_in_frame);
                CHECK(a.no_results());
            }
            next_is_normal(a, {&f.p}, f.b, Status::ok);
            if (A::stateful) next_is_normal(a, {&f.p, &f.b}, f.c, Status::ok);
        }

    // (c) Size changes between frames: smaller, an odd size, larger again.
    {
        INFO("(c) 320x240 -> 160x120 -> 203x151 -> 320x240");
        A a;
        REQUIRE(feed(a, f.p) == Status::ok);
        next_is_normal(a, {&f.p}, f.s, Status::ok);
        next_is_normal(a, {&f.p, &f.s}, f.o, Status::ok);
        next_is_normal(a, {&f.p, &f.s, &f.o}, f.b, Status::ok);
    }
    // (c) Sizes refused: 0, above the width capacity, above the height capacity; between frames
    // and in the middle of one. No frame afterwards, whatever length the rows have.
    struct Size {
        int w, h;
    };
    std::vector<Size> bad = {{0, h}, {w, 0}, {A::max_w + 1, h}};
    if (A::max_h > 0) bad.push_back({w, A::max_h + 1});
    for (const Size& s : bad)
        for (int mid : {0, 1}) {
            INFO("(c) begin_frame(" << s.w << ", " << s.h << ")"
                                    << (mid ? " in the middle of a frame" : ""));
            A a;
            REQUIRE(feed(a, f.p) == Status::ok);
            if (mid) feed_part(a, f.t, h / 2);
            CHECK(a.begin(u16(s.w), u16(s.h)) == Status::bad_size);
            // The refused frame's rows (as long as it said) and the torn frame's next row.
            if (s.w > 0) CHECK(a.push(f.t, h / 2, u16(s.w)) == Status::not_in_frame);
            CHECK(a.push(f.t, h / 2, u16(w)) == Status::not_in_frame);
            if (A::has_finish) {
                CHECK(a.finish() == Status::not_in_frame);
                CHECK(a.no_results());
            }
            next_is_normal(a, {&f.p}, f.b, Status::ok);
            if (A::stateful) next_is_normal(a, {&f.p, &f.b}, f.c, Status::ok);
        }
}

}  // namespace

TEST_CASE("torn input: GradientStage", "[torn]") { torn_cases<GradientAdapter>(board_frames()); }

TEST_CASE("torn input: LineDetectorQvga, camera rows and gradient rows", "[torn]") {
    torn_cases<LineAdapter<false>>(board_frames());
    torn_cases<LineAdapter<true>>(board_frames());
}

TEST_CASE("torn input: BoardDetectorQvga, camera rows and gradient rows", "[torn]") {
    torn_cases<BoardAdapter<false>>(board_frames());
    torn_cases<BoardAdapter<true>>(board_frames());
}

TEST_CASE("torn input: HarrisDetector, pixel rows and gradient rows", "[torn]") {
    torn_cases<HarrisAdapter<false>>(ground_frames());
    torn_cases<HarrisAdapter<true>>(ground_frames());
}

TEST_CASE("torn input: TargetPipelineQvga, without and with a target", "[torn]") {
    torn_cases<TargetAdapter<false>>(ground_frames());
    torn_cases<TargetAdapter<true>>(ground_frames());
}

TEST_CASE("torn input: a second finish() of one frame is refused and leaves the results",
          "[torn]") {
    LineAdapter<false> a;
    const Status first = feed(a, board_frames().p);
    REQUIRE((first == Status::ok || first == Status::capacity_exceeded));
    REQUIRE(a.meaningful());
    const Out before = a.output();
    // PPHT consumes the edge list: a second run would find other lines from what is left.
    CHECK(a.finish() == Status::not_in_frame);
    CHECK(a.output().v == before.v);
}
