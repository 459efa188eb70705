// The compile-time capacities of the pipeline for one camera size, as one named configuration:
// each stage reads the fields it needs (LineDetector<Qvga>, BoardDetector<Qvga>,
// TargetPipeline<Qvga>). A variant overrides fields by deriving:
//   struct TwoSegments : qt::Qvga { static constexpr uint16_t segments = 2; };
// When one fills, a stage keeps going and says so (Status::capacity_exceeded and its stats).
#pragma once
#include <stdint.h>

namespace qt {

struct Qvga {
    // The largest frame, px.
    static constexpr uint16_t max_width = 320, max_height = 240;
    // Lines stage: edge points kept (the strongest, lines/edge_list.h); the Hough accumulator's
    // angle bins over 180° and distance step, px (its bins follow from the frame); PPHT's
    // segments and the clustered lines.
    static constexpr uint16_t edge_points = 4096;
    static constexpr uint16_t theta_bins = 90, rho_step = 2;
    static constexpr uint16_t segments = 64, lines = 32;
    // Quadrangles: parallel line pairs searched; candidates ranked by their lines' coverage,
    // verified by their edge evidence in that order until `quads` are kept.
    static constexpr uint16_t parallel_pairs = 128, quad_candidates = 8, quads = 4;
    // Target tracker: Harris corners a frame, their patches' radius (9 × 9 at 4), the largest
    // template side and the side of the region captured around the expected target, px.
    static constexpr uint16_t features = 96;
    static constexpr int patch_radius = 4;
    static constexpr uint8_t max_template = 16;
    static constexpr uint16_t max_region = 84;
    // The work window of the morphological detector (the paper's Table III step 2, an option
    // beside the NCC template), px a side: 12 192 B of RAM at 84. 0 leaves the detector out of the
    // build (firmware that uses the template), and asking for it is then Status::not_in_build.
    static constexpr uint16_t morph_region = 84;
};

// QVGA without the morphological detector: firmware that measures with the NCC template (the
// default) and has no RAM for a detector it never uses (the Cortex-M4F target image).
struct QvgaTemplateOnly : Qvga {
    static constexpr uint16_t morph_region = 0;
};

// The host and ARM Linux configuration (no 64 KiB budget): a 640 × 480 facade holds more edge
// pixels at the default threshold than 8192, and a board's weakest side must not be what a
// full list thins away (the photo bench: bash bench.sh photos-host).
struct Vga : Qvga {
    static constexpr uint16_t max_width = 640, max_height = 480;
    static constexpr uint16_t edge_points = 16384;
    static constexpr uint16_t segments = 128, lines = 64;
    static constexpr uint16_t parallel_pairs = 256;
    static constexpr uint16_t features = 160;
};

}  // namespace qt
