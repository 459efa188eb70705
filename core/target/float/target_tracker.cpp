#include "target/float/target_tracker.h"

#include <math.h>  // sqrtf

namespace qt {

const char* target_state_name(TargetState s) {
    switch (s) {
        case TargetState::measured: return "measured";
        case TargetState::reacquired: return "reacquired";
        case TargetState::predicted: return "predicted";
        case TargetState::out_of_view: return "out_of_view";
        case TargetState::lost: return "lost";
    }
    return "unknown";
}

const char* target_method_name(TargetMethod m) {
    switch (m) {
        case TargetMethod::fused: return "fused";
        case TargetMethod::filter_only: return "filter_only";
        case TargetMethod::homography_only: return "homography_only";
        case TargetMethod::template_only: return "template_only";
    }
    return "unknown";
}

const char* rep_gate_name(RepGate g) {
    switch (g) {
        case RepGate::capped: return "capped";
        case RepGate::paper: return "paper";
    }
    return "unknown";
}

const char* target_formulation_name(TargetFormulation f) {
    switch (f) {
        case TargetFormulation::reference: return "reference";
        case TargetFormulation::paper: return "paper";
    }
    return "unknown";
}

const char* search_region_name(SearchRegionShape r) {
    switch (r) {
        case SearchRegionShape::square: return "square";
        case SearchRegionShape::paper: return "paper";
    }
    return "unknown";
}

bool geometry_trusted(const FrameGeometry& g, const TargetTrackerParams& p) {
    return p.rep_gate == RepGate::paper ? g.d_rep <= p.th_rep_px2
                                        : g.d_rep_capped_px <= p.gate_rep_px;
}

void TargetTracker::init(float x, float y, uint16_t width, uint16_t height,
                         const TargetTrackerParams& params) {
    params_ = params;
    last_h_ = Homography{};
    width_ = width;
    height_ = height;
    state_ = TargetState::measured;
    geometry_ok_ = true;
    geometry_assumed_ = false;
    looking_ = looked_ = false;
    last_x_ = x;
    last_y_ = y;
    lost_frames_ = 0;
    frame_ = 0;
    restart_on(x, y);  // the filter, A, the history and the counts since the last measurement
    for (int i = 0; i < 4; ++i) {
        roi_x_[i] = x;
        roi_y_[i] = y;
    }
}

bool TargetTracker::in_image(float x, float y) const {
    // Pixel centres at integers: the image covers [-0.5, width - 0.5) × [-0.5, height - 0.5).
    return x >= -0.5f && y >= -0.5f && x < static_cast<float>(width_) - 0.5f &&
           y < static_cast<float>(height_) - 0.5f;
}

bool TargetTracker::within_reach(float x, float y) const {
    const float w = static_cast<float>(width_), h = static_cast<float>(height_);
    const float rx = params_.max_outside * w, ry = params_.max_outside * h;
    return x >= -0.5f - rx && y >= -0.5f - ry && x <= w - 0.5f + rx && y <= h - 0.5f + ry;
}

bool TargetTracker::paper_formulation() const {
    return params_.method == TargetMethod::fused && params_.formulation == TargetFormulation::paper;
}

bool TargetTracker::accumulation_plausible() const {
    // A maps the estimate (paper formulation: the reference point) to a finite point, and the
    // area around it by a factor within [1/max_scale², max_scale²] (a camera whose altitude
    // changed more than max_scale-fold since frame m, or an A gone wrong).
    float j[4];
    const bool paper = paper_formulation();
    if (!homography_jacobian(acc_, paper ? ref_x_ : kf_.x(), paper ? ref_y_ : kf_.y(), j))
        return false;
    const float det = j[0] * j[3] - j[1] * j[2];
    const float s2 = params_.max_scale * params_.max_scale;
    return det >= 1.0f / s2 && det <= s2;
}

void TargetTracker::position(float& x, float& y) const {
    x = kf_.x();
    y = kf_.y();
    if (paper_formulation()) return;  // the filter lives in the current image
    float xo, yo;
    if (apply_homography(acc_, x, y, xo, yo)) {
        x = xo;
        y = yo;
    }
}

bool TargetTracker::unconfirmed_exit(float x, float y, float& mx, float& my) const {
    if (params_.method != TargetMethod::fused || paper_formulation() ||
        params_.max_unconfirmed_exit == kCheckOff || unconfirmed_ <= params_.max_unconfirmed_exit ||
        in_image(x, y))
        return false;
    return apply_homography(acc_, meas_x_, meas_y_, mx, my) && in_image(mx, my);
}

bool TargetTracker::searching_lost() const {
    return state_ == TargetState::lost && lost_by_exit_ && params_.lost_search_px > 0;
}

// The filter started again on a match at (x, y) in the current image, which becomes the
// reference image; the camera's motion (last_h_) and the frame count go on (init() sets them).
void TargetTracker::restart_on(float x, float y) {
    kf_.init(x, y, params_.kalman);
    acc_ = Homography{};
    ref_x_ = meas_x_ = held_x_ = x;
    ref_y_ = meas_y_ = held_y_ = y;
    history_start_ = 0;
    history_count_ = 0;
    coasting_ = false;
    lost_by_exit_ = false;
    unseen_ = 0;
    unconfirmed_ = 0;
    bad_geometry_ = 0;
    remember(x, y);
}

void TargetTracker::look_at(float x, float y, float radius, float min_score) {
    looking_ = true;
    look_score_ = min_score;
    look_x_ = x;
    look_y_ = y;
    look_radius_ = radius;
}

SearchWindow TargetTracker::predict(const FrameGeometry& g) {
    looked_ = looking_;
    looking_ = false;
    SearchWindow w = predict_from_state(g);
    if (!looked_) return w;
    // The camera's motion since look_at(): this frame's trusted homography, or the last one.
    const Homography& h = g.valid && geometry_trusted(g, params_) ? g.h : last_h_;
    SearchWindow look;
    look.x = look_x_;
    look.y = look_y_;
    apply_homography(h, look_x_, look_y_, look.x, look.y);
    look.radius = look_radius_;
    return look;
}

SearchWindow TargetTracker::predict_from_state(const FrameGeometry& g) {
    SearchWindow w;
    if (state_ == TargetState::lost) {
        if (!searching_lost()) return w;
        if (lost_frames_ < UINT16_MAX) ++lost_frames_;
        const float r =
            params_.min_radius_px + params_.lost_search_px * static_cast<float>(lost_frames_);
        w.x = lost_x_;
        w.y = lost_y_;
        w.radius = r < params_.max_radius_px ? r : params_.max_radius_px;
        return w;
    }
    ++frame_;
    switch (params_.method) {
        case TargetMethod::template_only:
            w.x = last_x_;
            w.y = last_y_;
            w.radius = params_.template_radius_px;
            return w;
        case TargetMethod::filter_only: break;
        case TargetMethod::fused:
        case TargetMethod::homography_only: {
            geometry_ok_ = g.valid && geometry_trusted(g, params_);
            geometry_assumed_ = !geometry_ok_ && g.unmeasured;
            if (geometry_ok_) {
                last_h_ = g.h;
                bad_geometry_ = 0;
            } else if (!geometry_assumed_ && bad_geometry_ < UINT16_MAX) {
                ++bad_geometry_;
            }
            Homography next;
            // A product that degenerates leaves A as it was; the plausibility test below and
            // the lost rule catch an A that has stopped describing the camera.
            if (multiply_homographies(last_h_, acc_, next)) acc_ = next;
            // The paper's formulation: the filter is carried into this frame's image.
            if (paper_formulation()) kf_.change_frame(last_h_);
            break;
        }
    }
    kf_.predict();
    // Out of view, the estimate stays on the coasting track (the filter's constant velocity
    // is its tangent, which a perspective track leaves).
    if (coasting_) coast_at(frame_);
    if (params_.method == TargetMethod::homography_only) {
        position(w.x, w.y);
        return w;  // radius 0: never measured
    }
    return window_from_state();
}

// S in the current image, to first order: J S Jᵀ with J the Jacobian at x̂ of the map from
// the filter's image (A; the identity in the paper's formulation). s[0], s[2]: its diagonal.
static void current_s(const TargetKalman& kf, const Homography& a, bool identity, float s[2]) {
    const Innovation gate = kf.gate();
    float j[4] = {1, 0, 0, 1};
    if (!identity) homography_jacobian(a, kf.x(), kf.y(), j);
    s[0] = j[0] * j[0] * gate.s[0] + 2 * j[0] * j[1] * gate.s[1] + j[1] * j[1] * gate.s[2];
    s[1] = j[2] * j[2] * gate.s[0] + 2 * j[2] * j[3] * gate.s[1] + j[3] * j[3] * gate.s[2];
}

SearchWindow TargetTracker::window_from_state() {
    if (params_.method == TargetMethod::fused && params_.region == SearchRegionShape::paper)
        return paper_region(unseen_ == 0);
    SearchWindow w;
    position(w.x, w.y);
    float s[2];
    current_s(kf_, acc_, paper_formulation() || params_.method == TargetMethod::filter_only, s);
    const float r = params_.gate_sigmas * sqrtf(s[0] > s[1] ? s[0] : s[1]);
    w.radius = r < params_.min_radius_px   ? params_.min_radius_px
               : r > params_.max_radius_px ? params_.max_radius_px
                                           : r;
    return w;
}

SearchWindow TargetTracker::paper_region(bool refresh) {
    SearchWindow w;
    w.corners = true;
    const bool paper = paper_formulation();
    if (refresh) {
        // Four points x̂ ± k·(σx, σy) in the filter's image, mapped into this one by A (the
        // paper's formulation: the filter's image is this one).
        const Innovation gate = kf_.gate();
        const float hx = params_.gate_sigmas * sqrtf(gate.s[0]);
        const float hy = params_.gate_sigmas * sqrtf(gate.s[2]);
        const float px[4] = {kf_.x() - hx, kf_.x() + hx, kf_.x() + hx, kf_.x() - hx};
        const float py[4] = {kf_.y() - hy, kf_.y() - hy, kf_.y() + hy, kf_.y() + hy};
        for (int i = 0; i < 4; ++i) {
            float xo = px[i], yo = py[i];
            if (paper || apply_homography(acc_, px[i], py[i], xo, yo)) {
                roi_x_[i] = xo;
                roi_y_[i] = yo;
            }
        }
    } else {
        // Perturbed: the region of the last measured frame carried by this frame's homography
        // (so, since then, by the accumulated one).
        for (int i = 0; i < 4; ++i) {
            float xo, yo;
            if (apply_homography(last_h_, roi_x_[i], roi_y_[i], xo, yo)) {
                roi_x_[i] = xo;
                roi_y_[i] = yo;
            }
        }
    }
    float x0 = roi_x_[0], x1 = roi_x_[0], y0 = roi_y_[0], y1 = roi_y_[0];
    bool inside = true;
    for (int i = 0; i < 4; ++i) {
        w.cx[i] = roi_x_[i];
        w.cy[i] = roi_y_[i];
        x0 = roi_x_[i] < x0 ? roi_x_[i] : x0;
        x1 = roi_x_[i] > x1 ? roi_x_[i] : x1;
        y0 = roi_y_[i] < y0 ? roi_y_[i] : y0;
        y1 = roi_y_[i] > y1 ? roi_y_[i] : y1;
        inside = inside && in_image(roi_x_[i], roi_y_[i]);
    }
    w.x = 0.5f * (x0 + x1);
    w.y = 0.5f * (y0 + y1);
    const float r = 0.5f * (x1 - x0 > y1 - y0 ? x1 - x0 : y1 - y0);
    w.radius = r > params_.max_radius_px ? params_.max_radius_px : r;
    // "Wait for that region of interest transformed by homography comes into FOV": while the
    // target is perturbed, no search until the whole region is inside the image.
    if (!refresh && !inside) w.radius = 0;
    return w;
}

SearchWindow TargetTracker::expected() const {
    TargetTracker copy = *this;
    FrameGeometry none;
    none.h = last_h_;
    none.valid = true;
    return copy.predict(none);
}

TargetEstimate TargetTracker::update(const TargetMeasurement& measured) {
    TargetEstimate e;
    TargetMeasurement m = measured;
    if (looked_) {
        looked_ = false;
        if (m.found && m.score >= look_score_) {
            restart_on(m.x, m.y);
            last_x_ = m.x;  // template_only's track
            last_y_ = m.y;
            state_ = TargetState::reacquired;
            e.x = held_x_;
            e.y = held_y_;
            e.state = state_;
            return e;
        }
        m.found = false;  // the window was not the prediction's: no measurement of it
    }
    const bool found = m.found && m.score >= params_.min_score;
    if (state_ != TargetState::lost && params_.method == TargetMethod::template_only) {
        if (found) {
            state_ = unseen_ > 0 ? TargetState::reacquired : TargetState::measured;
            last_x_ = m.x;
            last_y_ = m.y;
            unseen_ = 0;
        } else {
            if (unseen_ < UINT16_MAX) ++unseen_;
            state_ = in_image(last_x_, last_y_) ? TargetState::predicted : TargetState::out_of_view;
            if (unseen_ > params_.max_unseen) state_ = TargetState::lost;
        }
        e.state = state_;
        e.x = last_x_;
        e.y = last_y_;
        e.unseen = unseen_;
        return e;
    }
    const Innovation gate = kf_.gate();
    float j[4] = {1, 0, 0, 1};
    const bool paper = paper_formulation();
    if (!paper) homography_jacobian(acc_, kf_.x(), kf_.y(), j);
    const float det_j = j[0] * j[3] - j[1] * j[2];
    e.det_s = gate.det_s * det_j * det_j;  // det(J S Jᵀ), px⁴ in the current image
    if (state_ == TargetState::lost) {
        if (searching_lost() && found) {
            restart_on(m.x, m.y);
            state_ = TargetState::reacquired;
        }
        e.x = held_x_;
        e.y = held_y_;
        e.state = state_;
        e.unseen = unseen_;
        return e;
    }
    bool accepted = false;
    Innovation in;
    float zx = m.x, zy = m.y;
    const bool uses_measurements = params_.method != TargetMethod::homography_only;
    const bool geometry_needed = params_.method == TargetMethod::fused;
    if (found && uses_measurements && (geometry_ok_ || geometry_assumed_ || !geometry_needed)) {
        // The measurement in the reference image: A⁻¹ z (equation (10)).
        Homography inv;
        const bool mapped =
            paper || (invert_homography(acc_, inv) && apply_homography(inv, m.x, m.y, zx, zy));
        if (mapped) {
            in = kf_.innovation(zx, zy);
            e.nds = in.nds;
            accepted = in.nds <= params_.gate_nds;
        }
    }
    if (accepted) {
        kf_.update(in);
        coasting_ = false;
        state_ = unseen_ > 0 ? TargetState::reacquired : TargetState::measured;
        unseen_ = 0;
        unconfirmed_ = 0;
        meas_x_ = zx;
        meas_y_ = zy;
        remember(zx, zy);
        if (params_.method == TargetMethod::fused && params_.reset && in.nds <= params_.reset_nds &&
            e.det_s <= params_.reset_det_s && (paper || kf_.change_frame(acc_))) {
            if (!paper) carry_history(acc_);
            acc_ = Homography{};  // Table III: the accumulation starts again at this frame
            ref_x_ = kf_.x();     // x_m of equation (11), m = this frame
            ref_y_ = kf_.y();
            meas_x_ = m.x;  // the measurement in the new reference image, this one
            meas_y_ = m.y;
            e.reset = true;
        }
    } else {
        const bool leaving = state_ != TargetState::out_of_view;  // inside until this frame
        if (unseen_ < UINT16_MAX) ++unseen_;
        if (m.searched && unconfirmed_ < UINT16_MAX) ++unconfirmed_;
        float x, y;
        // The paper's formulation while perturbed: x_n = A x_m (equation (11)); the filter
        // follows it (re-initialised there when the target returns).
        if (paper && apply_homography(acc_, ref_x_, ref_y_, x, y)) kf_.set_position(x, y);
        position(x, y);
        // Leaving the image: the estimate coasts on the track fitted to the last measurements.
        if (!in_image(x, y) && state_ != TargetState::out_of_view && !paper &&
            params_.method == TargetMethod::fused && coast_from_history())
            position(x, y);
        state_ = in_image(x, y) ? TargetState::predicted : TargetState::out_of_view;
        const bool geometry_gone =
            params_.method != TargetMethod::filter_only &&
            (bad_geometry_ > params_.max_bad_geometry || !accumulation_plausible());
        if (unseen_ > params_.max_unseen || geometry_gone || !within_reach(x, y))
            state_ = TargetState::lost;
        float mx, my;
        if (state_ != TargetState::lost && leaving && unconfirmed_exit(x, y, mx, my)) {
            state_ = TargetState::lost;
            lost_by_exit_ = true;
            lost_frames_ = 0;
            lost_x_ = held_x_ = mx;  // reported while lost: where it was last seen
            lost_y_ = held_y_ = my;
        }
    }
    // A lost target's estimate is the last one reported before it was lost (within reach).
    if (state_ != TargetState::lost) position(held_x_, held_y_);
    e.x = held_x_;
    e.y = held_y_;
    e.state = state_;
    e.unseen = unseen_;
    return e;
}

void TargetTracker::remember(float x, float y) {
    const uint16_t slot = static_cast<uint16_t>((history_start_ + history_count_) % kHistory);
    history_[slot] = Sample{x, y, frame_};
    if (history_count_ < kHistory)
        ++history_count_;
    else
        history_start_ = static_cast<uint16_t>((history_start_ + 1u) % kHistory);
}

void TargetTracker::carry_history(const Homography& h) {
    for (uint16_t i = 0; i < history_count_; ++i) {
        Sample& s = history_[(history_start_ + i) % kHistory];
        float xo, yo;
        if (apply_homography(h, s.x, s.y, xo, yo)) {
            s.x = xo;
            s.y = yo;
        }
    }
}

bool TargetTracker::coast_from_history() {
    const uint32_t window = params_.coast_fit_frames < kMaxCoastFitFrames ? params_.coast_fit_frames
                                                                          : kMaxCoastFitFrames;
    if (window == 0) return false;
    // Means over the window's samples, t in frames from now (≤ 0).
    float n = 0, st = 0, sx = 0, sy = 0;
    for (uint16_t i = 0; i < history_count_; ++i) {
        const Sample& s = history_[(history_start_ + i) % kHistory];
        if (frame_ - s.frame > window) continue;
        n += 1;
        st -= static_cast<float>(frame_ - s.frame);
        sx += s.x;
        sy += s.y;
    }
    if (n < static_cast<float>(kMinCoastSamples)) return false;
    const float tm = st / n, xm = sx / n, ym = sy / n;
    // About the means (u = t − t̄, dx = x − x̄): Σu², Σu·dx, Σu²·dx (and y).
    float suu = 0, sux = 0, suy = 0, suux = 0, suuy = 0;
    for (uint16_t i = 0; i < history_count_; ++i) {
        const Sample& s = history_[(history_start_ + i) % kHistory];
        if (frame_ - s.frame > window) continue;
        const float u = -static_cast<float>(frame_ - s.frame) - tm;
        const float dx = s.x - xm, dy = s.y - ym;
        suu += u * u;
        sux += u * dx;
        suy += u * dy;
        suux += u * u * dx;
        suuy += u * u * dy;
    }
    if (!(suu > 0)) return false;
    // dx = (ax + bx·u) / (1 + c·u), the same c for both axes, by least squares on
    // ax + bx·u − c·u·dx = dx. For a given c, ax and bx are the straight-line fit of
    // (1 + c·u)·dx on (1, u); what is left of dx is p + c·q with p = dx − (Σu·dx/Σu²)·u and
    // q = u·dx − Σu·dx/n − (Σu²·dx/Σu²)·u, so c = −Σp·q / Σq² over both axes.
    float c = 0;
    if (params_.coast_projective) {
        float spq = 0, sqq = 0;
        for (uint16_t i = 0; i < history_count_; ++i) {
            const Sample& s = history_[(history_start_ + i) % kHistory];
            if (frame_ - s.frame > window) continue;
            const float u = -static_cast<float>(frame_ - s.frame) - tm;
            const float dx = s.x - xm, dy = s.y - ym;
            const float px = dx - (sux / suu) * u, py = dy - (suy / suu) * u;
            const float qx = u * dx - sux / n - (suux / suu) * u;
            const float qy = u * dy - suy / n - (suuy / suu) * u;
            spq += px * qx + py * qy;
            sqq += qx * qx + qy * qy;
        }
        if (sqq > 0) c = -spq / sqq;
    }
    coast_.frame = frame_;
    coast_.t_mean = tm;
    coast_.x_mean = xm;
    coast_.y_mean = ym;
    coast_.c = c;
    coast_.ax = c * sux / n;
    coast_.ay = c * suy / n;
    coast_.bx = (sux + c * suux) / suu;
    coast_.by = (suy + c * suuy) / suu;
    coasting_ = true;
    return coast_at(frame_);
}

bool TargetTracker::coast_at(uint32_t frame) {
    const float u = static_cast<float>(frame - coast_.frame) - coast_.t_mean;
    const float d = 1.0f + coast_.c * u;
    // The track's depth has fallen below a quarter of its value over the fit (nearing the
    // horizon in the reference image, or a c the samples did not pin down): no further.
    if (!(d >= kMinCoastDepth)) return false;
    kf_.set_position(coast_.x_mean + (coast_.ax + coast_.bx * u) / d,
                     coast_.y_mean + (coast_.ay + coast_.by * u) / d);
    kf_.set_velocity((coast_.bx - coast_.c * coast_.ax) / (d * d),
                     (coast_.by - coast_.c * coast_.ay) / (d * d));
    return true;
}

}  // namespace qt
