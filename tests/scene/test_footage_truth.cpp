// The hand-marked truth of the real-footage bench (vectors/footage, format in
// platform/scene/footage_truth.h): the reader and the interpolation on hand-worked files, every
// committed file well formed, and each first marking against a second, independent marking of
// some of its frames (*.second.txt): the two agree within 2 px and on the state.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/footage_truth.h"
#include "support/temp_dir.h"

using qt::scene::FootageMark;
using qt::scene::FootageTruth;
using qt::scene::read_footage_truth;
using qt::scene::Seen;

namespace {

std::string write(const qt::test::TempDir& d, const std::string& name, const std::string& text) {
    const std::string path = (d.dir / name).string();
    std::ofstream(path) << text;
    return path;
}

const char* kHeader = "# a walker\ntarget w\nvideo v.avi 384x288\nstart 10 100 50 12 30\n";

bool is_second(const std::filesystem::path& p) {
    const std::string s = p.filename().string();
    return s.size() > 11 && s.compare(s.size() - 11, 11, ".second.txt") == 0;
}

}  // namespace

TEST_CASE("footage truth: marks are read and interpolated between, never across out", "[footage]") {
    qt::test::TempDir d;
    FootageTruth t;
    std::string error;
    REQUIRE(read_footage_truth(write(d, "a.txt",
                                     std::string(kHeader) + "10 105.5 64.5 12 30 visible\n"
                                                            "15 95.5 74.5 12 30 occluded\n"
                                                            "18 89.5 74.5 12 30 occluded\n"
                                                            "20 85.5 74.5 12 30 visible\n"
                                                            "25 - - - - out\n"),
                               t, error));
    CHECK(t.name == "w");
    CHECK(t.width == 384);
    CHECK(t.start == 10);
    CHECK(t.box_w == 12);
    CHECK(t.last_frame() == 25);
    double x = 0, y = 0;
    Seen seen;
    REQUIRE(t.at(10, x, y, seen));
    CHECK(x == 105.5);
    CHECK(seen == Seen::visible);
    REQUIRE(t.at(12, x, y, seen));  // 2/5 of the way from frame 10 to 15
    CHECK(std::fabs(x - 101.5) < 1e-12);
    CHECK(std::fabs(y - 68.5) < 1e-12);
    CHECK(seen == Seen::visible);   // 15 is the occlusion's first frame
    REQUIRE(t.at(16, x, y, seen));  // between two occluded marks: hidden
    CHECK(std::fabs(x - 93.5) < 1e-12);
    CHECK(seen == Seen::occluded);
    REQUIRE(t.at(19, x, y, seen));  // 18 is the occlusion's last frame
    CHECK(std::fabs(x - 87.5) < 1e-12);
    CHECK(seen == Seen::visible);
    CHECK(!t.at(22, x, y, seen));  // next to out: no position
    CHECK(!t.at(25, x, y, seen));
    CHECK(seen == Seen::out);
    CHECK(!t.at(9, x, y, seen));
    CHECK(!t.at(26, x, y, seen));
}

TEST_CASE("footage truth: malformed files are refused with their line", "[footage]") {
    qt::test::TempDir d;
    FootageTruth t;
    std::string error;
    CHECK(!read_footage_truth(write(d, "b.txt", std::string(kHeader) + "10 1 2 3 4 hidden\n"), t,
                              error));
    CHECK(error.find("b.txt:5: state 'hidden'") != std::string::npos);
    CHECK(!read_footage_truth(
        write(d, "c.txt", std::string(kHeader) + "10 1 2 3 4 visible\n9 1 2 3 4 visible\n"), t,
        error));
    CHECK(error.find(":6: marks must be in increasing frame order") != std::string::npos);
    CHECK(!read_footage_truth(write(d, "e.txt", std::string(kHeader) + "11 1 2 3 4 visible\n"), t,
                              error));
    CHECK(error.find("the first mark must be at the start frame") != std::string::npos);
    CHECK(!read_footage_truth(write(d, "f.txt", "target w\n10 1 2 3 4 visible\n"), t, error));
    CHECK(!read_footage_truth((d.dir / "missing.txt").string(), t, error));
}

TEST_CASE("footage truth: the committed markings are well formed and a second marking agrees",
          "[footage]") {
    const std::filesystem::path dir = QT_FOOTAGE_DIR;
    int files = 0, compared = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::filesystem::path p = entry.path();
        if (p.extension() != ".txt" || is_second(p)) continue;
        ++files;
        FootageTruth t;
        std::string error;
        INFO(p.string());
        REQUIRE(read_footage_truth(p.string(), t, error));
        // The start box holds the first mark's centre, and every mark lies in the frame.
        const FootageMark& m0 = t.marks.front();
        CHECK(std::fabs(t.box_x + (t.box_w - 1) / 2.0 - m0.x) <= 2.0);
        CHECK(std::fabs(t.box_y + (t.box_h - 1) / 2.0 - m0.y) <= 2.0);
        for (const FootageMark& m : t.marks) {
            if (m.seen == Seen::out) continue;
            CHECK(m.x >= 0);
            CHECK(m.x <= t.width - 1);
            CHECK(m.y >= 0);
            CHECK(m.y <= t.height - 1);
        }
        // The second marking: the same frames, marked again without looking at the first.
        std::filesystem::path second = p;
        second.replace_extension(".second.txt");
        REQUIRE(std::filesystem::exists(second));
        FootageTruth u;
        REQUIRE(read_footage_truth(second.string(), u, error));
        for (const FootageMark& b : u.marks) {
            for (const FootageMark& a : t.marks) {
                if (a.frame != b.frame) continue;
                INFO("frame " << a.frame);
                ++compared;
                CHECK(a.seen == b.seen);
                if (a.seen != Seen::out && b.seen != Seen::out)
                    CHECK(std::hypot(a.x - b.x, a.y - b.y) <= 2.0);
            }
        }
    }
    CHECK(files >= 4);
    CHECK(compared >= 3 * files);
}
