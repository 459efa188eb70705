// Host throughput of the core gradient stage on the 640×480 demo scene, median over repeats;
// beside it cv::spatialGradient (3×3 Sobel, int16 outputs) on the same frame in the same run,
// when OpenCV was found at configure time. Run by `bash bench.sh gradient-host`.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "gradient/gradient_stage.h"
#include "scene/board_scene.h"

#ifdef QT_HAVE_OPENCV
#include <opencv2/imgproc.hpp>
#endif

namespace {

constexpr int kRepeats = 31;          // medians over this many timings
constexpr int kFramesPerTiming = 10;  // frames per timing, to rise above clock resolution

template <class F>
double median_seconds_per_frame(F&& run_frame) {
    std::vector<double> t;
    for (int r = 0; r < kRepeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        for (int f = 0; f < kFramesPerTiming; ++f) run_frame();
        const auto t1 = std::chrono::steady_clock::now();
        t.push_back(std::chrono::duration<double>(t1 - t0).count() / kFramesPerTiming);
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

}  // namespace

int main() {
    const qt::io::GreyImage frame = qt::scene::render_board(qt::scene::default_board_scene());
    const int w = frame.width, h = frame.height;
    const double mpix = static_cast<double>(w) * h / 1e6;
    static qt::GradientStage<640> stage;
    volatile uint32_t checksum = 0;
    auto sink = [&](uint16_t, const qt::gradient_word* words, uint16_t width) {
        checksum = checksum + words[width / 2];
    };
    const double core_s = median_seconds_per_frame([&] {
        stage.begin_frame(static_cast<uint16_t>(w), static_cast<uint16_t>(h));
        for (int y = 0; y < h; ++y) stage.push_row(frame.row(y), static_cast<uint16_t>(w), sink);
    });
    std::printf("gradient %dx%d, median of %d timings x %d frames\n", w, h, kRepeats,
                kFramesPerTiming);
    std::printf(
        "  core GradientStage (gx, gy, L1, 16-bin direction): %.3f ms/frame, %.1f Mpixel/s\n",
        core_s * 1e3, mpix / core_s);
#ifdef QT_HAVE_OPENCV
    cv::setNumThreads(1);  // one core each: a fair per-core comparison
    const cv::Mat img(h, w, CV_8UC1, const_cast<uint8_t*>(frame.pixels.data()));
    cv::Mat dx, dy;
    const double cv_s = median_seconds_per_frame([&] { cv::spatialGradient(img, dx, dy); });
    std::printf(
        "  OpenCV cv::spatialGradient (3x3 Sobel dx, dy only): %.3f ms/frame, %.1f Mpixel/s\n",
        cv_s * 1e3, mpix / cv_s);
    std::printf("  ratio core / OpenCV throughput: %.2f\n", cv_s / core_s);
#else
    std::printf(
        "  OpenCV not found at configure time: no comparison row "
        "(apt-get install libopencv-imgproc-dev, then reconfigure)\n");
#endif
    return 0;
}
