#include "cli/detect_command.h"

#include "cli/cli_options.h"
#include "cli/detect_json.h"
#include "host/board_runner.h"
#include "host/draw_results.h"
#include "io/error_line.h"
#include "io/image_io.h"
#include "io/write_check.h"

namespace qt::cli {

std::string detect_usage() {
    return "usage: quadtrack detect IMAGE [OPTIONS]\n"
           "  IMAGE is a PGM (P5), PPM (P6, converted to grey) or Y4M file (first frame's Y "
           "plane),\n"
           "  or - for standard input. A frame larger than " +
           std::to_string(host::kMaxFrameWidth) + " x " + std::to_string(host::kMaxFrameHeight) +
           " pixels (320 x 240 with --capacity qvga) is binned to fit (--bin).\n"
           "  Prints one JSON object on stdout (see docs/cli.md).\n"
           "options (--name VALUE or --name=VALUE):\n" +
           options_help();
}

bool detect_frame(const io::GreyImage& frame, const DetectOptions& options, uint8_t bin,
                  host::DetectResult& result, std::string& error, BandWindow* window) {
    if (!host::detect_board(frame, options.params, result, bin, options.capacity, window)) {
        error = status_name(result.status);
        return false;
    }
    if (result.quads.size() > options.max_quads) result.quads.resize(options.max_quads);
    return true;
}

int run_detect(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    DetectOptions options;
    std::string path, error;
    const int parsed =
        parse_command_line(args, Command::detect, detect_usage(), options, path, out, err);
    if (parsed >= 0) return parsed;

    io::GreyImage frame;
    if (!io::read_image(path, frame, error)) {
        qt::io::print_error_line(err, "quadtrack detect: %s", error.c_str());
        return 1;
    }
    const std::string name = io::input_name(path);
    const uint8_t bin =
        host::choose_bin(frame.width, frame.height, options.bin, error, options.capacity);
    host::DetectResult result;
    if (bin == 0 || !detect_frame(frame, options, bin, result, error)) {
        qt::io::print_error_line(err, "quadtrack detect: %s: %s", name.c_str(), error.c_str());
        return 1;
    }
    host::to_input_pixels(result, frame.width, frame.height);
    const auto found = [&](io::RgbImage& pic) {
        host::draw_lines(pic, result.lines);
        host::draw_quads(pic, result.quads);
    };
    if (!options.draw.empty() &&
        !host::write_drawn(options.draw, frame, found, err, "quadtrack detect"))
        return 1;
    std::fprintf(out, "%s\n",
                 detect_json(result, options.display_width, options.display_height).c_str());
    return io::output_written(out, err, "quadtrack detect") ? 0 : 1;
}

}  // namespace qt::cli
