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

// Where the ring position of `from` is, to list the ring starting there.
std::size_t position_of(const std::vector<Index>& clockwise, Index from) {
    return static_cast<std::size_t>(std::find(clockwise.begin(), clockwise.end(), from) - clockwise.begin());
}

// The exact clockwise order, starting after the edge arrived along (at
// most 12 neighbours).
std::string exact_order_line(const WrongTurn& t, const std::vector<Index>& clockwise) {
    std::string order = "clockwise from " + vertex_name(t.from) + ", exact:     ";
    const std::size_t at = position_of(clockwise, t.from);
    for (std::size_t k = 1; k < clockwise.size() && k <= 12; ++k) {
        order += " " + vertex_name(clockwise[(at + k) % clockwise.size()]);
    }
    return order + (clockwise.size() > 13 ? " ..." : "");
}

// The answer's turns at vertex v: from each neighbour, where it goes on.
std::map<Index, Index> answer_turns_at(Index v, const std::vector<std::vector<Index>>& answer_cycles) {
    std::map<Index, Index> turn;
    for (const auto& cycle : answer_cycles) {
        for (std::size_t i = 0; i < cycle.size() && cycle.size() >= 2; ++i) {
            if (cycle[(i + 1) % cycle.size()] == v) turn.emplace(cycle[i], cycle[(i + 2) % cycle.size()]);
        }
    }
    return turn;
}

// "the answer's turns: 3->5 ...", at most six, in clockwise order from the
// edge arrived along; nothing when the answer turns at none of them.
std::optional<std::string> turns_line(const WrongTurn& t, const std::vector<Index>& clockwise,
                                      const std::map<Index, Index>& turn) {
    std::string turns = "the answer's turns:";
    const std::size_t at = position_of(clockwise, t.from);
    std::size_t listed = 0;
    for (std::size_t k = 0; k < clockwise.size() && listed < 6; ++k) {
        const Index from = clockwise[(at + k) % clockwise.size()];
        const auto it = turn.find(from);
        if (it == turn.end()) continue;
        turns += " " + std::to_string(from) + "->" + std::to_string(it->second);
        ++listed;
    }
    if (listed == 0) return std::nullopt;
    return turns;
}

// When the answer's turns go once round all the edges, they are an order:
// the answer's clockwise order, to set beside the exact one. Nothing
// otherwise.
std::optional<std::string> answer_order_line(const WrongTurn& t, const std::vector<Index>& clockwise,
                                             const std::map<Index, Index>& turn) {
    if (turn.size() != clockwise.size()) return std::nullopt;
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
    if (steps + 1 != clockwise.size() || back == turn.end() || back->second != t.from) return std::nullopt;
    return order_of_answer;
}

// "2 more wrong turns here, from v4 v7": the inset draws the first only.
std::string more_turns_line(const Inset& inset) {
    std::string more = std::to_string(inset.turns.size() - 1) + " more wrong turn" + (inset.turns.size() > 2 ? "s" : "") +
                       " here, from";
    for (std::size_t k = 1; k < inset.turns.size() && k < 5; ++k) more += " " + vertex_name(inset.turns[k].from);
    return more;
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
    lines.push_back({exact_order_line(t, clockwise), io::svg::kNoteInk, false});
    const std::map<Index, Index> turn = answer_turns_at(inset.vertex, answer_cycles);
    if (auto line = answer_order_line(t, clockwise, turn)) lines.push_back({std::move(*line), io::svg::kAnswerInk, false});
    if (auto line = turns_line(t, clockwise, turn)) lines.push_back({std::move(*line), io::svg::kNoteInk, false});
    if (inset.turns.size() > 1) lines.push_back({more_turns_line(inset), io::svg::kNoteInk, false});
    return wrapped(lines, static_cast<std::size_t>((kInsetWidth - 20) / (io::svg::kCharWidth * 10.5)));
}

constexpr double kInsetFan = 2 * kFanRadius + 56;  // the fan and its labels
constexpr double kInsetLine = 14;

double inset_height(std::size_t lines) { return 8 + kInsetFan + static_cast<double>(lines) * kInsetLine + 10; }

// Where an inset paints: the SVG text, the label layout it shares with the
// panels, and the list of labels that found no room.
struct InsetCanvas {
    std::string& out;
    LabelLayout& labels;
    std::vector<std::string>& left_out;
};

// The vertex's edges as the inset draws them.
struct Fan {
    const Inset& inset;
    const DrawnDcel& g;             // the panel drawing, whose directions the spokes follow
    std::vector<HalfEdgeId> ring;   // the half-edges leaving the vertex, clockwise
    std::vector<Index> clockwise;   // their targets
    Xy centre;                      // of the fan, in the inset
    std::vector<std::size_t> kept;  // the ring positions drawn as spokes
    std::vector<double> angle;      // of each kept spoke, as drawn

    // The angle of the spoke towards `neighbour`, if it is drawn.
    [[nodiscard]] std::optional<double> angle_of(Index neighbour) const {
        for (std::size_t k = 0; k < kept.size(); ++k) {
            if (clockwise[kept[k]] == neighbour) return angle[k];
        }
        return std::nullopt;
    }
};

// The spokes shown: all of them up to 12 edges; beyond, the three that
// matter (arrived along, the reference's next, the answer's) and one on
// each side of each, with the hidden ones counted between them.
std::vector<std::size_t> kept_spokes(const std::vector<Index>& clockwise, const WrongTurn& t) {
    const std::size_t n = clockwise.size();
    std::vector<std::size_t> kept;
    if (n <= 12) {
        for (std::size_t i = 0; i < n; ++i) kept.push_back(i);
        return kept;
    }
    std::vector<char> keep(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (clockwise[i] == t.from || clockwise[i] == t.reference_to || clockwise[i] == t.answer_to) {
            keep[(i + n - 1) % n] = keep[i] = keep[(i + 1) % n] = 1;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (keep[i] != 0) kept.push_back(i);
    }
    return kept;
}

// The fan of the inset's vertex: its ring, the spokes kept, and their
// directions as drawn in the panels, spread to at least 40 degrees (less
// for many edges), in the exact order.
Fan make_fan(const Inset& inset, const DrawnDcel& g, Xy centre) {
    const Dcel& d = g.dcel();
    Fan fan{inset, g, {}, {}, centre, {}, {}};
    for (const HalfEdgeId h : d.around_origin_cw(d.out(VertexId(inset.vertex)))) {
        fan.ring.push_back(h);
        fan.clockwise.push_back(d.target(h).index());
    }
    fan.kept = kept_spokes(fan.clockwise, inset.turns.front());
    std::vector<double> drawn;
    for (const std::size_t i : fan.kept) {
        const Xy a = g.at(d.origin(fan.ring[i])), b = g.at(d.target(fan.ring[i]));
        drawn.push_back(std::atan2(-(b.y - a.y), b.x - a.x));
    }
    fan.angle = io::svg::spread_clockwise(drawn, 0.7);
    return fan;
}

void open_inset(std::string& out, const Inset& inset, const Box& box) {
    out += "<g class=\"inset\" data-vertex=\"" + std::to_string(inset.vertex) + "\" data-tag=\"" +
           std::string(1, inset.tag) + "\">\n<rect class=\"inset-frame\" x=\"" + io::svg::num(box.x) + "\" y=\"" +
           io::svg::num(box.y) + "\" width=\"" + io::svg::num(box.w) + "\" height=\"" + io::svg::num(box.h) +
           "\" rx=\"4\" fill=\"#fbfbfb\" stroke=\"#b0b0b0\" stroke-width=\"1\"/>\n";
}

void paint_spokes(InsetCanvas& canvas, const Fan& fan) {
    const Xy c = fan.centre;
    canvas.labels.block({c.x - 5, c.y - 5, 10, 10});
    for (std::size_t k = 0; k < fan.kept.size(); ++k) {
        const Xy end = on_circle(c, kFanRadius, fan.angle[k]);
        canvas.out += "<path class=\"spoke\" d=\"" + io::svg::path_data({c, end}) +
                      "\" stroke=\"#707070\" stroke-width=\"1.2\"/>\n";
        canvas.labels.add_line(c, end);
    }
}

// The arcs from the edge arrived along, clockwise to where the reference
// and the answer go on, and the three arrows: arrival, reference's next,
// answer's next (when its neighbour is drawn).
void paint_turns(std::string& out, const Fan& fan) {
    const Xy c = fan.centre;
    const WrongTurn& t = fan.inset.turns.front();
    const double from = *fan.angle_of(t.from);
    io::svg::arrow(out, clockwise_arc(c, 0.42 * kFanRadius, from, *fan.angle_of(t.reference_to)),
                   {io::svg::kReferenceInk, 1.8, 0, "", "reference-turn"});
    if (const auto x = fan.angle_of(t.answer_to)) {
        io::svg::arrow(out, clockwise_arc(c, 0.66 * kFanRadius, from, *x),
                       {io::svg::kAnswerInk, 1.8, 0, "4 2", "answer-turn"});
        io::svg::arrow(out, {c, on_circle(c, kFanRadius, *x)}, {io::svg::kAnswerInk, 2.6, 0, "", "answer-next"});
    }
    io::svg::arrow(out, {c, on_circle(c, kFanRadius, *fan.angle_of(t.reference_to))},
                   {io::svg::kReferenceInk, 2.6, 0, "", "reference-next"});
    io::svg::arrow(out, {on_circle(c, kFanRadius, from), c}, {"#202020", 2.6, 0, "", "arrival"});
    out += "<circle cx=\"" + io::svg::num(c.x) + "\" cy=\"" + io::svg::num(c.y) + "\" r=\"3.2\" fill=\"#000000\"/>\n";
}

// Each spoke's neighbour name at its tip, and after it, when spokes are
// hidden before the next one shown, a dotted arc with their count.
void label_spokes(InsetCanvas& canvas, const Fan& fan, const Box& fan_area) {
    const Xy c = fan.centre;
    const WrongTurn& t = fan.inset.turns.front();
    const std::string in_inset = " (inset " + std::string(1, fan.inset.tag) + ")";
    const std::size_t n = fan.clockwise.size();
    for (std::size_t k = 0; k < fan.kept.size(); ++k) {
        const Index neighbour = fan.clockwise[fan.kept[k]];
        const Xy end = on_circle(c, kFanRadius, fan.angle[k]);
        const std::string colour = neighbour == t.reference_to ? io::svg::kReferenceInk
                                   : neighbour == t.answer_to  ? io::svg::kAnswerInk
                                                               : "#000000";
        if (!canvas.labels.place(end, 3, vertex_name(neighbour), fan_area, {colour, 11, false, "label spoke-label"},
                                 {on_circle(c, kFanRadius + 14, fan.angle[k])})) {
            canvas.left_out.push_back(vertex_name(neighbour) + in_inset);
        }
        const std::size_t next = fan.kept[(k + 1) % fan.kept.size()];
        const std::size_t hidden = (next + n - fan.kept[k] - 1) % n;
        if (hidden == 0 || fan.kept.size() == n) continue;
        const Polyline arc = clockwise_arc(c, 0.9 * kFanRadius, fan.angle[k], fan.angle[(k + 1) % fan.kept.size()]);
        canvas.out += "<path class=\"hidden-spokes\" d=\"" + io::svg::path_data(arc) +
                      "\" stroke=\"#909090\" stroke-width=\"1.2\" stroke-dasharray=\"1 3\" fill=\"none\"/>\n";
        const Xy mid = arc[arc.size() / 2];
        const Xy away{c.x + (mid.x - c.x) * 1.25, c.y + (mid.y - c.y) * 1.25};
        if (!canvas.labels.place(mid, 2, "+" + std::to_string(hidden), fan_area, {"#707070", 10, true, "label hidden-count"},
                                 {away})) {
            canvas.left_out.push_back("+" + std::to_string(hidden) + in_inset);
        }
    }
}

// The inset's words, under the fan.
void paint_text(std::string& out, const Box& box, const std::vector<InsetText>& text) {
    double y = box.y + 8 + kInsetFan + kInsetLine - 2;
    for (const InsetText& line : text) {
        io::svg::text(out, {box.x + 10, y}, line.line, 10.5, line.colour, "start", line.bold);
        y += kInsetLine;
    }
}

}  // namespace

double paint_inset(std::string& out, LabelLayout& labels, const Inset& inset, const DrawnDcel& g,
                   const std::vector<std::vector<Index>>& answer_cycles, Xy at, std::vector<std::string>& left_out) {
    InsetCanvas canvas{out, labels, left_out};
    const Xy centre{at.x + kInsetWidth / 2, at.y + 8 + kInsetFan / 2};
    const Fan fan = make_fan(inset, g, centre);
    const std::vector<InsetText> text = inset_text(inset, g.dcel(), fan.clockwise, answer_cycles);
    const Box box{at.x, at.y, kInsetWidth, inset_height(text.size())};
    open_inset(out, inset, box);
    paint_spokes(canvas, fan);
    paint_turns(out, fan);
    label_spokes(canvas, fan, {box.x + 4, box.y + 4, box.w - 8, kInsetFan + 4});
    paint_text(out, box, text);
    out += "</g>\n";
    return box.h;
}

}  // namespace dcel::check
