#include "cli/homography_command.h"

#include <memory>

#include "cli/target_json.h"
#include "io/error_line.h"
#include "io/image_io.h"

namespace qt::cli {

std::string homography_usage() {
    return "usage: quadtrack homography A B [OPTIONS]\n"
           "  A and B are PGM/PPM/Y4M frames of at most 640 x 480 pixels (the first frame of a "
           "Y4M).\n"
           "  Prints {\"H\",\"inliers\",\"matches\",...}: H maps A's pixels into B (see\n"
           "  docs/cli.md).\n"
           "options (--name VALUE or --name=VALUE):\n" +
           target_options_help(GeometryCommand::homography);
}

namespace {

using Detector = HarrisDetector<640, 160>;
using Features = FeatureSet<4, 160>;

// Reads one image and finds its corners; false with one line in `error`.
bool corners_of(const std::string& path, const HarrisParams& config, Detector& detector,
                Features& out, std::string& error) {
    io::GreyImage image;
    if (!io::read_image(path, image, error)) return false;
    if (image.width > 640 || image.height > 480) {
        error = path + ": " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                " is above the 640 x 480 capacity";
        return false;
    }
    const Status s = detect_features(
        detector, image.pixels.data(), static_cast<uint16_t>(image.width),
        static_cast<uint16_t>(image.height), static_cast<uint32_t>(image.width), config, out);
    if (s != Status::ok && s != Status::capacity_exceeded) {
        error = path + ": " + status_name(s);
        return false;
    }
    return true;
}

}  // namespace

int run_homography(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    TargetOptions options;
    std::vector<std::string> files;
    const int parsed = parse_target_command_line(args, GeometryCommand::homography,
                                                 homography_usage(), options, files, out, err);
    if (parsed >= 0) return parsed;
    // About 90 KB of detector and corners: on the heap, not the stack.
    auto detector = std::make_unique<Detector>();
    auto a = std::make_unique<Features>();
    auto b = std::make_unique<Features>();
    auto scratch = std::make_unique<FrameHomographyScratch<4, 160>>();
    std::string error;
    if (!corners_of(files[0], options.config.harris, *detector, *a, error) ||
        !corners_of(files[1], options.config.harris, *detector, *b, error)) {
        qt::io::print_error_line(err, "quadtrack homography: %s", error.c_str());
        return 1;
    }
    const FrameHomography g = homography_between(*a, *b, options.config.geometry, *scratch);
    std::fprintf(out, "%s\n", homography_json(g, a->count, b->count).c_str());
    return 0;
}

}  // namespace qt::cli
