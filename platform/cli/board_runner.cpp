#include "cli/board_runner.h"

#include "io/push_frame.h"

namespace qt::cli {

bool detect_board(const io::GreyImage& frame, const BoardParams& params, DetectResult& result) {
    static HostBoardDetector det;  // ~90 KB: static, as firmware keeps it
    result = DetectResult{};
    result.width = static_cast<uint16_t>(frame.width);
    result.height = static_cast<uint16_t>(frame.height);
    if (frame.width <= 0 || frame.height <= 0 || frame.width > kMaxFrameWidth ||
        frame.height > kMaxFrameHeight) {
        result.status = Status::bad_size;
        return false;
    }
    const Status s = io::push_frame(det, frame, params);
    result.status = s;
    if (s != Status::ok && s != Status::capacity_exceeded) return false;
    const auto& lines = det.lines();
    result.lines.assign(lines.lines(), lines.lines() + lines.line_count());
    result.quads.assign(det.quads(), det.quads() + det.quad_count());
    result.line_stats = lines.stats();
    result.quad_stats = det.quad_stats();
    return true;
}

}  // namespace qt::cli
