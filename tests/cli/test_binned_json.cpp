// Results of a binned frame written in the input's pixels, against cases worked by hand from
// the mapping x = N·u + (N − 1)/2 (binned pixel u covers input pixels N·u .. N·u + N − 1):
// the homography conjugated by A's and B's factors, the target's position, a line's rho.
#include <catch2/catch.hpp>

#include <string>

#include "cli/target_json.h"
#include "host/board_runner.h"
#include "support/json_reader.h"

using qt::test::Json;
using qt::test::JsonReader;

namespace {

qt::FrameHomography shift(float tx, float ty) {
    qt::FrameHomography g;
    g.ransac.status = qt::HomographyStatus::ok;
    g.ransac.h.m[2] = tx;
    g.ransac.h.m[5] = ty;
    g.ransac.reprojection_px = 0.25f;
    return g;
}

void check_h(const Json& h, const double (&want)[9]) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            INFO("H[" << r << "][" << c << "]");
            CHECK(h[static_cast<size_t>(r)][static_cast<size_t>(c)].num ==
                  Approx(want[3 * r + c]).margin(1e-6));
        }
}

}  // namespace

TEST_CASE("homography JSON of binned frames maps the input's pixels", "[cli][binning]") {
    // Binned B = binned A + (5, −3). A and B both by 2: input x = 2u + 0.5, so
    // x_B = 2((x_A − 0.5)/2 + 5) + 0.5 = x_A + 10, and y_B = y_A − 6.
    const Json both = JsonReader::parse(qt::cli::homography_json(shift(5, -3), 10, 12, 2, 2));
    check_h(both["H"], {1, 0, 10, 0, 1, -6, 0, 0, 1});
    CHECK(both["reprojection_px"].num == Approx(0.5));  // 0.25 binned px of B, by 2
    CHECK(both["bin"][0].num == 2);
    CHECK(both["bin"][1].num == 2);
    // A by 3, B as it is: x_B = (x_A − 1)/3 + 5 = x_A/3 + 14/3, y_B = y_A/3 − 10/3.
    const Json mixed = JsonReader::parse(qt::cli::homography_json(shift(5, -3), 10, 12, 3, 1));
    check_h(mixed["H"], {1.0 / 3, 0, 14.0 / 3, 0, 1.0 / 3, -10.0 / 3, 0, 0, 1});
    CHECK(mixed["reprojection_px"].num == Approx(0.25));
    // Not binned: H as it is.
    check_h(JsonReader::parse(qt::cli::homography_json(shift(5, -3), 10, 12))["H"],
            {1, 0, 5, 0, 1, -3, 0, 0, 1});
}

TEST_CASE("target JSON of a binned frame gives the input's pixels", "[cli][binning]") {
    qt::TargetFrame f;
    f.estimate.x = 10;
    f.estimate.y = -4;  // out of view: above the frame
    const Json by3 = JsonReader::parse(qt::cli::target_json(7, f, 3));
    CHECK(by3["x"].num == Approx(31));   // 3·10 + 1
    CHECK(by3["y"].num == Approx(-11));  // 3·(−4) + 1
    CHECK(by3["bin"].num == 3);
    const Json by1 = JsonReader::parse(qt::cli::target_json(7, f));
    CHECK(by1["x"].num == Approx(10));
    CHECK(by1["bin"].num == 1);
}

TEST_CASE("a binned line's rho and theta in the input's pixels", "[cli][binning]") {
    // The vertical line u = 5 (normal 0°, rho 5) binned by 2 is x = 10.5 in the input.
    qt::Segment s{};
    s.x1 = s.x2 = qt::q16_16::from_int(5);
    s.y1 = qt::q16_16::from_int(0);
    s.y2 = qt::q16_16::from_int(20);
    s.rho = qt::q16_16::from_int(5);
    s.theta = qt::angle_from_deg(0);
    const qt::Segment v = qt::host::to_input_pixels(s, 2);
    CHECK(v.rho.raw == qt::q16_16::from_ratio(21, 2).raw);
    CHECK(v.theta == s.theta);
    CHECK(v.x1.raw == qt::q16_16::from_ratio(21, 2).raw);
    CHECK(v.y2.raw == qt::q16_16::from_ratio(81, 2).raw);  // 2·20 + 0.5
    // The line u = 0 by 3 lies at x = 1: rho 0 becomes 1.
    s.x1 = s.x2 = s.rho = qt::q16_16::from_int(0);
    CHECK(qt::host::to_input_pixels(s, 3).rho.raw == qt::q16_16::from_int(1).raw);
}
