/* The C interface (core/api/quadtrack_c.h) used from C11, as firmware written in C would: no
 * Catch2, every failed check printed, exit status non-zero on any failure. Compiling this file
 * as C (with -Wpedantic) is also the check that the header is valid C.
 *
 * The scene, worked by hand. A 320 x 240 frame of grey 40 with a filled rectangle of grey 200
 * over pixel columns 80..239 and rows 60..179. Pixel centres are at integer coordinates, so a
 * step between columns 79 and 80 lies at x = 79.5; the true corners are
 *   top-left (79.5, 59.5), bottom-left (79.5, 179.5), bottom-right (239.5, 179.5),
 *   top-right (239.5, 59.5)
 * which is also detect's order: anti-clockwise as seen, corner 0 with the smallest x + y.
 * Why the detector lands on the step and not on a pixel centre (gradient_word.h,
 * core/lines/edge_stage.h): on a row through the rectangle gx = p(x+1) - p(x-1) is 160 at
 * x = 79 and at x = 80 and 0 elsewhere, a plateau two pixels wide. NMS keeps a pixel whose
 * magnitude m is greater than the neighbour ahead (along +gradient) and not less than the one
 * behind: x = 79 fails (160 > 160 is false), x = 80 passes (160 > 0, 160 >= 160). Its sub-pixel
 * offset is the vertex of the parabola through (behind, m, ahead) = (160, 160, 0) at -1, 0, +1:
 * (behind - ahead) / (2 (behind - 2m + ahead)) = 160 / (2 * -160) = -1/2 step, so the edge
 * point sits at 80 - 0.5 = 79.5. The right side is the mirror image (gx = -160 at 239 and 240,
 * the gradient points to -x, x = 239 is kept, offset +1/2 towards +x): 239.5. Rows likewise:
 * 59.5 and 179.5. Every edge point of a side lies exactly on the side, so the fitted lines
 * and their crossings are exact up to the fixed-point steps; 1 px is the tolerance asked of
 * the interface (a corner mixing two sides' gradients must not pull a line off by more).
 * The sides' lines (segment.h: theta is the normal's direction from the origin, rho >= 0):
 *   side 0, left  x = 79.5:  theta 0,   rho 79.5,  inside at +normal: bright_side +1
 *   side 1, bottom y = 179.5: theta 90, rho 179.5, inside at -normal: bright_side -1
 *   side 2, right x = 239.5: theta 0,   rho 239.5, bright_side -1
 *   side 3, top   y = 59.5:  theta 90,  rho 59.5,  bright_side +1
 * Magnitudes: 160 along the sides, 320 only at the four inner corner pixels (|gx| = |gy| =
 * 160); the longest side is 160 px. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "api/quadtrack_c.h"

#define W 320
#define H 240
#define BACKGROUND 40
#define BOARD 200
#define ONE_PX 65536 /* q16.16 */

static unsigned failures;

static void check(int ok, const char* what, int line) {
    if (!ok) {
        ++failures;
        printf("test_c_api.c:%d: FAILED: %s\n", line, what);
    }
}
#define CHECK(cond) check((cond) != 0, #cond, __LINE__)

static void check_status(qt_status got, qt_status want, const char* what, int line) {
    if (got != want) {
        ++failures;
        printf("test_c_api.c:%d: FAILED: %s gave %d (%s), expected %d (%s)\n", line, what, (int)got,
               qt_status_name(got), (int)want, qt_status_name(want));
    }
}
#define CHECK_STATUS(expr, want) check_status((expr), (want), #expr, __LINE__)

/* A rectangle of pixel columns left..right and rows top..bottom (inclusive). */
typedef struct rect {
    int left, top, right, bottom;
} rect;

static uint8_t image[H][W];

static void render(rect r) {
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            image[y][x] =
                (x >= r.left && x <= r.right && y >= r.top && y <= r.bottom) ? BOARD : BACKGROUND;
}

/* The rectangle's true corners in detect's order, q16.16: its outline lies half a pixel
 * outside its outer pixel centres, i.e. at (2 c -+ 1) / 2. */
static void truth(rect r, qt_point c[4]) {
    const int32_t half = ONE_PX / 2;
    const int32_t l = (2 * r.left - 1) * half, ri = (2 * r.right + 1) * half;
    const int32_t t = (2 * r.top - 1) * half, b = (2 * r.bottom + 1) * half;
    c[0].x = l;
    c[0].y = t;
    c[1].x = l;
    c[1].y = b;
    c[2].x = ri;
    c[2].y = b;
    c[3].x = ri;
    c[3].y = t;
}

static int64_t distance2(qt_point a, qt_point b) {
    const int64_t dx = (int64_t)a.x - b.x, dy = (int64_t)a.y - b.y;
    return dx * dx + dy * dy;
}

/* Every corner within 1 px of the truth, in the same order; prints both on failure. */
static void check_corners(const qt_point got[4], const qt_point want[4], const char* what,
                          int line) {
    int ok = 1;
    for (int i = 0; i < 4; ++i) ok = ok && distance2(got[i], want[i]) <= (int64_t)ONE_PX * ONE_PX;
    if (ok) return;
    ++failures;
    printf("test_c_api.c:%d: FAILED: %s corners beyond 1 px:\n", line, what);
    for (int i = 0; i < 4; ++i)
        printf("  corner %d: got (%.3f, %.3f), expected (%.3f, %.3f)\n", i, got[i].x / 65536.0,
               got[i].y / 65536.0, want[i].x / 65536.0, want[i].y / 65536.0);
}

/* |a - b| of two binary angles, the short way round. */
static uint32_t angle_diff(uint32_t a, uint32_t b) {
    const uint32_t d = a - b;
    return d > 0x80000000u ? 0u - d : d;
}

static qt_status detect_image(qt_detector* det) {
    CHECK_STATUS(qt_begin_frame(det, W, H), QT_OK);
    for (int y = 0; y < H; ++y) CHECK_STATUS(qt_push_row(det, image[y], W), QT_OK);
    return qt_finish(det);
}

static qt_detector det;
static qt_tracker trk;

/* The image in tracking mode: begun in the bands the tracker planned, then tracked. */
static void track_in_bands(qt_tracked_quad* t) {
    CHECK_STATUS(qt_begin_tracked_frame(&det, &trk, W, H), QT_OK);
    for (int y = 0; y < H; ++y) CHECK_STATUS(qt_push_row(&det, image[y], W), QT_OK);
    CHECK_STATUS(qt_finish(&det), QT_OK);
    CHECK_STATUS(qt_track(&trk, &det, t), QT_OK);
}

/* The rectangle of the tracking tests in frame k: 160 x 120 px, moving 2 px right a frame. */
static rect moving_rect(int k) { return (rect){80 + 2 * k, 60, 239 + 2 * k, 179}; }

/* Renders frame k of the moving rectangle and writes its corners' truth to want. */
static void render_moving(int k, qt_point want[4]) {
    const rect r = moving_rect(k);
    truth(r, want);
    render(r);
}

/* The hand-worked frame through the camera path: four lines, one quadrangle, corners and
 * sides as worked out at the top. */
static void test_detect(const qt_config* cfg) {
    const rect r = {80, 60, 239, 179};
    qt_point want[4];
    qt_quad q;
    truth(r, want);
    render(r);
    CHECK_STATUS(qt_detector_init(&det, cfg), QT_OK);
    CHECK_STATUS(detect_image(&det), QT_OK);
    CHECK(qt_line_count(&det) == 4);
    CHECK(qt_quad_count(&det) == 1);
    if (qt_quad_count(&det) < 1) return;
    CHECK_STATUS(qt_get_quad(&det, 0, &q), QT_OK);
    check_corners(q.corners, want, "detected quadrangle", __LINE__);
    printf("detected corners: (%.3f, %.3f) (%.3f, %.3f) (%.3f, %.3f) (%.3f, %.3f), score %.3f\n",
           q.corners[0].x / 65536.0, q.corners[0].y / 65536.0, q.corners[1].x / 65536.0,
           q.corners[1].y / 65536.0, q.corners[2].x / 65536.0, q.corners[2].y / 65536.0,
           q.corners[3].x / 65536.0, q.corners[3].y / 65536.0, q.score / 65536.0);
    /* The whole outline is edge: the sides cover (nearly) all of the perimeter. */
    CHECK(q.score > ONE_PX * 9 / 10 && q.score <= ONE_PX);

    {
        const uint32_t deg90 = 0x40000000u, one_deg = 11930465u; /* 2^32 / 360, rounded down */
        const uint32_t theta[4] = {0, deg90, 0, deg90};
        const int32_t rho[4] = {want[0].x, want[1].y, want[2].x, want[0].y};
        const int8_t bright[4] = {1, -1, -1, 1};
        for (int i = 0; i < 4; ++i) {
            qt_line l;
            CHECK(q.lines[i] < qt_line_count(&det));
            CHECK_STATUS(qt_get_line(&det, q.lines[i], &l), QT_OK);
            CHECK(angle_diff(l.theta, theta[i]) <= one_deg);
            CHECK(l.rho - rho[i] <= ONE_PX / 2 && rho[i] - l.rho <= ONE_PX / 2);
            CHECK(l.bright_side == bright[i]);
            CHECK(l.points >= 100); /* sides of 120 and 160 px, one edge point per pixel */
        }
    }
}

/* The gradient word of (gx, gy) from its documented layout (gradient_word.h): gx [8:0], gy
 * [17:9] (9-bit two's complement), L1 magnitude [26:18], direction bin [30:27], bin k centred
 * on k * 22.5 degrees from +x towards +y. This scene has only the eight directions that are
 * multiples of 45 degrees (axis gradients on the sides, |gx| = |gy| at the corner pixels);
 * anything else sets *ok to 0. */
static qt_gradient_word word_of(int gx, int gy, int* ok) {
    const int sx = (gx > 0) - (gx < 0), sy = (gy > 0) - (gy < 0);
    static const uint32_t bin[3][3] = {/* [sy + 1][sx + 1] */
                                       {10, 12, 14},
                                       {8, 0, 0},
                                       {6, 4, 2}};
    const uint32_t ax = (uint32_t)(gx < 0 ? -gx : gx), ay = (uint32_t)(gy < 0 ? -gy : gy);
    if (ax != 0 && ay != 0 && ax != ay) *ok = 0;
    return ((uint32_t)gx & 0x1FFu) | (((uint32_t)gy & 0x1FFu) << 9) | ((ax + ay) << 18) |
           (bin[sy + 1][sx + 1] << 27);
}

/* The same frame through the FPGA path: gradient words made here from the image (central
 * differences, borders replicated: docs/gradient.md), pushed row by row. */
static void test_gradient_path(const qt_config* cfg) {
    static qt_gradient_word words[W];
    const rect r = {80, 60, 239, 179};
    qt_point want[4];
    qt_quad q;
    int ok = 1;
    truth(r, want);
    render(r);
    CHECK_STATUS(qt_detector_init(&det, cfg), QT_OK);
    CHECK_STATUS(qt_begin_frame(&det, W, H), QT_OK);
    for (int y = 0; y < H; ++y) {
        const int up = y > 0 ? y - 1 : 0, down = y < H - 1 ? y + 1 : H - 1;
        for (int x = 0; x < W; ++x) {
            const int left = x > 0 ? x - 1 : 0, right = x < W - 1 ? x + 1 : W - 1;
            words[x] =
                word_of(image[y][right] - image[y][left], image[down][x] - image[up][x], &ok);
        }
        CHECK_STATUS(qt_push_gradient_row(&det, words, W), QT_OK);
    }
    CHECK(ok);
    CHECK_STATUS(qt_finish(&det), QT_OK);
    CHECK(qt_line_count(&det) == 4);
    CHECK(qt_quad_count(&det) == 1);
    if (qt_quad_count(&det) < 1) return;
    CHECK_STATUS(qt_get_quad(&det, 0, &q), QT_OK);
    check_corners(q.corners, want, "quadrangle from gradient words", __LINE__);
}

/* The rectangle moving 2 px to the right per frame for 10 frames: the track starts on frame 0
 * and follows it with every side seen; corners within 1 px of the truth every frame. */
static void test_track(const qt_config* cfg) {
    int32_t worst = 0; /* largest coordinate error over all frames, q16.16 */
    CHECK_STATUS(qt_detector_init(&det, cfg), QT_OK);
    CHECK_STATUS(qt_tracker_init(&trk, cfg, W, H), QT_OK);
    for (int k = 0; k < 10; ++k) {
        qt_point want[4];
        qt_tracked_quad t;
        char what[40];
        render_moving(k, want);
        CHECK_STATUS(detect_image(&det), QT_OK);
        CHECK_STATUS(qt_track(&trk, &det, &t), QT_OK);
        CHECK(t.state == (k == 0 ? QT_TRACK_STARTED : QT_TRACK_TRACKING));
        CHECK(t.track_id == 1);
        CHECK(t.age == (uint32_t)k);
        CHECK(t.detected == 0x0F);
        CHECK(t.lost_reason == QT_LOST_NONE);
        snprintf(what, sizeof what, "tracked frame %d", k);
        check_corners(t.corners, want, what, __LINE__);
        for (int i = 0; i < 4; ++i) {
            const int32_t ex = t.corners[i].x - want[i].x, ey = t.corners[i].y - want[i].y;
            if (ex > worst || -ex > worst) worst = ex > 0 ? ex : -ex;
            if (ey > worst || -ey > worst) worst = ey > 0 ? ey : -ey;
        }
        /* Each side's line runs through its two corners. */
        CHECK(t.sides[0].x1 == t.corners[0].x && t.sides[0].y1 == t.corners[0].y);
        CHECK(t.sides[3].x2 == t.corners[0].x && t.sides[3].y2 == t.corners[0].y);
    }
    printf("tracked 10 frames, largest corner coordinate error %.4f px\n", worst / 65536.0);
}

/* Tracking mode: the same moving rectangle through qt_begin_tracked_frame with full_every 4.
 * Frame 0 is whole (no track yet); after it every frame runs in the bands planned from the one
 * before, but every fourth (frames 4 and 8: the fourth after three banded ones); the track
 * keeps every side, and each frame's corners lie within 1 px of the truth and within 1/16 px of
 * the whole frame's (the run without tracking mode, frame by frame). */
static void test_tracking_mode(const qt_config* defaults) {
    qt_config cfg = *defaults;
    qt_point whole[10][4];
    CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
    CHECK_STATUS(qt_tracker_init(&trk, &cfg, W, H), QT_OK);
    for (int k = 0; k < 10; ++k) {
        qt_tracked_quad t;
        render(moving_rect(k));
        track_in_bands(&t); /* tracking mode off: every frame whole */
        CHECK(t.banded == 0);
        for (int i = 0; i < 4; ++i) whole[k][i] = t.corners[i];
    }
    cfg.tracking_mode = QT_TRACKING_MODE_ON;
    cfg.full_every = 4;
    CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
    CHECK_STATUS(qt_tracker_init(&trk, &cfg, W, H), QT_OK);
    for (int k = 0; k < 10; ++k) {
        qt_point want[4];
        qt_tracked_quad t;
        char what[40];
        render_moving(k, want);
        track_in_bands(&t);
        CHECK(t.banded == (k % 4 != 0));
        CHECK(t.track_id == 1);
        CHECK(t.detected == 0x0F);
        snprintf(what, sizeof what, "tracking mode, frame %d", k);
        check_corners(t.corners, want, what, __LINE__);
        for (int i = 0; i < 4; ++i)
            CHECK(distance2(t.corners[i], whole[k][i]) <= (int64_t)(ONE_PX / 16) * (ONE_PX / 16));
    }
    /* A reset drops the bands with the track: the next frame is whole. */
    {
        qt_tracked_quad t;
        CHECK_STATUS(qt_tracker_reset(&trk), QT_OK);
        track_in_bands(&t);
        CHECK(t.banded == 0);
        CHECK(t.state == QT_TRACK_STARTED && t.track_id == 2);
    }
    CHECK_STATUS(qt_begin_tracked_frame(NULL, &trk, W, H), QT_NULL_POINTER);
    CHECK_STATUS(qt_begin_tracked_frame(&det, NULL, W, H), QT_NULL_POINTER);
}

/* The config's fields reach the chain: each changed value has an effect worked out from the
 * scene. */
static void test_config_applied(const qt_config* defaults) {
    const rect r = {80, 60, 239, 179};
    qt_config cfg;
    render(r);

    /* Every side's magnitude is 160 grey levels: a threshold of 161 leaves only the four
     * corner pixels, too few for a line. */
    cfg = *defaults;
    cfg.edge_threshold = 161;
    CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
    CHECK_STATUS(detect_image(&det), QT_OK);
    CHECK(qt_line_count(&det) == 0);

    /* The longest side is 160 px. */
    cfg = *defaults;
    cfg.min_line_length = 161;
    CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
    CHECK_STATUS(detect_image(&det), QT_OK);
    CHECK(qt_line_count(&det) == 0);

    /* The board is bright: asking for a dark one keeps the lines and refuses the quadrangle. */
    cfg = *defaults;
    cfg.contrast = QT_CONTRAST_DARK;
    CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
    CHECK_STATUS(detect_image(&det), QT_OK);
    CHECK(qt_line_count(&det) == 4);
    CHECK(qt_quad_count(&det) == 0);
    cfg.contrast = QT_CONTRAST_ANY;
    CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
    CHECK_STATUS(detect_image(&det), QT_OK);
    CHECK(qt_quad_count(&det) == 1);

    /* Gate of 1 px: on the frame after the start the filters know no velocity yet, so the
     * prediction is frame 0's board; the left and right sides moved 2 px and fall outside the
     * gate, the top and bottom (sides 3 and 1) lie on the same lines and match. The left and
     * right are then taken back from the whole detection, which agrees with the top and bottom
     * (quad_tracker.h, rule 2b): every side detected. */
    cfg = *defaults;
    cfg.gate_distance_px = 1;
    CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
    CHECK_STATUS(qt_tracker_init(&trk, &cfg, W, H), QT_OK);
    for (int k = 0; k < 2; ++k) {
        const rect moved = moving_rect(k);
        qt_tracked_quad t;
        render(moved);
        CHECK_STATUS(detect_image(&det), QT_OK);
        CHECK_STATUS(qt_track(&trk, &det, &t), QT_OK);
        CHECK(t.state == (k == 0 ? QT_TRACK_STARTED : QT_TRACK_TRACKING));
        CHECK(t.detected == 0x0F);
    }
}

/* Defaults as documented (line_detector.h, hough.h, quad_rules.h, quad_tracker.h,
 * docs/tracking.md), and the range of every field. */
static void test_config(void) {
    qt_config cfg, bad;
    qt_config_default(&cfg, W, H);
    CHECK(cfg.edge_threshold == 40);
    CHECK(cfg.hough_threshold == 12);
    CHECK(cfg.min_line_length == 20);
    CHECK(cfg.max_line_gap == 4);
    CHECK(cfg.contrast == QT_CONTRAST_BRIGHT);
    CHECK(cfg.model == QT_MODEL_PAPER);
    CHECK(cfg.filters == 3);
    CHECK(cfg.max_predicted == 15);
    CHECK(cfg.gate_angle_deg == 8);
    CHECK(cfg.gate_distance_px == 12);
    CHECK(cfg.tracking_mode == QT_TRACKING_MODE_OFF);
    CHECK(cfg.band_half_width_px == 8);
    CHECK(cfg.full_every == 16);
    CHECK_STATUS(qt_config_check(&cfg), QT_OK);
    qt_config_default(NULL, W, H); /* no crash */
    CHECK_STATUS(qt_config_check(NULL), QT_NULL_POINTER);

#define RANGE(field, lo, hi)                                \
    do {                                                    \
        bad = cfg;                                          \
        bad.field = (lo);                                   \
        CHECK_STATUS(qt_config_check(&bad), QT_OK);         \
        bad.field = (hi);                                   \
        CHECK_STATUS(qt_config_check(&bad), QT_OK);         \
        bad.field = (hi) + 1;                               \
        CHECK_STATUS(qt_config_check(&bad), QT_BAD_CONFIG); \
    } while (0)
#define BELOW(field, lo)                                    \
    do {                                                    \
        bad = cfg;                                          \
        bad.field = (lo)-1;                                 \
        CHECK_STATUS(qt_config_check(&bad), QT_BAD_CONFIG); \
    } while (0)
    RANGE(edge_threshold, 1, 510);
    BELOW(edge_threshold, 1);
    RANGE(hough_threshold, 1, 255);
    BELOW(hough_threshold, 1);
    RANGE(min_line_length, 2, 2048);
    BELOW(min_line_length, 2);
    RANGE(max_line_gap, 0, 255);
    RANGE(contrast, 0, 2);
    RANGE(model, 0, 1);
    RANGE(filters, 1, 3);
    BELOW(filters, 1);
    RANGE(gate_angle_deg, 0, 90);
    RANGE(gate_distance_px, 0, 1000);
    RANGE(tracking_mode, 0, 1);
    RANGE(band_half_width_px, 2, 64);
    BELOW(band_half_width_px, 2);
    BELOW(full_every, 2);
#undef RANGE
#undef BELOW

    /* A refused config leaves objects that refuse to run until initialised again. */
    bad = cfg;
    bad.filters = 4;
    {
        qt_tracked_quad t;
        CHECK_STATUS(qt_detector_init(&det, &bad), QT_BAD_CONFIG);
        CHECK_STATUS(qt_begin_frame(&det, W, H), QT_BAD_CONFIG);
        CHECK_STATUS(qt_finish(&det), QT_BAD_CONFIG);
        CHECK_STATUS(qt_detector_init(&det, NULL), QT_NULL_POINTER);
        CHECK_STATUS(qt_begin_frame(&det, W, H), QT_BAD_CONFIG);
        CHECK_STATUS(qt_tracker_init(&trk, &bad, W, H), QT_BAD_CONFIG);
        CHECK_STATUS(qt_tracker_init(&trk, NULL, W, H), QT_NULL_POINTER);
        CHECK_STATUS(qt_tracker_init(&trk, &cfg, W + 1, H), QT_BAD_SIZE);
        CHECK_STATUS(qt_tracker_init(&trk, &cfg, W, 0), QT_BAD_SIZE);
        CHECK_STATUS(qt_detector_init(&det, &cfg), QT_OK);
        render((rect){80, 60, 239, 179});
        CHECK_STATUS(detect_image(&det), QT_OK);
        CHECK_STATUS(qt_track(&trk, &det, &t), QT_BAD_CONFIG);
        CHECK_STATUS(qt_tracker_reset(&trk), QT_BAD_CONFIG);
        CHECK_STATUS(qt_begin_tracked_frame(&det, &trk, W, H), QT_BAD_CONFIG);
        CHECK_STATUS(qt_tracker_init(&trk, &cfg, W, H), QT_OK);
        CHECK_STATUS(qt_track(&trk, &det, &t), QT_OK);
        CHECK(t.state == QT_TRACK_STARTED);
    }
}

/* Sizes, row lengths, call order, NULL pointers, indices. */
static void test_errors(const qt_config* cfg) {
    static uint8_t row[W + 1];
    qt_line l;
    qt_quad q;
    qt_tracked_quad t;

    CHECK_STATUS(qt_detector_init(&det, cfg), QT_OK);
    CHECK_STATUS(qt_tracker_init(&trk, cfg, W, H), QT_OK);

    /* Frame sizes: 320 x 240 is the most the C interface serves. */
    CHECK_STATUS(qt_begin_frame(&det, W + 1, H), QT_BAD_SIZE);
    CHECK_STATUS(qt_begin_frame(&det, W, H + 1), QT_BAD_SIZE);
    CHECK_STATUS(qt_begin_frame(&det, 0, H), QT_BAD_SIZE);
    CHECK_STATUS(qt_begin_frame(&det, W, 0), QT_BAD_SIZE);
    CHECK_STATUS(qt_begin_frame(&det, 640, 480), QT_BAD_SIZE);
    CHECK_STATUS(qt_push_row(&det, row, W), QT_NOT_IN_FRAME); /* no frame after a refusal */
    CHECK_STATUS(qt_finish(&det), QT_NOT_IN_FRAME);
    CHECK_STATUS(qt_track(&trk, &det, &t), QT_NOT_IN_FRAME);
    CHECK(t.state == QT_TRACK_NONE);
    CHECK_STATUS(qt_begin_frame(&det, 1, 1), QT_OK); /* smallest */
    CHECK_STATUS(qt_push_row(&det, row, 1), QT_OK);
    CHECK_STATUS(qt_finish(&det), QT_OK);
    CHECK(qt_line_count(&det) == 0 && qt_quad_count(&det) == 0);

    /* A row of the wrong length abandons the frame. */
    CHECK_STATUS(qt_begin_frame(&det, W, H), QT_OK);
    CHECK_STATUS(qt_push_row(&det, row, W), QT_OK);
    CHECK_STATUS(qt_push_row(&det, row, W - 1), QT_BAD_ROW_LENGTH);
    CHECK_STATUS(qt_push_row(&det, row, W), QT_NOT_IN_FRAME);
    CHECK_STATUS(qt_finish(&det), QT_NOT_IN_FRAME);
    CHECK_STATUS(qt_begin_frame(&det, W, H), QT_OK);
    CHECK_STATUS(qt_push_row(&det, row, W + 1), QT_BAD_ROW_LENGTH);
    CHECK_STATUS(qt_begin_frame(&det, W, H), QT_OK);
    CHECK_STATUS(qt_push_gradient_row(&det, NULL, W), QT_NULL_POINTER);

    /* qt_finish before the last row: refused, the frame stays open and completes later; no
     * results (and no tracking) in between. */
    render((rect){80, 60, 239, 179});
    CHECK_STATUS(qt_begin_frame(&det, W, H), QT_PREVIOUS_FRAME_INCOMPLETE); /* the one above */
    for (int y = 0; y < 100; ++y) CHECK_STATUS(qt_push_row(&det, image[y], W), QT_OK);
    CHECK_STATUS(qt_finish(&det), QT_NOT_IN_FRAME);
    CHECK(qt_line_count(&det) == 0 && qt_quad_count(&det) == 0);
    CHECK_STATUS(qt_get_quad(&det, 0, &q), QT_BAD_INDEX);
    CHECK_STATUS(qt_track(&trk, &det, &t), QT_NOT_IN_FRAME);
    for (int y = 100; y < H; ++y) CHECK_STATUS(qt_push_row(&det, image[y], W), QT_OK);
    CHECK_STATUS(qt_push_row(&det, image[0], W), QT_NOT_IN_FRAME); /* one row too many */
    CHECK_STATUS(qt_finish(&det), QT_OK);
    CHECK(qt_quad_count(&det) == 1);
    CHECK_STATUS(qt_finish(&det), QT_NOT_IN_FRAME); /* finished already */
    CHECK(qt_quad_count(&det) == 1);                /* results kept */

    /* A new frame abandoning an incomplete one. */
    CHECK_STATUS(qt_begin_frame(&det, W, H), QT_OK);
    CHECK_STATUS(qt_push_row(&det, image[0], W), QT_OK);
    CHECK(qt_quad_count(&det) == 0);
    CHECK_STATUS(qt_begin_frame(&det, W, H), QT_PREVIOUS_FRAME_INCOMPLETE);
    for (int y = 0; y < H; ++y) CHECK_STATUS(qt_push_row(&det, image[y], W), QT_OK);
    CHECK_STATUS(qt_finish(&det), QT_OK);
    CHECK(qt_quad_count(&det) == 1);

    /* Indices. */
    CHECK_STATUS(qt_get_line(&det, 3, &l), QT_OK);
    CHECK_STATUS(qt_get_line(&det, qt_line_count(&det), &l), QT_BAD_INDEX);
    CHECK_STATUS(qt_get_line(&det, 65535, &l), QT_BAD_INDEX);
    CHECK_STATUS(qt_get_quad(&det, 0, &q), QT_OK);
    CHECK_STATUS(qt_get_quad(&det, 1, &q), QT_BAD_INDEX);
    CHECK_STATUS(qt_get_quad(&det, 65535, &q), QT_BAD_INDEX);

    /* NULL pointers. */
    CHECK_STATUS(qt_detector_init(NULL, cfg), QT_NULL_POINTER);
    CHECK_STATUS(qt_begin_frame(NULL, W, H), QT_NULL_POINTER);
    CHECK_STATUS(qt_push_row(NULL, row, W), QT_NULL_POINTER);
    CHECK_STATUS(qt_push_row(&det, NULL, W), QT_NULL_POINTER);
    CHECK_STATUS(qt_push_gradient_row(NULL, NULL, W), QT_NULL_POINTER);
    CHECK_STATUS(qt_finish(NULL), QT_NULL_POINTER);
    CHECK(qt_line_count(NULL) == 0);
    CHECK(qt_quad_count(NULL) == 0);
    CHECK_STATUS(qt_get_line(NULL, 0, &l), QT_NULL_POINTER);
    CHECK_STATUS(qt_get_line(&det, 0, NULL), QT_NULL_POINTER);
    CHECK_STATUS(qt_get_quad(NULL, 0, &q), QT_NULL_POINTER);
    CHECK_STATUS(qt_get_quad(&det, 0, NULL), QT_NULL_POINTER);
    CHECK_STATUS(qt_tracker_init(NULL, cfg, W, H), QT_NULL_POINTER);
    CHECK_STATUS(qt_tracker_reset(NULL), QT_NULL_POINTER);
    CHECK_STATUS(qt_track(NULL, &det, &t), QT_NULL_POINTER);
    CHECK_STATUS(qt_track(&trk, NULL, &t), QT_NULL_POINTER);
    CHECK_STATUS(qt_track(&trk, &det, NULL), QT_NULL_POINTER);
    /* The detector's finished frame survived all of that. */
    CHECK(qt_quad_count(&det) == 1);
    CHECK_STATUS(qt_track(&trk, &det, &t), QT_OK);
    CHECK(t.state == QT_TRACK_STARTED && t.track_id == 1);
    CHECK_STATUS(qt_tracker_reset(&trk), QT_OK);
    CHECK_STATUS(qt_track(&trk, &det, &t), QT_OK);
    CHECK(t.state == QT_TRACK_STARTED && t.track_id == 2);
}

/* Status numbers (status.h's order) and names. */
static void test_names(void) {
    static const qt_status all[] = {QT_OK,
                                    QT_BAD_SIZE,
                                    QT_BAD_ROW_LENGTH,
                                    QT_NOT_IN_FRAME,
                                    QT_PREVIOUS_FRAME_INCOMPLETE,
                                    QT_CAPACITY_EXCEEDED,
                                    QT_NULL_POINTER,
                                    QT_BAD_INDEX,
                                    QT_BAD_CONFIG};
    const size_t n = sizeof all / sizeof all[0];
    CHECK(QT_OK == 0 && QT_BAD_SIZE == 1 && QT_BAD_ROW_LENGTH == 2 && QT_NOT_IN_FRAME == 3 &&
          QT_PREVIOUS_FRAME_INCOMPLETE == 4 && QT_CAPACITY_EXCEEDED == 5);
    CHECK(strcmp(qt_status_name(QT_OK), "ok") == 0);
    for (size_t i = 0; i < n; ++i) {
        const char* a = qt_status_name(all[i]);
        CHECK(a != NULL && a[0] != 0 && strcmp(a, "unknown status") != 0);
        for (size_t j = 0; j < i; ++j) CHECK(strcmp(a, qt_status_name(all[j])) != 0);
    }
    CHECK(qt_track_lost_name(QT_LOST_NONE) == NULL);
    CHECK(strcmp(qt_track_lost_name(QT_LOST_SIDE_UNSEEN), "side_unseen") == 0);
    CHECK(strcmp(qt_track_lost_name(QT_LOST_SHAPE), "shape") == 0);
    CHECK(strcmp(qt_track_lost_name(QT_LOST_SATURATED), "saturated") == 0);
    CHECK(strcmp(qt_track_lost_name(QT_LOST_DETECTION_DISAGREES), "detection_disagrees") == 0);
    CHECK(qt_track_lost_name(5) == NULL);
}

int main(void) {
    qt_config cfg;
    qt_config_default(&cfg, W, H);
    printf("qt_detector %u B, qt_tracker %u B\n", (unsigned)sizeof(qt_detector),
           (unsigned)sizeof(qt_tracker));
    test_names();
    test_config();
    test_detect(&cfg);
    test_gradient_path(&cfg);
    test_track(&cfg);
    test_tracking_mode(&cfg);
    test_config_applied(&cfg);
    test_errors(&cfg);
    if (failures != 0) {
        printf("%u check(s) failed\n", failures);
        return 1;
    }
    printf("all checks passed\n");
    return 0;
}
