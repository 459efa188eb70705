#include "base/status.h"

namespace qt {

const char* status_name(Status s) {
    switch (s) {
        case Status::ok: return "ok";
        case Status::bad_size: return "bad size (zero or above capacity)";
        case Status::bad_row_length: return "row length differs from frame width";
        case Status::not_in_frame: return "no frame in progress";
        case Status::previous_frame_incomplete: return "previous frame ended early";
        case Status::capacity_exceeded: return "capacity exceeded (results incomplete)";
        case Status::bad_row_order: return "rows out of order";
        case Status::bad_stream: return "edge beats broken off or not fitting the frame";
        case Status::not_in_build: return "option left out of this build's capacity";
    }
    return "unknown status";
}

}  // namespace qt
