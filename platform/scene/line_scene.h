// Synthetic line and polygon scenes with exact ground truth, for accuracy tests of the line
// and quadrangle chain: anti-aliased straight lines and filled polygons over a background
// with optional smooth texture and clutter blobs, then Gaussian blur and Gaussian noise.
// Host only (heap, double). Randomness comes from qt::Pcg32 alone and the double arithmetic
// uses only IEEE basic operations and sqrt (own exp/log/sin/cos, FP contraction off), so a
// (scene, seed) pair gives the same bytes on every platform.
#pragma once
#include <stdint.h>

#include <vector>

#include "base/prng.h"
#include "io/grey_image.h"

namespace qt::scene {

// A point in pixels; pixel centres at integer coordinates, pixel (x, y) covers
// [x - 0.5, x + 0.5] × [y - 0.5, y + 0.5].
struct Point2 {
    double x, y;
};

// Ground truth of one straight edge or drawn line, end points in pixels.
struct TrueSegment {
    Point2 a, b;
};

struct SceneOptions {
    int width = 320, height = 240;  // pixels
    uint8_t background = 60;        // grey level
    double noise_sigma = 0;         // Gaussian noise, grey levels (clamped to 0..255 after adding)
    double blur_sigma = 0;    // Gaussian blur of the rendered scene before noise, pixels (0 = none)
    int clutter_blobs = 0;    // random filled discs/ellipses of random grey under the shapes
    int clutter_texture = 0;  // peak amplitude of a smooth random background texture, grey levels
    uint64_t seed = 1;        // texture, clutter and noise (and the random_* generators)
    uint8_t clutter_blob_max =
        255;  // clutter blobs' grey levels are uniform in 0..clutter_blob_max
    // Smooth multiplicative illumination of the composed scene (background, texture, blobs and
    // shapes), applied before blur and noise; with d = (x − centre_x, y − centre_y) px:
    //   gain(x, y) = max(0, centre_gain + ramp_x·d.x + ramp_y·d.y − falloff·|d|²).
    // The defaults are gain ≡ 1: the render is then unchanged (the multiply is skipped).
    struct Illumination {
        double centre_x = 0, centre_y = 0;  // px, origin of the ramp and centre of the falloff
        double centre_gain = 1;             // gain at the centre, before the falloff
        double ramp_x = 0, ramp_y = 0;      // gain change per px along x and along y
        double falloff = 0;                 // gain decrease per px² of squared distance, >= 0
    } illumination;
};

class LineScene {
public:
    // Throws std::invalid_argument on a non-positive size, a negative sigma/count/falloff or a
    // non-finite illumination parameter.
    explicit LineScene(const SceneOptions& options);

    // A straight line of `width_px` pixels thickness (the rectangle a-b widened by width_px / 2
    // on each side, no caps), grey level `level`, anti-aliased. Ground truth: the centre line a-b.
    // Throws std::invalid_argument if a == b or width_px <= 0.
    void add_line(Point2 a, Point2 b, double width_px, uint8_t level);

    // A filled simple polygon, convex or concave (vertices in order, either winding), grey
    // level `level`, anti-aliased. Ground truth: one TrueSegment per side, v[i] -> v[i + 1 mod n].
    // Throws std::invalid_argument for fewer than 3 vertices.
    void add_polygon(const std::vector<Point2>& vertices, uint8_t level);
    // The same with a level that changes linearly across the frame (a shaded surface): grey
    // level + ramp_x·(x − vertices[0].x) + ramp_y·(y − vertices[0].y) at pixel (x, y).
    void add_shaded_polygon(const std::vector<Point2>& vertices, double level, double ramp_x,
                            double ramp_y);

    // A background of width × height grey levels (row-major; e.g. a photograph) instead of the
    // flat options().background; texture and blobs still go on top. Throws
    // std::invalid_argument on a wrong size.
    void set_background(std::vector<double> levels);

    // Background (+ texture, + clutter blobs), the shapes in the order added, illumination,
    // blur, noise;
    // rounded and clamped to 0..255. Coverage: 8×8 samples per pixel on edge pixels.
    io::GreyImage render() const;

    const std::vector<TrueSegment>& truth() const { return truth_; }  // in order added
    const SceneOptions& options() const { return options_; }

private:
    struct Shape {
        std::vector<Point2> polygon;  // pixels
        double level;                 // grey level at polygon[0]
        double ramp_x, ramp_y;        // its change per px along x and y
    };
    SceneOptions options_;
    std::vector<double> background_;  // empty: options_.background everywhere
    std::vector<Shape> shapes_;
    std::vector<TrueSegment> truth_;
};

// Uneven lighting over a w × h frame: a ramp of up to 1 per half diagonal along a random
// direction minus a radial falloff around a hot spot near the frame, rescaled so that the gain
// over the pixel centres spans [gain_lo, 1]. Draws from `rng` in any case; returns false (and
// leaves *out alone: even lighting) when gain_lo >= 1.
bool uneven_illumination(int w, int h, double gain_lo, Pcg32& rng, SceneOptions::Illumination* out);

// `polygons` random convex triangles/quadrangles, sides >= min_side px, inner angles >=
// min_corner_deg, every vertex at least 4 px inside the outermost pixel centres, grey level in
// 10..245 and at least 60 from the background, circumcircles at least 4 px apart (no polygon
// hides another's side). Deterministic in options.seed. Throws std::invalid_argument if such a
// polygon cannot fit, std::runtime_error if no placement is found.
LineScene random_polygon_scene(const SceneOptions& options, int polygons, double min_side,
                               double min_corner_deg = 0);

// `lines` random straight lines of width 2 px, grey level in 10..245 and >= 60 from the
// background, length in [min_len, max_len] px, end points at least 4 px inside the outermost
// pixel centres (lines may cross). Deterministic in options.seed. Throws std::invalid_argument
// unless 0 < min_len <= max_len and min_len fits in the frame.
LineScene random_line_scene(const SceneOptions& options, int lines, double min_len, double max_len);

}  // namespace qt::scene
