// The target tracker on real footage with hand-marked truth (vectors/footage/*.txt, format in
// platform/scene/footage_truth.h): each target is started from its truth file's start box and
// run to its last mark by the project's pipeline (the configuration `quadtrack target` uses)
// and, when OpenCV's tracking module is built in, by OpenCV's CSRT and KCF trackers on the same
// frames and boxes, with their default parameters, in colour when --colour gives the frames'
// BGR pixels (the video is in colour; our tracker sees its grey levels), in grey otherwise; each
// row's name says which. The truth between marks is interpolated linearly (marks are every 5th
// frame and at each occlusion's first and last frame).
//
// A user's box is never exact, and a tracker that holds on one box may let go on the next: each
// target is run from its start box and from the box moved by 1 px left, right, up and down
// (--starts 1 runs the box alone), and the figures add up over the runs.
//
// Per target and tracker: frames within --radius of the truth, the median error, identity
// switches, frames claimed while the walker is out of the frame, occlusions followed by a wrong
// claim and the re-acquisitions after them (defined in footage_score.h), the median time a
// frame. A claim: ours `measured` or `reacquired`, OpenCV's update() true.
// Usage: bench_footage VIDEO.y4m TRUTH.txt... [--colour FRAMES.bgr] [--radius PX] [--starts N]
//                     [--out DIR] [--quadtrack-only] [--trace] [-- TARGET FLAGS]
//   --colour: the same frames as raw BGR, 3 bytes a pixel, frame after frame (ffmpeg -f rawvideo
//   -pix_fmt bgr24), for OpenCV's trackers;
//   --radius: default 10 px; --starts: start boxes a target, 1..5 (default 5); --out: a chart
//   a target, DIR/error_NAME.svg (each tracker's error over the frames from the marked box, the
//   occlusions and the frames out of view shaded); --quadtrack-only: no OpenCV rows; --trace:
//   our tracker's every frame beside the truth, on stderr; after --, flags of `quadtrack
//   target` (--min-score 0.6, ...) change our tracker's settings.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bench/footage_score.h"
#include "cli/target_options.h"
#include "io/image_io.h"
#include "io/svg_plot.h"
#include "scene/footage_truth.h"

#ifdef QT_HAVE_OPENCV_TRACKING
#include <opencv2/imgproc.hpp>
#include <opencv2/tracking.hpp>
#endif

namespace {

using qt::bench::median;
using qt::bench::Score;
using qt::bench::score;
using qt::bench::Step;
using qt::scene::FootageTruth;
using qt::scene::Seen;

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The start box moved by (dx, dy) px.
struct Shift {
    int dx, dy;
};

std::vector<Step> run_quadtrack(const std::vector<qt::io::GreyImage>& frames, const FootageTruth& t,
                                Shift d, const qt::TargetPipelineParams& config) {
    auto pipe = std::make_unique<qt::cli::CliTargetPipeline>();
    std::vector<Step> run;
    if (pipe->set_target(t.box_x + d.dx, t.box_y + d.dy, static_cast<uint16_t>(t.box_w),
                         static_cast<uint16_t>(t.box_h)) != qt::Status::ok) {
        std::fprintf(stderr, "bench_footage: %s: start box refused\n", t.name.c_str());
        std::exit(1);
    }
    for (int k = t.start; k <= t.last_frame(); ++k) {
        const qt::io::GreyImage& f = frames[static_cast<size_t>(k)];
        const auto t0 = std::chrono::steady_clock::now();
        pipe->begin_frame(static_cast<uint16_t>(f.width), static_cast<uint16_t>(f.height), config);
        for (int y = 0; y < f.height; ++y) pipe->push_row(f.row(y), static_cast<uint16_t>(f.width));
        qt::TargetFrame r;
        const qt::Status s = pipe->finish(r);
        Step step;
        step.ms = ms_since(t0);
        step.tracking =
            s == qt::Status::ok && r.tracking && r.estimate.state != qt::TargetState::lost;
        step.claims = step.tracking && (r.estimate.state == qt::TargetState::measured ||
                                        r.estimate.state == qt::TargetState::reacquired);
        step.x = r.estimate.x;
        step.y = r.estimate.y;
        step.state = qt::target_state_name(r.estimate.state);
        step.score = r.hit.score_q15 / 32768.0;
        step.nds = r.estimate.nds;
        step.wx = r.window.x;
        step.wy = r.window.y;
        step.unseen = r.estimate.unseen;
        run.push_back(step);
    }
    return run;
}

// The colour frames, BGR, read from their raw file a frame at a time (all of them would take
// 3 bytes a pixel of memory).
class ColourFrames {
public:
    ~ColourFrames() {
        if (f_) std::fclose(f_);
    }
    bool open(const std::string& path, int width, int height, size_t count, std::string& error) {
        f_ = std::fopen(path.c_str(), "rb");
        bytes_ = static_cast<size_t>(width) * static_cast<size_t>(height) * 3;
        if (!f_ || std::fseek(f_, 0, SEEK_END) != 0 ||
            static_cast<size_t>(std::ftell(f_)) != bytes_ * count) {
            error = path + ": not " + std::to_string(count) + " BGR frames of " +
                    std::to_string(width) + "x" + std::to_string(height);
            return false;
        }
        return true;
    }
    bool is_open() const { return f_ != nullptr; }
    // Frame k into *pixels (width · height · 3 bytes); false on a read error.
    bool read(int k, uint8_t* pixels) const {
        return std::fseek(f_, static_cast<long>(bytes_ * static_cast<size_t>(k)), SEEK_SET) == 0 &&
               std::fread(pixels, 1, bytes_, f_) == bytes_;
    }

private:
    std::FILE* f_ = nullptr;
    size_t bytes_ = 0;
};
ColourFrames colour_frames;  // open when --colour was given

#ifdef QT_HAVE_OPENCV_TRACKING
// OpenCV's tracker from make(), default parameters, on the colour frames when they are open
// and on the grey levels (as three equal channels) otherwise.
template <class Make>
std::vector<Step> run_opencv(const std::vector<qt::io::GreyImage>& frames, const FootageTruth& t,
                             Shift d, Make make) {
    cv::Ptr<cv::Tracker> tracker = make();
    std::vector<Step> run;
    cv::Rect box(t.box_x + d.dx, t.box_y + d.dy, t.box_w, t.box_h);
    cv::Mat bgr(frames[0].height, frames[0].width, CV_8UC3);
    for (int k = t.start; k <= t.last_frame(); ++k) {
        const qt::io::GreyImage& f = frames[static_cast<size_t>(k)];
        if (colour_frames.is_open() && !colour_frames.read(k, bgr.data)) {
            std::fprintf(stderr, "bench_footage: colour frame %d unreadable\n", k);
            std::exit(1);
        }
        const auto t0 = std::chrono::steady_clock::now();
        if (!colour_frames.is_open())  // the grey conversion timed, as it was before
            cv::cvtColor(cv::Mat(f.height, f.width, CV_8UC1, const_cast<uint8_t*>(f.row(0))), bgr,
                         cv::COLOR_GRAY2BGR);
        Step step;
        if (k == t.start) {
            tracker->init(bgr, box);
            step.claims = true;
        } else {
            step.claims = tracker->update(bgr, box);
        }
        step.ms = ms_since(t0);
        step.tracking = step.claims;  // a failed update gives no box
        step.x = box.x + (box.width - 1) / 2.0;
        step.y = box.y + (box.height - 1) / 2.0;
        run.push_back(step);
    }
    return run;
}
#endif

void trace(const std::vector<Step>& run, const FootageTruth& t, int start_box) {
    for (size_t i = 0; i < run.size(); ++i) {
        const int frame = t.start + static_cast<int>(i);
        double x = 0, y = 0;
        Seen seen;
        const bool present = t.at(frame, x, y, seen);
        const Step& st = run[i];
        std::fprintf(stderr,
                     "%s/%d %4d truth %6.1f %6.1f %-8s  ours %7.1f %7.1f %-11s ncc %.3f nds %6.2f "
                     "window %7.1f %7.1f unseen %3d error %6.1f\n",
                     t.name.c_str(), start_box, frame, x, y, qt::scene::seen_name(seen), st.x, st.y,
                     st.state, st.score, st.nds, st.wx, st.wy, i > 0 ? run[i - 1].unseen : 0,
                     present ? std::hypot(st.x - x, st.y - y) : NAN);
    }
}

// The chart of one target: each tracker's error over the span (from the marked box; no box:
// drawn at the top), occlusions and frames out of the picture shaded.
bool plot_errors(const std::string& path, const FootageTruth& t,
                 const std::vector<const char*>& names, const std::vector<std::vector<Step>>& runs,
                 double radius) {
    qt::io::LinePlot plot;
    plot.title = "target " + t.name + " in " + t.video + ": error from the marked box (" +
                 std::to_string(static_cast<int>(radius)) + " px: 'within')";
    plot.x_label = "frame";
    plot.y_label = "error, px (no box: at the top)";
    plot.y_max = 60;
    plot.markers = false;
    for (size_t k = 0; k < names.size(); ++k) plot.series.push_back({names[k], {}});
    Seen last = Seen::visible;
    double span_start = 0;
    for (int frame = t.start; frame <= t.last_frame(); ++frame) {
        plot.x.push_back(frame);
        double x = 0, y = 0;
        Seen seen;
        const bool present = t.at(frame, x, y, seen);
        for (size_t k = 0; k < names.size(); ++k) {
            const Step& st = runs[k][static_cast<size_t>(frame - t.start)];
            plot.series[k].y.push_back(!present      ? NAN
                                       : st.tracking ? std::hypot(st.x - x, st.y - y)
                                                     : plot.y_max);
        }
        if (seen != last || frame == t.last_frame()) {
            if (last != Seen::visible)
                plot.spans.push_back(
                    {span_start, static_cast<double>(frame), last == Seen::out ? "out" : "hidden"});
            span_start = frame;
            last = seen;
        }
    }
    if (plot.x.size() > 20) {
        for (int f = (t.start + 9) / 10 * 10; f <= t.last_frame(); f += 20)
            plot.ticks.push_back({static_cast<double>(f), std::to_string(f)});
    }
    std::string error;
    if (!qt::io::write_svg_line_plot(path, plot, error)) {
        std::fprintf(stderr, "bench_footage: %s\n", error.c_str());
        return false;
    }
    return true;
}

struct Row {
    std::string target, tracker;
    Score s;
};

std::string percent(int n, int of) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f %%", 100.0 * n / std::max(1, of));
    return b;
}

void print_row(const Row& r) {
    const Score& s = r.s;
    std::string reacq = "-";
    if (s.occlusions > 0) {
        std::vector<double> f(s.reacquire_frames.begin(), s.reacquire_frames.end());
        char b[64];
        std::snprintf(b, sizeof b, "%d of %d", s.reacquired, s.occlusions);
        reacq = b;
        if (!f.empty()) {
            std::snprintf(b, sizeof b, ", median %.0f", median(f));
            reacq += b;
        }
    }
    std::printf("| %s | %s | %d | %s | %.1f | %d in %d runs of %d | %d | %d of %d | %s | %.2f |\n",
                r.target.c_str(), r.tracker.c_str(), s.frames, percent(s.within, s.frames).c_str(),
                median(s.errors), s.switches, s.runs - s.kept, s.runs, s.claims_out, s.wrong_after,
                s.occlusions, reacq.c_str(), median(s.times));
}

}  // namespace

int main(int argc, char** argv) {
    std::string video;
    std::vector<std::string> truths;
    double radius = 10;
    int starts = 5;
    bool tracing = false, only_ours = false;
    std::string out_dir, colour_path;
    const char* usage =
        "usage: bench_footage VIDEO.y4m TRUTH.txt... [--colour FRAMES.bgr] [--radius PX] "
        "[--starts N]\n"
        "       [--out DIR] [--quadtrack-only] [--trace] [-- TARGET FLAGS]\n";
    qt::cli::TargetOptions options;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--")) {
            // The rest: quadtrack target's flags, parsed by its own parser (with a stand-in
            // sequence and box, which the truth files give here).
            std::vector<std::string> args(argv + i + 1, argv + argc), positional;
            args.push_back("--roi=0,0,1,1");
            args.push_back("-");
            const int parsed = qt::cli::parse_target_command_line(
                args, qt::cli::GeometryCommand::target, usage, options, positional, stdout, stderr);
            if (parsed >= 0) return parsed;
            break;
        }
        if (!std::strcmp(argv[i], "--radius") && i + 1 < argc) {
            radius = std::atof(argv[++i]);
        } else if (!std::strcmp(argv[i], "--starts") && i + 1 < argc) {
            starts = std::max(1, std::min(5, std::atoi(argv[++i])));
        } else if (!std::strcmp(argv[i], "--colour") && i + 1 < argc) {
            colour_path = argv[++i];
        } else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) {
            out_dir = argv[++i];
        } else if (!std::strcmp(argv[i], "--quadtrack-only")) {
            only_ours = true;
        } else if (!std::strcmp(argv[i], "--trace")) {
            tracing = true;
        } else if (argv[i][0] == '-') {
            std::fputs(usage, stderr);
            return 2;
        } else if (video.empty()) {
            video = argv[i];
        } else {
            truths.push_back(argv[i]);
        }
    }
    if (video.empty() || truths.empty()) {
        std::fputs(usage, stderr);
        return 2;
    }
    std::string error;
    qt::io::FrameSource source;
    if (!source.open(video, error)) {
        std::fprintf(stderr, "bench_footage: %s\n", error.c_str());
        return 1;
    }
    std::vector<qt::io::GreyImage> frames;
    qt::io::GreyImage frame;
    qt::io::FrameSource::Next n;
    while ((n = source.next(frame, error)) == qt::io::FrameSource::Next::frame)
        frames.push_back(frame);
    if (n == qt::io::FrameSource::Next::error) {
        std::fprintf(stderr, "bench_footage: %s\n", error.c_str());
        return 1;
    }
    if (!colour_path.empty() &&
        (frames.empty() || !colour_frames.open(colour_path, frames[0].width, frames[0].height,
                                               frames.size(), error))) {
        std::fprintf(stderr, "bench_footage: %s\n", error.empty() ? "no frames" : error.c_str());
        return 1;
    }
    const bool colour = colour_frames.is_open();
    // The trackers, each run from every start box of every target.
    struct Tracker {
        const char* name;
        std::vector<Step> (*run)(const std::vector<qt::io::GreyImage>&, const FootageTruth&, Shift,
                                 const qt::TargetPipelineParams&);
    };
    std::vector<Tracker> trackers = {{"quadtrack (grey)", run_quadtrack}};
#ifdef QT_HAVE_OPENCV_TRACKING
    if (!only_ours) {
        trackers.push_back(
            {colour ? "OpenCV CSRT (colour, defaults)" : "OpenCV CSRT (grey, defaults)",
             [](const std::vector<qt::io::GreyImage>& f, const FootageTruth& t, Shift d,
                const qt::TargetPipelineParams&) {
                 return run_opencv(f, t, d, [] { return cv::TrackerCSRT::create(); });
             }});
        trackers.push_back(
            {colour ? "OpenCV KCF (colour, defaults)" : "OpenCV KCF (grey, defaults)",
             [](const std::vector<qt::io::GreyImage>& f, const FootageTruth& t, Shift d,
                const qt::TargetPipelineParams&) {
                 return run_opencv(f, t, d, [] { return cv::TrackerKCF::create(); });
             }});
    }
#else
    (void)only_ours;  // no OpenCV rows to leave out
    (void)colour;
#endif
    const Shift all_shifts[] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    std::vector<Row> rows;
    std::vector<Score> totals(trackers.size());
    std::vector<std::string> csrt_kept;  // targets CSRT keeps in every run
    int ours_switches_on_kept = 0;
    for (const std::string& path : truths) {
        FootageTruth t;
        if (!qt::scene::read_footage_truth(path, t, error)) {
            std::fprintf(stderr, "bench_footage: %s\n", error.c_str());
            return 1;
        }
        if (frames.empty() || frames[0].width != t.width || frames[0].height != t.height ||
            t.last_frame() >= static_cast<int>(frames.size())) {
            std::fprintf(stderr,
                         "bench_footage: %s: marked on %dx%d frames up to %d, the video "
                         "has %zu frames\n",
                         path.c_str(), t.width, t.height, t.last_frame(), frames.size());
            return 1;
        }
        std::vector<std::vector<Step>> first_runs;  // each tracker's run from the marked box
        std::vector<int> switches;                  // each tracker's, over the runs
        for (size_t k = 0; k < trackers.size(); ++k) {
            Score s;
            for (int i = 0; i < starts; ++i) {
                std::vector<Step> run = trackers[k].run(frames, t, all_shifts[i], options.config);
                if (tracing && k == 0) trace(run, t, i);
                s.add(score(run, t, radius));
                if (i == 0) first_runs.push_back(std::move(run));
            }
            rows.push_back({t.name, trackers[k].name, s});
            totals[k].add(s);
            switches.push_back(s.switches);
        }
        if (!out_dir.empty()) {
            std::vector<const char*> names;
            for (const Tracker& k : trackers) names.push_back(k.name);
            if (!plot_errors(out_dir + "/error_" + t.name + ".svg", t, names, first_runs, radius))
                return 1;
        }
        if (trackers.size() > 1 && switches[1] == 0) {  // trackers[1]: CSRT
            csrt_kept.push_back(t.name);
            ours_switches_on_kept += switches[0];
        }
    }
    for (size_t k = 0; k < trackers.size(); ++k)
        rows.push_back({"all", trackers[k].name, totals[k]});
    std::printf(
        "%zu frames of %s; each target from %d start box%s; within: the estimate within "
        "%.0f px of the truth; a switch: a run of frames claiming a measurement more than "
        "%.0f px from the truth while the target is in the frame\n\n",
        frames.size(), video.c_str(), starts, starts > 1 ? "es" : "", radius, 2 * radius);
    std::printf(
        "| target | tracker | frames in view | within %.0f px | median error, px | "
        "switches | frames claimed while out | occlusions with a wrong claim | "
        "re-acquired after an occlusion, frames | ms/frame |\n",
        radius);
    std::printf("|---|---|---:|---:|---:|---|---:|---:|---|---:|\n");
    for (const Row& r : rows) print_row(r);
    const Score& ours = totals[0];
    std::printf(
        "\nquadtrack: occlusions followed by a wrong claim before the target was re-acquired: "
        "%d of %d (aim 0): %s\n",
        ours.wrong_after, ours.occlusions, ours.wrong_after == 0 ? "met" : "NOT met");
    std::printf(
        "quadtrack: frames giving a position more than a frame width (height) outside the image "
        "while the target is in it: %d (aim 0): %s\n",
        ours.far_outside, ours.far_outside == 0 ? "met" : "NOT met");
    if (trackers.size() > 1) {
        std::string kept;
        for (const std::string& n : csrt_kept) kept += (kept.empty() ? "" : ", ") + n;
        std::printf(
            "targets CSRT keeps in every run (no switch): %s; quadtrack's switches on them: "
            "%d (aim 0): %s\n",
            kept.empty() ? "none" : kept.c_str(), ours_switches_on_kept,
            ours_switches_on_kept == 0 ? "met" : "NOT met");
        const double a = 100.0 * ours.within / std::max(1, ours.frames),
                     b = 100.0 * totals[1].within / std::max(1, totals[1].frames);
        std::printf(
            "frames within %.0f px: quadtrack %.1f %%, CSRT %.1f %% (aim: at least CSRT's): "
            "%s\n",
            radius, a, b, a >= b ? "met" : "NOT met");
        const double ta = median(ours.times), tb = median(totals[1].times);
        std::printf(
            "time per frame, median: quadtrack %.2f ms, CSRT %.2f ms (aim: at most a "
            "fifth of CSRT's): %s\n",
            ta, tb, 5 * ta <= tb ? "met" : "NOT met");
    }
    return 0;
}
