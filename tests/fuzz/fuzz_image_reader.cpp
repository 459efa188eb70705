// Fuzz target: the input bytes as an image file, read through the path-based API users call —
// qt::io::read_image, then qt::io::FrameSource (open, next() to the end or an error, so the
// y4m multi-frame paths run). Invariants (platform/io/image_io.h):
//   - a frame read has width, height in 1..kMaxImageSide and width·height pixels;
//   - a failure is ONE line beginning with the file name, and read_image leaves `out` as it was;
//   - FrameSource's first frame is read_image's frame (same pixels), or the same error line;
//     later y4m frames have the header's size; frames_read() counts them;
//   - after the end or an error, next() repeats the same result and message.
#include <stddef.h>
#include <stdint.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz_check.h"
#include "io/image_io.h"

namespace {

using qt::io::FrameSource;
using qt::io::GreyImage;
using qt::io::kMaxImageSide;

std::string pick_temp_path() {
    std::string dir = "/tmp";
    const char* tmp = std::getenv("TMPDIR");
    if (access("/dev/shm", W_OK) == 0)
        dir = "/dev/shm";
    else if (tmp != nullptr && *tmp != '\0')
        dir = tmp;
    // No '%' in the name: FrameSource would take it for a numbered pattern.
    if (dir.find('%') != std::string::npos) dir = "/tmp";
    return dir + "/qt_fuzz_image_reader_" + std::to_string(static_cast<long>(getpid())) + ".bin";
}

// One file per process, rewritten for every input and removed after it (libFuzzer ends the
// process without running atexit handlers).
const std::string& temp_path() {
    static const std::string path = pick_temp_path();
    return path;
}

void write_file(const std::string& path, const uint8_t* data, size_t size) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr || (size > 0 && std::fwrite(data, 1, size, f) != size) ||
        std::fclose(f) != 0) {
        std::fprintf(stderr, "fuzz_image_reader: cannot write %s\n", path.c_str());
        std::abort();
    }
}

// "<path>: what", one line of printable ASCII.
bool one_line_about(const std::string& error, const std::string& path) {
    const std::string head = path + ": ";
    if (error.size() <= head.size() || error.compare(0, head.size(), head) != 0) return false;
    for (char c : error) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7F) return false;
    }
    return true;
}

bool sane(const GreyImage& img) {
    return img.width >= 1 && img.height >= 1 && img.width <= kMaxImageSide &&
           img.height <= kMaxImageSide &&
           img.pixels.size() == static_cast<size_t>(img.width) * static_cast<size_t>(img.height);
}

// The invariants above, for the file at `path`.
void check(const std::string& path) {
    // read_image: one frame, or one line about the file with `out` untouched.
    GreyImage image(3, 2, 7);
    std::string error;
    const bool ok = qt::io::read_image(path, image, error);
    if (ok) {
        QT_FUZZ_CHECK(sane(image));
    } else {
        QT_FUZZ_CHECK(one_line_about(error, path));
        QT_FUZZ_CHECK(image.width == 3 && image.height == 2 &&
                      image.pixels == std::vector<uint8_t>(6, 7));
    }

    // FrameSource over the same file.
    FrameSource source;
    std::string open_error;
    if (!source.open(path, open_error)) {
        QT_FUZZ_CHECK(one_line_about(open_error, path));
        QT_FUZZ_CHECK(!ok);                  // a file read_image accepts opens as a sequence
        QT_FUZZ_CHECK(open_error == error);  // and a header it refuses is refused alike
        return;
    }
    int frames = 0;
    for (;;) {
        GreyImage frame;
        std::string e;
        const FrameSource::Next n = source.next(frame, e);
        if (n == FrameSource::Next::frame) {
            QT_FUZZ_CHECK(sane(frame));
            if (frames == 0) {
                QT_FUZZ_CHECK(ok && frame.width == image.width && frame.height == image.height &&
                              frame.pixels == image.pixels);
            } else {
                QT_FUZZ_CHECK(frame.width == image.width && frame.height == image.height);
            }
            ++frames;
            QT_FUZZ_CHECK(source.frames_read() == frames);
            continue;
        }
        if (n == FrameSource::Next::error) {
            QT_FUZZ_CHECK(one_line_about(e, path));
            if (frames == 0) QT_FUZZ_CHECK(!ok && e == error);
        } else {
            QT_FUZZ_CHECK(n == FrameSource::Next::end);
            QT_FUZZ_CHECK(frames > 0 || !ok);  // an empty y4m: read_image says it has no frames
        }
        // Sticky: the same result and the same line again.
        GreyImage again;
        std::string e2;
        QT_FUZZ_CHECK(source.next(again, e2) == n);
        if (n == FrameSource::Next::error) QT_FUZZ_CHECK(e2 == e);
        QT_FUZZ_CHECK(source.frames_read() == frames);
        break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string& path = temp_path();
    write_file(path, data, size);
    check(path);
    std::remove(path.c_str());
    return 0;
}
