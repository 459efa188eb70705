#include "cli/target_command.h"

#include <memory>

#include "base/floor_div.h"
#include "cli/target_json.h"
#include "host/board_runner.h"
#include "host/draw_results.h"
#include "host/frame_loop.h"
#include "io/error_line.h"
#include "io/image_io.h"
#include "io/push_frame.h"
#include "io/write_check.h"

namespace qt::cli {

std::string target_usage() {
    return "usage: quadtrack target SEQUENCE --roi X,Y,W,H [OPTIONS]\n"
           "  SEQUENCE is a Y4M file, a printf pattern of PGM/PPM files (frames/f%03d.pgm), one\n"
           "  PGM/PPM file, or - for standard input (Y4M, or PGM/PPM images one after another);\n"
           "  every frame the same size; frames larger than 640 x 480 pixels are binned to fit\n"
           "  (--bin). The target is the box X,Y,W,H of frame 0 (input pixels; at most " +
           std::to_string(kMaxRoiSide) +
           " px a side\n"
           "  once binned); one JSON line per frame {\"frame\",\"x\",\"y\",\"state\",...}\n"
           "  (see docs/cli.md); x, y may lie outside the image while the target is out of view.\n"
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
    const std::string name = io::input_name(spec);
    auto pipeline = std::make_unique<CliTargetPipeline>();  // ~120 KB: heap, not stack
    auto binning = std::make_unique<BinningStage<640>>();
    uint8_t bin = 1;
    return host::for_each_frame(spec, "target", err, [&](int k, const io::GreyImage& frame) {
        std::string error;
        if (k == 0) {
            bin = host::choose_bin(frame.width, frame.height, options.bin, error);
            if (bin == 0) {
                qt::io::print_error_line(err, "quadtrack target: %s: %s", name.c_str(),
                                         error.c_str());
                return 1;
            }
            // The box in the binned frame: every binned pixel it touches.
            const int x0 = static_cast<int>(floor_div(options.roi_x, bin)),
                      y0 = static_cast<int>(floor_div(options.roi_y, bin));
            const int w =
                static_cast<int>(floor_div(options.roi_x + options.roi_w - 1, bin)) - x0 + 1;
            const int h =
                static_cast<int>(floor_div(options.roi_y + options.roi_h - 1, bin)) - y0 + 1;
            if (w > kMaxRoiSide || h > kMaxRoiSide ||
                pipeline->set_target(x0, y0, static_cast<uint16_t>(w), static_cast<uint16_t>(h)) !=
                    Status::ok) {
                qt::io::print_error_line(
                    err,
                    "quadtrack target: --roi %d,%d,%d,%d: boxes are at most %d x %d px once "
                    "binned, this one is %d x %d binned by %d",
                    options.roi_x, options.roi_y, options.roi_w, options.roi_h, kMaxRoiSide,
                    kMaxRoiSide, w, h, bin);
                return 2;
            }
        }
        const int width = frame.width / bin, height = frame.height / bin;
        Status s = pipeline->begin_frame(static_cast<uint16_t>(width),
                                         static_cast<uint16_t>(height), options.config);
        if (s == Status::ok || s == Status::previous_frame_incomplete) {
            s = io::push_binned_rows(*binning, frame, bin, [&](const uint8_t* row, uint16_t n) {
                const Status r = pipeline->push_row(row, n);
                return r == Status::previous_frame_incomplete ? Status::ok : r;
            });
        }
        TargetFrame result;
        if (s == Status::ok) s = pipeline->finish(result);
        if (s == Status::bad_size && k == 0) {
            qt::io::print_error_line(
                err, "quadtrack target: --roi %d,%d,%d,%d is not wholly inside the %d x %d frame 0",
                options.roi_x, options.roi_y, options.roi_w, options.roi_h, frame.width,
                frame.height);
            return 2;  // a command-line mistake, as every other --roi problem
        }
        if (s != Status::ok && s != Status::capacity_exceeded) {
            qt::io::print_error_line(err, "quadtrack target: %s: frame %d: %s", name.c_str(), k,
                                     status_name(s));
            return 1;
        }
        const TargetEstimate& e = result.estimate;
        const auto box = [&](io::RgbImage& pic) {
            host::draw_target(pic, host::input_pixel(e.x, bin), host::input_pixel(e.y, bin),
                              options.roi_w, options.roi_h, e.state);
        };
        std::string file;
        if (host::frame_picture(options.draw, options.draw_every, k, &file) &&
            !host::write_drawn(file, frame, box, err, "quadtrack target"))
            return 1;
        std::fprintf(out, "%s\n", target_json(k, result, bin).c_str());
        return io::output_written(out, err, "quadtrack target") ? 0 : 1;
    });
}

}  // namespace qt::cli
