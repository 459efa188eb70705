#include "demo/demo.h"
#include "demo/demo_target.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "demo/demo_sequence.h"
#include "gradient/gradient_stage.h"
#include "io/error_line.h"
#include "io/image_io.h"
#include "io/overlay.h"
#include "io/png_writer.h"
#include "lines/line_detector.h"
#include "scene/board_scene.h"

namespace qt::cli {

namespace {

constexpr uint16_t kDemoMaxWidth = 640;

// Colour of direction bin k (0..15): hue k·22.5°, full saturation, scaled by `level` 0..255.
void direction_colour(uint32_t bin, int level, uint8_t* rgb) {
    const int hue = static_cast<int>(bin) * 360 / 16;  // degrees
    const int sector = hue / 60, f = (hue % 60) * 255 / 60;
    const int up = f, down = 255 - f;
    const int table[6][3] = {{255, up, 0},   {down, 255, 0}, {0, 255, up},
                             {0, down, 255}, {up, 0, 255},   {255, 0, down}};
    for (int c = 0; c < 3; ++c) rgb[c] = static_cast<uint8_t>(table[sector][c] * level / 255);
}

}  // namespace

bool save_demo_picture(const std::string& path, int width, int height, int channels,
                       const std::vector<uint8_t>& pixels) {
    std::string error;
    if (!io::write_png(path, width, height, channels, pixels, error)) {
        qt::io::print_error_line(stderr, "quadtrack demo: %s", error.c_str());
        return false;
    }
    std::printf("wrote %s\n", path.c_str());
    return true;
}

int run_demo(const std::string& out_dir) {
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) {
        qt::io::print_error_line(stderr, "quadtrack demo: cannot create %s: %s", out_dir.c_str(),
                                 ec.message().c_str());
        return 1;
    }
    const io::GreyImage frame = scene::render_board(scene::default_board_scene());
    const int w = frame.width, h = frame.height;

    static GradientStage<kDemoMaxWidth> stage;  // 3.8 KB: static, as firmware would keep it
    std::vector<uint8_t> magnitude(static_cast<size_t>(w) * h);
    std::vector<uint8_t> direction(static_cast<size_t>(w) * h * 3);
    uint64_t sum = 0;
    uint32_t max_mag = 0, strong = 0;
    uint32_t strong_per_bin[16] = {};
    constexpr uint32_t kStrong = 64;  // |g| in grey levels counted as a strong edge
    auto sink = [&](uint16_t y, const gradient_word* words, uint16_t width) {
        for (uint16_t x = 0; x < width; ++x) {
            const uint32_t m = gradient_mag(words[x]);
            const size_t i = static_cast<size_t>(y) * w + x;
            magnitude[i] = static_cast<uint8_t>(m > 255 ? 255 : m);
            direction_colour(gradient_dir(words[x]), m >= 128 ? 255 : static_cast<int>(m * 2),
                             &direction[3 * i]);
            sum += m;
            max_mag = m > max_mag ? m : max_mag;
            if (m >= kStrong) {
                ++strong;
                ++strong_per_bin[gradient_dir(words[x])];
            }
        }
    };
    Status s = stage.begin_frame(static_cast<uint16_t>(w), static_cast<uint16_t>(h));
    for (int y = 0; y < h && s == Status::ok; ++y)
        s = stage.push_row(frame.row(y), static_cast<uint16_t>(w), sink);
    if (s != Status::ok) {
        qt::io::print_error_line(stderr, "quadtrack demo: gradient stage: %s", status_name(s));
        return 1;
    }

    std::printf("demo: synthetic board scene %dx%d, gradient stage (core, fixed point)\n", w, h);
    std::printf("|g| (L1, grey levels): mean %.2f, max %u; %u pixels with |g| >= %u\n",
                static_cast<double>(sum) / (static_cast<double>(w) * h), max_mag, strong, kStrong);
    std::printf("strong pixels per direction bin (22.5 deg each, 0 = +x, 4 = +y/down):");
    for (uint32_t n : strong_per_bin) std::printf(" %u", n);
    std::printf("\n");
    std::string error;
    if (!io::write_pgm(out_dir + "/input.pgm", frame, error)) {
        qt::io::print_error_line(stderr, "quadtrack demo: %s", error.c_str());
        return 1;
    }
    std::printf("wrote %s/input.pgm (try: quadtrack detect %s/input.pgm)\n", out_dir.c_str(),
                out_dir.c_str());
    bool ok = save_demo_picture(out_dir + "/input.png", w, h, 1, frame.pixels) &&
              save_demo_picture(out_dir + "/gradient_magnitude.png", w, h, 1, magnitude) &&
              save_demo_picture(out_dir + "/gradient_direction.png", w, h, 3, direction);

    // Lines stage: edges (blue), PPHT segments (yellow), clustered lines (red).
    static LineDetectorVga lines;  // ram_bytes(): static, as firmware would keep it
    s = lines.begin_frame(static_cast<uint16_t>(w), static_cast<uint16_t>(h), LineParams{});
    for (int y = 0; y < h && s == Status::ok; ++y)
        s = lines.push_row(frame.row(y), static_cast<uint16_t>(w));
    if (s == Status::ok) s = lines.finish();
    if (s != Status::ok) {
        qt::io::print_error_line(stderr, "quadtrack demo: lines stage: %s", status_name(s));
        return 1;
    }
    io::RgbImage overlay = io::RgbImage::from_grey(frame, 50);
    const EdgeList& edges = lines.edges();
    for (uint16_t i = 0; i < edges.size(); ++i)
        overlay.set(static_cast<int>(ep::x(edges[i])), static_cast<int>(ep::y(edges[i])),
                    {60, 120, 255});
    auto draw = [&](const Segment& l, io::Rgb c) {
        overlay.line(l.x1.raw / 65536.0, l.y1.raw / 65536.0, l.x2.raw / 65536.0, l.y2.raw / 65536.0,
                     c);
    };
    for (uint16_t i = 0; i < lines.segment_count(); ++i) draw(lines.segments()[i], {255, 230, 0});
    for (uint16_t i = 0; i < lines.line_count(); ++i) draw(lines.lines()[i], {255, 40, 40});
    const LineStats& st = lines.stats();
    std::printf(
        "lines stage (fixed point, %u B of RAM at VGA): %u edge points, %u PPHT segments, "
        "%u lines after clustering\n",
        LineDetectorVga::ram_bytes(), st.edges, lines.segment_count(), lines.line_count());
    for (uint16_t i = 0; i < lines.line_count(); ++i) {
        const Segment& l = lines.lines()[i];
        std::printf(
            "  line %u: (%.2f, %.2f) - (%.2f, %.2f)  rho %.2f px  theta %.2f deg  %u points\n", i,
            l.x1.raw / 65536.0, l.y1.raw / 65536.0, l.x2.raw / 65536.0, l.y2.raw / 65536.0,
            l.rho.raw / 65536.0, angle_to_deg(l.theta).raw / 65536.0, l.points);
    }
    ok = ok && save_demo_picture(out_dir + "/lines.png", w, h, 3, overlay.pixels);
    ok = ok && run_demo_sequence(out_dir);
    ok = ok && run_demo_target(out_dir);
    return ok ? 0 : 1;
}

}  // namespace qt::cli
