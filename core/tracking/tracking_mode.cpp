#include "tracking/tracking_mode.h"

namespace qt {

BandWindow* TrackingMode::plan(const TrackedQuad& tracked) {
    const bool held = tracked.state != TrackState::none && tracked.detected == 0xFu;
    const bool same_board = held && last_id_ != 0 && tracked.track_id == last_id_;
    q16_16 x[4], y[4];
    for (int i = 0; i < 4; ++i) {
        // Corner i moved on by its motion since the last frame (q16_16, saturating).
        const Point16 c = tracked.corners[i];
        const int64_t dx = same_board ? int64_t{c.x.raw} - last_[i].x.raw : 0;
        const int64_t dy = same_board ? int64_t{c.y.raw} - last_[i].y.raw : 0;
        x[i] = q16_16::from_raw(c.x.raw + dx);
        y[i] = q16_16::from_raw(c.y.raw + dy);
        last_[i] = c;
    }
    last_id_ = held ? tracked.track_id : 0;
    if (!params_.enabled || !held || banded_run_ + 1u >= params_.full_every) {
        banded_run_ = 0;
        ++stats_.whole;
        window_.clear();
        return nullptr;
    }
    ++banded_run_;
    ++stats_.banded;
    window_.set_quad(x, y, params_.half_width, params_.reach, params_.line_angle);
    if (params_.fit_sides) {
        // Each side's polarity along it (BandWindow::set_sides), from its line's.
        int8_t bright_right[4];
        for (int i = 0; i < 4; ++i) {
            const Segment& s = tracked.sides[i];
            const Point16 a = tracked.corners[i], b = tracked.corners[(i + 1) & 3];
            const SinCos n = sin_cos(s.theta);
            const int64_t dot = (int64_t{n.cos.raw} * -(int64_t{b.y.raw} - a.y.raw) +
                                 int64_t{n.sin.raw} * (int64_t{b.x.raw} - a.x.raw));
            bright_right[i] = static_cast<int8_t>(dot >= 0 ? s.bright_side : -s.bright_side);
        }
        window_.set_sides(bright_right);
    }
    return &window_;
}

void TrackingMode::reset() {
    last_id_ = 0;
    banded_run_ = 0;
    window_.clear();
}

}  // namespace qt
