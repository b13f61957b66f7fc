// A scatter plot of error against time with the Pareto front marked, written as SVG (each point's
// <title> tooltip holds its exact settings), and the same SVG rendered to PNG by librsvg (cairo,
// fonts through fontconfig).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "measure/image_io.h"

namespace penumbra::tools {

enum class Marker { Circle, Square, Triangle, Diamond, Cross, Star, TriangleDown, Hexagon };

struct PlotPoint {
    double x = 0.0;
    double y = 0.0;
    int color = 0;        // index into Plot::colors
    Marker marker = Marker::Circle;
    double radius = 4.0;  // marker size in pixels
    std::string label;    // drawn beside the point when it is on the front
    std::string callout;  // drawn beside the point (and the point ringed) wherever it is
    std::string tooltip;  // SVG <title>
};

struct Plot {
    std::string title;
    std::string subtitle;
    std::string xlabel;
    std::string ylabel;
    bool log_x = true;
    bool log_y = false;  // decades up the y axis (points at or below 0 left out)
    std::vector<PlotPoint> points;
    std::vector<std::size_t> front;  // indices into points, by increasing x
    // Series drawn as lines: each a list of indices into points, joined in the first one's colour.
    std::vector<std::vector<std::size_t>> lines;
    std::vector<std::string> colors; // "#rrggbb"
    std::string color_title = "encoding (colour)";  // the legend's headings
    std::string marker_title = "filter (shape)";
    std::vector<std::pair<std::string, int>> color_legend;     // label, color index
    std::vector<std::pair<std::string, Marker>> marker_legend; // label, marker
    std::vector<std::string> notes;  // lines under the legend
};

// The plot as an SVG document of width x height user units.
std::string plot_svg(const Plot& plot, int width, int height);
// The same plot as an RGB image: plot_svg's document rendered by librsvg onto a white page.
// Throws std::runtime_error when librsvg cannot parse or render it.
measure::Pixels plot_png(const Plot& plot, int width, int height);
// Any SVG document rendered by librsvg at width x height pixels (its viewBox fitted into them).
measure::Pixels svg_to_pixels(const std::string& svg, int width, int height);

}  // namespace penumbra::tools
