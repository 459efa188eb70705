// The airborne target sequence (the Filtering and Geometry paper's setting): a pinhole camera
// flying over a textured ground plane Z = 0 keeps a small vehicle in view, loses it under a flare
// for a spell (occlusion), then looks away so that the vehicle leaves the image for a spell (out of
// view) and comes back. Every frame comes with its ground truth: where the vehicle is in the image
// (also when hidden or outside), the ground → image homography and the true inter-frame homography
// of the ground plane, which a tracker estimates from Harris corners and NCC matches.
//
// Geometry. Ground units are metres, X east, Y north. The camera at altitude A looks ahead of
// nadir by the tilt θ along its heading ψ (the image's up direction), so there is perspective;
// focal length f px, principal point at the image centre ((w−1)/2, (h−1)/2), pixel centres at
// integer coordinates. Ground → image: G = K [r1 r2 t] (r1, r2 the first columns of the world →
// camera rotation, t = −R·C). The camera's position is chosen every frame so that the vehicle's
// centre appears at an aim point: the image centre plus a slow wander, plus a swing that carries
// it out through one side of the image (picked by the seed) and back. The swing's timing is
// solved for at construction, so in_view is false exactly in frames out_of_view_start ..
// out_of_view_start + out_of_view_frames − 1. The ground under the camera moves with the
// vehicle's speed, the swing, the yaw rate and the altitude and tilt changes: with the defaults
// a ground point moves 1–7 px a frame (≤ 6.7 px anywhere in the image over seeds 1–30; ≤ 4 px
// at the centre) and the image turns ≤ 0.5° a frame.
//
// Ground texture: an infinite, non-periodic patchwork of fields (columns with jittered edges, each
// cut into fields with their own jittered edges; hashed grey levels), some straight roads, and
// small dark or light discs and squares (bushes, huts) on a jittered lattice — corners everywhere
// at the default scale (~2.5 px/m). Hashed from the seed and integer cell indices, so it is the
// same wherever and whenever it is seen. The vehicle is a dark box with a bright roof, drawn on
// the ground; both are rendered through the inverse homography with 3×3 samples per pixel. The
// flare (the occluder) is a saturated disc with a halo, in image space, over the vehicle. Then
// Gaussian noise; rounded and clamped to 0..255.
//
// Determinism: IEEE +, −, ×, ÷, sqrt and floor, det_math's sincos, the project's PCG32 and
// integer hashes only, compiled with -ffp-contract=off: the same config gives the same bytes on
// x86-64 and aarch64.
#pragma once
#include <stdint.h>

#include "io/grey_image.h"

namespace qt::scene {

struct GroundSequenceConfig {
    int width = 320, height = 240;  // px
    int frames = 360;
    uint64_t seed = 1;             // terrain, vehicle start, wander, exit side, flare drift
    int out_of_view_start = 110;   // first frame with the vehicle's box not wholly in the image
    int out_of_view_frames = 100;  // frames until its box is wholly inside again (0: never out)
    int occlusion_start = 40;      // first frame the flare covers the vehicle
    int occlusion_frames = 12;     // (0: no flare)
    double noise_sigma = 2.0;      // Gaussian pixel noise, grey levels

    // Camera.
    double focal_px = 300;             // focal length: 56° horizontal field of view at 320 px
    double altitude_m = 100;           // mean altitude: ~2.5 px/m at the image centre
    double altitude_variation = 0.10;  // altitude = mean·(1 ± this), a sinusoid …
    int altitude_period_frames = 240;  // … of this period
    double tilt_deg = 30;              // optical axis from nadir, forward (perspective)
    double tilt_variation_deg = 3;     // tilt ± this, a sinusoid …
    int tilt_period_frames = 300;      // … of this period
    double yaw_rate_deg = 0.2;         // heading change, degrees a frame (image rotation)

    // Vehicle (the target): constant speed, straight on by default (a turn is an option).
    double target_speed_m = 0.2;   // metres a frame (5 m/s at 25 frames/s)
    double target_turn_deg = 0.0;  // heading change, degrees a frame (0: a straight road)
    double target_length_m = 4.0, target_width_m = 2.8;  // ~10 × 7 px at the default scale

    // Where the vehicle appears in the image.
    double wander_px = 15;             // slow drift of the aim point about the image centre, px
    double swing_speed_px = 3.0;       // top speed of the swing out of view and back, px a frame
    double out_of_view_depth_px = 60;  // a full swing puts the vehicle's centre this far
                                       // beyond the image border, px

    bool draw_target = true;  // false: the ground and the flare only (tests isolate the
                              // vehicle's pixels by difference)
};

struct GroundTruth {
    double target_x = 0, target_y = 0;  // vehicle centre in this frame's image, px (pixel centres
                                        // at integers); may lie outside the image
    bool in_view = false;               // the vehicle's box lies wholly inside the image
                                        // [−0.5, w − 0.5] × [−0.5, h − 0.5]
    bool occluded = false;              // the flare's core covers the vehicle's centre
    double h_from_previous[9] = {};     // previous frame's image points → this frame's (ground
                                        // plane), row-major, h[8] = 1; identity for frame 0
    double h_ground_to_image[9] = {};   // ground (X, Y, 1) in metres → image px, row-major,
                                        // scaled so that the third coordinate is the point's
                                        // depth along the optical axis in metres (> 0 in front
                                        // of the camera; h[8] is not 1: the ground origin may
                                        // lie anywhere, even behind the camera)
    int target_w = 0, target_h = 0;     // the vehicle's image bounding box, px (rounded)
};

class GroundSequence {
public:
    // Throws std::invalid_argument on a bad size or frame count, or when the requested
    // out-of-view spell cannot be produced at swing_speed_px (too short to get the box out).
    explicit GroundSequence(const GroundSequenceConfig& config);

    int frames() const { return config_.frames; }
    const GroundSequenceConfig& config() const { return config_; }

    GroundTruth truth(int frame) const;     // 0 <= frame < frames(), else std::out_of_range
    io::GreyImage render(int frame) const;  // deterministic: same config → same bytes

private:
    struct State;  // camera and vehicle at a (possibly fractional) time, in frames
    State state_at(double t) const;
    double swing_at(double t) const;    // 0 (aim point at home) .. 1 (full swing)
    double box_excess(double t) const;  // how far the vehicle's box sticks out of the image, px
                                        // (≤ 0: wholly inside)
    void time_swing();                  // solves rise_t0_ and fall_t0_ for the spell
    bool flare_offset(int frame, double& dx, double& dy) const;  // false: no flare this frame

    GroundSequenceConfig config_;
    // Drawn from the seed at construction.
    double start_x_ = 0, start_y_ = 0, start_heading_ = 0;  // vehicle at frame 0: m, m, rad
    double yaw0_ = 0;                                       // camera heading at frame 0, rad
    double altitude_phase_ = 0, tilt_phase_ = 0;            // rad
    double wander_phase_x_ = 0, wander_phase_y_ = 0;        // rad
    double side_x_ = 0, side_y_ = 0;      // unit direction of the swing in the image
    double flare_dx_ = 0, flare_dy_ = 0;  // unit direction of the flare's drift over the vehicle
    // The swing: the camera turns by up to swing_rad_; one ramp lasts swing_frames_; the ramp
    // out starts at rise_t0_, the ramp back at fall_t0_ (frames).
    double swing_rad_ = 0, swing_frames_ = 0, rise_t0_ = 0, fall_t0_ = 0;
};

// The test command's sequence: 72 frames, flare over frames 8–15, out of view 36–55
// (20 frames), back in view from frame 56. The swing out is long (the image centre moves at most
// swing_speed_px a frame), so the camera is already turning at frame 0.
GroundSequenceConfig short_ground_sequence();

// The benches' sequence: the defaults above (360 frames, flare 40–51, out of view 110–209).
GroundSequenceConfig long_ground_sequence();

}  // namespace qt::scene
