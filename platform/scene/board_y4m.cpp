// qt_board_y4m: a board sequence of platform/scene/board_sequence.h at any camera size, written
// as a YUV4MPEG2 stream on stdout, for `quadtrack track -` and friends without a camera:
//   qt_board_y4m --size 1280x720 | quadtrack track -
// The scene generator's corners of each frame go to --truth FILE as JSON lines
//   {"frame":K,"corners":[[x,y],[x,y],[x,y],[x,y]]}   (top-left, top-right, bottom-right,
//   bottom-left as generated; px, pixel centres at integers)
// --cut BYTES stops the stream after that many bytes of the last frame (a pipe that ends inside
// a frame). Errors: one line on stderr, exit status 1 (2 for a bad command line).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "host/parse_number.h"
#include "io/error_line.h"
#include "io/image_io.h"
#include "scene/board_sequence.h"

namespace {

const char* kUsage =
    "usage: qt_board_y4m [--size WxH] [--sequence demo|turning] [--frames N] [--colour mono|420]\n"
    "                    [--truth FILE] [--cut BYTES]\n"
    "  Writes the board sequence (default: the demo's, 640x480, all its frames, mono) as Y4M\n"
    "  on stdout; --truth writes each frame's corners as JSON lines; --cut ends the stream\n"
    "  BYTES into its last frame.\n";

int usage_error(const std::string& what) {
    qt::io::print_error_line(stderr, "qt_board_y4m: %s (see qt_board_y4m --help)", what.c_str());
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    int width = 640, height = 480, frames = -1;
    long cut = -1;
    bool mono = true;
    std::string truth_path;
    qt::scene::BoardMotionSpec spec = qt::scene::kDemoSequence;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (i + 1 >= argc) return usage_error(a + " needs a value");
        const std::string v = argv[++i];
        std::string why;
        long n = 0;
        if (a == "--size") {
            const size_t x = v.find('x');
            long w = 0, h = 0;
            if (x == std::string::npos || !qt::host::parse_int(v.substr(0, x), 64, 16384, w, why) ||
                !qt::host::parse_int(v.substr(x + 1), 48, 16384, h, why))
                return usage_error("--size: '" + v + "' is not WxH (64x48 .. 16384x16384)");
            width = static_cast<int>(w);
            height = static_cast<int>(h);
        } else if (a == "--sequence") {
            if (v == "demo")
                spec = qt::scene::kDemoSequence;
            else if (v == "turning")
                spec = qt::scene::kTurningSequence;
            else
                return usage_error("--sequence: '" + v + "' is not demo or turning");
        } else if (a == "--frames") {
            if (!qt::host::parse_int(v, 1, 1000, n, why)) return usage_error("--frames: " + why);
            frames = static_cast<int>(n);
        } else if (a == "--colour") {
            if (v != "mono" && v != "420")
                return usage_error("--colour: '" + v + "' is not mono or 420");
            mono = v == "mono";
        } else if (a == "--truth") {
            truth_path = v;
        } else if (a == "--cut") {
            if (!qt::host::parse_int(v, 0, 1000000000, n, why)) return usage_error("--cut: " + why);
            cut = n;
        } else {
            return usage_error("unknown option '" + a + "'");
        }
    }
    if (frames < 0 || frames > spec.frames) frames = spec.frames;
    std::FILE* truth = nullptr;
    if (!truth_path.empty() && (truth = std::fopen(truth_path.c_str(), "w")) == nullptr) {
        qt::io::print_error_line(stderr, "qt_board_y4m: %s: cannot create (%s)", truth_path.c_str(),
                                 std::strerror(errno));
        return 1;
    }
    std::string error;
    bool ok = qt::io::write_y4m_header(stdout, "stdout", width, height, mono, error);
    for (int f = 0; f < frames && ok; ++f) {
        const qt::scene::BoardSequenceFrame d =
            qt::scene::sized_sequence_frame(spec, f, width, height);
        if (truth != nullptr) {
            std::fprintf(truth, "{\"frame\":%d,\"corners\":[", f);
            for (int i = 0; i < 4; ++i)
                std::fprintf(truth, "%s[%.6f,%.6f]", i ? "," : "", d.scene.corners[i].x / 256.0,
                             d.scene.corners[i].y / 256.0);
            std::fprintf(truth, "]}\n");
        }
        if (f + 1 == frames && cut >= 0) {
            // The last frame, cut: its first `cut` bytes (FRAME line included) only.
            std::FILE* mem = std::tmpfile();
            ok = mem != nullptr && qt::io::write_y4m_frame(mem, "stdout", d.image, mono, error);
            if (mem != nullptr) {
                std::rewind(mem);
                for (long b = 0; b < cut && ok; ++b) {
                    const int c = std::getc(mem);
                    if (c == EOF) break;
                    ok = std::putc(c, stdout) != EOF;
                }
                std::fclose(mem);
            }
        } else {
            ok = qt::io::write_y4m_frame(stdout, "stdout", d.image, mono, error);
        }
        ok = ok && std::fflush(stdout) == 0;
    }
    if (truth != nullptr) ok = std::fclose(truth) == 0 && ok;
    if (!ok) {
        qt::io::print_error_line(stderr, "qt_board_y4m: %s",
                                 error.empty() ? "write failed" : error.c_str());
        return 1;
    }
    return 0;
}
