#include "dcel/check/counterexample_inset.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

namespace dcel::check {
namespace {

using io::svg::Box;
using io::svg::DrawnDcel;
using io::svg::LabelLayout;
using io::svg::Polyline;
using io::svg::Xy;

constexpr double kFanRadius = 66;
constexpr double kTwoPi = 2 * std::numbers::pi;

std::string vertex_name(Index v) { return "v" + std::to_string(v); }

Xy on_circle(Xy c, double r, double angle) { return {c.x + r * std::cos(angle), c.y - r * std::sin(angle)}; }

// From angle a clockwise to angle b, at radius r.
Polyline clockwise_arc(Xy c, double r, double a, double b) {
    double sweep = std::fmod(a - b, kTwoPi);
    if (sweep <= 1e-9) sweep += kTwoPi;
    Polyline arc;
    const int steps = std::max(6, static_cast<int>(sweep / 0.08));
    for (int i = 0; i <= steps; ++i) arc.push_back(on_circle(c, r, a - sweep * i / steps));
    return arc;
}

struct InsetText {
    std::string line;
    const char* colour;
    bool bold;
};

// Long lines wrapped at spaces to fit an inset, continued with an indent.
std::vector<InsetText> wrapped(const std::vector<InsetText>& lines, std::size_t width) {
    std::vector<InsetText> out;
    for (const InsetText& l : lines) {
        std::string rest = l.line;
        bool first = true;
        while (rest.size() > width) {
            std::size_t cut = rest.rfind(' ', width);
            if (cut == std::string::npos || cut < 8) cut = width;
            out.push_back({rest.substr(0, cut), l.colour, l.bold && first});
            rest = "    " + rest.substr(rest[cut] == ' ' ? cut + 1 : cut);
            first = false;
        }
        out.push_back({rest, l.colour, l.bold && first});
    }
    return out;
}

std::vector<InsetText> inset_text(const Inset& inset, const Dcel& d, const std::vector<Index>& clockwise,
                                  const std::vector<std::vector<Index>>& answer_cycles) {
    const WrongTurn& t = inset.turns.front();
    const Point p = d.point(VertexId(inset.vertex));
    std::vector<InsetText> lines;
    lines.push_back({std::string(1, inset.tag) + "  at " + vertex_name(inset.vertex) + " (" + io::svg::exact_number(p.x) +
                         ", " + io::svg::exact_number(p.y) + ")",
                     io::svg::kNoteInk, true});
    lines.push_back({"arriving along " + vertex_name(t.from) + "->" + vertex_name(t.at) + ":", io::svg::kNoteInk, false});
    lines.push_back(
        {"  the reference goes on to " + vertex_name(t.reference_to) + " (next clockwise)", io::svg::kReferenceInk, false});
    const bool neighbour = std::find(clockwise.begin(), clockwise.end(), t.answer_to) != clockwise.end();
    lines.push_back({"  the answer goes on to " + vertex_name(t.answer_to) + (neighbour ? "" : " (not a neighbour)"),
                     io::svg::kAnswerInk, false});
    // The exact order, starting from the edge arrived along.
    std::string order = "clockwise from " + vertex_name(t.from) + ", exact:     ";
    const auto at = std::find(clockwise.begin(), clockwise.end(), t.from);
    for (std::size_t k = 1; k < clockwise.size() && k <= 12; ++k) {
        order += " " + vertex_name(clockwise[(static_cast<std::size_t>(at - clockwise.begin()) + k) % clockwise.size()]);
    }
    lines.push_back({order + (clockwise.size() > 13 ? " ..." : ""), io::svg::kNoteInk, false});
    // The answer's turns at this vertex: from each neighbour, where it goes on.
    std::map<Index, Index> turn;
    for (const auto& cycle : answer_cycles) {
        for (std::size_t i = 0; i < cycle.size() && cycle.size() >= 2; ++i) {
            if (cycle[(i + 1) % cycle.size()] == inset.vertex) turn.emplace(cycle[i], cycle[(i + 2) % cycle.size()]);
        }
    }
    std::string turns = "the answer's turns:";
    std::size_t listed = 0;
    for (std::size_t k = 0; k < clockwise.size() && listed < 6; ++k) {
        const Index from = clockwise[(static_cast<std::size_t>(at - clockwise.begin()) + k) % clockwise.size()];
        const auto it = turn.find(from);
        if (it == turn.end()) continue;
        turns += " " + std::to_string(from) + "->" + std::to_string(it->second);
        ++listed;
    }
    // When the turns go once round all the edges, they are an order: the
    // answer's clockwise order, to set beside the exact one.
    if (turn.size() == clockwise.size()) {
        std::string order_of_answer = "clockwise from " + vertex_name(t.from) + ", the answer:";
        Index v = t.from;
        std::size_t steps = 0;
        for (; steps + 1 < clockwise.size(); ++steps) {
            const auto it = turn.find(v);
            if (it == turn.end() || it->second == t.from) break;
            v = it->second;
            if (steps < 12) order_of_answer += " " + vertex_name(v);
        }
        if (clockwise.size() > 13) order_of_answer += " ...";
        const auto back = turn.find(v);
        if (steps + 1 == clockwise.size() && back != turn.end() && back->second == t.from) {
            lines.push_back({order_of_answer, io::svg::kAnswerInk, false});
        }
    }
    if (listed > 0) lines.push_back({turns, io::svg::kNoteInk, false});
    if (inset.turns.size() > 1) {
        std::string more = std::to_string(inset.turns.size() - 1) + " more wrong turn" +
                           (inset.turns.size() > 2 ? "s" : "") + " here, from";
        for (std::size_t k = 1; k < inset.turns.size() && k < 5; ++k) more += " " + vertex_name(inset.turns[k].from);
        lines.push_back({more, io::svg::kNoteInk, false});
    }
    return wrapped(lines, static_cast<std::size_t>((kInsetWidth - 20) / (io::svg::kCharWidth * 10.5)));
}

constexpr double kInsetFan = 2 * kFanRadius + 56;  // the fan and its labels
constexpr double kInsetLine = 14;

double inset_height(std::size_t lines) { return 8 + kInsetFan + static_cast<double>(lines) * kInsetLine + 10; }

void paint_fan(std::string& out, LabelLayout& labels, const Inset& inset, const DrawnDcel& g, const Box& box,
               const std::vector<InsetText>& text, const std::vector<Index>& clockwise, const std::vector<HalfEdgeId>& ring,
               std::vector<std::string>& left_out) {
    const Dcel& d = g.dcel();
    out += "<g class=\"inset\" data-vertex=\"" + std::to_string(inset.vertex) + "\" data-tag=\"" +
           std::string(1, inset.tag) + "\">\n<rect class=\"inset-frame\" x=\"" + io::svg::num(box.x) + "\" y=\"" +
           io::svg::num(box.y) + "\" width=\"" + io::svg::num(box.w) + "\" height=\"" + io::svg::num(box.h) +
           "\" rx=\"4\" fill=\"#fbfbfb\" stroke=\"#b0b0b0\" stroke-width=\"1\"/>\n";
    const Xy c{box.x + box.w / 2, box.y + 8 + kInsetFan / 2};
    const WrongTurn& t = inset.turns.front();
    // The spokes shown: all of them up to 12 edges; beyond, the three that
    // matter (arrived along, the reference's next, the answer's) and one on
    // each side of each, with the hidden ones counted between them.
    const std::size_t n = clockwise.size();
    std::vector<std::size_t> kept;
    if (n <= 12) {
        for (std::size_t i = 0; i < n; ++i) kept.push_back(i);
    } else {
        std::vector<char> keep(n, 0);
        for (std::size_t i = 0; i < n; ++i) {
            if (clockwise[i] == t.from || clockwise[i] == t.reference_to || clockwise[i] == t.answer_to) {
                keep[(i + n - 1) % n] = keep[i] = keep[(i + 1) % n] = 1;
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (keep[i] != 0) kept.push_back(i);
        }
    }
    // Directions as drawn in the panels, spread to at least 40 degrees (less
    // for many edges), in the exact order.
    std::vector<double> drawn;
    for (const std::size_t i : kept) {
        const Xy a = g.at(d.origin(ring[i])), b = g.at(d.target(ring[i]));
        drawn.push_back(std::atan2(-(b.y - a.y), b.x - a.x));
    }
    const std::vector<double> angle = io::svg::spread_clockwise(drawn, 0.7);
    const auto angle_of = [&](Index neighbour) -> std::optional<double> {
        for (std::size_t k = 0; k < kept.size(); ++k) {
            if (clockwise[kept[k]] == neighbour) return angle[k];
        }
        return std::nullopt;
    };
    const Box fan_area{box.x + 4, box.y + 4, box.w - 8, kInsetFan + 4};
    labels.block({c.x - 5, c.y - 5, 10, 10});
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const Xy end = on_circle(c, kFanRadius, angle[k]);
        out += "<path class=\"spoke\" d=\"" + io::svg::path_data({c, end}) +
               "\" stroke=\"#707070\" stroke-width=\"1.2\"/>\n";
        labels.add_line(c, end);
    }
    // The arcs: from the edge arrived along, clockwise to where each goes on.
    const double from = *angle_of(t.from);
    io::svg::arrow(out, clockwise_arc(c, 0.42 * kFanRadius, from, *angle_of(t.reference_to)),
                   {io::svg::kReferenceInk, 1.8, 0, "", "reference-turn"});
    if (const auto x = angle_of(t.answer_to)) {
        io::svg::arrow(out, clockwise_arc(c, 0.66 * kFanRadius, from, *x),
                       {io::svg::kAnswerInk, 1.8, 0, "4 2", "answer-turn"});
        io::svg::arrow(out, {c, on_circle(c, kFanRadius, *x)}, {io::svg::kAnswerInk, 2.6, 0, "", "answer-next"});
    }
    io::svg::arrow(out, {c, on_circle(c, kFanRadius, *angle_of(t.reference_to))},
                   {io::svg::kReferenceInk, 2.6, 0, "", "reference-next"});
    io::svg::arrow(out, {on_circle(c, kFanRadius, from), c}, {"#202020", 2.6, 0, "", "arrival"});
    out += "<circle cx=\"" + io::svg::num(c.x) + "\" cy=\"" + io::svg::num(c.y) + "\" r=\"3.2\" fill=\"#000000\"/>\n";
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const Index neighbour = clockwise[kept[k]];
        const Xy end = on_circle(c, kFanRadius, angle[k]);
        const std::string colour = neighbour == t.reference_to ? io::svg::kReferenceInk
                                   : neighbour == t.answer_to  ? io::svg::kAnswerInk
                                                               : "#000000";
        if (!labels.place(end, 3, vertex_name(neighbour), fan_area, {colour, 11, false, "label spoke-label"},
                          {on_circle(c, kFanRadius + 14, angle[k])})) {
            left_out.push_back(vertex_name(neighbour) + " (inset " + std::string(1, inset.tag) + ")");
        }
        // Hidden spokes between this one and the next shown: a dotted arc and their count.
        const std::size_t next = kept[(k + 1) % kept.size()];
        const std::size_t hidden = (next + n - kept[k] - 1) % n;
        if (hidden == 0 || kept.size() == n) continue;
        const Polyline arc = clockwise_arc(c, 0.9 * kFanRadius, angle[k], angle[(k + 1) % kept.size()]);
        out += "<path class=\"hidden-spokes\" d=\"" + io::svg::path_data(arc) +
               "\" stroke=\"#909090\" stroke-width=\"1.2\" stroke-dasharray=\"1 3\" fill=\"none\"/>\n";
        const Xy mid = arc[arc.size() / 2];
        const Xy away{c.x + (mid.x - c.x) * 1.25, c.y + (mid.y - c.y) * 1.25};
        if (!labels.place(mid, 2, "+" + std::to_string(hidden), fan_area, {"#707070", 10, true, "label hidden-count"},
                          {away})) {
            left_out.push_back("+" + std::to_string(hidden) + " (inset " + std::string(1, inset.tag) + ")");
        }
    }
    double y = box.y + 8 + kInsetFan + kInsetLine - 2;
    for (const InsetText& line : text) {
        io::svg::text(out, {box.x + 10, y}, line.line, 10.5, line.colour, "start", line.bold);
        y += kInsetLine;
    }
    out += "</g>\n";
}
}  // namespace

double paint_inset(std::string& out, LabelLayout& labels, const Inset& inset, const DrawnDcel& g,
                   const std::vector<std::vector<Index>>& answer_cycles, Xy at, std::vector<std::string>& left_out) {
    const Dcel& d = g.dcel();
    std::vector<HalfEdgeId> ring;
    std::vector<Index> clockwise;
    for (const HalfEdgeId h : d.around_origin_cw(d.out(VertexId(inset.vertex)))) {
        ring.push_back(h);
        clockwise.push_back(d.target(h).index());
    }
    const std::vector<InsetText> text = inset_text(inset, d, clockwise, answer_cycles);
    const Box box{at.x, at.y, kInsetWidth, inset_height(text.size())};
    paint_fan(out, labels, inset, g, box, text, clockwise, ring, left_out);
    return box.h;
}

}  // namespace dcel::check
