// The synthetic line motions of the Quadrangle Detection paper §3 and its score, the overlap ratio,
// in double precision, for benchmarking the line tracker (core/tracking/line_tracker.h) against
// exact ground truth. Host only (heap, double). Randomness comes from qt::Pcg32 and sines/cosines
// from det_math.h, so the data are the same on every platform; measured_segment() uses std::atan2,
// whose last ulp may differ between libms (it can flip a binary angle's last unit, 8e-8°, very
// rarely).
//
// Coordinates: pixels, pixel centres at integers, x to the right, y down; angles in degrees
// measured from +x towards +y (clockwise on screen), as in core/lines/segment.h.
#pragma once
#include <stdint.h>

#include <vector>

#include "lines/segment.h"
#include "scene/line_scene.h"  // Point2
#include "tracking/line_tracker.h"

namespace qt::scene {

// A ground-truth segment: its two end points, pixels.
struct GtSegment {
    double x1, y1, x2, y2;
};

// One track: the truth in frames 0, 1, 2, ...
using GtTrack = std::vector<GtSegment>;

// The segment as a line detector would report it, every field rounded to nearest (ties away
// from zero): end points as given, rho >= 0 the distance of the line from the image origin,
// theta the direction of its normal from the origin towards the line (for a line through the
// origin, the normal (−dy, dx) of the direction end 1 -> end 2), cx, cy = rho·(cos θ, sin θ),
// points = 0, bright_side = 0. Throws std::invalid_argument if the end points coincide.
Segment measured_segment(const GtSegment& s);

// The overlap ratio of §3, in [0, 1]. The truth is drawn band_px wide: pixel (x, y) (integer
// centre) lies in the band when its centre is within band_px / 2 (inclusive) of the truth
// *segment* (round caps at the ends, not the infinite line). The tracker reports an infinite
// line, so it is drawn over the truth's extent: the piece between the truth's two end points
// projected perpendicularly onto the tracked line (rho, theta; the tracked end points are not
// used). That piece is rasterised one pixel per step along its major axis (DDA): every integer
// column (row) from its rounded start to its rounded end, the other coordinate being the line's
// there, rounded to nearest (ties towards +inf). Result = pixels in the band / pixels drawn.
// Throws std::invalid_argument unless band_px > 0.
double overlap_ratio(const GtSegment& truth, const Segment& tracked, double band_px = 2.0);

constexpr int kMotionFrames = 20;  // frames per track (§3: "20 consecutive frames")
constexpr int kMotionTracks = 20;  // random segments (Exp. 1) or start angles (Exp. 2)

// Experiment 1's random segments: centre uniform over [0, width − 1] × [0, height − 1] (the
// outermost pixel centres), direction uniform in [0°, 180°), length uniform in [40, 160] px.
// Deterministic in seed.
std::vector<GtSegment> random_segments(uint64_t seed, int count = kMotionTracks, int width = 320,
                                       int height = 240);

// Experiment 1's motion: in frame k the segment is `base` moved by k·speed·(cos φ, sin φ),
// φ = direction_deg, speed in px/frame. No clipping: segments may leave the frame (the score
// is geometric).
GtTrack translation_track(const GtSegment& base, double direction_deg, double speed_px,
                          int frames = kMotionFrames);

// Experiment 2's motion: in frame k the line is {p : n_k·(p − centre) = r} with normal
// n_k = (cos θ_k, sin θ_k), θ_k = theta0_deg + k·omega_deg (omega in °/frame), so its Hough
// distance from `centre` stays r px; the segment is length_px long, centred at the tangent
// point centre + r·n_k.
GtTrack rotation_track(Point2 centre, double r_px, double theta0_deg, double omega_deg,
                       int frames = kMotionFrames, double length_px = 100);

// Experiment 2's start angles θ0: uniform in [0°, 360°), deterministic in seed.
std::vector<double> random_start_angles(uint64_t seed, int count = kMotionTracks);

struct MotionOptions {
    double noise_sigma = 0;  // Gaussian noise on each measured end-point coordinate, px (§3: 0)
    uint64_t seed = 1;       // the random segments / start angles and the noise
    double band_px = 2;      // width of the ground-truth band, px (§3: 2)
    // §3: "the length of the line is not fixed for some data set to simulate the lines
    // extracted in real images". Below 1, each frame's segment is a random piece of the
    // track's segment, of length share uniform in [min_length_share, 1] and placed uniformly
    // along it (its own stream, the same for every tracker); it is that frame's truth and the
    // measurement. 1: fixed length.
    double min_length_share = 1;
};

// One tracker over one track: init() on frame 0's measurement; then for each frame k >= 1,
// predict(), score line() against frame k's truth, update() with frame k's measurement.
// Returns the mean overlap over frames 1 .. n − 1, in [0, 1]. Measurements are the truth plus
// end-point noise of options.noise_sigma drawn from noise_stream (each track its own stream, so
// every tracker sees the same noise). Throws std::invalid_argument for fewer than 2 frames.
double track_mean_overlap(const GtTrack& track, const LineTrackerParams& params,
                          const MotionOptions& options = MotionOptions{},
                          uint64_t noise_stream = 0);

// Experiment 1: overlap[s][d] = mean of track_mean_overlap over the random segments moving at
// speeds[s] px/frame in direction directions_deg[d].
struct TranslationTable {
    std::vector<double> speeds;                // px/frame: 1, 2, 3
    std::vector<double> directions_deg;        // 0, 15, ..., 345
    std::vector<std::vector<double>> overlap;  // [speed][direction], [0, 1]
};
TranslationTable translation_experiment(const LineTrackerParams& params,
                                        const MotionOptions& options = MotionOptions{});

// Experiment 2 about `centre`: overlap[i][j] = mean of track_mean_overlap over the start angles
// for radius radii[i] px and turn rate omegas_deg[j] °/frame.
struct RotationTable {
    Point2 centre;                             // px
    std::vector<double> radii;                 // px: 10, 50, 100
    std::vector<double> omegas_deg;            // °/frame: 1, 2, 4, 8, 16
    std::vector<std::vector<double>> overlap;  // [radius][omega], [0, 1]
};
RotationTable rotation_experiment(const LineTrackerParams& params, Point2 centre,
                                  const MotionOptions& options = MotionOptions{});

// The mean of a row of overlaps (0 for an empty row).
double mean_of(const std::vector<double>& values);

}  // namespace qt::scene
