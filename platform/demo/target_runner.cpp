#include "demo/target_runner.h"

#include <cmath>
#include <memory>
#include <stdexcept>

namespace qt::cli {

TargetBox start_box(const scene::GroundTruth& t, int side) {
    const int half = side / 2;
    return {static_cast<int>(std::lround(t.target_x)) - half,
            static_cast<int>(std::lround(t.target_y)) - half, side};
}

TargetPipelineParams qvga_target_config(TargetMethod method, bool reset) {
    TargetPipelineParams c;
    c.tracker.method = method;
    c.tracker.reset = reset;
    return c;
}

std::vector<TargetRunFrame> run_target_sequence(const scene::GroundSequence& sequence,
                                                const TargetPipelineParams& config,
                                                const std::vector<io::GreyImage>* frames) {
    const int w = sequence.config().width, h = sequence.config().height;
    if (w > 320 || h > 240)
        throw std::invalid_argument("run_target_sequence: frames above 320 x 240");
    auto pipeline = std::make_unique<TargetPipelineQvga>();
    const TargetBox box = start_box(sequence.truth(0));
    pipeline->set_target(box.x, box.y, static_cast<uint8_t>(box.side),
                         static_cast<uint8_t>(box.side));
    const bool given = frames && static_cast<int>(frames->size()) == sequence.frames();
    std::vector<TargetRunFrame> run;
    io::GreyImage rendered;
    for (int k = 0; k < sequence.frames(); ++k) {
        if (!given) rendered = sequence.render(k);
        const io::GreyImage& image = given ? (*frames)[static_cast<size_t>(k)] : rendered;
        TargetRunFrame f;
        f.truth = sequence.truth(k);
        pipeline->begin_frame(static_cast<uint16_t>(w), static_cast<uint16_t>(h), config);
        for (int y = 0; y < h; ++y) pipeline->push_row(image.row(y), static_cast<uint16_t>(w));
        pipeline->finish(f.result);
        f.accumulated = pipeline->tracker().accumulated();
        f.error_px = std::hypot(f.result.estimate.x - f.truth.target_x,
                                f.result.estimate.y - f.truth.target_y);
        run.push_back(f);
    }
    return run;
}

}  // namespace qt::cli
