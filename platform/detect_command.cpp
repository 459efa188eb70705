#include "detect_command.h"

#include "board_runner.h"
#include "cli_options.h"
#include "detect_json.h"
#include "image_io.h"

namespace qt::cli {

std::string detect_usage() {
    return "usage: quadtrack detect IMAGE [OPTIONS]\n"
           "  IMAGE is a PGM (P5), PPM (P6, converted to grey) or Y4M file (first frame's Y plane),\n"
           "  at most " + std::to_string(kMaxFrameWidth) + " x " + std::to_string(kMaxFrameHeight) +
           " pixels. Prints one JSON object on stdout (see README, \"quadtrack detect\").\n"
           "options (--name VALUE or --name=VALUE):\n" + options_help();
}

int run_detect(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    DetectOptions options;
    std::string path, error;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--help" || a == "-h") {
            std::fputs(detect_usage().c_str(), out);
            return 0;
        }
        if (a.rfind("--", 0) == 0) {
            std::string name = a.substr(2), value;
            const size_t eq = name.find('=');
            if (eq != std::string::npos) {
                value = name.substr(eq + 1);
                name.resize(eq);
            } else if (!is_option(name)) {
                std::fprintf(err, "quadtrack detect: unknown option '%s' (see quadtrack detect --help)\n", a.c_str());
                return 2;
            } else if (i + 1 == args.size()) {
                std::fprintf(err, "quadtrack detect: %s needs a value\n", a.c_str());
                return 2;
            } else {
                value = args[++i];
            }
            if (!apply_option(name, value, options, error)) {
                std::fprintf(err, "quadtrack detect: %s\n", error.c_str());
                return 2;
            }
            continue;
        }
        if (!path.empty()) {
            std::fprintf(err, "quadtrack detect: one image only, got '%s' and '%s'\n", path.c_str(), a.c_str());
            return 2;
        }
        path = a;
    }
    if (path.empty()) {
        std::fputs("quadtrack detect: no IMAGE given (see quadtrack detect --help)\n", err);
        return 2;
    }
    if (options.params.quads.min_side_length > options.params.quads.max_side_length) {
        std::fputs("quadtrack detect: --min-side is above --max-side\n", err);
        return 2;
    }

    scene::GreyImage frame;
    if (!io::read_image(path, frame, error)) {
        std::fprintf(err, "quadtrack detect: %s\n", error.c_str());
        return 1;
    }
    if (frame.width > kMaxFrameWidth || frame.height > kMaxFrameHeight) {
        std::fprintf(err, "quadtrack detect: %s: %d x %d is over this build's capacity of %d x %d\n", path.c_str(),
                     frame.width, frame.height, kMaxFrameWidth, kMaxFrameHeight);
        return 1;
    }
    DetectResult result;
    if (!detect_board(frame, options.params, result)) {
        std::fprintf(err, "quadtrack detect: %s: %s\n", path.c_str(), status_name(result.status));
        return 1;
    }
    if (result.quads.size() > options.max_quads) result.quads.resize(options.max_quads);
    std::fprintf(out, "%s\n", detect_json(result, options.display_width, options.display_height).c_str());
    return 0;
}

}  // namespace qt::cli
