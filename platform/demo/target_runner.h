// The target pipeline (core/target/float/target_pipeline.h) run over a generated ground sequence
// (platform/scene/ground_sequence.h) with its truth beside it: what the target bench, the
// end-to-end test and the demo share. Host only.
#pragma once
#include <vector>

#include "scene/ground_sequence.h"
#include "target/float/target_pipeline.h"

namespace qt::cli {

// One frame's outcome next to the truth.
struct TargetRunFrame {
    TargetFrame result;
    scene::GroundTruth truth;
    double error_px = 0;     // |estimate − truth|, px
    Homography accumulated;  // the tracker's A after the frame: reference image → this one
};

// The box of frame 0 the tracker starts from: side × side px (odd) centred on the pixel nearest
// the truth's target centre.
struct TargetBox {
    int x, y, side;
};
TargetBox start_box(const scene::GroundTruth& truth0, int side = 15);

// Renders each frame of `sequence` (or takes it from `frames` when that holds them all) and
// runs the QVGA pipeline with `config`, starting on start_box(frame 0). Frames larger than
// 320 × 240 are refused (std::invalid_argument).
std::vector<TargetRunFrame> run_target_sequence(const scene::GroundSequence& sequence,
                                                const TargetPipelineParams& config,
                                                const std::vector<io::GreyImage>* frames = nullptr);

// The configuration of the QVGA pipeline used by the bench, the tests and the demo.
TargetPipelineParams qvga_target_config(TargetMethod method = TargetMethod::fused,
                                        bool reset = true);

}  // namespace qt::cli
