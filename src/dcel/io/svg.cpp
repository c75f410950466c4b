#include "dcel/io/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dcel::io {

namespace {

constexpr double kDrawing = 640;  // px along the longer side of the points' box
constexpr double kMargin = 36;
constexpr double kTitleBand = 30;
constexpr double kCaptionBand = 40;
constexpr double kMinWidth = 360;         // room for the caption under thin drawings
constexpr double kOffset = 4.5;           // a half-edge's distance from its edge, to its face's side
constexpr double kHead = 9;               // arrowhead length
constexpr std::size_t kMaxLabels = 2000;  // beyond this, ids are unreadable anyway

struct Xy {
    double x;
    double y;
};

// Maps input points into the picture. Differences are taken before scaling,
// so points 1 apart near 1e15 stay apart; a quarter scale first keeps spans
// near the double limit finite.
class Frame {
public:
    explicit Frame(const std::vector<Point>& points) {
        if (points.empty()) return;
        if (!bounds(points, 1.0)) (void)bounds(points, 0.25);
        span_ = std::max(dx_, dy_);
        if (!(span_ > 0)) span_ = 1;    // one point, or all at one point
        w_ = kDrawing * (dx_ / span_);  // the ratio first: 640 * 1e308 overflows
        h_ = kDrawing * (dy_ / span_);
    }
    [[nodiscard]] double width() const { return std::max(w_ + 2 * kMargin, kMinWidth); }
    [[nodiscard]] double height() const { return h_ + 2 * kMargin + kTitleBand + kCaptionBand; }
    [[nodiscard]] Xy at(Point p) const {
        const double left = (width() - w_) / 2;
        const double tx = (p.x * pre_ - min_x_) / span_;
        const double ty = (p.y * pre_ - min_y_) / span_;
        return {left + tx * kDrawing, kTitleBand + kMargin + h_ - ty * kDrawing};  // y grows downwards
    }

private:
    bool bounds(const std::vector<Point>& points, double pre) {
        pre_ = pre;
        min_x_ = max_x_ = points[0].x * pre;
        min_y_ = max_y_ = points[0].y * pre;
        for (const Point p : points) {
            min_x_ = std::min(min_x_, p.x * pre);
            max_x_ = std::max(max_x_, p.x * pre);
            min_y_ = std::min(min_y_, p.y * pre);
            max_y_ = std::max(max_y_, p.y * pre);
        }
        dx_ = max_x_ - min_x_;
        dy_ = max_y_ - min_y_;
        return std::isfinite(dx_) && std::isfinite(dy_);
    }

    double pre_ = 1, min_x_ = 0, max_x_ = 0, min_y_ = 0, max_y_ = 0, dx_ = 0, dy_ = 0;
    double span_ = 1, w_ = 0, h_ = 0;
};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

std::string escape(const std::string& s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                // XML 1.0 has no other control characters than tab and newlines.
                if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n') out += c;
        }
    }
    return out;
}

// A colour per face: hues a golden angle apart, so neighbouring ids differ.
std::string hsl(double hue, double saturation, double lightness) {
    const double c = (1 - std::fabs(2 * lightness - 1)) * saturation;
    const double h = hue / 60;
    const double x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1));
    double r = 0, g = 0, b = 0;
    if (h < 1) {
        r = c;
        g = x;
    } else if (h < 2) {
        r = x;
        g = c;
    } else if (h < 3) {
        g = c;
        b = x;
    } else if (h < 4) {
        g = x;
        b = c;
    } else if (h < 5) {
        r = x;
        b = c;
    } else {
        r = c;
        b = x;
    }
    const double m = lightness - c / 2;
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<unsigned>(std::lround((r + m) * 255)),
                  static_cast<unsigned>(std::lround((g + m) * 255)), static_cast<unsigned>(std::lround((b + m) * 255)));
    return buf;
}
double face_hue(Index f) { return std::fmod(f * 137.50776, 360.0); }
std::string face_fill(Index f) { return hsl(face_hue(f), 0.75, 0.86); }
std::string face_ink(Index f) { return f == 0 ? "#8a8a8a" : hsl(face_hue(f), 0.7, 0.36); }
constexpr const char* kWarning = "#e8112d";

// An arrow from a to b, moved `offset` px to its left (as seen in the plane,
// y up) and shortened at both ends so arrows meeting at a vertex stay apart.
void arrow(std::string& out, Xy a, Xy b, const std::string& colour, double width, double offset) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len = std::hypot(dx, dy);
    if (!(len > 1)) return;
    const double ux = dx / len, uy = dy / len;
    const double nx = uy * offset, ny = -ux * offset;  // the plane's left, with y flipped
    const double trim = std::min(0.25 * len, 10.0 + offset);
    const Xy s{a.x + nx + ux * trim, a.y + ny + uy * trim};
    const Xy e{b.x + nx - ux * trim, b.y + ny - uy * trim};
    const double head = std::min(kHead + width, 0.45 * (len - 2 * trim));
    const Xy base{e.x - ux * head, e.y - uy * head};
    const double half = head * 0.45;
    out += "<path d=\"M" + num(s.x) + " " + num(s.y) + "L" + num(base.x) + " " + num(base.y) + "\" stroke=\"" + colour +
           "\" stroke-width=\"" + num(width) + "\" fill=\"none\"/>";
    out += "<path d=\"M" + num(e.x) + " " + num(e.y) + "L" + num(base.x + uy * half) + " " + num(base.y - ux * half) + "L" +
           num(base.x - uy * half) + " " + num(base.y + ux * half) + "Z\" fill=\"" + colour + "\"/>\n";
}

void cycle_path(std::string& out, const Dcel& d, const Frame& frame, HalfEdgeId start) {
    bool first = true;
    for (const HalfEdgeId h : d.cycle(start)) {
        const Xy p = frame.at(d.point(d.origin(h)));
        out += (first ? "M" : "L") + num(p.x) + " " + num(p.y);
        first = false;
    }
    out += "Z";
}

void draw_faces(std::string& out, const Dcel& d, const Frame& frame) {
    out += "<g id=\"faces\" stroke=\"none\" fill-rule=\"evenodd\">\n";
    for (Index f = 1; f < d.num_faces(); ++f) {
        out += "<path fill=\"" + face_fill(f) + "\" d=\"";
        cycle_path(out, d, frame, d.outer(FaceId(f)));
        for (const HalfEdgeId h : d.inner(FaceId(f))) cycle_path(out, d, frame, h);
        out += "\"><title>f" + std::to_string(f) + "</title></path>\n";
    }
    out += "</g>\n";
}

void draw_edges(std::string& out, const Dcel& d, const Frame& frame) {
    out += "<g id=\"edges\" stroke=\"#303030\" stroke-width=\"1\" stroke-linecap=\"round\">\n";
    for (Index e = 0; e < d.num_edges(); ++e) {
        const Xy a = frame.at(d.point(d.origin(HalfEdgeId(2 * e))));
        const Xy b = frame.at(d.point(d.target(HalfEdgeId(2 * e))));
        out += "<path d=\"M" + num(a.x) + " " + num(a.y) + "L" + num(b.x) + " " + num(b.y) + "\"/>\n";
    }
    out += "</g>\n<g id=\"half-edges\">\n";
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        const HalfEdgeId he(h);
        arrow(out, frame.at(d.point(d.origin(he))), frame.at(d.point(d.target(he))), face_ink(d.face(he).index()), 1.3,
              kOffset);
    }
    out += "</g>\n";
}

void draw_highlights(std::string& out, const Dcel& d, const Frame& frame, const SvgOptions& options) {
    if (options.highlight_cycles.empty()) return;
    out += "<g id=\"highlight\" opacity=\"0.85\">\n";
    const auto vertices = d.num_vertices();
    for (const auto& cycle : options.highlight_cycles) {
        for (std::size_t i = 0; i < cycle.size(); ++i) {
            const Index u = cycle[i];
            const Index v = cycle[(i + 1) % cycle.size()];
            if (u >= vertices) continue;
            const Xy a = frame.at(d.point(VertexId(u)));
            if (u == v || v >= vertices) {  // a lone or unknown step: ring the vertex
                out += "<circle cx=\"" + num(a.x) + "\" cy=\"" + num(a.y) + "\" r=\"9\" fill=\"none\" stroke=\"" + kWarning +
                       "\" stroke-width=\"2.5\"/>\n";
                continue;
            }
            arrow(out, a, frame.at(d.point(VertexId(v))), kWarning, 3, 2 * kOffset);  // beside the face's own arrows
        }
    }
    out += "</g>\n";
}

void draw_vertices(std::string& out, const Dcel& d, const Frame& frame) {
    out += "<g id=\"vertices\">\n";
    for (Index v = 0; v < d.num_vertices(); ++v) {
        const Xy p = frame.at(d.point(VertexId(v)));
        const bool isolated = d.out(VertexId(v)).is_null();
        out += "<circle cx=\"" + num(p.x) + "\" cy=\"" + num(p.y) +
               (isolated ? "\" r=\"4\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n"
                         : "\" r=\"2.8\" fill=\"#000000\"/>\n");
    }
    if (d.num_vertices() <= kMaxLabels) {
        out +=
            "<g font-family=\"sans-serif\" font-size=\"12\" fill=\"#000000\" stroke=\"#ffffff\" "
            "stroke-width=\"3\" paint-order=\"stroke\" stroke-linejoin=\"round\">\n";
        for (Index v = 0; v < d.num_vertices(); ++v) {
            const Xy p = frame.at(d.point(VertexId(v)));
            out += "<text x=\"" + num(p.x + 5) + "\" y=\"" + num(p.y - 5) + "\">" + std::to_string(v) + "</text>\n";
        }
        out += "</g>\n";
    }
    out += "</g>\n";
}

std::string count(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string render_svg(const Dcel& dcel, const SvgOptions& options) {
    const Frame frame(dcel.points());
    const double w = frame.width(), h = frame.height();
    std::string out;
    out.reserve(1024 + dcel.num_half_edges() * 200 + dcel.num_vertices() * 120);
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(w) + "\" height=\"" + num(h) + "\" viewBox=\"0 0 " +
           num(w) + " " + num(h) + "\">\n";
    out += "<title>" + escape(options.title) + "</title>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    draw_faces(out, dcel, frame);
    draw_edges(out, dcel, frame);
    draw_highlights(out, dcel, frame, options);
    draw_vertices(out, dcel, frame);
    out += "<g font-family=\"sans-serif\" fill=\"#202020\">\n";
    if (!options.title.empty()) {
        out += "<text x=\"12\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" + escape(options.title) + "</text>\n";
    }
    out += "<text x=\"12\" y=\"" + num(h - 24) + "\" font-size=\"11\">" + count(dcel.num_vertices(), "vertex", "vertices") +
           ", " + count(dcel.num_edges(), "edge", "edges") + ", " +
           count(dcel.num_faces() - 1, "bounded face", "bounded faces") + " (tinted)</text>\n";
    out += "<text x=\"12\" y=\"" + num(h - 10) + "\" font-size=\"11\">arrows: half-edges, on the side of their face;" +
           std::string(options.highlight_cycles.empty() ? "" : " red: highlighted cycles;") +
           " rings: isolated vertices</text>\n";
    out += "</g>\n</svg>\n";
    return out;
}

}  // namespace dcel::io
