#include "cli/homography_command.h"

#include <algorithm>
#include <memory>

#include "cli/target_json.h"
#include "host/board_runner.h"
#include "io/error_line.h"
#include "io/image_io.h"
#include "io/push_frame.h"
#include "io/write_check.h"

namespace qt::cli {

std::string homography_usage() {
    return "usage: quadtrack homography A B [OPTIONS]\n"
           "  A and B are PGM/PPM/Y4M frames (the first frame of a Y4M); either may be - for\n"
           "  standard input. Frames larger than 640 x 480 pixels are binned to fit (--bin).\n"
           "  Prints {\"H\",\"inliers\",\"matches\",...}: H maps A's pixels into B (see\n"
           "  docs/cli.md). Made for neighbouring frames of one camera: a corner of A is matched\n"
           "  only within --search-radius of the same place in B, so the motion between A and\n"
           "  B must stay within it (in the binned frame's pixels); a wider baseline gives\n"
           "  status too_few_pairs or no_consensus, with H and reprojection_px null.\n"
           "options (--name VALUE or --name=VALUE):\n" +
           target_options_help(GeometryCommand::homography);
}

namespace {

using Detector = HarrisDetector<640, 160>;
using Features = FeatureSet<4, 160>;

// Reads one image, bins it to fit (`requested`, 0: auto; the factor used in `bin`) and finds
// its corners in the binned frame; false with one line in `error`.
bool corners_of(const std::string& path, const HarrisParams& config, uint8_t requested,
                Detector& detector, Features& out, uint8_t& bin, std::string& error) {
    io::GreyImage image;
    if (!io::read_image(path, image, error)) return false;
    bin = host::choose_bin(image.width, image.height, requested, error);
    if (bin == 0) {
        error = io::input_name(path) + ": " + error;
        return false;
    }
    if (bin > 1) {
        // detect_features takes a whole frame: the binned one, made row by row.
        static BinningStage<640> binning;
        io::GreyImage binned(image.width / bin, image.height / bin);
        uint8_t* to = binned.pixels.data();
        const Status s =
            io::push_binned_rows(binning, image, bin, [&](const uint8_t* row, uint16_t n) {
                std::copy(row, row + n, to);
                to += n;
                return Status::ok;
            });
        if (s != Status::ok) {
            error = io::input_name(path) + ": " + status_name(s);
            return false;
        }
        image = std::move(binned);
    }
    const Status s = detect_features(
        detector, image.pixels.data(), static_cast<uint16_t>(image.width),
        static_cast<uint16_t>(image.height), static_cast<uint32_t>(image.width), config, out);
    if (s != Status::ok && s != Status::capacity_exceeded) {
        error = io::input_name(path) + ": " + status_name(s);
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
    if (files[0] == io::kStandardInput && files[1] == io::kStandardInput) {
        qt::io::print_error_line(err,
                                 "quadtrack homography: A and B cannot both be standard input (-)");
        return 2;
    }
    // About 90 KB of detector and corners: on the heap, not the stack.
    auto detector = std::make_unique<Detector>();
    auto a = std::make_unique<Features>();
    auto b = std::make_unique<Features>();
    auto scratch = std::make_unique<FrameHomographyScratch<4, 160>>();
    std::string error;
    uint8_t bin_a = 1, bin_b = 1;
    if (!corners_of(files[0], options.config.harris, options.bin, *detector, *a, bin_a, error) ||
        !corners_of(files[1], options.config.harris, options.bin, *detector, *b, bin_b, error)) {
        qt::io::print_error_line(err, "quadtrack homography: %s", error.c_str());
        return 1;
    }
    const FrameHomography g = homography_between(*a, *b, options.config.geometry, *scratch);
    std::fprintf(out, "%s\n", homography_json(g, a->count, b->count, bin_a, bin_b).c_str());
    return io::output_written(out, err, "quadtrack homography") ? 0 : 1;
}

}  // namespace qt::cli
