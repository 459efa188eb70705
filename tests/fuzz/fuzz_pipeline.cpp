// Fuzz target: the input bytes are a program of calls on static core objects — a
// BoardDetectorQvga, a QuadTracker stepping on its results and a TargetPipelineQvga — so that
// frames of any size (0, up to capacity, above it), torn frames (wrong row lengths, rows
// missing, rows after the end, a new frame mid-frame), arbitrary pixels and arbitrary 32-bit
// gradient words (the FPGA link can deliver any word) and arbitrary target boxes all run.
//
// Program: a sequence of operations, each an opcode byte (value % 12) and its operands; bytes
// past the end read as 0. Integers are little-endian.
//   0 board begin    u16 wcode, u16 hcode, u8 flags [, u16 edge threshold if flags&1]
//                    [, u8 Hough threshold - 1 (mod 255) if flags&2]; flags&4: contrast any
//   1 board rows     u8 count (0: the rest of the frame), u8 lenmode [, u16 bad length if
//                    lenmode%8 == 0: the last row has that length]
//   2 board words    as 1, then u8 wordmode: 0 words of the pattern, 1 raw words from the
//                    program (4 bytes each, row after row), 2 the pattern's with u8 k, then k
//                    (u16 index, u32 word) overwriting words in every row, 3 u32 word: that
//                    word everywhere
//   3 board finish   then the tracker steps on the lines and quadrangles
//   4 pattern        u8 kind (%5: 0 flat, 1 board, 2 noise, 3 pixels from the program, 4 board +
//                    noise), u8 lo, u8 hi, u16 cx, u16 cy (1/64 px), u8 half width, u8 half
//                    height (px), u8 angle (1/256 turn), u8 noise, u8 seed, i8 dx, i8 dy (1/8 px
//                    per frame), i8 turn (1/2048 turn per frame)
//   5 target box     u8 mode; mode%4 == 0: i32 x, i32 y; 1: u8 dx, u8 dy: INT32_MAX − (d >> 1),
//                    or INT32_MIN + (d >> 1) for odd d; else i16 x, i16 y; then u8 w, u8 h
//                    (each doubled when mode & 4: boxes past the largest one taken)
//   6 target begin   u16 wcode, u16 hcode
//   7 target rows    as 1
//   8 target finish
//   9 configure      u8 method (%4, the target tracker's), u8 flags: &1 tracker reset, &2
//                    turn model for the quadrangle tracker's sides
//  10 board frame    u16 wcode, u16 hcode, u8 how (&1: gradient words): begin, every row,
//                    finish, tracker step; then the pattern moves
//  11 target frame   u16 wcode, u16 hcode: begin, every row, finish; then the pattern moves
// A size code gives (code & 3): 0 the capacity, 1 (code >> 2) % (capacity + 1) (0 included),
// 2 1 + (code >> 2) % 48, 3 above the capacity: capacity + 1 + 4·(code >> 2), at most 65535.
//
// Invariants: every Status is one of the enum's; counts within capacities; begin_frame
// refuses exactly the sizes over capacity; row and finish statuses follow the frame's state
// (a model of it is kept for frames fed by one path); detected quadrangles have their corners
// inside the frame and their lines among the lines; a tracked quadrangle is convex,
// anti-clockwise, corner 0 of least x + y, sides within the shape limits; target positions,
// search windows and homographies are finite where the contract says so; a target box is
// refused exactly when it is not wholly inside the frame.
#include <stddef.h>
#include <stdint.h>

#include <cmath>
#include <cstring>
#include <new>

#include "fuzz_check.h"
#include "gradient/gradient_stage.h"
#include "quads/board_detector.h"
#include "target/float/target_pipeline.h"
#include "tracking/quad_tracker.h"

namespace {

using qt::Status;

constexpr uint16_t kBoardW = 320, kBoardH = 240;  // BoardDetectorQvga's capacity
constexpr uint16_t kTargetW = 320;                // TargetPipelineQvga's rows
constexpr uint16_t kTargetH = 32767;              // its Harris stage's height limit
// Work per input (time): pixels of rows pushed, board and target together (a QVGA frame;
// smaller frames make longer sequences), and finish() calls.
constexpr uint32_t kPixelBudget = 320 * 240;
constexpr int kFinishBudget = 8;
constexpr int kOpBudget = 512;
constexpr double kPi = 3.14159265358979323846;

bool valid(Status s) { return std::strcmp(qt::status_name(s), "unknown status") != 0; }

struct Program {
    const uint8_t* data;
    size_t size;
    size_t at = 0;
    bool done() const { return at >= size; }
    uint8_t u8() { return at < size ? data[at++] : 0; }
    uint16_t u16() {
        const uint16_t lo = u8();
        return static_cast<uint16_t>(lo | (u8() << 8));
    }
    uint32_t u32() {
        const uint32_t lo = u16();
        return lo | (static_cast<uint32_t>(u16()) << 16);
    }
};

uint16_t size_from(uint16_t code, uint16_t capacity) {
    const uint32_t v = code >> 2;
    switch (code & 3) {
        case 0: return capacity;
        case 1: return static_cast<uint16_t>(v % (capacity + 1u));
        case 2: return static_cast<uint16_t>(1 + v % 48);
        default: {
            const uint32_t big = capacity + 1u + 4u * v;
            return static_cast<uint16_t>(big > 65535u ? 65535u : big);
        }
    }
}

uint32_t hash3(uint32_t x, uint32_t y, uint32_t seed) {
    uint32_t h = x * 0x9E3779B1u ^ y * 0x85EBCA77u ^ seed * 0xC2B2AE3Du;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    return h;
}

// What the rows show: flat, a turned rectangle (the board), noise, bytes of the program.
struct Pattern {
    uint8_t kind = 1, lo = 40, hi = 200, noise = 0;
    uint32_t seed = 1;
    double cx = 160, cy = 120, half_w = 70, half_h = 52, angle = 0.1;
    double dx = 0, dy = 0, turn = 0;

    void row(uint32_t y, uint8_t* out, uint32_t n, Program& in) const {
        const double c = std::cos(angle), s = std::sin(angle);
        for (uint32_t x = 0; x < n; ++x) {
            int v = lo;
            switch (kind) {
                case 0: break;
                case 2: v = static_cast<int>(hash3(x, y, seed) & 0xFF); break;
                case 3: v = in.u8(); break;
                default: {
                    const double u = (x - cx) * c + (y - cy) * s, w = -(x - cx) * s + (y - cy) * c;
                    if (std::fabs(u) <= half_w && std::fabs(w) <= half_h) v = hi;
                    if (kind == 4 && noise > 0)
                        v += static_cast<int>(hash3(x, y, seed) % (2u * noise + 1)) - noise;
                }
            }
            out[x] = static_cast<uint8_t>(v < 0 ? 0 : v > 255 ? 255 : v);
        }
    }
    void move() {
        cx += dx;
        cy += dy;
        angle += turn;
    }
};

// The state of one frame as the caller sees it, for frames fed by one path (pixel rows or
// gradient words); a frame fed by both is "mixed" and only checked for memory safety and
// valid statuses.
struct FrameModel {
    enum State { idle, in_frame, complete, abandoned, finished } state = idle;  // finished: once
    uint16_t w = 0, h = 0;
    uint32_t rows = 0;
    uint8_t paths = 0;  // bit 0 pixel rows, bit 1 gradient words
    bool mixed() const { return paths == 3; }
};

uint8_t row_buf[65536];
uint8_t rows3[3][65536];
qt::gradient_word word_buf[65536];

qt::BoardDetectorQvga board;
qt::QuadTracker tracker;
qt::TargetPipelineQvga target;

struct Run {
    explicit Run(Program program) : in(program) {}

    Program in;
    Pattern pattern;
    FrameModel bm, tm;  // board, target
    qt::BoardParams params;
    qt::TargetPipelineParams target_params;  // each input starts from the defaults
    uint16_t tracker_w = 0, tracker_h = 0;
    uint32_t last_track_id = 0;
    bool tracker_active = false;
    bool target_pending = false;
    bool target_captured = false;  // the frame in progress began with the box pending
    int32_t box_x = 0, box_y = 0;
    uint16_t box_w = 0, box_h = 0;
    uint32_t pixels_left = kPixelBudget;
    int finishes_left = kFinishBudget;
    bool turn_model = false;
    bool board_finished = false;  // finish() succeeded since the last board_begin()

    // --- board ---------------------------------------------------------------------------
    void board_begin(uint16_t w, uint16_t h) {
        const Status s = board.begin_frame(w, h, params);
        board_finished = false;
        QT_FUZZ_CHECK(valid(s));
        const bool refuse = w == 0 || h == 0 || w > kBoardW || h > kBoardH;
        if (refuse) {
            QT_FUZZ_CHECK(s == Status::bad_size);
            bm = FrameModel{};
            return;
        }
        QT_FUZZ_CHECK(s == Status::ok || s == Status::previous_frame_incomplete);
        if (!bm.mixed()) {
            if (bm.state == FrameModel::in_frame)
                QT_FUZZ_CHECK(s == Status::previous_frame_incomplete);
            if (bm.state == FrameModel::idle || bm.state == FrameModel::complete ||
                bm.state == FrameModel::finished)
                QT_FUZZ_CHECK(s == Status::ok);
        }
        bm = FrameModel{};
        bm.state = FrameModel::in_frame;
        bm.w = w;
        bm.h = h;
    }

    // Expected status of a row of `len` on path `path`, and the model after it.
    void board_row_done(Status s, uint16_t len, uint8_t path) {
        QT_FUZZ_CHECK(valid(s));
        bm.paths = static_cast<uint8_t>(bm.paths | path);
        if (bm.mixed()) return;
        if (bm.state != FrameModel::in_frame) {
            QT_FUZZ_CHECK(s == Status::not_in_frame);
        } else if (len != bm.w) {
            QT_FUZZ_CHECK(s == Status::bad_row_length);
            bm.state = FrameModel::abandoned;
        } else {
            QT_FUZZ_CHECK(s == Status::ok);
            if (++bm.rows == bm.h) bm.state = FrameModel::complete;
        }
    }

    // Rows an operation pushes: `count`, or with 0 the rest of the frame; fewer when the
    // pixel budget runs out (a row of a zero-width frame costs one pixel).
    uint32_t rows_wanted(uint8_t count, const FrameModel& m) {
        uint32_t n = count;
        if (n == 0) n = m.state == FrameModel::in_frame && m.h > m.rows ? m.h - m.rows : 1;
        const uint32_t row = m.w > 0 ? m.w : 1;
        if (n > pixels_left / row) n = pixels_left / row;
        pixels_left -= n * row;
        return n;
    }

    void board_rows(uint8_t count, uint8_t lenmode) {
        const uint32_t n = rows_wanted(count, bm);
        const uint16_t bad = lenmode % 8 == 0 ? in.u16() : bm.w;
        for (uint32_t i = 0; i < n; ++i) {
            const uint16_t len = i + 1 == n ? bad : bm.w;
            pattern.row(bm.rows, row_buf, len, in);
            board_row_done(board.push_row(row_buf, len), len, 1);
        }
    }

    // Gradient words of pattern row y of a frame `w` wide and `h` high (replicated borders).
    void pattern_words(uint32_t y, uint16_t w, uint16_t h, qt::gradient_word* out) {
        const uint32_t last = h > 0 ? h - 1u : 0;
        const uint32_t ya = y > 0 ? y - 1 : 0, yb = y < last ? y + 1 : last;
        pattern.row(ya, rows3[0], w, in);
        pattern.row(y, rows3[1], w, in);
        pattern.row(yb, rows3[2], w, in);
        if (w > 0) qt::gradient_row(rows3[0], rows3[1], rows3[2], w, out);
    }

    // mode < 0: the word mode is the program's next byte.
    void board_words(uint8_t count, uint8_t lenmode, int mode = -1) {
        const uint32_t n = rows_wanted(count, bm);
        const uint16_t bad = lenmode % 8 == 0 ? in.u16() : bm.w;
        if (mode < 0) mode = in.u8() % 4;
        // Mode 2: k (index, word) pairs overwrite the pattern's words in every row; mode 3: one
        // word everywhere. Read once for the operation.
        uint16_t at[256];
        qt::gradient_word put[256];
        const uint8_t k = mode == 2 ? in.u8() : 0;
        for (uint8_t j = 0; j < k; ++j) {
            at[j] = in.u16();
            put[j] = in.u32();
        }
        const qt::gradient_word same = mode == 3 ? in.u32() : 0;
        for (uint32_t i = 0; i < n; ++i) {
            const uint16_t len = i + 1 == n ? bad : bm.w;
            if (mode == 1) {
                for (uint32_t x = 0; x < len; ++x) word_buf[x] = in.u32();
            } else if (mode == 3) {
                for (uint32_t x = 0; x < len; ++x) word_buf[x] = same;
            } else {
                pattern_words(bm.rows, len, bm.h, word_buf);
                for (uint8_t j = 0; j < k && len > 0; ++j) word_buf[at[j] % len] = put[j];
            }
            board_row_done(board.push_gradient_row(word_buf, len), len, 2);
        }
    }

    void check_lines_and_quads() {
        const auto& lines = board.lines();
        QT_FUZZ_CHECK(lines.line_count() <= qt::LineDetectorQvga::max_lines());
        QT_FUZZ_CHECK(lines.segment_count() <= 64);
        QT_FUZZ_CHECK(lines.stats().edges <= 4096);
        QT_FUZZ_CHECK(board.quad_count() <= qt::BoardDetectorQvga::max_quads());
        const int64_t one = qt::q16_16::one_raw;
        // Segment ends are edge points of the frame projected onto a line fitted through
        // some of them (so within a diagonal of the frame), then moved a little by clustering
        // and corner joining (3 px by default). A segment fitted on very few points of its own
        // (Hough threshold 1 or 2) may end well outside the frame (17 px off a 40 x 40 frame
        // was seen), which no contract excludes: "sane" here is within twice the frame's
        // width + height, enough to catch garbage or overflow.
        const int64_t margin = 2 * (int64_t{lines.width()} + lines.height()) + 16;
        const int64_t lo = -margin * one, hi_x = (int64_t{lines.width()} + margin) * one,
                      hi_y = (int64_t{lines.height()} + margin) * one;
        for (uint16_t i = 0; i < lines.line_count(); ++i) {
            const qt::Segment& l = lines.lines()[i];
            QT_FUZZ_CHECK(l.rho.raw >= 0);
            QT_FUZZ_CHECK(l.x1.raw >= lo && l.x1.raw <= hi_x && l.x2.raw >= lo && l.x2.raw <= hi_x);
            QT_FUZZ_CHECK(l.y1.raw >= lo && l.y1.raw <= hi_y && l.y2.raw >= lo && l.y2.raw <= hi_y);
            QT_FUZZ_CHECK(l.bright_side >= -1 && l.bright_side <= 1);
        }
        for (uint16_t i = 0; i < board.quad_count(); ++i) {
            const qt::Quad& q = board.quads()[i];
            QT_FUZZ_CHECK(q.score.raw >= 0 && q.score.raw <= one);
            // Rule 3 with corner_margin 0: inside the frame's outer pixel edges.
            for (int k = 0; k < 4; ++k) {
                QT_FUZZ_CHECK(q.lines[k] < lines.line_count());
                QT_FUZZ_CHECK(q.corners[k].x.raw >= -one / 2 &&
                              q.corners[k].x.raw <= lines.width() * one - one / 2);
                QT_FUZZ_CHECK(q.corners[k].y.raw >= -one / 2 &&
                              q.corners[k].y.raw <= lines.height() * one - one / 2);
            }
        }
    }

    void check_tracked(const qt::TrackedQuad& t) {
        QT_FUZZ_CHECK(t.state == qt::TrackState::none || t.state == qt::TrackState::started ||
                      t.state == qt::TrackState::tracking);
        QT_FUZZ_CHECK(tracker.stats().lost_reason <= qt::QuadTrackLost::detection_disagrees);
        if (t.state == qt::TrackState::none) {
            QT_FUZZ_CHECK(!tracker.tracking());
            tracker_active = false;
            return;
        }
        QT_FUZZ_CHECK(tracker.tracking());
        QT_FUZZ_CHECK(t.detected <= 0x0F);
        if (t.state == qt::TrackState::started) {
            QT_FUZZ_CHECK(t.track_id == last_track_id + 1 && t.age == 0 && t.detected == 0x0F);
        } else {
            QT_FUZZ_CHECK(tracker_active && t.track_id == last_track_id && t.age >= 1);
        }
        last_track_id = t.track_id;
        tracker_active = true;
        // detect's corner order: anti-clockwise as seen (negative shoelace in y-down
        // coordinates), convex, corner 0 of least x + y; sides within the shape limits.
        double x[4], y[4];
        for (int i = 0; i < 4; ++i) {
            x[i] = t.corners[i].x.raw / 65536.0;
            y[i] = t.corners[i].y.raw / 65536.0;
        }
        double shoelace = 0;
        const qt::QuadParams shape;
        for (int i = 0; i < 4; ++i) {
            const int j = (i + 1) % 4, k = (i + 2) % 4;
            shoelace += x[i] * y[j] - x[j] * y[i];
            const double cross = (x[j] - x[i]) * (y[k] - y[j]) - (y[j] - y[i]) * (x[k] - x[j]);
            QT_FUZZ_CHECK(cross < 1e-6);  // every turn the same way (anti-clockwise as seen)
            const double side = std::hypot(x[j] - x[i], y[j] - y[i]);
            QT_FUZZ_CHECK(side >= shape.min_side_length.raw / 65536.0 - 0.01 &&
                          side <= shape.max_side_length.raw / 65536.0 + 0.01);
            QT_FUZZ_CHECK(t.corners[0].x.raw + int64_t{t.corners[0].y.raw} <=
                          t.corners[i].x.raw + int64_t{t.corners[i].y.raw});
            QT_FUZZ_CHECK(t.sides[i].x1 == t.corners[i].x && t.sides[i].y1 == t.corners[i].y);
            QT_FUZZ_CHECK(t.sides[i].x2 == t.corners[j].x && t.sides[i].y2 == t.corners[j].y);
        }
        QT_FUZZ_CHECK(shoelace < 0);
    }

    void board_finish() {
        if (finishes_left-- <= 0) return;
        const bool again = board_finished;  // a second finish(): the first one's results stand
        const Status s = board.finish();
        if (s == Status::ok || s == Status::capacity_exceeded) board_finished = true;
        QT_FUZZ_CHECK(valid(s));
        if (!bm.mixed()) {
            if (bm.state == FrameModel::complete) {
                QT_FUZZ_CHECK(s == Status::ok || s == Status::capacity_exceeded);
                bm.state = FrameModel::finished;
            } else {
                QT_FUZZ_CHECK(s == Status::not_in_frame);
            }
        }
        if (s == Status::not_in_frame &&
            !again)  // no results (none of an earlier frame left standing)
            QT_FUZZ_CHECK(board.lines().line_count() == 0 && board.lines().segment_count() == 0 &&
                          board.quad_count() == 0);
        check_lines_and_quads();
        // The tracker follows the frame size of the board's frames (set_params resets it).
        const uint16_t w = board.lines().width(), h = board.lines().height();
        if (w != 0 && (w != tracker_w || h != tracker_h)) {
            qt::QuadTrackerParams p = qt::default_quad_tracker_params(w, h);
            if (turn_model) p.lines.model = qt::LineModel::turn;
            tracker.set_params(p);
            tracker_w = w;
            tracker_h = h;
            tracker_active = false;
        }
        const auto& lines = board.lines();
        check_tracked(
            tracker.step(lines.lines(), lines.line_count(), board.quads(), board.quad_count()));
    }

    // --- target ------------------------------------------------------------------------------
    void target_box(uint8_t mode) {
        int32_t x, y;
        if (mode % 4 == 0) {
            x = static_cast<int32_t>(in.u32());
            y = static_cast<int32_t>(in.u32());
        } else if (mode % 4 == 1) {  // near the ends of int32
            const uint8_t dx = in.u8(), dy = in.u8();
            x = dx & 1 ? INT32_MIN + (dx >> 1) : INT32_MAX - (dx >> 1);
            y = dy & 1 ? INT32_MIN + (dy >> 1) : INT32_MAX - (dy >> 1);
        } else {
            x = static_cast<int16_t>(in.u16());
            y = static_cast<int16_t>(in.u16());
        }
        // Sizes up to 255 + 255·(u8 & 1): past the largest box (16 blocks of up to 16 px).
        const uint16_t w = static_cast<uint16_t>(in.u8() * (mode & 4 ? 2 : 1)),
                       h = static_cast<uint16_t>(in.u8() * (mode & 4 ? 2 : 1));
        const Status s = target.set_target(x, y, w, h);
        // The model: a box is taken up to 16 blocks of up to 16 px a side, wherever it lies.
        const bool fits = w <= 16 * 16 && h <= 16 * 16;
        const bool refuse = w == 0 || h == 0 || !fits;
        QT_FUZZ_CHECK(s == (refuse ? Status::bad_size : Status::ok));
        if (!refuse) {
            target_pending = true;  // from the next frame begun
            target_captured = false;
            box_x = x;
            box_y = y;
            box_w = w;
            box_h = h;
        }
    }

    void target_begin(uint16_t w, uint16_t h) {
        const Status s = target.begin_frame(w, h, target_params);
        QT_FUZZ_CHECK(valid(s));
        const bool refuse = w == 0 || h == 0 || w > kTargetW || h > kTargetH;
        if (refuse) {
            QT_FUZZ_CHECK(s == Status::bad_size);
            tm = FrameModel{};
            return;
        }
        QT_FUZZ_CHECK(s == Status::ok || s == Status::previous_frame_incomplete);
        if (tm.state == FrameModel::in_frame) QT_FUZZ_CHECK(s == Status::previous_frame_incomplete);
        if (tm.state == FrameModel::idle || tm.state == FrameModel::complete)
            QT_FUZZ_CHECK(s == Status::ok);
        tm = FrameModel{};
        tm.state = FrameModel::in_frame;
        tm.w = w;
        tm.h = h;
        target_captured = target_pending;
    }

    void target_rows(uint8_t count, uint8_t lenmode) {
        const uint32_t n = rows_wanted(count, tm);
        const uint16_t bad = lenmode % 8 == 0 ? in.u16() : tm.w;
        for (uint32_t i = 0; i < n; ++i) {
            const uint16_t len = i + 1 == n ? bad : tm.w;
            pattern.row(tm.rows, row_buf, len, in);
            const Status s = target.push_row(row_buf, len);
            QT_FUZZ_CHECK(valid(s));
            if (tm.state != FrameModel::in_frame) {
                QT_FUZZ_CHECK(s == Status::not_in_frame);
            } else if (len != tm.w) {
                QT_FUZZ_CHECK(s == Status::bad_row_length);
                tm.state = FrameModel::abandoned;
            } else {
                QT_FUZZ_CHECK(s == Status::ok);
                if (++tm.rows == tm.h) tm.state = FrameModel::complete;
            }
        }
    }

    void target_finish() {
        if (finishes_left-- <= 0) return;
        const uint16_t fw = tm.w, fh = tm.h;
        qt::TargetFrame out;
        const Status s = target.finish(out);
        QT_FUZZ_CHECK(valid(s));
        QT_FUZZ_CHECK(out.features <= 96);
        if (s == Status::not_in_frame)
            QT_FUZZ_CHECK(!out.started && !out.tracking && out.features == 0);
        if (tm.state != FrameModel::complete) {
            QT_FUZZ_CHECK(s == Status::not_in_frame);  // rows missing: the frame goes on
            return;
        }
        const bool was_pending = target_pending && target_captured;
        if (was_pending) target_pending = false;
        tm = FrameModel{};
        if (was_pending) {
            const bool inside = box_x >= 0 && box_y >= 0 && int64_t{box_x} + box_w <= fw &&
                                int64_t{box_y} + box_h <= fh;
            if (!inside) {
                QT_FUZZ_CHECK(s == Status::bad_size && !out.tracking);
                return;
            }
            QT_FUZZ_CHECK(out.started && out.tracking);
        }
        QT_FUZZ_CHECK(s == Status::ok || s == Status::capacity_exceeded);
        QT_FUZZ_CHECK(
            std::strcmp(qt::homography_status_name(out.geometry.ransac.status), "unknown") != 0);
        if (out.geometry.ransac.status == qt::HomographyStatus::ok) {
            for (float m : out.geometry.ransac.h.m) QT_FUZZ_CHECK(std::isfinite(m));
            QT_FUZZ_CHECK(std::isfinite(out.geometry.ransac.reprojection_px) &&
                          out.geometry.ransac.reprojection_px >= 0);
            QT_FUZZ_CHECK(out.geometry.ransac.inliers <= out.geometry.matches);
        }
        if (out.tracking) {
            QT_FUZZ_CHECK(std::strcmp(qt::target_state_name(out.estimate.state), "unknown") != 0);
            if (out.estimate.state != qt::TargetState::lost)
                QT_FUZZ_CHECK(std::isfinite(out.estimate.x) && std::isfinite(out.estimate.y));
            const qt::TargetTrackerParams& p = target.params().tracker;
            const float most =
                p.max_radius_px > p.template_radius_px ? p.max_radius_px : p.template_radius_px;
            QT_FUZZ_CHECK(std::isfinite(out.window.radius) && out.window.radius >= 0 &&
                          out.window.radius <= most);
            if (out.window.radius > 0)
                QT_FUZZ_CHECK(std::isfinite(out.window.x) && std::isfinite(out.window.y));
            if (out.hit.found) QT_FUZZ_CHECK(out.hit.positions >= 1);
        }
    }

    void configure(uint8_t method, uint8_t flags) {
        target_params.tracker.method = static_cast<qt::TargetMethod>(method % 4);
        if (flags & 1) {
            tracker.reset();
            tracker_active = false;
        }
        turn_model = (flags & 2) != 0;
        tracker_w = tracker_h = 0;  // set_params at the next finish
    }

    void step() {
        const uint8_t op = in.u8() % 12;
        switch (op) {
            case 0: {
                const uint16_t w = size_from(in.u16(), kBoardW), h = size_from(in.u16(), kBoardH);
                const uint8_t flags = in.u8();
                params = qt::BoardParams{};
                if (flags & 1)
                    params.lines.edge_threshold = static_cast<uint16_t>(1 + in.u16() % 510);
                if (flags & 2)
                    params.lines.hough.threshold = static_cast<uint16_t>(1 + in.u8() % 255);
                if (flags & 4) params.quads.contrast = qt::Contrast::any;
                board_begin(w, h);
                break;
            }
            case 1: {
                const uint8_t count = in.u8();
                board_rows(count, in.u8());
                break;
            }
            case 2: {
                const uint8_t count = in.u8();
                board_words(count, in.u8());
                break;
            }
            case 3: board_finish(); break;
            case 4: {
                Pattern p;
                p.kind = in.u8() % 5;
                p.lo = in.u8();
                p.hi = in.u8();
                p.cx = in.u16() / 64.0;
                p.cy = in.u16() / 64.0;
                p.half_w = in.u8();
                p.half_h = in.u8();
                p.angle = in.u8() * (2 * kPi / 256);
                p.noise = in.u8();
                p.seed = in.u8();
                p.dx = static_cast<int8_t>(in.u8()) / 8.0;
                p.dy = static_cast<int8_t>(in.u8()) / 8.0;
                p.turn = static_cast<int8_t>(in.u8()) * (2 * kPi / 2048);
                pattern = p;
                break;
            }
            case 5: target_box(in.u8()); break;
            case 6: {
                const uint16_t w = size_from(in.u16(), kTargetW), h = size_from(in.u16(), 240);
                target_begin(w, h);
                break;
            }
            case 7: {
                const uint8_t count = in.u8();
                target_rows(count, in.u8());
                break;
            }
            case 8: target_finish(); break;
            case 9: {
                const uint8_t method = in.u8();
                configure(method, in.u8());
                break;
            }
            case 10: {
                const uint16_t w = size_from(in.u16(), kBoardW), h = size_from(in.u16(), kBoardH);
                const uint8_t how = in.u8();
                board_begin(w, h);
                if (how & 1)
                    board_words(0, 1, 0);
                else
                    board_rows(0, 1);
                board_finish();
                pattern.move();
                break;
            }
            default: {
                const uint16_t w = size_from(in.u16(), kTargetW), h = size_from(in.u16(), 240);
                target_begin(w, h);
                target_rows(0, 1);
                target_finish();
                pattern.move();
            }
        }
    }
};

// Each input starts from freshly constructed objects (in the same static storage), so that
// an input replays alone exactly as it ran.
template <class T>
void renew(T& object) {
    object.~T();
    new (&object) T();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    renew(board);
    renew(tracker);
    renew(target);
    Run run(Program{data, size});
    for (int ops = 0;
         ops < kOpBudget && !run.in.done() && run.pixels_left > 0 && run.finishes_left > 0; ++ops)
        run.step();
    return 0;
}
