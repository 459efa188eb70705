/* The C interface of the detection and tracking chain, for firmware written in C: the board
 * detector (board_detector.h) and the quadrangle tracker (quad_tracker.h) behind plain
 * functions and structs. Valid C99, C11 and C++; implemented in quadtrack_c.cpp.
 *
 * QVGA ONLY: frames up to QT_MAX_WIDTH x QT_MAX_HEIGHT (320 x 240) pixels, with the capacities
 * of qt::BoardDetectorQvga (32 lines, 4 quadrangles). C++ users who need other frame sizes or
 * capacities instantiate the templates (qt::BoardDetector, qt::LineDetector) directly.
 *
 * No heap: the caller owns the storage of every object (qt_detector, qt_tracker), typically
 * as a static variable; its size is a constant of this header. Nothing here allocates, throws
 * or uses floating point. The functions are not reentrant on one object; distinct objects are
 * independent.
 *
 *   static qt_detector det;                      // QT_DETECTOR_BYTES of RAM
 *   static qt_tracker trk;                       // QT_TRACKER_BYTES of RAM
 *   qt_config cfg;
 *   qt_config_default(&cfg, 320, 240);           // then change what the field needs
 *   qt_detector_init(&det, &cfg);
 *   qt_tracker_init(&trk, &cfg, 320, 240);
 *   each frame:
 *     qt_begin_frame(&det, 320, 240);
 *     for each camera row: qt_push_row(&det, row, 320);   // or qt_push_gradient_row
 *     qt_finish(&det);                           // lines, then quadrangles
 *     qt_track(&trk, &det, &tracked);            // tracked.corners, tracked.state
 *
 * Units of every result:
 *   - positions and lengths: int32_t q16.16 pixels, value / 65536 px; the origin is the centre
 *     of pixel (0, 0), x to the right, y down. A step edge between pixel columns 79 and 80
 *     lies at x = 79.5.
 *   - line directions: uint32_t binary angles, 2^32 units per turn (degrees = value * 360 /
 *     2^32); a line's theta is the direction of its normal from the origin, [0, 360) degrees,
 *     measured from +x towards +y (clockwise on screen, since y is down).
 *   - fractions (a quadrangle's score): int32_t q16.16, 65536 = 1.
 *
 * Errors: every function that can fail returns a qt_status. NULL pointers give QT_NULL_POINTER
 * and out-of-range indices QT_BAD_INDEX; nothing is written through a NULL pointer. An object
 * must have gone through its *_init function before any other call on it (the storage is
 * opaque bytes; an object never initialised cannot be told apart from one that was). */
#ifndef QUADTRACK_C_H
#define QUADTRACK_C_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Largest frame, pixels, and the result capacities (qt::BoardDetectorQvga's). */
#define QT_MAX_WIDTH 320
#define QT_MAX_HEIGHT 240
#define QT_MAX_LINES 32
#define QT_MAX_QUADS 4

/* Storage sizes, bytes: the C++ objects (BoardDetectorQvga; QuadTracker and TrackingMode, with
 * a few flags) on x86-64, AArch64 and Cortex-M4 with room to spare; quadtrack_c.cpp
 * static_asserts that they fit, alignment 8. The margin keeps this ABI across small changes
 * inside the C++ objects; a larger one stops the build at those static_asserts, and then these
 * constants (and every C object file using them) change together. */
#define QT_DETECTOR_BYTES 51200u /* 50 KiB */
#define QT_TRACKER_BYTES 3072u   /* 3 KiB: the tracker and its tracking mode */

/* Opaque, caller-owned objects: suitably aligned bytes. Touch only through the functions. */
typedef struct qt_detector {
    union {
        uint64_t align; /* 8-byte alignment, the C++ object's */
        unsigned char bytes[QT_DETECTOR_BYTES];
    } opaque;
} qt_detector;

typedef struct qt_tracker {
    union {
        uint64_t align;
        unsigned char bytes[QT_TRACKER_BYTES];
    } opaque;
} qt_tracker;

/* Results and errors. 0..5 are qt::Status's values (status.h), number for number; 64 and up
 * are the C interface's own (qt::Status counts up from 0, so its future values cannot
 * collide with these). */
typedef enum qt_status {
    QT_OK = 0,
    QT_BAD_SIZE = 1,                  /* width or height 0 or above 320 x 240 */
    QT_BAD_ROW_LENGTH = 2,            /* a row's length differs from the frame width; the
                                         frame is abandoned */
    QT_NOT_IN_FRAME = 3,              /* a row with no frame begun or after the last row;
                                         qt_finish before the last row; qt_track with no
                                         finished frame in the detector */
    QT_PREVIOUS_FRAME_INCOMPLETE = 4, /* qt_begin_frame abandoned a frame whose rows had not
                                         all arrived; the new frame has started normally */
    QT_CAPACITY_EXCEEDED = 5,         /* a capacity filled: results valid but incomplete */
    QT_NULL_POINTER = 64,             /* C only: a pointer argument was NULL */
    QT_BAD_INDEX = 65,                /* C only: index >= qt_line_count / qt_quad_count */
    QT_BAD_CONFIG = 66                /* C only: a qt_config field out of its range (listed
                                         in qt_config), or an object whose init failed */
} qt_status;

/* Short English name of a status, for logs; never NULL. */
const char* qt_status_name(qt_status status);

/* Values of qt_config.model: the line tracker per side (line_tracker.h). */
enum qt_model {
    QT_MODEL_PAPER = 0, /* the paper's N Kalman filters on closest points (N = filters) */
    QT_MODEL_TURN = 1   /* angle with turn rate plus an offset bent by it: fast turns */
};

/* Values of qt_config.tracking_mode (tracking_mode.h, docs/tracking.md). */
enum qt_tracking_mode {
    QT_TRACKING_MODE_OFF = 0, /* every frame whole */
    QT_TRACKING_MODE_ON = 1   /* while the board is tracked, qt_begin_tracked_frame processes
                                 the next frame only in bands around its predicted sides */
};

/* Values of qt_config.contrast: which way the board's outline is brighter. */
enum qt_contrast {
    QT_CONTRAST_BRIGHT = 0, /* the board is brighter than its surroundings on every side */
    QT_CONTRAST_DARK = 1,   /* darker on every side */
    QT_CONTRAST_ANY = 2     /* polarity not checked */
};

/* The parameters tuned in the field, in integer units, each with its accepted range;
 * qt_detector_init and qt_tracker_init refuse a config with any field outside its range
 * (QT_BAD_CONFIG). Everything not here keeps the C++ defaults (BoardParams{} and
 * default_quad_tracker_params(width, height); see docs/lines.md, docs/quadrangles.md and
 * docs/tracking.md for their tables). Enumerated fields are
 * plain integers so that the struct's layout does not depend on the size of an enum (8 bits
 * with arm-none-eabi's short enums, 32 bits on hosts). */
typedef struct qt_config {
    /* Detector (read by qt_detector_init). */
    uint16_t edge_threshold;  /* edge pixel: L1 gradient magnitude |gx| + |gy| at least this,
                                 grey levels (gx = p(x+1) - p(x-1)), 1..510 */
    uint16_t hough_threshold; /* votes a Hough bin needs before its line is followed, 1..255 */
    uint16_t min_line_length; /* shortest segment reported, pixels, 2..2048 */
    uint16_t max_line_gap;    /* longest run of missing edge pixels inside a segment,
                                 pixels, 0..255 */
    uint8_t contrast;         /* enum qt_contrast, 0..2 */
    /* Tracker (read by qt_tracker_init). */
    uint8_t model;              /* enum qt_model, 0..1 */
    uint8_t filters;            /* QT_MODEL_PAPER: Kalman filters per side, 1..3 (3 = 3KF) */
    uint8_t max_predicted;      /* a side may go unseen this many frames in a row before the
                                   track is dropped, frames, 0..254, or 255: never for that
                                   reason (off) */
    uint16_t gate_angle_deg;    /* a detected line serves a tracked side only within this
                                   angle of its prediction, whole degrees, 0..90 */
    uint16_t gate_distance_px;  /* ... and with both ends within this distance of it, whole
                                   pixels, 0..1000 */
    uint8_t tracking_mode;      /* enum qt_tracking_mode, 0..1 */
    uint8_t band_half_width_px; /* tracking mode: a band reaches this far either side of a
                                   predicted side, whole pixels, 2..64 */
    uint16_t full_every;        /* tracking mode: every full_every-th frame is whole (a side
                                   the bands missed, another board), frames, 2..65535 */
} qt_config;

/* Fills *config with the C++ API's defaults for a width x height frame. None of the fields
 * above depends on the frame size today; the size is taken so that callers keep working if
 * one comes to. Does nothing when config is NULL. */
void qt_config_default(qt_config* config, uint16_t width, uint16_t height);

/* QT_OK when every field is within its range, QT_BAD_CONFIG otherwise, QT_NULL_POINTER. */
qt_status qt_config_check(const qt_config* config);

/* A point, q16.16 pixels. */
typedef struct qt_point {
    int32_t x, y;
} qt_point;

/* A line of the lines stage (segment.h): a segment on its fitted line. */
typedef struct qt_line {
    int32_t x1, y1, x2, y2; /* end points, q16.16 px */
    int32_t rho;            /* distance from the origin to the line, q16.16 px, >= 0 */
    uint32_t theta;         /* direction of the normal from the origin, binary angle */
    uint16_t points;        /* edge points it was fitted to */
    int8_t bright_side;     /* +1: the brighter side lies along +normal (away from the
                               origin); -1: towards it; 0: unknown */
} qt_line;

/* A detected quadrangle (quad_detector.h). Corners anti-clockwise as seen in the image,
 * corner 0 the one with the smallest x + y: for a board turned by less than 45 degrees
 * top-left, bottom-left, bottom-right, top-right. Side i runs from corner i to corner i + 1. */
typedef struct qt_quad {
    qt_point corners[4]; /* q16.16 px */
    uint8_t lines[4];    /* side i lies on line lines[i] (qt_get_line's index) */
    int32_t score;       /* share of the perimeter with edge evidence of each side's polarity
                            (quad_refine.h), q16.16, 0..1 */
} qt_quad;

/* Values of qt_tracked_quad.state. */
enum qt_track_state {
    QT_TRACK_NONE = 0,    /* no quadrangle this frame */
    QT_TRACK_STARTED = 1, /* a new track from this frame's best detected quadrangle */
    QT_TRACK_TRACKING = 2 /* carried by the side trackers (see detected) */
};

/* Values of qt_tracked_quad.lost_reason: why a track ended this frame. */
enum qt_track_lost {
    QT_LOST_NONE = 0,
    QT_LOST_SIDE_UNSEEN = 1,        /* a side predicted for more than max_predicted frames */
    QT_LOST_SHAPE = 2,              /* the sides no longer make a convex quadrangle with
                                        sides from a tenth of the frame height to 2048 px */
    QT_LOST_SATURATED = 3,          /* a filter saturated */
    QT_LOST_DETECTION_DISAGREES = 4 /* no side matched, and the detection is elsewhere */
};

/* One frame of the tracker (quad_tracker.h). */
typedef struct qt_tracked_quad {
    uint8_t state;       /* enum qt_track_state */
    uint8_t detected;    /* bit i: side i was matched to a detected line this frame, else
                               it was predicted */
    uint8_t lost_reason; /* enum qt_track_lost: a track that ended this frame (a new one may
                               have started in the same frame: see state) */
    uint8_t banded;      /* 1: this frame was processed in tracking mode's bands, 0: whole */
    uint32_t track_id;   /* 1, 2, ...: a new id every time a track starts; 0 with no track */
    uint32_t age;        /* frames since the track started, 0 on its first frame */
    qt_point corners[4]; /* q16.16 px, in qt_quad's order; zero when state is NONE */
    qt_line sides[4];    /* side i's line, corner i to corner i + 1, measured or predicted */
} qt_tracked_quad;

/* ---- Detector ------------------------------------------------------------------------- */

/* Constructs the detector in *detector with the config's detector fields. QT_BAD_CONFIG (or
 * QT_NULL_POINTER for a NULL config) leaves a detector that refuses every frame with
 * QT_BAD_CONFIG until initialised again. May be called again at any time (drops the frame
 * in progress and the results). */
qt_status qt_detector_init(qt_detector* detector, const qt_config* config);

/* Starts a frame of width x height pixels, 1..320 x 1..240 (else QT_BAD_SIZE, no frame).
 * Clears the previous frame's results. */
qt_status qt_begin_frame(qt_detector* detector, uint16_t width, uint16_t height);

/* The same in tracking mode: the frame is processed only in the bands the tracker planned at
 * its last qt_track (whole when tracking mode is off, with no track, after a side was
 * predicted, and every full_every-th frame). Inside the bands the edges are the whole frame's;
 * rows no band crosses cost next to nothing. Pass the same tracker to qt_track after
 * qt_finish. QT_BAD_CONFIG when the tracker is not configured. */
qt_status qt_begin_tracked_frame(qt_detector* detector, qt_tracker* tracker, uint16_t width,
                                 uint16_t height);

/* The next camera row, grey levels, `length` pixels (must equal the frame width), top to
 * bottom. */
qt_status qt_push_row(qt_detector* detector, const uint8_t* pixels, uint16_t length);

/* The gradient word: 32 bits from the FPGA block, layout in gradient_word.h (gx, gy, L1
 * magnitude, direction bin). */
typedef uint32_t qt_gradient_word;

/* The next row of gradient words instead of camera pixels (one or the other for a whole
 * frame); `width` must equal the frame width. */
qt_status qt_push_gradient_row(qt_detector* detector, const qt_gradient_word* words,
                               uint16_t width);

/* After the last row: lines, then quadrangles. QT_OK or QT_CAPACITY_EXCEEDED: the results are
 * valid (the latter: some were cut). QT_NOT_IN_FRAME when no frame was begun, or before the
 * last row (the frame stays open: push the missing rows and finish again), or after a row of
 * the wrong length (the frame was abandoned). */
qt_status qt_finish(qt_detector* detector);

/* Results of the last frame that finished with QT_OK or QT_CAPACITY_EXCEEDED; 0 and
 * QT_BAD_INDEX between qt_begin_frame and such a finish, and for a NULL detector. */
uint16_t qt_line_count(const qt_detector* detector);
qt_status qt_get_line(const qt_detector* detector, uint16_t index, qt_line* out);
/* Quadrangles, best first (highest score). */
uint16_t qt_quad_count(const qt_detector* detector);
qt_status qt_get_quad(const qt_detector* detector, uint16_t index, qt_quad* out);

/* ---- Tracker -------------------------------------------------------------------------- */

/* Constructs the tracker for width x height frames (1..320 x 1..240, else QT_BAD_SIZE; the
 * size places the filters' origins) with the config's tracker fields. After QT_BAD_CONFIG,
 * QT_BAD_SIZE or a NULL config the tracker refuses qt_track with QT_BAD_CONFIG until
 * initialised again. No track until the first qt_track with a quadrangle. */
qt_status qt_tracker_init(qt_tracker* tracker, const qt_config* config, uint16_t width,
                          uint16_t height);

/* Drops the current track (the next track gets a new id; the next frame is whole). */
qt_status qt_tracker_reset(qt_tracker* tracker);

/* One frame: steps the tracker on the detector's lines and quadrangles of its last finished
 * frame (call once per frame, after qt_finish), and in tracking mode plans the next frame's
 * bands. QT_NOT_IN_FRAME when the detector has no finished frame (between qt_begin_frame and a
 * successful qt_finish): the tracker is not stepped. On any error *out (if not NULL) is zeroed:
 * state NONE. */
qt_status qt_track(qt_tracker* tracker, const qt_detector* detector, qt_tracked_quad* out);

/* Name of a qt_track_lost reason ("side_unseen", "shape", "saturated",
 * "detection_disagrees"); NULL for QT_LOST_NONE and unknown values. */
const char* qt_track_lost_name(uint8_t reason);

#ifdef __cplusplus
}
#endif

#endif /* QUADTRACK_C_H */
