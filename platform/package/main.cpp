// A consumer of the installed quadtrack package: one synthetic QVGA frame (a bright board on a
// dark background, generated row by row) through qt::BoardDetectorQvga. Exit status 0 when
// exactly one quadrangle is found with its corners on the board's, 1 otherwise, 2 when a stage
// reports an error.
// No heap, no iostream, so the same source links for Cortex-M4 with newlib-nano; on a
// POSIX host it also prints the count and the corners on stdout.
#include <stdint.h>

#include "quads/board_detector.h"

#if defined(__unix__)
#include <stdio.h>
#include <unistd.h>
#endif

namespace {

constexpr uint16_t kWidth = 320;   // pixels
constexpr uint16_t kHeight = 240;  // pixels
// The board: columns [kLeft, kRight), rows [kTop, kBottom), pixels; 4:3 like the display.
constexpr uint16_t kLeft = 88, kRight = 232, kTop = 66, kBottom = 174;
constexpr uint8_t kBackground = 30;  // grey level
constexpr uint8_t kBoard = 220;      // grey level
// Largest distance of a found corner from the board's, per axis, pixels.
constexpr int32_t kCornerTolerance = 2;

qt::BoardDetectorQvga detector;  // static: the whole detector's RAM, fixed at compile time
uint8_t row[kWidth];

void fill_row(uint16_t y) {
    const bool board_row = y >= kTop && y < kBottom;
    for (uint16_t x = 0; x < kWidth; ++x)
        row[x] = board_row && x >= kLeft && x < kRight ? kBoard : kBackground;
}

bool usable(qt::Status s) { return s == qt::Status::ok || s == qt::Status::capacity_exceeded; }

// The board's outline runs along pixel edges, half a pixel outside its outer pixels' centres.
// Corners come anti-clockwise from the one with the smallest x + y (quad_rules.h).
bool on_board(const qt::Quad& quad) {
    constexpr int64_t one = qt::q16_16::one_raw;  // 1 px in raw q16.16 units
    const int64_t left = kLeft * one - one / 2, right = kRight * one - one / 2;
    const int64_t top = kTop * one - one / 2, bottom = kBottom * one - one / 2;
    const int64_t expected[4][2] = {{left, top}, {left, bottom}, {right, bottom}, {right, top}};
    const int64_t tolerance = kCornerTolerance * one;
    for (int i = 0; i < 4; ++i) {
        const int64_t dx = quad.corners[i].x.raw - expected[i][0];
        const int64_t dy = quad.corners[i].y.raw - expected[i][1];
        if (dx > tolerance || -dx > tolerance || dy > tolerance || -dy > tolerance) return false;
    }
    return true;
}

void report(qt::Status status) {
#if defined(__unix__)
    char text[256];
    int n = snprintf(text, sizeof text, "quadtrack_consumer: status %s, lines %u, quadrangles %u",
                     qt::status_name(status), static_cast<unsigned>(detector.lines().line_count()),
                     static_cast<unsigned>(detector.quad_count()));
    if (detector.quad_count() > 0 && n > 0 && n < static_cast<int>(sizeof text)) {
        const qt::Point16* c = detector.quads()[0].corners;
        n += snprintf(text + n, sizeof text - static_cast<unsigned>(n),
                      ", corners (%d,%d) (%d,%d) (%d,%d) (%d,%d) px",
                      static_cast<int>(c[0].x.round_int()), static_cast<int>(c[0].y.round_int()),
                      static_cast<int>(c[1].x.round_int()), static_cast<int>(c[1].y.round_int()),
                      static_cast<int>(c[2].x.round_int()), static_cast<int>(c[2].y.round_int()),
                      static_cast<int>(c[3].x.round_int()), static_cast<int>(c[3].y.round_int()));
    }
    if (n > 0 && n < static_cast<int>(sizeof text) - 1) {
        text[n++] = '\n';
        const ssize_t written = write(STDOUT_FILENO, text, static_cast<size_t>(n));
        (void)written;  // nothing to do about a closed stdout; the exit status carries the result
    }
#else
    (void)status;  // a firmware would send the count to its UART or debugger here
#endif
}

}  // namespace

int main() {
    if (detector.begin_frame(kWidth, kHeight, qt::BoardParams{}) != qt::Status::ok) return 2;
    for (uint16_t y = 0; y < kHeight; ++y) {
        fill_row(y);
        if (detector.push_row(row, kWidth) != qt::Status::ok) return 2;
    }
    const qt::Status status = detector.finish();
    report(status);
    if (!usable(status)) return 2;
    return detector.quad_count() == 1 && on_board(detector.quads()[0]) ? 0 : 1;
}
