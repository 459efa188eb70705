// Minimal SVG line chart for benchmark figures a person opens in a browser: a title, axis
// labels, ticks, a grid, several named series in distinct colours with a legend. The y axis
// always spans 0..100 (percent). Host only.
#pragma once
#include <string>
#include <vector>

namespace qt::io {

struct PlotTick {
    double x;           // position on the x axis, in the series' x units
    std::string label;  // text under the tick
};

struct PlotSeries {
    std::string name;       // legend text
    std::vector<double> y;  // percent, one per LinePlot::x; values outside 0..100 are clipped
};

struct LinePlot {
    std::string title, x_label, y_label;
    std::vector<double> x;        // x of every point, increasing; shared by all series
    std::vector<PlotTick> ticks;  // x ticks; empty: one per x value, labelled with the value
    std::vector<PlotSeries> series;
};

// Writes `plot` as a standalone .svg file (640 × 400 user units). Returns false and sets
// `error` ("PATH: reason", the reason from errno) when the file cannot be written, or a short
// message when the plot is malformed (no x values, a series of the wrong length, x not
// increasing).
bool write_svg_line_plot(const std::string& path, const LinePlot& plot, std::string& error);

}  // namespace qt::io
