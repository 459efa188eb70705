// quadtrack: the command-line front end (host). Results go to stdout, errors to stderr as one
// line each; the exit status is 0 when done, 1 on bad input data or a file that cannot be read
// or written, 2 on a bad command line.
#include <cstdio>
#include <cstring>
#include <string>

#include <vector>

#include "cli/detect_command.h"
#include "cli/homography_command.h"
#include "cli/target_command.h"
#include "cli/track_command.h"
#include "demo/demo.h"
#include "io/error_line.h"
#include "io/write_check.h"

namespace {

const char* kUsage =
    "usage: quadtrack COMMAND [OPTIONS]\n"
    "\n"
    "commands:\n"
    "  detect IMAGE [OPTIONS]\n"
    "                     find the board's lines and quadrangles in one PGM/PPM/Y4M frame and\n"
    "                     print them as JSON; options: quadtrack detect --help\n"
    "  track SEQUENCE [OPTIONS]\n"
    "                     detect and track the board through a Y4M file or numbered PGM files\n"
    "                     (e.g. frames/f%03d.pgm): one JSON line per frame, each side detected\n"
    "                     or predicted; options: quadtrack track --help\n"
    "  homography A B [OPTIONS]\n"
    "                     the homography mapping image A's pixels into image B (Harris corners,\n"
    "                     NCC matches, RANSAC) as JSON; options: quadtrack homography --help\n"
    "  target SEQUENCE --roi X,Y,W,H [OPTIONS]\n"
    "                     track the target in frame 0's box through the sequence, also while it\n"
    "                     is hidden or out of view (Kalman filter + accumulated homographies):\n"
    "                     one JSON line per frame; options: quadtrack target --help\n"
    "  demo [--out DIR]   run the pipeline on the built-in synthetic board scene and write\n"
    "                     pictures under DIR (default: demo_out): input.png and input.pgm,\n"
    "                     gradient_magnitude.png (L1 |g| in grey levels, clipped at 255),\n"
    "                     gradient_direction.png (hue = direction bin, brightness = |g|),\n"
    "                     lines.png, and board_00.png .. board_11.png: a moving board tracked\n"
    "                     through frames where bars hide its top and bottom sides, with its\n"
    "                     lines, detected sides (solid green), predicted sides (dashed orange)\n"
    "                     and corners\n"
    "  --help             this text\n"
    "  --version          the version\n"
    "\n"
    "exit status: 0 done; 1 bad input data, or a file that cannot be read or written;\n"
    "2 bad command line (an unknown command or option, a bad value, pattern or ROI)\n";

const char* kDemoUsage =
    "usage: quadtrack demo [--out DIR]\n"
    "run the pipeline on the built-in synthetic board scene and write its pictures under DIR\n"
    "(default: demo_out); quadtrack --help lists them\n";

// Writes `text` on stdout: 0, or 1 after an error line when it could not be written.
int print(const char* text, const char* who) {
    std::fputs(text, stdout);
    return qt::io::output_written(stdout, stderr, who) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        qt::io::print_error_line(stderr, "quadtrack: no command given (see quadtrack --help)");
        return 2;
    }
    const std::string command = argv[1];
    if (command == "--help" || command == "-h" || command == "help")
        return print(kUsage, "quadtrack");
    if (command == "--version") return print("quadtrack " QT_VERSION "\n", "quadtrack");
    if (command == "detect")
        return qt::cli::run_detect(std::vector<std::string>(argv + 2, argv + argc), stdout, stderr);
    if (command == "track")
        return qt::cli::run_track(std::vector<std::string>(argv + 2, argv + argc), stdout, stderr);
    if (command == "homography")
        return qt::cli::run_homography(std::vector<std::string>(argv + 2, argv + argc), stdout,
                                       stderr);
    if (command == "target")
        return qt::cli::run_target(std::vector<std::string>(argv + 2, argv + argc), stdout, stderr);
    if (command == "demo") {
        std::string out = "demo_out";
        for (int i = 2; i < argc; ++i) {
            if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
                out = argv[++i];
            } else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
                return print(kDemoUsage, "quadtrack demo");
            } else {
                qt::io::print_error_line(
                    stderr, "quadtrack demo: unknown option '%s' (see quadtrack --help)", argv[i]);
                return 2;
            }
        }
        return qt::cli::run_demo(out);
    }
    qt::io::print_error_line(stderr, "quadtrack: unknown command '%s' (see quadtrack --help)",
                             command.c_str());
    return 2;
}
