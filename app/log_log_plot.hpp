// A log-log line plot written as SVG: curves of (x, y) points with decade
// grid lines, axis labels and a legend. Enough for `hexant bench`'s figures
// without a plotting dependency.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace hexant::app {

struct PlotCurve {
    std::string name;
    std::string colour;                             // an SVG colour, e.g. "#1f77b4"
    std::vector<std::pair<double, double>> points;  // positive x and y
    bool dashed = false;  // a dashed line (an estimate beside its measurement)
    bool dotted = false;  // a dotted line (adaptive sampling beside uniform)
};

struct LogLogPlot {
    std::string title, x_label, y_label;
    std::vector<PlotCurve> curves;
};

// The SVG text. Points with x or y not positive are left out.
std::string to_svg(const LogLogPlot& plot);

}  // namespace hexant::app
