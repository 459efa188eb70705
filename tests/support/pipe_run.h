// Runs one of the CLI's commands in a child process whose standard input, output and error are
// pipes to this process, as a shell pipeline `producer | quadtrack COMMAND -` would (tests
// only, POSIX). The test writes the child's input piece by piece and can wait for its output
// lines in between: a live stream.
#pragma once
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

namespace qt::test {

class PipeRun {
public:
    // command is run_track, run_detect, ...: int(const std::vector<std::string>&, FILE*, FILE*),
    // called in the child with its own stdout and stderr; the child exits with its status.
    template <class Command>
    PipeRun(Command command, const std::vector<std::string>& args) {
        // A child that stops reading must not kill the test with SIGPIPE: writes fail instead.
        std::signal(SIGPIPE, SIG_IGN);
        int in[2], out[2], err[2];
        REQUIRE(pipe(in) == 0);
        REQUIRE(pipe(out) == 0);
        REQUIRE(pipe(err) == 0);
        std::fflush(stdout);
        std::fflush(stderr);
        pid_ = fork();
        REQUIRE(pid_ >= 0);
        if (pid_ == 0) {
            dup2(in[0], 0);
            dup2(out[1], 1);
            dup2(err[1], 2);
            for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) close(fd);
            const int status = command(args, stdout, stderr);
            std::fflush(stdout);
            std::fflush(stderr);
            _exit(status);
        }
        close(in[0]);
        close(out[1]);
        close(err[1]);
        in_ = in[1];
        out_ = out[0];
        err_ = err[0];
        fcntl(in_, F_SETFL, fcntl(in_, F_GETFL) | O_NONBLOCK);
    }
    ~PipeRun() {
        if (pid_ > 0 && !finished_) {
            kill(pid_, SIGKILL);
            finish();
        }
    }
    PipeRun(const PipeRun&) = delete;
    PipeRun& operator=(const PipeRun&) = delete;

    // Writes all of data to the child's standard input, reading its output meanwhile. False
    // when the child stopped reading (closed its input or exited).
    bool write(const std::string& data) {
        size_t done = 0;
        while (done < data.size()) {
            if (!pump(1000, true)) return false;
            const ssize_t n = ::write(in_, data.data() + done, data.size() - done);
            if (n > 0) done += static_cast<size_t>(n);
            if (n < 0 && errno != EAGAIN && errno != EINTR) return false;
        }
        return true;
    }

    // Reads the child's output until it holds `lines` newlines or `seconds` pass. True when it
    // does.
    bool wait_for_lines(size_t lines, double seconds) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (count_lines() < lines && std::chrono::steady_clock::now() < end)
            if (!pump(100, false) && out_ < 0) break;
        return count_lines() >= lines;
    }

    // Closes the child's standard input (the stream ends), reads everything it still writes and
    // waits for it. Returns its exit status (-1 if it did not exit normally).
    int finish() {
        close_input();
        while (out_ >= 0 || err_ >= 0) pump(1000, false);
        int status = 0;
        waitpid(pid_, &status, 0);
        finished_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    void close_input() {
        if (in_ >= 0) close(in_);
        in_ = -1;
    }

    size_t count_lines() const {
        size_t n = 0;
        for (char c : out) n += c == '\n';
        return n;
    }

    std::string out, err;  // what the child wrote so far

private:
    // One poll: reads what the child wrote; with `writable`, also returns once its input takes
    // more. False when there is nothing left to wait for.
    bool pump(int timeout_ms, bool writable) {
        pollfd fds[3];
        nfds_t n = 0;
        if (out_ >= 0) fds[n++] = {out_, POLLIN, 0};
        if (err_ >= 0) fds[n++] = {err_, POLLIN, 0};
        if (writable && in_ >= 0) fds[n++] = {in_, POLLOUT, 0};
        if (n == 0) return false;
        if (poll(fds, n, timeout_ms) < 0) return errno == EINTR;
        for (nfds_t i = 0; i < n; ++i) {
            if (fds[i].fd == in_) {
                if (fds[i].revents & (POLLERR | POLLHUP)) return false;
                continue;
            }
            if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            char buf[65536];
            const ssize_t got = read(fds[i].fd, buf, sizeof buf);
            std::string& to = fds[i].fd == out_ ? out : err;
            if (got > 0) {
                to.append(buf, static_cast<size_t>(got));
            } else if (got == 0 || errno != EINTR) {
                close(fds[i].fd);
                (fds[i].fd == out_ ? out_ : err_) = -1;
            }
        }
        return true;
    }

    pid_t pid_ = -1;
    int in_ = -1, out_ = -1, err_ = -1;
    bool finished_ = false;
};

}  // namespace qt::test
