#include "cli/track_command.h"

#include "cli/detect_command.h"
#include "cli/detect_json.h"
#include "host/draw_results.h"
#include "host/frame_loop.h"
#include "io/error_line.h"
#include "io/image_io.h"
#include "io/write_check.h"
#include "tracking/quad_tracker.h"

namespace qt::cli {

std::string track_usage() {
    return "usage: quadtrack track SEQUENCE [OPTIONS]\n"
           "  SEQUENCE is a Y4M file (every frame's Y plane), a printf pattern of PGM/PPM files\n"
           "  (frames/f%03d.pgm: numbered from 0, or 1, to the first missing number), one\n"
           "  PGM/PPM file, or - for standard input (a Y4M stream, or PGM/PPM images one after\n"
           "  another: each frame's line is written as soon as the frame has been read). Every\n"
           "  frame the same size; frames larger than " +
           std::to_string(host::kMaxFrameWidth) + " x " + std::to_string(host::kMaxFrameHeight) +
           " pixels (320 x 240 with --capacity qvga) are binned to fit (--bin).\n"
           "  Each frame is detected as by quadtrack detect, then the quadrangle tracker carries "
           "the\n"
           "  board: one JSON line per frame on stdout (see docs/cli.md).\n"
           "options (--name VALUE or --name=VALUE):\n" +
           options_help(Command::track);
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
    p.shape = sized_quad_params(o.params.quads, height);
    return p;
}

}  // namespace

int run_track(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    DetectOptions options;
    std::string spec;
    const int parsed =
        parse_command_line(args, Command::track, track_usage(), options, spec, out, err);
    if (parsed >= 0) return parsed;

    const std::string name = io::input_name(spec);
    QuadTracker tracker;
    TrackingMode mode(options.track.mode);
    BandWindow* window = nullptr;  // this frame's bands (tracking mode), or null: whole
    uint8_t bin = 1;
    return host::for_each_frame(spec, "track", err, [&](int k, const io::GreyImage& frame) {
        std::string error;
        if (k == 0) {
            // Every frame has frame 0's size: one bin factor, and the tracker works in the
            // binned frame's pixels.
            bin = host::choose_bin(frame.width, frame.height, options.bin, error, options.capacity);
            if (bin == 0) {
                qt::io::print_error_line(err, "quadtrack track: %s: %s", name.c_str(),
                                         error.c_str());
                return 1;
            }
            tracker.set_params(tracker_params(options, static_cast<uint16_t>(frame.width / bin),
                                              static_cast<uint16_t>(frame.height / bin)));
        }
        host::DetectResult result;
        if (!detect_frame(frame, options, bin, result, error, window)) {
            qt::io::print_error_line(err, "quadtrack track: %s: frame %d: %s", name.c_str(), k,
                                     error.c_str());
            return 1;
        }
        TrackedQuad t =
            tracker.step(result.lines.data(), static_cast<uint16_t>(result.lines.size()),
                         result.quads.data(), static_cast<uint16_t>(result.quads.size()));
        const q16_16 score = host::evidence_share(t, options.params.refine, options.capacity);
        window = mode.plan(t);  // in the binned frame's pixels, before they become the input's
        host::to_input_pixels(result, frame.width, frame.height);
        host::to_input_pixels(t, bin);
        const std::string line =
            track_json(k, result, t, score, tracker.stats().lost_reason, options.display_width,
                       options.display_height, options.track_lines);
        const auto tracked = [&](io::RgbImage& pic) {
            host::draw_lines(pic, result.lines);
            host::draw_tracked(pic, t);
        };
        std::string file;
        if (host::frame_picture(options.draw, options.draw_every, k, &file) &&
            !host::write_drawn(file, frame, tracked, err, "quadtrack track"))
            return 1;
        // Written and flushed before the next frame is read: a live pipe gets each frame's
        // line as soon as the frame is in.
        std::fprintf(out, "%s\n", line.c_str());
        return io::output_written(out, err, "quadtrack track") ? 0 : 1;
    });
}

}  // namespace qt::cli
