#include "io/svg_plot.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace qt::io {

namespace {

// Canvas and plot area, SVG user units (1 unit = 1 CSS px when opened in a browser).
constexpr double kWidth = 640, kHeight = 400;
constexpr double kLeft = 70, kRight = 470, kTop = 40, kBottom = 340;  // plot area
constexpr double kLegendX = 490;

// Okabe–Ito colour-blind-safe colours, then black: distinct for up to 8 series (cycled after).
const char* const kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                "#E69F00", "#56B4E9", "#000000", "#F0E442"};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

// Shortest natural form of a tick value: "15", "2.5".
std::string tick_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string text(double x, double y, const std::string& s, const char* anchor, int size,
                 const std::string& extra = "") {
    return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor +
           "\" font-size=\"" + std::to_string(size) + "\"" + extra + ">" + escape(s) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const char* stroke, double width) {
    return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" +
           num(y2) + "\" stroke=\"" + stroke + "\" stroke-width=\"" + num(width) + "\"/>\n";
}

std::string render(const LinePlot& p) {
    const double x0 = p.x.front(), x1 = p.x.size() > 1 ? p.x.back() : p.x.front() + 1;
    const double xlo = p.x.size() > 1 ? x0 : x0 - 1;
    auto sx = [&](double x) { return kLeft + (x - xlo) / (x1 - xlo) * (kRight - kLeft); };
    auto sy = [&](double v) {
        return kBottom - std::min(p.y_max, std::max(0.0, v)) / p.y_max * (kBottom - kTop);
    };
    std::string s =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
        num(kWidth) + "\" height=\"" + num(kHeight) + "\" viewBox=\"0 0 " + num(kWidth) + " " +
        num(kHeight) + "\" font-family=\"sans-serif\">\n";
    s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s += text(kWidth / 2, 24, p.title, "middle", 16);
    for (const PlotSpan& span : p.spans) {
        const double a = std::max(kLeft, sx(span.x0)), b = std::min(kRight, sx(span.x1));
        s += "<rect x=\"" + num(a) + "\" y=\"" + num(kTop) + "\" width=\"" +
             num(std::max(0.0, b - a)) + "\" height=\"" + num(kBottom - kTop) +
             "\" fill=\"#eeeeee\"/>\n";
        s += text((a + b) / 2, kTop + 14, span.label, "middle", 11);
    }
    // y ticks and grid every fifth of the axis.
    for (int k = 0; k <= 5; ++k) {
        const double v = p.y_max * k / 5;
        s += line(kLeft, sy(v), kRight, sy(v), "#dddddd", 1);
        s += line(kLeft - 5, sy(v), kLeft, sy(v), "black", 1);
        s += text(kLeft - 8, sy(v) + 4, tick_text(v), "end", 12);
    }
    // x ticks.
    std::vector<PlotTick> ticks = p.ticks;
    if (ticks.empty())
        for (double x : p.x) ticks.push_back({x, tick_text(x)});
    for (const PlotTick& t : ticks) {
        s += line(sx(t.x), kBottom, sx(t.x), kBottom + 5, "black", 1);
        s += text(sx(t.x), kBottom + 18, t.label, "middle", 12);
    }
    // Axes and their labels.
    s += line(kLeft, kBottom, kRight, kBottom, "black", 1);
    s += line(kLeft, kTop, kLeft, kBottom, "black", 1);
    s += text((kLeft + kRight) / 2, kBottom + 42, p.x_label, "middle", 13);
    const double ymid = (kTop + kBottom) / 2;
    s += text(20, ymid, p.y_label, "middle", 13, " transform=\"rotate(-90 20 " + num(ymid) + ")\"");
    // Series: polyline with point markers, and the legend entry.
    for (std::size_t i = 0; i < p.series.size(); ++i) {
        const PlotSeries& ser = p.series[i];
        const char* colour = kColours[i % (sizeof kColours / sizeof kColours[0])];
        // One polyline per run of values; a NaN leaves a gap (no value there).
        std::string pts;
        auto flush = [&] {
            if (!pts.empty())
                s += "<polyline fill=\"none\" stroke=\"" + std::string(colour) +
                     "\" stroke-width=\"2\" points=\"" + pts + "\"/>\n";
            pts.clear();
        };
        for (std::size_t k = 0; k < p.x.size(); ++k) {
            if (std::isnan(ser.y[k])) {
                flush();
                continue;
            }
            pts += (pts.empty() ? "" : " ") + num(sx(p.x[k])) + "," + num(sy(ser.y[k]));
        }
        flush();
        for (std::size_t k = 0; p.markers && k < p.x.size(); ++k)
            if (!std::isnan(ser.y[k]))
                s += "<circle cx=\"" + num(sx(p.x[k])) + "\" cy=\"" + num(sy(ser.y[k])) +
                     "\" r=\"2.5\" fill=\"" + colour + "\"/>\n";
        const double ly = kTop + 10 + 22 * static_cast<double>(i);
        s += line(kLegendX, ly, kLegendX + 24, ly, colour, 3);
        s += text(kLegendX + 30, ly + 4, ser.name, "start", 13);
    }
    s += "</svg>\n";
    return s;
}

}  // namespace

bool write_svg_line_plot(const std::string& path, const LinePlot& plot, std::string& error) {
    if (!(plot.y_max > 0)) {
        error = path + ": plot y_max is not positive";
        return false;
    }
    if (plot.x.empty()) {
        error = path + ": plot has no x values";
        return false;
    }
    for (std::size_t k = 1; k < plot.x.size(); ++k)
        if (!(plot.x[k] > plot.x[k - 1])) {
            error = path + ": plot x values are not increasing";
            return false;
        }
    for (const PlotSeries& ser : plot.series)
        if (ser.y.size() != plot.x.size()) {
            error = path + ": series '" + ser.name + "' has " + std::to_string(ser.y.size()) +
                    " values for " + std::to_string(plot.x.size()) + " x values";
            return false;
        }
    const std::string svg = render(plot);
    errno = 0;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    const bool wrote = std::fwrite(svg.data(), 1, svg.size(), f) == svg.size();
    const int write_errno = errno;
    const bool closed = std::fclose(f) == 0;  // a full disk may only show here
    if (!wrote || !closed) {
        const int e = !wrote ? write_errno : errno;
        error = path + ": " + (e ? std::strerror(e) : "write failed");
        return false;
    }
    return true;
}

}  // namespace qt::io
