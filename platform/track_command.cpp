#include "track_command.h"

#include "detect_command.h"
#include "detect_json.h"
#include "image_io.h"
#include "quad_tracker.h"

namespace qt::cli {

std::string track_usage() {
    return "usage: quadtrack track SEQUENCE [OPTIONS]\n"
           "  SEQUENCE is a Y4M file (every frame's Y plane), a printf pattern of PGM/PPM files\n"
           "  (frames/f%03d.pgm: numbered from 0, or 1, to the first missing number) or one\n"
           "  PGM/PPM file; every frame the same size, at most " + std::to_string(kMaxFrameWidth) + " x " +
           std::to_string(kMaxFrameHeight) + " pixels.\n"
           "  Each frame is detected as by quadtrack detect, then the quadrangle tracker carries the\n"
           "  board: one JSON line per frame on stdout (see README, \"quadtrack track\").\n"
           "options (--name VALUE or --name=VALUE):\n" + options_help(Command::track);
}

namespace {

// The tracker's parameters for a width × height frame: the size-dependent defaults, then the
// command line's choices, with the detection's shape limits.
QuadTrackerParams tracker_params(const DetectOptions& o, uint16_t width, uint16_t height) {
    QuadTrackerParams p = default_quad_tracker_params(width, height);
    p.lines.model = o.track.model;
    p.lines.filters = o.track.filters;
    p.gate_angle = o.track.gate_angle;
    p.gate_distance = o.track.gate_distance;
    p.max_predicted = o.track.max_predicted;
    p.shape = o.params.quads;
    return p;
}

}  // namespace

int run_track(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    DetectOptions options;
    std::string spec, error;
    const int parsed = parse_command_line(args, Command::track, track_usage(), options, spec, out, err);
    if (parsed >= 0) return parsed;

    io::FrameSource source;
    if (!source.open(spec, error)) {
        std::fprintf(err, "quadtrack track: %s\n", error.c_str());
        return 1;
    }
    QuadTracker tracker;
    scene::GreyImage frame;
    int width = 0, height = 0;
    for (int k = 0;; ++k) {
        const io::FrameSource::Next next = source.next(frame, error);
        if (next == io::FrameSource::Next::end) {
            if (k > 0) return 0;
            std::fprintf(err, "quadtrack track: %s: no frames\n", spec.c_str());
            return 1;
        }
        if (next == io::FrameSource::Next::error) {
            std::fprintf(err, "quadtrack track: %s\n", error.c_str());
            return 1;
        }
        if (k == 0) {
            width = frame.width;
            height = frame.height;
            tracker.set_params(tracker_params(options, static_cast<uint16_t>(width), static_cast<uint16_t>(height)));
        } else if (frame.width != width || frame.height != height) {
            std::fprintf(err, "quadtrack track: %s: frame %d is %d x %d, the sequence started at %d x %d\n",
                         spec.c_str(), k, frame.width, frame.height, width, height);
            return 1;
        }
        DetectResult result;
        if (!detect_frame(frame, options, result, error)) {
            std::fprintf(err, "quadtrack track: %s: frame %d: %s\n", spec.c_str(), k, error.c_str());
            return 1;
        }
        const TrackedQuad t = tracker.step(result.lines.data(), static_cast<uint16_t>(result.lines.size()),
                                           result.quads.data(), static_cast<uint16_t>(result.quads.size()));
        const std::string line = track_json(k, result, t, tracker.stats().lost_reason, options.display_width,
                                            options.display_height);
        std::fprintf(out, "%s\n", line.c_str());
        std::fflush(out);
    }
}

}  // namespace qt::cli
