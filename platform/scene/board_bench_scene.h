// Board scenes with ground-truth corners for the detection benchmark: a bright rectangular board
// (a display of a given aspect) seen by a pinhole camera under perspective, over a darker
// textured background with clutter that has straight edges but is not board-like (lines,
// triangles, thin bars, strongly skewed parallelograms), uneven lighting, blur and noise;
// optionally an arm-like occluder over part of one side; or the same kind of frame without a
// board. Host only (heap, double). All randomness comes from qt::Pcg32 seeded from the scene
// seed, and the double arithmetic uses only IEEE basic operations and sqrt (det_math.h, FP
// contraction off), so an (options, seed) pair gives the same bytes on every platform.
//
// Rendering is LineScene's (line_scene.h): background + SceneOptions::clutter_texture +
// clutter_blobs, then clutter lines and shapes, then the board (drawn over any clutter below
// it, so nothing overlaps its interior), then the occluder, then illumination, blur, noise.
#pragma once
#include <stdint.h>

#include <vector>

#include "io/grey_image.h"
#include "scene/line_scene.h"  // Point2, TrueSegment

namespace qt::scene {

// Every range [min, max] is drawn uniformly per scene; min == max pins the value.
struct BoardBenchOptions {
    int width = 320, height = 240;  // frame, pixels (>= 64 × 48)
    double aspect = 4.0 / 3;        // board (display) width / height, in [0.25, 4]
    double focal_px = 0;            // pinhole focal length, px; 0 = the frame width. Principal
        // point at the frame centre ((width − 1) / 2, (height − 1) / 2).
    // Tilt: the angle between the board's normal and the optical axis, degrees, in [0, 80]; the
    // board plane is turned by it about an axis lying in the board plane, of uniform direction.
    double tilt_deg_min = 0, tilt_deg_max = 40;
    // In-plane rotation of the board about its normal, applied before the tilt, degrees, in
    // [-180, 180]. Positive turns clockwise as seen in the image (y down): at tilt 0 the
    // display's top side (top-left -> top-right) points along (cos r, sin r) in pixels.
    double rotation_deg_min = -30, rotation_deg_max = 30;
    // Scale: max(bbox_width / width, bbox_height / height) of the projected board, where
    // bbox_width = max x − min x of the four corners in px (likewise height): the board's
    // bounding box spans `scale` of the frame in its tighter direction. In
    // (0, min((width − 9) / width, (height − 9) / height)] so a fitting position exists.
    double scale_min = 0.15, scale_max = 0.8;
    double noise_sigma_min = 4, noise_sigma_max = 4;    // Gaussian noise, grey levels, >= 0
    double blur_sigma_min = 0.7, blur_sigma_max = 0.7;  // Gaussian blur, px, >= 0
    // Lighting: gain = linear ramp + radial falloff, rescaled so that over the pixel centres
    // its maximum is 1 and its minimum is drawn in [light_gain_min, 1]; in (0, 1], 1 = even.
    double light_gain_min = 0.55;
    int board_level_min = 170,
        board_level_max = 240;  // board grey level before lighting, in [130, 255]
    int clutter_texture = 20;  // peak amplitude of the smooth background texture, grey levels, >= 0
    int clutter_blobs = 6;     // LineScene clutter discs/ellipses, grey 0..board_level − 50
    int clutter_lines = 6;     // straight lines, 1–3 px wide, 8–60 % of min(width, height) long
    int clutter_shapes =
        6;  // triangles, thin bars (length >= 6 × width), parallelograms with a 15–40° angle
    bool board = true;     // false: a board-free frame (same background, clutter, light, noise)
    bool occlude = false;  // an arm over part of one side (ignored without a board)
};

struct BoardBenchScene {
    io::GreyImage image;
    bool has_board = false;
    // Ground truth, px (pixel centres at integer coordinates, as in line_scene.h): the display's
    // top-left, bottom-left, bottom-right, top-right corners. That order is anti-clockwise as
    // seen in the image: with y pointing down, the shoelace sum
    //   S = Σ_i (x_i·y_{i+1} − x_{i+1}·y_i)  (i + 1 mod 4)
    // is negative (S = −2·area). Every corner lies in [4, width − 5] × [4, height − 5].
    // All zero without a board.
    Point2 corners[4] = {};
    // -1: no occlusion; else side i = corners[i] -> corners[(i + 1) % 4] is covered from
    // fraction occluded_from to occluded_to of its length (0 at corners[i], 1 at corners[i + 1]),
    // at least 10 px from either corner and at most half the side; no other side and no corner
    // is covered. -1 also when occlusion was asked but no side is >= 30 px long.
    int occluded_side = -1;
    double occluded_from = 0, occluded_to = 0;
    // The pose actually used (0 without a board): tilt_deg and rotation_deg as defined in
    // BoardBenchOptions, tilt_axis_deg the direction of the tilt axis in the board plane before
    // the rotation (degrees from the display's x axis), scale as defined there.
    double tilt_deg = 0, rotation_deg = 0, tilt_axis_deg = 0, scale = 0;
    double focal_px = 0;                     // px, the focal length used
    double noise_sigma = 0, blur_sigma = 0;  // grey levels, px: the values drawn
    double light_gain_min = 1;  // darkest illumination gain over the pixel centres (brightest: 1)
    int board_level = 0;        // board grey level before lighting (drawn even without a board)
    int background_level = 0;   // background grey level before texture and lighting
    // The clutter drawn (px): centre lines of the straight lines, and the shapes' vertices.
    std::vector<TrueSegment> clutter_lines;
    std::vector<std::vector<Point2>> clutter_shapes;
};

// Throws std::invalid_argument on options outside the documented ranges and
// std::runtime_error if no board placement is found (not expected within those ranges).
BoardBenchScene make_board_bench_scene(const BoardBenchOptions& options, uint64_t seed);

}  // namespace qt::scene
