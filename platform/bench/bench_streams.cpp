// The board sequences at camera sizes, as `quadtrack track` runs them (binned to fit the VGA
// build, results in the camera's pixels), with each line model: the figures behind the default
// model and behind "any camera size" (docs/cli.md, docs/tracking.md). Markdown tables on stdout.
// Corner errors are the worst distance of the tracked corners from the scene generator's, px of
// the camera frame; "hidden" is over the frames with a side under a bar, "after" from the first
// frame after the bars on, "all" over every frame.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "demo/demo_sequence.h"
#include "host/board_runner.h"
#include "io/error_line.h"

namespace {

struct Camera {
    int width, height;
};

struct Sequence {
    const char* name;
    qt::scene::BoardMotionSpec spec;
};

struct Figures {
    double hidden = 0, after = 0, all = 0, mean = 0;
    int predicted = 0, taken_back = 0, lost = 0;  // side-frames predicted, sides taken, tracks lost
};

bool measure(const Sequence& s, Camera c, qt::LineModel model, uint8_t& bin, Figures& out) {
    std::string error;
    bin = qt::host::choose_bin(c.width, c.height, 0, error);
    std::vector<qt::cli::BoardTrackFrame> frames;
    if (bin == 0 || !qt::cli::track_board_sequence(
                        s.spec, c.width, c.height,
                        qt::cli::demo_tracker_params(model, static_cast<uint16_t>(c.width / bin),
                                                     static_cast<uint16_t>(c.height / bin)),
                        frames, error)) {
        qt::io::print_error_line(stderr, "bench_streams: %s at %d x %d: %s", s.name, c.width,
                                 c.height, error.c_str());
        return false;
    }
    out = Figures{};
    for (size_t f = 0; f < frames.size(); ++f) {
        const qt::cli::BoardTrackFrame& k = frames[f];
        // No quadrangle counts as an unbounded error.
        const double e = k.worst_error_px < 0 ? 1e9 : k.worst_error_px;
        out.all = std::max(out.all, e);
        out.mean += e / static_cast<double>(frames.size());
        if (k.hidden) out.hidden = std::max(out.hidden, e);
        if (static_cast<int>(f) > s.spec.last_hidden) out.after = std::max(out.after, e);
        for (int i = 0; i < 4; ++i) {
            out.predicted +=
                ((k.quad.detected >> i) & 1) == 0 && k.quad.state != qt::TrackState::none;
            out.taken_back += (k.taken_back >> i) & 1;
        }
        out.lost += k.lost != qt::QuadTrackLost::none;
    }
    return true;
}

}  // namespace

int main() {
    const Sequence sequences[] = {
        {"demo (bars over top and bottom, frames 5-7, 2.5 deg/frame)", qt::scene::kDemoSequence},
        {"turning (bar over the bottom, frames 6-9, 3 deg/frame)", qt::scene::kTurningSequence},
    };
    const Camera cameras[] = {{640, 480}, {768, 576}, {1280, 720}, {1920, 1080}};
    const struct {
        const char* name;
        qt::LineModel model;
    } models[] = {{"paper (3KF)", qt::LineModel::closest_points}, {"turn", qt::LineModel::turn}};
    for (const Sequence& s : sequences) {
        std::printf("Board sequence: %s; worst corner error, camera px\n\n", s.name);
        std::printf(
            "| camera | bin | model | hidden | after the bars | all frames | mean | sides "
            "predicted | taken back | lost |\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for (const Camera& c : cameras) {
            for (const auto& m : models) {
                uint8_t bin = 0;
                Figures f;
                if (!measure(s, c, m.model, bin, f)) return 1;
                std::printf("| %d x %d | %d | %s | %.2f | %.2f | %.2f | %.2f | %d | %d | %d |\n",
                            c.width, c.height, bin, m.name, f.hidden, f.after, f.all, f.mean,
                            f.predicted, f.taken_back, f.lost);
            }
        }
        std::printf("\n");
    }
    return 0;
}
