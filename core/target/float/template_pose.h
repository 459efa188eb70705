// The target template's pose: how the ground's motion since the template was cut changes the
// target's look. The template is cut in one frame; the camera then turns, tilts and changes
// height, and a target on the ground is seen rotated, sheared and scaled with it. The frame
// homographies the tracker accumulates say how (the Filtering and Geometry paper's eq. (11)),
// so the template is searched as the ground's motion since its cut would show it: warped by the
// Jacobian of that motion at the template's centre. A static camera leaves it as it is.
// Single-precision float (core/target/float/); no heap.
#pragma once
#include <stdint.h>

#include "target/float/homography.h"

namespace qt {

// The ground's motion from the image the template was cut in to the current image.
struct TemplatePose {
    Homography h;          // cut image → current image
    float cx = 0, cy = 0;  // the template's centre in the cut image, px

    // The template has just been cut (or blended with a cut) centred on (x, y) px.
    void reset(float x, float y) {
        h = Homography{};
        cx = x;
        cy = y;
    }
    // One more frame: the motion previous → current image. A product that degenerates leaves
    // the pose as it was.
    void follow(const Homography& frame_motion) {
        Homography next;
        if (multiply_homographies(frame_motion, h, next)) h = next;
    }
    // The motion's Jacobian at the centre, j = [∂x'/∂x, ∂x'/∂y, ∂y'/∂x, ∂y'/∂y]; false when the
    // centre maps to infinity.
    bool jacobian(float j[4]) const;
};

// The least and greatest area scale (det J) a warp accepts: beyond them the accumulated motion
// no longer describes a target the template could match (the tracker's max_scale rule loses such
// a target too).
constexpr float kWarpMinDet = 0.25f, kWarpMaxDet = 4.0f;
// The largest magnitude of an entry of j⁻¹ a warp accepts.
constexpr float kWarpMaxEntry = 16.0f;

// Whether the linear map j moves no pixel of a w × h template by 1/16 px or more about its
// centre: a warp would then only blur the template (bilinear resampling is a low-pass filter).
bool warp_negligible(const float j[4], uint8_t w, uint8_t h);

// out = the w × h template `in` as the linear map j about its centre ((w − 1)/2, (h − 1)/2) shows
// it: out(p) = in(c + j⁻¹(p − c)), bilinear, the source point clamped to the template (its edge
// pixels extend outwards), rounded to nearest. False (out untouched) when det j is not within
// [kWarpMinDet, kWarpMaxDet], an entry of j⁻¹ exceeds ±kWarpMaxEntry, or j is not finite. in and
// out must not overlap.
bool warp_template(const uint8_t* in, uint8_t w, uint8_t h, const float j[4], uint8_t* out);

}  // namespace qt
