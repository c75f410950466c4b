#include "dcel/io/svg_canvas.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace dcel::io::svg {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

std::string escape(std::string_view s) {
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

std::string exact_number(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return {buf, r.ptr};
}

namespace {

// HSL to #rrggbb.
std::string hsl(double hue, double saturation, double lightness) {
    const double c = (1 - std::fabs(2 * lightness - 1)) * saturation;
    const double h = hue / 60;
    const double x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1));
    const std::array<std::array<double, 3>, 6> sectors = {
        {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}}};
    const auto& rgb = sectors[std::min<std::size_t>(5, static_cast<std::size_t>(h))];
    const double m = lightness - c / 2;
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<unsigned>(std::lround((rgb[0] + m) * 255)),
                  static_cast<unsigned>(std::lround((rgb[1] + m) * 255)),
                  static_cast<unsigned>(std::lround((rgb[2] + m) * 255)));
    return buf;
}

// Hues a golden angle apart, so that neighbouring ids differ.
double face_hue(Index f) { return std::fmod(f * 137.50776, 360.0); }

}  // namespace

std::string face_fill(Index f) { return hsl(face_hue(f), 0.75, 0.88); }
std::string face_ink(Index f) { return f == 0 ? "#8a8a8a" : hsl(face_hue(f), 0.7, 0.34); }

void text(std::string& out, Xy at, std::string_view s, double font, const char* colour, const char* anchor, bool bold) {
    out += "<text x=\"" + num(at.x) + "\" y=\"" + num(at.y) + "\" font-size=\"" + num(font) + "\" fill=\"" + colour +
           "\" text-anchor=\"" + anchor + "\"" + (bold ? " font-weight=\"bold\"" : "") + " xml:space=\"preserve\">" +
           escape(s) + "</text>\n";
}

double length(const Polyline& line) {
    double total = 0;
    for (std::size_t i = 1; i < line.size(); ++i) total += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    return total;
}

Polyline offset_left(const Polyline& line, double d) {
    if (line.size() < 2) return line;
    // Per segment, its left normal in the plane: (dy, -dx) on screen.
    std::vector<Xy> normals;
    for (std::size_t i = 1; i < line.size(); ++i) {
        const double dx = line[i].x - line[i - 1].x, dy = line[i].y - line[i - 1].y;
        const double len = std::hypot(dx, dy);
        normals.push_back(len > 0 ? Xy{dy / len, -dx / len} : Xy{0, 0});
    }
    Polyline out;
    for (std::size_t i = 0; i < line.size(); ++i) {
        Xy n = i == 0 ? normals.front() : i == line.size() - 1 ? normals.back() : Xy{0, 0};
        if (i > 0 && i + 1 < line.size()) {  // the mean of the two segments' normals
            n = {normals[i - 1].x + normals[i].x, normals[i - 1].y + normals[i].y};
            const double len = std::hypot(n.x, n.y);
            n = len > 0 ? Xy{n.x / len, n.y / len} : normals[i];
        }
        out.push_back({line[i].x + n.x * d, line[i].y + n.y * d});
    }
    return out;
}

namespace {

// The point `at` px along the line, and the index of the segment it is on.
std::pair<Xy, std::size_t> along(const Polyline& line, double at) {
    for (std::size_t i = 1; i < line.size(); ++i) {
        const double seg = std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
        if (at <= seg || i + 1 == line.size()) {
            const double t = seg > 0 ? std::clamp(at / seg, 0.0, 1.0) : 0;
            return {{line[i - 1].x + (line[i].x - line[i - 1].x) * t, line[i - 1].y + (line[i].y - line[i - 1].y) * t}, i};
        }
        at -= seg;
    }
    return {line.back(), line.size() - 1};
}

}  // namespace

Polyline trimmed(const Polyline& line, double start, double end) {
    const double total = length(line);
    if (line.size() < 2 || total <= start + end) return {};
    const auto [first, i] = along(line, start);
    const auto [last, j] = along(line, total - end);
    Polyline out{first};
    for (std::size_t k = i; k < j; ++k) out.push_back(line[k]);
    out.push_back(last);
    return out;
}

std::string path_data(const Polyline& line, bool closed) {
    std::string d;
    for (std::size_t i = 0; i < line.size(); ++i) d += (i == 0 ? "M" : "L") + num(line[i].x) + " " + num(line[i].y);
    if (closed) d += "Z";
    return d;
}

void arrow(std::string& out, const Polyline& line, const ArrowStyle& style) {
    const double total = length(line);
    if (!(total > 2)) return;
    constexpr double kHead = 8;
    const double trim = std::min(0.22 * total, 9.0 + style.offset);
    const Polyline body = trimmed(offset_left(line, style.offset), trim, trim);
    if (body.size() < 2) return;
    const double head = std::min(kHead + style.width, 0.45 * length(body));
    const Xy tip = body.back();
    const auto [base, seg] = along(body, length(body) - head);
    (void)seg;
    const double dx = tip.x - base.x, dy = tip.y - base.y;
    const double len = std::hypot(dx, dy);
    if (!(len > 0)) return;
    const double half = 0.42 * head;
    const Xy left{base.x + dy / len * half, base.y - dx / len * half};
    const Xy right{base.x - dy / len * half, base.y + dx / len * half};
    const std::string cls = style.css_class.empty() ? "" : " class=\"" + style.css_class + "\"";
    out += "<g" + cls + ">";
    out += "<path d=\"" + path_data(trimmed(body, 0, head * 0.8)) + "\" stroke=\"" + style.colour + "\" stroke-width=\"" +
           num(style.width) + "\" fill=\"none\"" + (style.dash.empty() ? "" : " stroke-dasharray=\"" + style.dash + "\"") +
           "/>";
    out += "<path d=\"" + path_data({tip, left, right}, true) + "\" fill=\"" + style.colour + "\"/></g>\n";
}

// ---------------------------------------------------------------------------
// LabelLayout

namespace {

long long cell_key(long long cx, long long cy) { return (cx << 32) ^ (cy & 0xffffffffLL); }

template <class F>
void for_cells(const Box& b, double cell, F f) {
    const auto x0 = static_cast<long long>(std::floor(b.x / cell)),
               x1 = static_cast<long long>(std::floor(b.right() / cell));
    const auto y0 = static_cast<long long>(std::floor(b.y / cell)),
               y1 = static_cast<long long>(std::floor(b.bottom() / cell));
    for (long long cx = x0; cx <= x1; ++cx) {
        for (long long cy = y0; cy <= y1; ++cy) f(cell_key(cx, cy));
    }
}

// Does the segment a-b pass through the box? (Liang-Barsky clipping.)
bool crosses(const Box& b, Xy a, Xy c) {
    double t0 = 0, t1 = 1;
    const double dx = c.x - a.x, dy = c.y - a.y;
    const std::array<double, 4> p = {-dx, dx, -dy, dy};
    const std::array<double, 4> q = {a.x - b.x, b.right() - a.x, a.y - b.y, b.bottom() - a.y};
    for (std::size_t i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

void LabelLayout::remember(const Box& b, std::size_t id) {
    for_cells(b, kCell, [&](long long key) { box_grid_[key].push_back(id); });
}

void LabelLayout::block(const Box& b) {
    boxes_.push_back(b);
    remember(b, boxes_.size() - 1);
}

void LabelLayout::add_line(Xy a, Xy b) {
    lines_.emplace_back(a, b);
    const Box bounds{std::min(a.x, b.x), std::min(a.y, b.y), std::fabs(a.x - b.x), std::fabs(a.y - b.y)};
    // A very long line is kept out of the grid (it would fill thousands of
    // cells); such lines are few and only cost a little overlap.
    if (bounds.w + bounds.h > 4000) return;
    for_cells(bounds, kCell, [&](long long key) { line_grid_[key].push_back(lines_.size() - 1); });
}

std::vector<std::size_t> LabelLayout::near(const Box& b,
                                           const std::unordered_map<long long, std::vector<std::size_t>>& grid) const {
    std::vector<std::size_t> ids;
    for_cells(b, kCell, [&](long long key) {
        const auto it = grid.find(key);
        if (it != grid.end()) ids.insert(ids.end(), it->second.begin(), it->second.end());
    });
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

bool LabelLayout::free(const Box& b) const {
    const Box padded{b.x - 1, b.y - 1, b.w + 2, b.h + 2};  // a pixel of air between labels
    for (const std::size_t id : near(padded, box_grid_)) {
        if (boxes_[id].overlaps(padded)) return false;
    }
    return true;
}

int LabelLayout::lines_covered(const Box& b) const {
    int n = 0;
    for (const std::size_t id : near(b, line_grid_)) n += crosses(b, lines_[id].first, lines_[id].second) ? 1 : 0;
    return n;
}

Box LabelLayout::box_for(Xy centre, std::string_view label, double font) const {
    const double w = text_width(label, font) + 4, h = font + 4;
    return {centre.x - w / 2, centre.y - h / 2, w, h};
}

std::optional<Box> LabelLayout::place(Xy anchor, double clearance, std::string_view label, const Box& allowed,
                                      const Style& style, const std::vector<Xy>& centres) {
    const auto accept = [&](const Box& b, bool leader) {
        Placed p{b, std::string(label), style, std::nullopt};
        if (leader) p.leader_to = anchor;
        placed_.push_back(std::move(p));
        block(b);
        return b;
    };
    for (const Xy c : centres) {
        const Box b = box_for(c, label, style.font);
        if (allowed.contains(b) && free(b) && lines_covered(b) == 0) return accept(b, false);
    }
    // Rings around the anchor: the box's nearest side `r` px from it.
    const Box unit = box_for({0, 0}, label, style.font);
    constexpr std::array<double, 9> kRadii = {0, 4, 9, 16, 26, 38, 54, 74, 100};
    constexpr int kDirections = 16;
    for (const double r : kRadii) {
        std::optional<Box> best;
        int best_cost = 0;
        for (int k = 0; k < kDirections; ++k) {
            const double a = 2 * std::numbers::pi * k / kDirections;
            const double cx = std::cos(a), cy = -std::sin(a);
            // Push the box out along (cx, cy) until its edge is clearance + r away.
            const double reach = clearance + r +
                                 std::min(std::fabs(cx) > 1e-9 ? unit.w / 2 / std::fabs(cx) : 1e9,
                                          std::fabs(cy) > 1e-9 ? unit.h / 2 / std::fabs(cy) : 1e9);
            const Box b = box_for({anchor.x + cx * reach, anchor.y + cy * reach}, label, style.font);
            if (!allowed.contains(b) || !free(b)) continue;
            const int cost = lines_covered(b);
            if (!best || cost < best_cost) {
                best = b;
                best_cost = cost;
            }
        }
        if (best && (best_cost == 0 || r >= 16)) return accept(*best, r >= 16);
    }
    return std::nullopt;
}

void LabelLayout::emit(std::string& out) const {
    out += "<g id=\"labels\" font-family=\"" + std::string(kMonoFont) + "\">\n";
    for (const Placed& p : placed_) {
        if (p.leader_to) {
            const Xy c = p.box.centre();
            // From the anchor to the nearest point of the box's border.
            const Xy end{std::clamp(p.leader_to->x, p.box.x, p.box.right()),
                         std::clamp(p.leader_to->y, p.box.y, p.box.bottom())};
            (void)c;
            out += "<path class=\"leader\" d=\"" + path_data({*p.leader_to, end}) +
                   "\" stroke=\"#707070\" stroke-width=\"0.8\" fill=\"none\"/>\n";
        }
    }
    for (const Placed& p : placed_) {
        out += "<g class=\"" + p.style.css_class + "\"><rect class=\"label-box\" x=\"" + num(p.box.x) + "\" y=\"" +
               num(p.box.y) + "\" width=\"" + num(p.box.w) + "\" height=\"" + num(p.box.h) +
               "\" rx=\"2\" fill=\"#ffffff\" fill-opacity=\"0.88\" stroke=\"" + p.style.colour +
               "\" stroke-opacity=\"0.35\" stroke-width=\"0.6\"/>";
        out += "<text x=\"" + num(p.box.x + p.box.w / 2) + "\" y=\"" + num(p.box.bottom() - 2 - 0.18 * p.style.font) +
               "\" font-size=\"" + num(p.style.font) + "\" text-anchor=\"middle\" fill=\"" + p.style.colour + "\"" +
               (p.style.italic ? " font-style=\"italic\"" : "") + ">" + escape(p.text) + "</text></g>\n";
    }
    out += "</g>\n";
}

}  // namespace dcel::io::svg
