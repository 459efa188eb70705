// A bright board composited under perspective onto a real photograph, with ground-truth corners:
// what a camera sees when someone holds a card up in a real room. The photograph (any size, grey
// levels) is cropped to the frame's aspect at a random place and size, resampled, exposed for the
// board (its white, 255, becomes `darken` × the board's level: below 1 the card is the brightest
// surface, above 1 a pale wall, window or sky outshines it, clipped at 255) and lit unevenly; the
// board (aspect 4:3, 16:9 or 1:1; grey 200–245 with mild shading and sometimes faint print) is
// drawn over it, optionally with a dark disc or arm over part of one side; then blur and noise. Or
// the same frame without the board. Host only (heap, double); randomness from qt::Pcg32 and
// arithmetic from det_math.h (FP contraction off), so an (options, photograph, seed) triple gives
// the same bytes on every platform.
#pragma once
#include <stdint.h>

#include "io/grey_image.h"
#include "scene/board_pose.h"
#include "scene/line_scene.h"  // Point2

namespace qt::scene {

// Every range [min, max] is drawn uniformly per frame.
struct PhotoBoardOptions {
    int width = 640, height = 480;  // frame, px (>= 64 × 48)
    double tilt_deg_max = 35;       // BoardPose::tilt_deg in [0, max], degrees (<= 80)
    double roll_deg_max = 25;       // BoardPose::rotation_deg in [−max, max], degrees
    // BoardPose::scale (the board's bounding box over the frame in its tighter direction): for
    // a 4:3 board in a 4:3 frame, its height over the frame's.
    double scale_min = 0.25, scale_max = 0.70;
    int board_level_min = 200, board_level_max = 245;  // board grey before lighting, <= 255
    double shading_max = 0.10;  // largest level change across the board, fraction of its level
    double print_share = 0.5;   // share of boards with faint print (2–5 lines of "text")
    double darken_min = 0.5,
           darken_max = 0.9;       // the photograph's white over the board's level, (0, 1.25]
    double light_gain_min = 0.6;   // darkest illumination gain over the frame (brightest 1), (0, 1]
    double blur_sigma_max = 1.25;  // Gaussian blur σ in [0, max] px (a 5-px kernel spans ±2σ)
    double noise_sigma_min = 2, noise_sigma_max = 7;  // Gaussian noise, grey levels
    bool board = true;                                // false: the same frame without the board
    // A dark disc or arm (half of the frames each) over 15–70 % of one side >= 30 px long, with
    // at least max(6 px, 10 % of the side) of it visible at each end; no corner is covered.
    bool occlude = false;
};

// The board shapes drawn (width : height), one per frame uniformly.
constexpr double kPhotoBoardAspects[3] = {4.0 / 3.0, 16.0 / 9.0, 1.0};

struct PhotoBoardScene {
    io::GreyImage image;
    bool has_board = false;
    // Ground truth, px: the display's top-left, bottom-left, bottom-right, top-right corners
    // (anti-clockwise as seen), each >= 4 px inside the outermost pixel centres; zero without
    // a board.
    Point2 corners[4] = {};
    double aspect = 0;  // width / height of the board drawn (0 without)
    BoardPose pose;
    // The occluded side (corners[i] -> corners[i + 1 mod 4]) and the part of it covered, as
    // fractions of its length from corners[i]; -1 when none.
    int occluded_side = -1;
    double occluded_from = 0, occluded_to = 0;
    bool occluder_is_disc = false;
    bool printed = false;  // the board carries faint print
    int board_level = 0;   // before shading and lighting
    double darken = 1, light_gain_min = 1, blur_sigma = 0, noise_sigma = 0;
};

// Throws std::invalid_argument on options out of range or an empty photograph.
PhotoBoardScene make_photo_board_scene(const PhotoBoardOptions& options, const io::GreyImage& photo,
                                       uint64_t seed);

// A sequence in front of one photograph: a 4:3 board tilted 20° moves along an ellipse
// (±18 % of the width, ±12 % of the height around the centre; one turn in `frames` frames),
// turns ±10° and scales ±10 % around `scale`; in frames [arm_first, arm_first + arm_frames) a
// dark arm crosses 30 % of its bottom side (35–65 % of it, 12 % of the board's height deep).
// The background, its lighting and the blur are those of frame 0; the noise changes per frame.
struct PhotoSequenceOptions {
    int width = 640, height = 480;
    int frames = 150;
    double scale = 0.45;
    int arm_first = 70, arm_frames = 15;
    uint64_t seed = 1;
};

// Frame `index` (0 <= index < frames) of the sequence.
PhotoBoardScene make_photo_sequence_frame(const PhotoSequenceOptions& options,
                                          const io::GreyImage& photo, int index);

// The photograph cropped to a w:h window (at least `min_share` of the largest such window, at
// a random place) and resampled to w × h grey levels, row-major (box filter of the output
// pixel's footprint, at least one input pixel wide, so it also interpolates when enlarging).
std::vector<double> photo_background(const io::GreyImage& photo, int w, int h, double min_share,
                                     Pcg32& rng);

}  // namespace qt::scene
