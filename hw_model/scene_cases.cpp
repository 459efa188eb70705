#include "scene_cases.h"

#include "board_scene.h"
#include "line_detector.h"
#include "line_scene.h"
#include "line_text.h"

namespace qt::vec {

std::vector<SceneCase> scene_cases() {
    std::vector<SceneCase> cases;
    {   // The demo's board scene at half size.
        scene::BoardScene b = scene::default_board_scene();
        b.width = 320;
        b.height = 240;
        for (auto& c : b.corners) c = {c.x / 2, c.y / 2};
        cases.push_back({"board_qvga", scene::render_board(b)});
    }
    {   // Three shapes over blobs and texture, blurred and noisy: a cluttered frame.
        scene::SceneOptions o;
        o.noise_sigma = 5;
        o.blur_sigma = 0.8;
        o.clutter_blobs = 25;
        o.clutter_texture = 20;
        o.seed = 31;
        cases.push_back({"clutter_qvga", scene::random_polygon_scene(o, 3, 30, 60).render()});
    }
    return cases;
}

std::string format_pgm(const scene::GreyImage& img) {
    std::string s = "P5\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n255\n";
    s.append(img.pixels.begin(), img.pixels.end());
    return s;
}

std::string lines_text(const SceneCase& c) {
    static LineDetectorQvga det;
    std::string text;
    char buf[kLineTextMax];
    if (det.begin_frame(static_cast<uint16_t>(c.frame.width), static_cast<uint16_t>(c.frame.height),
                        LineParams{}) != Status::ok)
        return "error: frame does not fit LineDetectorQvga\n";
    for (int y = 0; y < c.frame.height; ++y)
        det.push_row(c.frame.row(y), static_cast<uint16_t>(c.frame.width));
    if (det.finish() != Status::ok) return "error: lines stage failed\n";
    text.append(buf, format_frame_header(c.name.c_str(), det.stats().edges, det.segment_count(),
                                         det.line_count(), buf));
    for (uint16_t i = 0; i < det.line_count(); ++i) text.append(buf, format_line_text(det.lines()[i], buf));
    return text;
}

}  // namespace qt::vec
