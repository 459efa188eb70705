// The benches' SVG charts (platform/io/svg_plot.h): a NaN value leaves a gap in its series, and
// malformed plots are refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "io/svg_plot.h"
#include "support/temp_dir.h"

namespace {

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("svg line plot: a NaN splits its series into two lines", "[svg]") {
    qt::test::TempDir d;
    qt::io::LinePlot plot;
    plot.x = {0, 1, 2, 3, 4};
    plot.series.push_back({"a", {1, 2, NAN, 3, 4}});
    plot.series.push_back({"b", {1, 2, 3, 4, 5}});
    const std::string path = (d.dir / "p.svg").string();
    std::string error;
    REQUIRE(qt::io::write_svg_line_plot(path, plot, error));
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    CHECK(count(text.str(), "<polyline") == 3);  // a: two runs, b: one
    CHECK(count(text.str(), "<circle") == 9);    // no marker for the NaN
    plot.series[1].y.pop_back();
    CHECK_FALSE(qt::io::write_svg_line_plot(path, plot, error));
}
