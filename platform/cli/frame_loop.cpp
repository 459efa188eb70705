#include "cli/frame_loop.h"

#include "io/error_line.h"
#include "io/image_io.h"

namespace qt::cli {

int for_each_frame(const std::string& spec, const char* command, std::FILE* err,
                   const std::function<int(int, const io::GreyImage&)>& body) {
    io::FrameSource source;
    std::string error;
    if (!source.open(spec, error)) {
        qt::io::print_error_line(err, "quadtrack %s: %s", command, error.c_str());
        return source.bad_pattern() ? 2 : 1;
    }
    io::GreyImage frame;
    int width = 0, height = 0;
    for (int k = 0;; ++k) {
        const io::FrameSource::Next next = source.next(frame, error);
        if (next == io::FrameSource::Next::end) {
            if (!source.gap().empty())
                qt::io::print_error_line(err, "quadtrack %s: warning: %s", command,
                                         source.gap().c_str());
            if (k > 0) return 0;
            qt::io::print_error_line(err, "quadtrack %s: %s: no frames", command,
                                     io::input_name(spec).c_str());
            return 1;
        }
        if (next == io::FrameSource::Next::error) {
            qt::io::print_error_line(err, "quadtrack %s: %s", command, error.c_str());
            return 1;
        }
        if (k == 0) {
            width = frame.width;
            height = frame.height;
        } else if (frame.width != width || frame.height != height) {
            qt::io::print_error_line(
                err, "quadtrack %s: %s: frame %d is %d x %d, the sequence started at %d x %d",
                command, io::input_name(spec).c_str(), k, frame.width, frame.height, width, height);
            return 1;
        }
        const int status = body(k, frame);
        if (status != 0) return status;
    }
}

}  // namespace qt::cli
