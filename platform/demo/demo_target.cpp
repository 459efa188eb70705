#include "demo/demo_target.h"

#include <cstdio>
#include <filesystem>

#include "demo/demo.h"
#include "demo/target_runner.h"
#include "io/error_line.h"
#include "io/image_io.h"
#include "io/overlay.h"

namespace qt::cli {

namespace {

constexpr int kMargin = 120;  // canvas border around the image, px: out-of-view estimates show

// Frame k on a grey canvas kMargin px wider on each side: the truth (magenta ring), the
// estimate (yellow ring; cyan while measured), the search window (green square).
bool picture(const std::string& path, const io::GreyImage& frame, const TargetRunFrame& f) {
    io::GreyImage canvas(frame.width + 2 * kMargin, frame.height + 2 * kMargin, 60);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) canvas.at(x + kMargin, y + kMargin) = frame.at(x, y);
    io::RgbImage rgb = io::RgbImage::from_grey(canvas, 70);
    const double m = kMargin;
    const TargetEstimate& e = f.result.estimate;
    const bool measured = e.state == TargetState::measured || e.state == TargetState::reacquired;
    if (f.result.window.radius > 0) {
        const double x0 = f.result.window.x - f.result.window.radius + m,
                     x1 = f.result.window.x + f.result.window.radius + m;
        const double y0 = f.result.window.y - f.result.window.radius + m,
                     y1 = f.result.window.y + f.result.window.radius + m;
        rgb.line(x0, y0, x1, y0, {0, 200, 0});
        rgb.line(x1, y0, x1, y1, {0, 200, 0});
        rgb.line(x1, y1, x0, y1, {0, 200, 0});
        rgb.line(x0, y1, x0, y0, {0, 200, 0});
    }
    rgb.ring(f.truth.target_x + m, f.truth.target_y + m, 9, {255, 0, 255});
    rgb.ring(e.x + m, e.y + m, 6, measured ? io::Rgb{0, 230, 255} : io::Rgb{255, 220, 0});
    // The image's border.
    rgb.line(m - 1, m - 1, m + frame.width, m - 1, {255, 255, 255});
    rgb.line(m + frame.width, m - 1, m + frame.width, m + frame.height, {255, 255, 255});
    rgb.line(m + frame.width, m + frame.height, m - 1, m + frame.height, {255, 255, 255});
    rgb.line(m - 1, m + frame.height, m - 1, m - 1, {255, 255, 255});
    return save_demo_picture(path, rgb.width, rgb.height, 3, rgb.pixels);
}

}  // namespace

bool run_demo_target(const std::string& out_dir) {
    const scene::GroundSequenceConfig cfg = scene::short_ground_sequence();
    const scene::GroundSequence seq(cfg);
    const std::string dir = out_dir + "/ground";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::vector<io::GreyImage> frames;
    std::string error;
    for (int k = 0; k < seq.frames(); ++k) {
        frames.push_back(seq.render(k));
        char name[32];
        std::snprintf(name, sizeof name, "/f%03d.pgm", k);
        if (!io::write_pgm(dir + name, frames.back(), error)) {
            qt::io::print_error_line(stderr, "quadtrack demo: %s", error.c_str());
            return false;
        }
    }
    const TargetBox box = start_box(seq.truth(0));
    std::printf(
        "\ntarget: a %d-frame airborne sequence in %s/f%%03d.pgm (flare over frames %d-%d, out of "
        "view %d-%d);\n"
        "  the vehicle's box in frame 0 is --roi %d,%d,%d,%d\n",
        seq.frames(), dir.c_str(), cfg.occlusion_start,
        cfg.occlusion_start + cfg.occlusion_frames - 1, cfg.out_of_view_start,
        cfg.out_of_view_start + cfg.out_of_view_frames - 1, box.x, box.y, box.side, box.side);
    const auto run = run_target_sequence(seq, qvga_target_config(), &frames);
    bool ok = true;
    for (size_t k = 0; k < run.size(); ++k) {
        const TargetRunFrame& f = run[k];
        if (k % 4 == 0 || k + 1 == run.size())
            std::printf(
                "  frame %2zu: %-11s estimate (%7.2f, %7.2f)  truth (%7.2f, %7.2f)  error %5.2f "
                "px\n",
                k, target_state_name(f.result.estimate.state), f.result.estimate.x,
                f.result.estimate.y, f.truth.target_x, f.truth.target_y, f.error_px);
    }
    for (int k : {4, cfg.occlusion_start + 4, cfg.out_of_view_start + cfg.out_of_view_frames / 2,
                  cfg.out_of_view_start + cfg.out_of_view_frames + 2}) {
        char name[32];
        std::snprintf(name, sizeof name, "/target_%02d.png", k);
        ok = ok &&
             picture(out_dir + name, frames[static_cast<size_t>(k)], run[static_cast<size_t>(k)]);
    }
    return ok;
}

}  // namespace qt::cli
