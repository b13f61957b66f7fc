#include "plot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <cairo.h>
#include <librsvg/rsvg.h>

namespace penumbra::tools {

using measure::Pixels;
namespace {

struct Vec {
    double x = 0.0, y = 0.0;
};

enum class Anchor { Start, Middle, End };

// One thing to draw, in the SVG's user units.
struct Item {
    enum Kind { Polyline, Polygon, Circle, Text } kind = Polyline;
    std::vector<Vec> pts;   // Polyline, Polygon; Circle: the centre; Text: the baseline start
    double radius = 0.0;    // Circle
    std::string stroke;     // "" none
    std::string fill;       // "" none
    double width = 1.0;     // stroke width
    bool dashed = false;
    std::string text;       // Text
    double size = 12.0;     // Text: font size
    Anchor anchor = Anchor::Start;
    bool bold = false;
    std::string tooltip;
};

// The layout: the display list the SVG writer emits.
class Layout {
public:
    Layout(const Plot& p, int w, int h) : p_(p), w_(w), h_(h) {}

    std::vector<Item> build() {
        left_ = 78.0;
        right_ = static_cast<double>(w_) - 250.0;
        top_ = 84.0;
        bottom_ = static_cast<double>(h_) - 58.0;
        ranges();
        items_.push_back(rect(0, 0, w_, h_, "#ffffff", ""));
        text(left_, 26, p_.title, 17, "#111111", Anchor::Start, true);
        text(left_, 46, p_.subtitle, 12, "#444444", Anchor::Start);
        grid_and_axes();
        series_lines();
        front_line();
        markers();
        legend();
        return items_;
    }

private:
    void ranges() {
        xmin_ = ymin_ = 1e300;
        xmax_ = ymax_ = -1e300;
        for (const auto& pt : p_.points) {
            if (!shown(pt)) continue;
            xmin_ = std::min(xmin_, pt.x);
            xmax_ = std::max(xmax_, pt.x);
            ymin_ = std::min(ymin_, pt.y);
            ymax_ = std::max(ymax_, pt.y);
        }
        if (p_.log_y) {
            if (ymin_ > ymax_) ymin_ = 1.0, ymax_ = 10.0;
            ymin_ = std::pow(10.0, std::floor(std::log10(ymin_ / 1.15)));
            ymax_ = std::pow(10.0, std::ceil(std::log10(ymax_ * 1.15)));
        }
        if (xmin_ > xmax_) xmin_ = 1.0, xmax_ = 10.0, ymax_ = 1.0;
        if (p_.log_x) {
            xmin_ = std::pow(10.0, std::floor(std::log10(xmin_ / 1.15) * 10.0) / 10.0);
            xmax_ = std::pow(10.0, std::ceil(std::log10(xmax_ * 1.15) * 10.0) / 10.0);
        } else {
            const double pad = 0.05 * std::max(xmax_ - xmin_, 1e-9);
            xmin_ = std::max(0.0, xmin_ - pad);
            xmax_ += pad;
        }
        if (p_.log_y) return;
        ymin_ = 0.0;
        ystep_ = nice_step(std::max(ymax_, 1e-9) / 6.0);
        ymax_ = std::ceil(std::max(ymax_ * 1.06, 1e-9) / ystep_) * ystep_;
    }

    bool shown(const PlotPoint& pt) const {
        return std::isfinite(pt.x) && std::isfinite(pt.y) && !(p_.log_x && pt.x <= 0.0) && !(p_.log_y && pt.y <= 0.0);
    }

    // 1, 2, 5 in each decade within [lo, hi] (every integer multiple where that gives under 4).
    static std::vector<double> decade_ticks(double lo, double hi) {
        std::vector<double> t;
        for (const std::vector<int>& ms : {std::vector<int>{1, 2, 5}, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
            t.clear();
            for (double d = std::pow(10.0, std::floor(std::log10(lo))); d <= hi; d *= 10.0)
                for (int m : ms)
                    if (d * m >= lo * 0.999 && d * m <= hi * 1.001) t.push_back(d * m);
            if (t.size() >= 4) break;
        }
        return t;
    }

    static double nice_step(double raw) {
        const double e = std::pow(10.0, std::floor(std::log10(raw)));
        const double f = raw / e;
        return (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 2.5 ? 2.5 : f <= 5.0 ? 5.0 : 10.0) * e;
    }

    double px(double x) const {
        const double t = p_.log_x ? (std::log10(x) - std::log10(xmin_)) / (std::log10(xmax_) - std::log10(xmin_))
                                  : (x - xmin_) / (xmax_ - xmin_);
        return left_ + t * (right_ - left_);
    }
    double py(double y) const {
        const double t = p_.log_y ? (std::log10(y) - std::log10(ymin_)) / (std::log10(ymax_) - std::log10(ymin_))
                                  : (y - ymin_) / (ymax_ - ymin_);
        return bottom_ - t * (bottom_ - top_);
    }

    static std::string fmt(double v) {
        char b[32];
        if (v == 0.0) return "0";
        if (std::fabs(v) >= 100.0 || std::fabs(v - std::round(v)) < 1e-9) std::snprintf(b, sizeof b, "%.0f", v);
        else if (std::fabs(v) >= 1.0) std::snprintf(b, sizeof b, "%.1f", v);
        else std::snprintf(b, sizeof b, "%.2g", v);
        return b;
    }

    static Item rect(double x, double y, double w, double h, const std::string& fill, const std::string& stroke) {
        Item it;
        it.kind = Item::Polygon;
        it.pts = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
        it.fill = fill;
        it.stroke = stroke;
        return it;
    }

    void line(double x0, double y0, double x1, double y1, const std::string& color, double width, bool dashed = false) {
        Item it;
        it.kind = Item::Polyline;
        it.pts = {{x0, y0}, {x1, y1}};
        it.stroke = color;
        it.width = width;
        it.dashed = dashed;
        items_.push_back(it);
    }

    void text(double x, double y, const std::string& s, double size, const std::string& color,
              Anchor a = Anchor::Start, bool bold = false) {
        if (s.empty()) return;
        Item it;
        it.kind = Item::Text;
        it.pts = {{x, y}};
        it.text = s;
        it.size = size;
        it.fill = color;
        it.anchor = a;
        it.bold = bold;
        items_.push_back(it);
    }

    void grid_and_axes() {
        const std::string grid = "#e3e3e3", axis = "#333333";
        std::vector<double> yt;
        if (p_.log_y) yt = decade_ticks(ymin_, ymax_);
        else
            for (double y = ymin_; y <= ymax_ + 1e-9 * ystep_; y += ystep_) yt.push_back(y);
        for (double y : yt) {
            line(left_, py(y), right_, py(y), grid, 1.0);
            text(left_ - 8, py(y) + 4, fmt(y), 11, axis, Anchor::End);
        }
        std::vector<double> xt;
        if (p_.log_x) {
            xt = decade_ticks(xmin_, xmax_);
        } else {
            const double step = nice_step((xmax_ - xmin_) / 6.0);
            for (double x = std::ceil(xmin_ / step) * step; x <= xmax_; x += step) xt.push_back(x);
        }
        for (double x : xt) {
            line(px(x), top_, px(x), bottom_, grid, 1.0);
            text(px(x), bottom_ + 17, fmt(x), 11, axis, Anchor::Middle);
        }
        line(left_, bottom_, right_, bottom_, axis, 1.2);
        line(left_, top_, left_, bottom_, axis, 1.2);
        text(0.5 * (left_ + right_), bottom_ + 40, p_.xlabel, 13, axis, Anchor::Middle);
        text(left_ - 60, top_ - 14, p_.ylabel, 13, axis, Anchor::Start);
    }

    void series_lines() {
        for (const std::vector<std::size_t>& series : p_.lines) {
            Item it;
            it.kind = Item::Polyline;
            it.width = 1.6;
            for (std::size_t i : series) {
                if (i >= p_.points.size() || !shown(p_.points[i])) continue;
                if (it.pts.empty()) it.stroke = color(p_.points[i].color);
                it.pts.push_back({px(p_.points[i].x), py(p_.points[i].y)});
            }
            if (it.pts.size() >= 2) items_.push_back(it);
        }
    }

    void front_line() {
        if (p_.front.empty()) return;
        Item it;
        it.kind = Item::Polyline;
        it.stroke = "#c0392b";
        it.width = 2.0;
        it.dashed = true;
        for (size_t k = 0; k < p_.front.size(); ++k) {
            const PlotPoint& a = p_.points[p_.front[k]];
            it.pts.push_back({px(a.x), py(a.y)});
            if (k + 1 < p_.front.size()) {
                const PlotPoint& b = p_.points[p_.front[k + 1]];
                it.pts.push_back({px(b.x), py(a.y)});  // a step: nothing between is better
            }
        }
        // Out to the right edge: everything slower than the last point is dominated by it.
        it.pts.push_back({right_, it.pts.back().y});
        items_.push_back(it);
    }

    void marker(double cx, double cy, Marker m, double r, const std::string& fill, const std::string& stroke,
                double width, const std::string& tooltip) {
        Item it;
        it.fill = fill;
        it.stroke = stroke;
        it.width = width;
        it.tooltip = tooltip;
        switch (m) {
            case Marker::Circle:
                it.kind = Item::Circle;
                it.pts = {{cx, cy}};
                it.radius = r;
                break;
            case Marker::Square:
                it.kind = Item::Polygon;
                r *= 0.9;
                it.pts = {{cx - r, cy - r}, {cx + r, cy - r}, {cx + r, cy + r}, {cx - r, cy + r}};
                break;
            case Marker::Triangle:
                it.kind = Item::Polygon;
                r *= 1.2;
                it.pts = {{cx, cy - r}, {cx + 0.866 * r, cy + 0.5 * r}, {cx - 0.866 * r, cy + 0.5 * r}};
                break;
            case Marker::Diamond:
                it.kind = Item::Polygon;
                r *= 1.2;
                it.pts = {{cx, cy - r}, {cx + r, cy}, {cx, cy + r}, {cx - r, cy}};
                break;
            case Marker::TriangleDown:
                it.kind = Item::Polygon;
                r *= 1.2;
                it.pts = {{cx, cy + r}, {cx + 0.866 * r, cy - 0.5 * r}, {cx - 0.866 * r, cy - 0.5 * r}};
                break;
            case Marker::Star:  // five points
            case Marker::Hexagon: {
                const bool star = m == Marker::Star;
                const int n = star ? 10 : 6;
                r *= star ? 1.3 : 1.05;
                it.kind = Item::Polygon;
                for (int k = 0; k < n; ++k) {
                    const double a = -1.5707963267948966 + 6.283185307179586 * k / n + (star ? 0.0 : 0.5235987755982988);
                    const double rr = star && (k % 2) ? 0.45 * r : r;
                    it.pts.push_back({cx + rr * std::cos(a), cy + rr * std::sin(a)});
                }
                break;
            }
            case Marker::Cross: {
                const double a = r * 0.35;
                it.kind = Item::Polygon;
                it.pts = {{cx - a, cy - r}, {cx + a, cy - r}, {cx + a, cy - a}, {cx + r, cy - a}, {cx + r, cy + a},
                          {cx + a, cy + a}, {cx + a, cy + r}, {cx - a, cy + r}, {cx - a, cy + a}, {cx - r, cy + a},
                          {cx - r, cy - a}, {cx - a, cy - a}};
                break;
            }
        }
        items_.push_back(it);
    }

    std::string color(int i) const {
        return i >= 0 && i < static_cast<int>(p_.colors.size()) ? p_.colors[static_cast<size_t>(i)] : "#555555";
    }

    void markers() {
        std::vector<bool> on_front(p_.points.size(), false);
        for (size_t i : p_.front) on_front[i] = true;
        for (int pass = 0; pass < 2; ++pass)  // the front's points on top
            for (size_t i = 0; i < p_.points.size(); ++i) {
                const PlotPoint& pt = p_.points[i];
                if (on_front[i] != (pass == 1)) continue;
                if (!shown(pt)) continue;
                const double cx = px(pt.x), cy = py(pt.y);
                if (on_front[i]) {
                    Item ring;
                    ring.kind = Item::Circle;
                    ring.pts = {{cx, cy}};
                    ring.radius = pt.radius + 4.5;
                    ring.stroke = "#c0392b";
                    ring.width = 1.6;
                    items_.push_back(ring);
                }
                if (!pt.callout.empty()) {
                    Item ring;
                    ring.kind = Item::Circle;
                    ring.pts = {{cx, cy}};
                    ring.radius = pt.radius + (on_front[i] ? 7.5 : 4.5);
                    ring.stroke = "#1f4e79";
                    ring.width = 1.6;
                    ring.dashed = true;
                    items_.push_back(ring);
                }
                marker(cx, cy, pt.marker, pt.radius, color(pt.color), "#222222", 0.7, pt.tooltip);
            }
        // Labels on the front, then the callouts, each at the first of eight places around its
        // point that overlaps no label already placed and no labelled marker (greedy, in order).
        struct Box {
            double x0, y0, x1, y1;
            bool hits(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
        };
        std::vector<Box> taken;
        std::vector<size_t> labelled = p_.front;  // the front's points, then the other callouts
        for (size_t i = 0; i < p_.points.size(); ++i)
            if (!p_.points[i].callout.empty() && !on_front[i] && shown(p_.points[i])) labelled.push_back(i);
        for (size_t i : labelled) {
            const PlotPoint& pt = p_.points[i];
            const double r = pt.radius + 5.0;
            taken.push_back({px(pt.x) - r, py(pt.y) - r, px(pt.x) + r, py(pt.y) + r});
        }
        constexpr double kSize = 10.5, kCharW = 6.3, kHeight = 11.0;
        for (size_t i : labelled) {
            const PlotPoint& pt = p_.points[i];
            const std::string& label = pt.callout.empty() ? pt.label : pt.callout;
            const double w = kCharW * static_cast<double>(label.size()), r = pt.radius + 6.0;
            const double cx = px(pt.x), cy = py(pt.y);
            // Baseline positions: right above, right below, left above, left below, then farther out.
            const double places[][2] = {{cx + r, cy - r}, {cx + r, cy + r + kHeight}, {cx - r - w, cy - r},
                                        {cx - r - w, cy + r + kHeight}, {cx - 0.5 * w, cy - r - 6.0},
                                        {cx - 0.5 * w, cy + r + kHeight + 6.0}, {cx + r, cy - r - 14.0},
                                        {cx + r, cy + r + kHeight + 14.0}};
            Box chosen{places[0][0], places[0][1] - kHeight, places[0][0] + w, places[0][1]};
            for (const auto& pl : places) {
                const Box b{pl[0], pl[1] - kHeight, pl[0] + w, pl[1] + 2.0};
                if (b.x0 < left_ || b.x1 > right_ + 40.0 || b.y0 < top_ || b.y1 > bottom_ - 2.0) continue;
                if (std::none_of(taken.begin(), taken.end(), [&](const Box& t) { return t.hits(b); })) {
                    chosen = b;
                    break;
                }
            }
            taken.push_back(chosen);
            text(chosen.x0, chosen.y1 - 2.0, label, kSize, pt.callout.empty() ? "#7b241c" : "#1f4e79");
        }
    }

    void legend() {
        double x = right_ + 22, y = top_ + 4;
        text(x, y, p_.color_title, 12, "#111111", Anchor::Start, true);
        y += 18;
        for (const auto& [label, c] : p_.color_legend) {
            marker(x + 6, y - 4, Marker::Circle, 5, color(c), "#222222", 0.7, "");
            text(x + 18, y, label, 11.5, "#222222");
            y += 17;
        }
        y += 8;
        text(x, y, p_.marker_title, 12, "#111111", Anchor::Start, true);
        y += 18;
        for (const auto& [label, m] : p_.marker_legend) {
            marker(x + 6, y - 4, m, 5, "#bbbbbb", "#222222", 0.7, "");
            text(x + 18, y, label, 11.5, "#222222");
            y += 17;
        }
        y += 8;
        if (!p_.front.empty()) {  // a plot without a front (lines of one measure against another) names none
            line(x, y - 4, x + 14, y - 4, "#c0392b", 2.0, true);
            text(x + 18, y, "Pareto front", 11.5, "#222222");
            y += 22;
        }
        for (const auto& n : p_.notes) {
            text(x, y, n, 10.5, "#555555");
            y += 15;
        }
    }

    const Plot& p_;
    int w_, h_;
    double left_ = 0, right_ = 0, top_ = 0, bottom_ = 0;
    double xmin_ = 0, xmax_ = 1, ymin_ = 0, ymax_ = 1, ystep_ = 1;
    std::vector<Item> items_;
};

std::string escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        switch (c) {
            case '&': o += "&amp;"; break;
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '"': o += "&quot;"; break;
            default: o += c;
        }
    }
    return o;
}

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2f", v);
    std::string s = b;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

}  // namespace

std::string plot_svg(const Plot& plot, int width, int height) {
    const std::vector<Item> items = Layout(plot, width, height).build();
    std::ostringstream o;
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << " " << height << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
    for (const Item& it : items) {
        const std::string paint = std::string(" fill=\"") + (it.fill.empty() ? "none" : it.fill) + "\"" +
                                  (it.stroke.empty() ? std::string() : " stroke=\"" + it.stroke + "\" stroke-width=\"" + num(it.width) + "\"") +
                                  (it.dashed ? " stroke-dasharray=\"7 5\"" : "");
        const std::string title = it.tooltip.empty() ? "" : "<title>" + escape(it.tooltip) + "</title>";
        const std::string close = title.empty() ? "/>\n" : ">" + title;
        switch (it.kind) {
            case Item::Polyline:
            case Item::Polygon: {
                o << (it.kind == Item::Polygon ? "<polygon" : "<polyline") << " points=\"";
                for (size_t i = 0; i < it.pts.size(); ++i) o << (i ? " " : "") << num(it.pts[i].x) << "," << num(it.pts[i].y);
                o << "\"" << (it.kind == Item::Polyline ? std::string(" fill=\"none\" stroke=\"") + it.stroke +
                                                              "\" stroke-width=\"" + num(it.width) + "\"" +
                                                              (it.dashed ? " stroke-dasharray=\"7 5\"" : "")
                                                        : paint)
                  << close;
                if (!title.empty()) o << (it.kind == Item::Polygon ? "</polygon>\n" : "</polyline>\n");
                break;
            }
            case Item::Circle:
                o << "<circle cx=\"" << num(it.pts[0].x) << "\" cy=\"" << num(it.pts[0].y) << "\" r=\"" << num(it.radius)
                  << "\"" << paint << close;
                if (!title.empty()) o << "</circle>\n";
                break;
            case Item::Text:
                o << "<text x=\"" << num(it.pts[0].x) << "\" y=\"" << num(it.pts[0].y) << "\" font-size=\"" << num(it.size)
                  << "\" fill=\"" << it.fill << "\""
                  << (it.anchor == Anchor::Middle ? " text-anchor=\"middle\"" : it.anchor == Anchor::End ? " text-anchor=\"end\"" : "")
                  << (it.bold ? " font-weight=\"bold\"" : "") << ">" << escape(it.text) << "</text>\n";
                break;
        }
    }
    o << "</svg>\n";
    return o.str();
}

Pixels svg_to_pixels(const std::string& svg, int width, int height) {
    GError* error = nullptr;
    RsvgHandle* handle = rsvg_handle_new_from_data(reinterpret_cast<const guint8*>(svg.data()), svg.size(), &error);
    const auto fail = [&](const char* what) -> std::runtime_error {
        std::string message = std::string("librsvg: ") + what + (error ? std::string(": ") + error->message : std::string());
        if (error) g_error_free(error);
        return std::runtime_error(message);
    };
    if (!handle) throw fail("cannot parse the SVG");
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);  // an opaque white page under the drawing
    cairo_paint(cr);
    const RsvgRectangle viewport{0.0, 0.0, static_cast<double>(width), static_cast<double>(height)};
    const bool drawn = rsvg_handle_render_document(handle, cr, &viewport, &error) && cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    g_object_unref(handle);
    if (!drawn || cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(surface);
        throw fail("cannot render the SVG");
    }
    cairo_surface_flush(surface);
    // CAIRO_FORMAT_ARGB32: one native-endian 32-bit word per pixel, 0xAARRGGBB, alpha premultiplied;
    // over the opaque page every alpha is 255, so the colour is as stored.
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const size_t stride = static_cast<size_t>(cairo_image_surface_get_stride(surface));
    Pixels out{width, height, 3, std::vector<std::uint8_t>(static_cast<size_t>(width) * static_cast<size_t>(height) * 3u)};
    for (size_t y = 0; y < static_cast<size_t>(height); ++y)
        for (size_t x = 0; x < static_cast<size_t>(width); ++x) {
            std::uint32_t argb;
            std::memcpy(&argb, data + y * stride + 4u * x, sizeof argb);
            std::uint8_t* o = &out.data[(y * static_cast<size_t>(width) + x) * 3u];
            o[0] = static_cast<std::uint8_t>(argb >> 16);
            o[1] = static_cast<std::uint8_t>(argb >> 8);
            o[2] = static_cast<std::uint8_t>(argb);
        }
    cairo_surface_destroy(surface);
    return out;
}

Pixels plot_png(const Plot& plot, int width, int height) { return svg_to_pixels(plot_svg(plot, width, height), width, height); }

}  // namespace penumbra::tools
