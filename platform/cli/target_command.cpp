#include "cli/target_command.h"

#include <memory>

#include "cli/frame_loop.h"
#include "cli/target_json.h"
#include "io/error_line.h"

namespace qt::cli {

std::string target_usage() {
    return "usage: quadtrack target SEQUENCE --roi X,Y,W,H [OPTIONS]\n"
           "  SEQUENCE is a Y4M file, a printf pattern of PGM/PPM files (frames/f%03d.pgm) or one\n"
           "  PGM/PPM file; every frame the same size, at most 640 x 480 pixels. The target is "
           "the\n"
           "  box X,Y,W,H of frame 0; one JSON line per frame "
           "{\"frame\",\"x\",\"y\",\"state\",...}\n"
           "  (see docs/cli.md); x, y may lie outside the image while the target\n"
           "  is out of view.\n"
           "options (--name VALUE or --name=VALUE):\n" +
           target_options_help(GeometryCommand::target);
}

int run_target(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    TargetOptions options;
    std::vector<std::string> positional;
    const int parsed = parse_target_command_line(args, GeometryCommand::target, target_usage(),
                                                 options, positional, out, err);
    if (parsed >= 0) return parsed;
    const std::string& spec = positional[0];
    auto pipeline = std::make_unique<CliTargetPipeline>();  // ~120 KB: heap, not stack
    pipeline->set_target(options.roi_x, options.roi_y, static_cast<uint8_t>(options.roi_w),
                         static_cast<uint8_t>(options.roi_h));
    return for_each_frame(spec, "target", err, [&](int k, const io::GreyImage& frame) {
        const int width = frame.width, height = frame.height;
        if (width > 640 || height > 480) {
            qt::io::print_error_line(
                err, "quadtrack target: %s: %d x %d is above the 640 x 480 capacity", spec.c_str(),
                width, height);
            return 1;
        }
        Status s = pipeline->begin_frame(static_cast<uint16_t>(width),
                                         static_cast<uint16_t>(height), options.config);
        for (int y = 0; y < height && (s == Status::ok || s == Status::previous_frame_incomplete);
             ++y)
            s = pipeline->push_row(frame.row(y), static_cast<uint16_t>(width));
        TargetFrame result;
        if (s == Status::ok || s == Status::previous_frame_incomplete) s = pipeline->finish(result);
        if (s == Status::bad_size && k == 0) {
            qt::io::print_error_line(
                err, "quadtrack target: --roi %d,%d,%d,%d is not wholly inside the %d x %d frame 0",
                options.roi_x, options.roi_y, options.roi_w, options.roi_h, width, height);
            return 1;
        }
        if (s != Status::ok && s != Status::capacity_exceeded) {
            qt::io::print_error_line(err, "quadtrack target: %s: frame %d: %s", spec.c_str(), k,
                                     status_name(s));
            return 1;
        }
        std::fprintf(out, "%s\n", target_json(k, result).c_str());
        std::fflush(out);
        return 0;
    });
}

}  // namespace qt::cli
