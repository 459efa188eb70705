#include "host/frame_loop.h"

#include <unistd.h>

#include <chrono>

#include "io/error_line.h"
#include "io/image_io.h"

namespace qt::host {

namespace {

// "frames done, frames a second" on a terminal's line, rewritten at most twice a second; nothing
// when `err` is not a terminal (a log file or a pipe gets error lines only).
class Progress {
public:
    Progress(std::FILE* err, const char* command)
        : err_(err), command_(command), on_(isatty(fileno(err)) == 1) {}
    void frame_done(int frames) {
        if (!on_) return;
        const Clock::time_point now = Clock::now();
        if (now - shown_ < std::chrono::milliseconds(500)) return;
        shown_ = now;
        const double s = std::chrono::duration<double>(now - start_).count();
        std::fprintf(err_, "\rquadtrack %s: %d frames, %.1f frames/s ", command_, frames,
                     s > 0 ? frames / s : 0.0);
        std::fflush(err_);
        shown_any_ = true;
    }
    // Ends the progress line, so that what follows starts on a line of its own.
    ~Progress() {
        if (shown_any_) std::fputc('\n', err_);
    }

private:
    using Clock = std::chrono::steady_clock;
    std::FILE* err_;
    const char* command_;
    bool on_, shown_any_ = false;
    Clock::time_point start_ = Clock::now(), shown_ = Clock::now();
};

}  // namespace

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
    Progress progress(err, command);
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
        progress.frame_done(k + 1);
    }
}

}  // namespace qt::host
