// Minimal SVG line chart for benchmark figures a person opens in a browser: a title, axis
// labels, ticks, a grid, several named series in distinct colours with a legend, and shaded
// x spans (e.g. frames where a target is hidden). The y axis spans 0..y_max. Host only.
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
    std::vector<double> y;  // one per LinePlot::x; values outside 0..y_max are clipped; NaN: a gap
};

struct PlotSpan {
    double x0, x1;      // shaded from x0 to x1, in the series' x units
    std::string label;  // written at the top of the span
};

struct LinePlot {
    std::string title, x_label, y_label;
    std::vector<double> x;        // x of every point, increasing; shared by all series
    std::vector<PlotTick> ticks;  // x ticks; empty: one per x value, labelled with the value
    std::vector<PlotSeries> series;
    double y_max = 100;   // top of the y axis (ticks every y_max / 5)
    bool markers = true;  // a dot on every point (off for long series)
    std::vector<PlotSpan> spans;
};

// Writes `plot` as a standalone .svg file (640 × 400 user units). Returns false and sets
// `error` ("PATH: reason", the reason from errno) when the file cannot be written, or a short
// message when the plot is malformed (no x values, a series of the wrong length, x not
// increasing).
bool write_svg_line_plot(const std::string& path, const LinePlot& plot, std::string& error);

}  // namespace qt::io
