// Status values returned by every core stage. No exceptions in core/: a stage that cannot do
// what was asked returns one of these and leaves its outputs in a defined state.
#pragma once
#include <stdint.h>

namespace qt {

enum class Status : uint8_t {
    ok = 0,
    bad_size,                   // width or height is 0 or above the compile-time capacity
    bad_row_length,             // a row's length differs from the frame width
    not_in_frame,               // push_row() without begin_frame(), or after the last row
    previous_frame_incomplete,  // begin_frame() abandoned a frame whose rows had not all arrived;
                                // the new frame has started normally
    capacity_exceeded,          // a compile-time capacity filled: results are valid but
                                // incomplete; the stage's stats count what was dropped
    bad_row_order,              // a row arrived out of the order the stage needs (harris.h:
                                // a gradient row before its pixel row, or too far behind it)
    bad_stream,                 // the FPGA's edge beats report the frame broken off, or do not
                                // fit it (lines/edge_beat.h)
    not_in_build,               // the parameters ask for an option the build's capacity leaves
                                // out (base/capacity.h: morph_region 0)
};

// Short English name for logs and CLI messages.
const char* status_name(Status s);

}  // namespace qt
