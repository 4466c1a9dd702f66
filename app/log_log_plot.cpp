#include "app/log_log_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace hexant::app {

namespace {

constexpr double kWidth = 640, kHeight = 440;
constexpr double kLeft = 80, kRight = 150, kTop = 40, kBottom = 60;

std::string escape(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

// Whole decades around [lo, hi].
std::pair<double, double> decades(double lo, double hi) {
    double a = std::floor(std::log10(lo)), b = std::ceil(std::log10(hi));
    if (a == b) b = a + 1;
    return {a, b};
}

std::string number(double exponent) {
    std::ostringstream s;
    s << std::defaultfloat << std::setprecision(3) << std::pow(10.0, exponent);
    return s.str();
}

}  // namespace

std::string to_svg(const LogLogPlot& plot) {
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
    double y_lo = x_lo, y_hi = -x_lo;
    for (const auto& curve : plot.curves)
        for (const auto& [x, y] : curve.points)
            if (x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y)) {
                x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
                y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
            }
    if (!(x_lo <= x_hi)) x_lo = 1, x_hi = 10, y_lo = 1, y_hi = 10;
    // Plain names, not structured bindings: lambdas capture these (clang
    // before 16, which the fuzz build uses, cannot capture a binding).
    const std::pair<double, double> x_decades = decades(x_lo, x_hi),
                                    y_decades = decades(y_lo, y_hi);
    const double xa = x_decades.first, xb = x_decades.second;
    const double ya = y_decades.first, yb = y_decades.second;
    const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
    const auto px = [&](double x) { return kLeft + (std::log10(x) - xa) / (xb - xa) * plot_w; };
    const auto py = [&](double y) { return kTop + (yb - std::log10(y)) / (yb - ya) * plot_h; };

    std::ostringstream svg;
    svg << std::fixed << std::setprecision(1);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\""
        << kHeight << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << kLeft + plot_w / 2 << "\" y=\"24\" text-anchor=\"middle\" "
        << "font-size=\"14\">" << escape(plot.title) << "</text>\n";
    // Decade grid lines with their labels.
    for (double e = xa; e <= xb; e += 1.0) {
        const double x = kLeft + (e - xa) / (xb - xa) * plot_w;
        svg << "<line x1=\"" << x << "\" y1=\"" << kTop << "\" x2=\"" << x << "\" y2=\""
            << kTop + plot_h << "\" stroke=\"#ddd\"/>\n"
            << "<text x=\"" << x << "\" y=\"" << kTop + plot_h + 16 << "\" text-anchor=\"middle\">"
            << number(e) << "</text>\n";
    }
    for (double e = ya; e <= yb; e += 1.0) {
        const double y = kTop + (yb - e) / (yb - ya) * plot_h;
        svg << "<line x1=\"" << kLeft << "\" y1=\"" << y << "\" x2=\"" << kLeft + plot_w
            << "\" y2=\"" << y << "\" stroke=\"#ddd\"/>\n"
            << "<text x=\"" << kLeft - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
            << number(e) << "</text>\n";
    }
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << plot_w << "\" height=\""
        << plot_h << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text x=\"" << kLeft + plot_w / 2 << "\" y=\"" << kHeight - 18
        << "\" text-anchor=\"middle\">" << escape(plot.x_label) << "</text>\n"
        << "<text transform=\"translate(20," << kTop + plot_h / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << escape(plot.y_label) << "</text>\n";
    // The curves and the legend.
    double legend_y = kTop + 10;
    for (const auto& curve : plot.curves) {
        const std::string dash = curve.dashed   ? "\" stroke-dasharray=\"6,4"
                                 : curve.dotted ? "\" stroke-dasharray=\"2,3"
                                                : "";
        svg << "<polyline fill=\"none\" stroke=\"" << curve.colour << dash
            << "\" stroke-width=\"2\" points=\"";
        for (const auto& [x, y] : curve.points)
            if (x > 0 && y > 0) svg << px(x) << "," << py(y) << " ";
        svg << "\"/>\n";
        for (const auto& [x, y] : curve.points)
            if (x > 0 && y > 0)
                svg << "<circle cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"3\" fill=\""
                    << curve.colour << "\"/>\n";
        svg << "<line x1=\"" << kLeft + plot_w + 12 << "\" y1=\"" << legend_y << "\" x2=\""
            << kLeft + plot_w + 36 << "\" y2=\"" << legend_y << "\" stroke=\"" << curve.colour
            << dash << "\" stroke-width=\"2\"/>\n"
            << "<text x=\"" << kLeft + plot_w + 42 << "\" y=\"" << legend_y + 4 << "\">"
            << escape(curve.name) << "</text>\n";
        legend_y += 18;
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace hexant::app
