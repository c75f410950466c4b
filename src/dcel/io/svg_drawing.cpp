#include "dcel/io/svg_drawing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace dcel::io::svg {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kDot = 2.8;      // vertex dot radius, px
constexpr double kRing = 4;       // isolated vertex ring radius, px
constexpr double kMinGap = 0.28;  // radians (16 degrees) between edges leaving a vertex, as drawn
constexpr std::size_t kMaxVertexLabels = 2000;
constexpr std::size_t kMaxFaceLabels = 1000;

// x in (-pi, pi].
double wrapped(double x) {
    x = std::fmod(x, kTwoPi);
    if (x <= -std::numbers::pi) x += kTwoPi;
    if (x > std::numbers::pi) x -= kTwoPi;
    return x;
}

// The direction from a to b in the plane (y up), radians.
double direction(Xy a, Xy b) { return std::atan2(-(b.y - a.y), b.x - a.x); }
Xy unit(double angle) { return {std::cos(angle), -std::sin(angle)}; }

// Pool-adjacent-violators: the non-increasing sequence nearest to v (least squares).
std::vector<double> non_increasing_fit(const std::vector<double>& v) {
    struct Block {
        double sum;
        std::size_t count;
        [[nodiscard]] double mean() const { return sum / static_cast<double>(count); }
    };
    std::vector<Block> blocks;
    for (const double x : v) {
        blocks.push_back({x, 1});
        while (blocks.size() > 1 && blocks[blocks.size() - 2].mean() < blocks.back().mean()) {
            blocks[blocks.size() - 2].sum += blocks.back().sum;
            blocks[blocks.size() - 2].count += blocks.back().count;
            blocks.pop_back();
        }
    }
    std::vector<double> out;
    for (const Block& b : blocks) out.insert(out.end(), b.count, b.mean());
    return out;
}

}  // namespace

std::vector<double> spread_clockwise(const std::vector<double>& drawn, double min_gap) {
    const std::size_t n = drawn.size();
    if (n < 2) return drawn;
    const double gap = std::min(min_gap, 0.8 * kTwoPi / static_cast<double>(n));
    // The clockwise gaps between neighbours. In the exact order they add up
    // to a full turn; when the frame drew some rays slightly out of order (a
    // monotone stretch keeps each direction's quadrant, so by less than a
    // quarter turn) those gaps are small and negative; beyond that, the
    // directions tell nothing and the rays are spaced evenly.
    std::vector<double> gaps(n);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        gaps[i] = std::fmod(drawn[i] - drawn[(i + 1) % n], kTwoPi);
        if (gaps[i] < 0) gaps[i] += kTwoPi;
        sum += gaps[i];
    }
    if (std::fabs(sum - kTwoPi) > 1e-9) {
        sum = 0;
        for (double& g : gaps) {
            if (g > 1.5 * std::numbers::pi) g -= kTwoPi;
            sum += g;
        }
        if (std::fabs(sum - kTwoPi) > 1e-9) gaps.assign(n, kTwoPi / static_cast<double>(n));
    }
    // Start after the widest gap, so that no cluster of rays is cut in two.
    const std::size_t start = (static_cast<std::size_t>(std::max_element(gaps.begin(), gaps.end()) - gaps.begin()) + 1) % n;
    std::vector<double> a(n);
    a[0] = drawn[start];
    for (std::size_t k = 1; k < n; ++k) a[k] = a[k - 1] - gaps[(start + k - 1) % n];
    // theta_k = c_k - k gap with c non-increasing: the gaps hold; the fit
    // moves the directions least.
    std::vector<double> c(n);
    for (std::size_t k = 0; k < n; ++k) c[k] = a[k] + static_cast<double>(k) * gap;
    c = non_increasing_fit(c);
    // The last must stay a gap short of a full turn from the first.
    const double room = kTwoPi - static_cast<double>(n) * gap;
    if (c.front() - c.back() > room) {
        double mean = 0;
        for (const double x : c) mean += x / static_cast<double>(n);
        const double k = room / (c.front() - c.back());
        for (double& x : c) x = mean + (x - mean) * k;
    }
    std::vector<double> out(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double theta = c[k] - static_cast<double>(k) * gap;
        // Unchanged directions stay bit for bit, so their edges stay straight.
        const double d = drawn[(start + k) % n];
        out[(start + k) % n] = std::fabs(wrapped(theta - d)) < 1e-12 ? d : theta;
    }
    return out;
}

DrawnDcel::DrawnDcel(const Dcel& d, const Frame& frame) : d_(&d) {
    for (Index v = 0; v < d.num_vertices(); ++v) at_.push_back(frame.at(v));
    // Each half-edge's direction at its origin, as drawn, then spread.
    std::vector<double> straight(d.num_half_edges()), shown(d.num_half_edges());
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        straight[h] = shown[h] = direction(at(d.origin(HalfEdgeId(h))), at(d.target(HalfEdgeId(h))));
    }
    std::vector<std::size_t> degree(d.num_vertices(), 0);
    for (Index v = 0; v < d.num_vertices(); ++v) {
        const HalfEdgeId first = d.out(VertexId(v));
        if (first.is_null()) continue;
        std::vector<HalfEdgeId> ring;
        for (const HalfEdgeId h : d.around_origin_cw(first)) ring.push_back(h);
        degree[v] = ring.size();
        std::vector<double> drawn;
        drawn.reserve(ring.size());
        for (const HalfEdgeId h : ring) drawn.push_back(straight[h.index()]);
        const std::vector<double> spread = spread_clockwise(drawn, kMinGap);
        for (std::size_t i = 0; i < ring.size(); ++i) shown[ring[i].index()] = spread[i];
    }
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h(2 * e), t(2 * e + 1);
        const Xy a = at(d.origin(h)), b = at(d.target(h));
        double dev_h = wrapped(shown[h.index()] - straight[h.index()]);
        double dev_t = wrapped(shown[t.index()] - straight[t.index()]);
        if (dev_h == 0 && dev_t == 0) {
            edge_line_.push_back({a, b});
            continue;
        }
        // An end of degree 1 is free: the edge arrives as a symmetric arc.
        if (dev_t == 0 && degree[d.target(h).index()] == 1) dev_t = -dev_h;
        if (dev_h == 0 && degree[d.origin(h).index()] == 1) dev_h = -dev_t;
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        const Xy ua = unit(straight[h.index()] + dev_h), ub = unit(straight[t.index()] + dev_t);
        const Xy p1{a.x + 0.38 * len * ua.x, a.y + 0.38 * len * ua.y};
        const Xy p2{b.x + 0.38 * len * ub.x, b.y + 0.38 * len * ub.y};
        Polyline curve;
        constexpr int kSteps = 24;
        for (int i = 0; i <= kSteps; ++i) {
            const double s = static_cast<double>(i) / kSteps, r = 1 - s;
            curve.push_back({r * r * r * a.x + 3 * r * r * s * p1.x + 3 * r * s * s * p2.x + s * s * s * b.x,
                             r * r * r * a.y + 3 * r * r * s * p1.y + 3 * r * s * s * p2.y + s * s * s * b.y});
        }
        edge_line_.push_back(std::move(curve));
        ++bent_;
    }
}

Polyline DrawnDcel::line(HalfEdgeId h) const {
    Polyline l = edge_line_[h.index() / 2];
    if ((h.index() & 1U) != 0) std::reverse(l.begin(), l.end());
    return l;
}

StepLines::StepLines(const DrawnDcel& g) : g_(&g) {
    const Dcel& d = g.dcel();
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        by_ends_.emplace((std::uint64_t{d.origin(HalfEdgeId(h)).index()} << 32) | d.target(HalfEdgeId(h)).index(),
                         HalfEdgeId(h));
    }
}

std::optional<DrawnStep> StepLines::operator()(Index u, Index v) const {
    const Dcel& d = g_->dcel();
    if (u >= d.num_vertices() || v >= d.num_vertices()) return std::nullopt;
    const auto it = by_ends_.find((std::uint64_t{u} << 32) | v);
    if (it != by_ends_.end()) return DrawnStep{g_->line(it->second), true};
    return DrawnStep{Polyline{g_->at(VertexId(u)), g_->at(VertexId(v))}, false};
}

std::vector<Polyline> DrawnDcel::rings(FaceId f) const {
    std::vector<HalfEdgeId> starts;
    if (!d_->outer(f).is_null()) starts.push_back(d_->outer(f));
    starts.insert(starts.end(), d_->inner(f).begin(), d_->inner(f).end());
    std::vector<Polyline> out;
    for (const HalfEdgeId s : starts) {
        Polyline ring;
        for (const HalfEdgeId h : d_->cycle(s)) {
            const Polyline l = line(h);
            ring.insert(ring.end(), l.begin(), l.end() - 1);  // the last point starts the next half-edge
        }
        out.push_back(std::move(ring));
    }
    return out;
}

void paint_faces(std::string& out, const DrawnDcel& g) {
    out += "<g id=\"faces\" stroke=\"none\" fill-rule=\"evenodd\">\n";
    for (Index f = 1; f < g.dcel().num_faces(); ++f) {
        std::string d;
        for (const Polyline& ring : g.rings(FaceId(f))) d += path_data(ring, true);
        out += "<path class=\"face\" fill=\"" + face_fill(f) + "\" d=\"" + d + "\"><title>f" + std::to_string(f) +
               "</title></path>\n";
    }
    out += "</g>\n";
}

void paint_edges(std::string& out, const DrawnDcel& g) {
    out += "<g id=\"edges\" stroke=\"#404040\" stroke-width=\"1\" fill=\"none\" stroke-linecap=\"round\">\n";
    for (Index e = 0; e < g.dcel().num_edges(); ++e) {
        out += "<path d=\"" + path_data(g.line(HalfEdgeId(2 * e))) + "\"/>\n";
    }
    out += "</g>\n";
}

HalfEdgeStyle by_face_colour(const DrawnDcel& g) {
    return [&g](HalfEdgeId h) -> std::optional<ArrowStyle> {
        return ArrowStyle{face_ink(g.dcel().face(h).index()), 1.3, 4.5, "", "half-edge"};
    };
}

void paint_half_edges(std::string& out, const DrawnDcel& g, const HalfEdgeStyle& style) {
    out += "<g id=\"half-edges\">\n";
    for (Index h = 0; h < g.dcel().num_half_edges(); ++h) {
        if (const auto s = style(HalfEdgeId(h))) arrow(out, g.line(HalfEdgeId(h)), *s);
    }
    out += "</g>\n";
}

void paint_vertices(std::string& out, const DrawnDcel& g) {
    out += "<g id=\"vertices\">\n";
    for (Index v = 0; v < g.dcel().num_vertices(); ++v) {
        const Xy p = g.at(VertexId(v));
        const Point q = g.dcel().point(VertexId(v));
        const bool isolated = g.dcel().out(VertexId(v)).is_null();
        out += "<circle cx=\"" + num(p.x) + "\" cy=\"" + num(p.y) +
               (isolated ? "\" r=\"" + num(kRing) + "\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"1.5\">"
                         : "\" r=\"" + num(kDot) + "\" fill=\"#000000\">") +
               "<title>v" + std::to_string(v) + " (" + exact_number(q.x) + ", " + exact_number(q.y) + ")" +
               (isolated ? ", isolated" : "") + "</title></circle>\n";
    }
    out += "</g>\n";
}

void block_drawing(LabelLayout& labels, const DrawnDcel& g) {
    for (Index v = 0; v < g.dcel().num_vertices(); ++v) {
        const Xy p = g.at(VertexId(v));
        labels.block({p.x - kRing - 1, p.y - kRing - 1, 2 * kRing + 2, 2 * kRing + 2});
    }
    for (Index e = 0; e < g.dcel().num_edges(); ++e) {
        const Polyline l = g.line(HalfEdgeId(2 * e));
        for (std::size_t i = 1; i < l.size(); ++i) labels.add_line(l[i - 1], l[i]);
    }
}

std::vector<std::string> label_vertices(LabelLayout& labels, const DrawnDcel& g, const Box& allowed,
                                        const std::vector<std::string>& names) {
    std::vector<std::string> left_out;
    if (g.dcel().num_vertices() > kMaxVertexLabels) return {"the vertex ids (more than 2000 vertices)"};
    for (Index v = 0; v < g.dcel().num_vertices(); ++v) {
        const std::string id = v < names.size() ? names[v] : std::to_string(v);
        if (!labels.place(g.at(VertexId(v)), kRing + 1, id, allowed, {"#000000", 11, false, "label vertex-label"})) {
            left_out.push_back("v" + id);
        }
    }
    return left_out;
}

std::vector<Xy> inner_points(const std::vector<Polyline>& rings, std::size_t count) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    std::size_t segments = 0;
    for (const Polyline& r : rings) {
        for (const Xy p : r) {
            x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        }
        segments += r.size();
    }
    if (segments == 0 || !(x1 > x0) || !(y1 > y0)) return {};
    // A grid of samples, fewer on long boundaries (each sample scans them all).
    const auto side = static_cast<std::size_t>(std::clamp(std::sqrt(200000.0 / static_cast<double>(segments)), 4.0, 24.0));
    struct Sample {
        Xy p;
        double depth;
    };
    std::vector<Sample> inside;
    for (std::size_t i = 0; i < side; ++i) {
        for (std::size_t j = 0; j < side; ++j) {
            const Xy p{x0 + (x1 - x0) * (static_cast<double>(i) + 0.5) / static_cast<double>(side),
                       y0 + (y1 - y0) * (static_cast<double>(j) + 0.5) / static_cast<double>(side)};
            bool in = false;
            double depth = 1e300;
            for (const Polyline& r : rings) {
                for (std::size_t k = 0; k < r.size(); ++k) {
                    const Xy a = r[k], b = r[(k + 1) % r.size()];
                    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
                    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
                    const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0;
                    depth = std::min(depth, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
                }
            }
            if (in) inside.push_back({p, depth});
        }
    }
    std::stable_sort(inside.begin(), inside.end(), [](const Sample& a, const Sample& b) { return a.depth > b.depth; });
    std::vector<Xy> out;
    for (std::size_t i = 0; i < inside.size() && i < count; ++i) out.push_back(inside[i].p);
    return out;
}

std::vector<std::string> label_faces(LabelLayout& labels, const DrawnDcel& g, const Box& allowed) {
    const Dcel& d = g.dcel();
    if (d.num_faces() > kMaxFaceLabels) return {"the face ids (more than 1000 faces)"};
    std::vector<std::string> left_out;
    for (Index f = 1; f < d.num_faces(); ++f) {
        const std::vector<Polyline> rings = g.rings(FaceId(f));
        const std::vector<Xy> centres = inner_points(rings, 12);
        Xy anchor = centres.empty() ? Xy{} : centres.front();
        if (centres.empty()) {  // too thin to sample: the mean of its outer ring
            for (const Xy p : rings.front())
                anchor = {anchor.x + p.x / static_cast<double>(rings.front().size()),
                          anchor.y + p.y / static_cast<double>(rings.front().size())};
        }
        const std::string id = "f" + std::to_string(f);
        if (!labels.place(anchor, 0, id, allowed, {face_ink(f), 11, true, "label face-label"}, centres)) {
            left_out.push_back(id);
        }
    }
    // The unbounded face: in a corner of the allowed area, outside the drawing.
    const std::vector<Xy> corners = {{allowed.x + 12, allowed.y + 9},
                                     {allowed.right() - 12, allowed.y + 9},
                                     {allowed.x + 12, allowed.bottom() - 9},
                                     {allowed.right() - 12, allowed.bottom() - 9}};
    if (!labels.place(corners.front(), 0, "f0", allowed, {face_ink(0), 11, true, "label face-label"}, corners)) {
        left_out.emplace_back("f0");
    }
    return left_out;
}

namespace {

constexpr std::string_view kTableHeading = "true coordinates";

struct Table {
    std::vector<std::array<std::string, 3>> rows;
    std::array<double, 3> width{};
};

Table table(const std::vector<Point>& points, double font, const std::vector<std::string>& names) {
    Table t;
    t.rows.push_back({"v", "x", "y"});
    for (std::size_t v = 0; v < points.size(); ++v) {
        t.rows.push_back(
            {v < names.size() ? names[v] : std::to_string(v), exact_number(points[v].x), exact_number(points[v].y)});
    }
    for (const auto& row : t.rows) {
        for (std::size_t c = 0; c < 3; ++c) t.width[c] = std::max(t.width[c], text_width(row[c], font));
    }
    return t;
}

}  // namespace

Xy coordinate_table_size(const std::vector<Point>& points, double font, const std::vector<std::string>& names) {
    const Table t = table(points, font, names);
    // As wide as the columns, or as its heading when that is wider (a few
    // small integers).
    const double width = std::max(t.width[0] + t.width[1] + t.width[2] + 24, text_width(kTableHeading, font) + 4);
    return {width, static_cast<double>(t.rows.size()) * (font + 4) + font + 8};
}

Xy coordinate_table(std::string& out, Xy top_left, const std::vector<Point>& points, double font,
                    const std::vector<std::string>& names) {
    const Table t = table(points, font, names);
    const double row = font + 4;
    out += "<g id=\"coordinates\" font-family=\"" + std::string(kMonoFont) + "\">\n";
    text(out, {top_left.x, top_left.y + font}, kTableHeading, font, kNoteInk, "start", true);
    double y = top_left.y + font + 4;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        y += row;
        double x = top_left.x;
        for (std::size_t c = 0; c < 3; ++c) {
            // The id left-aligned, the numbers right-aligned so their digits line up.
            const bool id = c == 0;
            text(out, {id ? x : x + t.width[c], y}, t.rows[r][c], font, r == 0 ? "#707070" : kNoteInk, id ? "start" : "end");
            x += t.width[c] + 12;
        }
    }
    out += "</g>\n";
    return coordinate_table_size(points, font, names);
}

}  // namespace dcel::io::svg
