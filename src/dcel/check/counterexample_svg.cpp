#include "dcel/check/counterexample_svg.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "dcel/check/counterexample_inset.hpp"
#include "dcel/check/wrong_turns.hpp"
#include "dcel/io/svg_canvas.hpp"
#include "dcel/io/svg_drawing.hpp"
#include "dcel/io/svg_frame.hpp"

namespace dcel::check {
namespace {

using io::svg::ArrowStyle;
using io::svg::Box;
using io::svg::DrawnDcel;
using io::svg::Frame;
using io::svg::LabelLayout;
using io::svg::Polyline;
using io::svg::Xy;

constexpr double kLongest = 380;  // px along the longer side of each panel's drawing
constexpr double kMargin = 40;    // around each drawing: room for labels
constexpr double kPad = 12;
constexpr double kGap = 24;  // between panels
constexpr double kFont = 11;
constexpr double kLine = 15;
constexpr std::size_t kMaxInsets = 6;
constexpr const char* kExtraInk = "#b35806";  // an answer cycle the reference does not have, or a repeat: brown

// A vertex cycle rotated to start at its smallest rotation, so that equal
// cycles compare equal whatever vertex they were listed from.
std::vector<Index> canonical(const std::vector<Index>& c) {
    if (c.empty()) return c;
    std::size_t best = 0;
    for (std::size_t s = 1; s < c.size(); ++s) {
        for (std::size_t k = 0; k < c.size(); ++k) {
            const Index a = c[(s + k) % c.size()], b = c[(best + k) % c.size()];
            if (a != b) {
                if (a < b) best = s;
                break;
            }
        }
    }
    std::vector<Index> out;
    for (std::size_t k = 0; k < c.size(); ++k) out.push_back(c[(best + k) % c.size()]);
    return out;
}

// The same ring up to rotation and direction (for regions, whose rings may
// be listed either way round).
std::vector<Index> canonical_ring(std::vector<Index> c) {
    std::vector<Index> forward = canonical(c);
    std::reverse(c.begin(), c.end());
    std::vector<Index> backward = canonical(c);
    return std::min(forward, backward);
}

struct ReferenceCycles {
    std::map<std::vector<Index>, Index> face_of;         // canonical vertex cycle -> its face
    std::map<std::vector<Index>, Index> face_of_ring;    // the same, up to direction
    std::vector<std::vector<Index>> cycle_of_half_edge;  // per half-edge: its cycle (canonical)
};

ReferenceCycles reference_cycles(const Dcel& d) {
    ReferenceCycles r;
    r.cycle_of_half_edge.resize(d.num_half_edges());
    std::vector<char> seen(d.num_half_edges(), 0);
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        if (seen[h] != 0) continue;
        std::vector<Index> cycle;
        std::vector<Index> members;
        for (const HalfEdgeId x : d.cycle(HalfEdgeId(h))) {
            seen[x.index()] = 1;
            cycle.push_back(d.origin(x).index());
            members.push_back(x.index());
        }
        const std::vector<Index> key = canonical(cycle);
        r.face_of.emplace(key, d.face(HalfEdgeId(h)).index());
        r.face_of_ring.emplace(canonical_ring(cycle), d.face(HalfEdgeId(h)).index());
        for (const Index m : members) r.cycle_of_half_edge[m] = key;
    }
    return r;
}

struct Panel {
    Box area;  // the drawing plus its margin: where its labels may go
    std::optional<Frame> frame;
    std::optional<DrawnDcel> drawn;
};

Panel make_panel(const Dcel& d, io::svg::FrameKind kind, Xy top_left) {
    Panel p;
    p.frame.emplace(d.points(), kind);
    const Xy size = p.frame->size(kLongest);
    p.area = {top_left.x, top_left.y, size.x + 2 * kMargin, size.y + 2 * kMargin};
    p.frame->place({top_left.x + kMargin, top_left.y + kMargin, size.x, size.y});
    p.drawn.emplace(d, *p.frame);
    return p;
}

void paint_answer_cycles(std::string& out, const DrawnDcel& g, const CounterexampleDrawing& in, const ReferenceCycles& ref,
                         const std::vector<Inset>& insets) {
    const io::svg::StepLines steps(g);
    out += "<g id=\"answer-cycles\">\n";
    // A cycle the answer lists twice is drawn brown the second time: in its
    // face's colour it would lie exactly on the first copy and not be seen.
    std::set<std::vector<Index>> drawn;
    for (const auto& cycle : in.answer_cycles) {
        const std::vector<Index> key = canonical(cycle);
        const bool repeat = !drawn.insert(key).second;
        const auto match = repeat ? ref.face_of.end() : ref.face_of.find(key);
        const std::string ink = match != ref.face_of.end() ? io::svg::face_ink(match->second) : kExtraInk;
        for (std::size_t i = 0; i < cycle.size(); ++i) {
            const auto step = steps(cycle[i], cycle[(i + 1) % cycle.size()]);
            if (!step) continue;
            io::svg::arrow(out, step->line,
                           {ink, 1.3, 4.5, step->along_edge ? "" : "5 3",
                            match != ref.face_of.end() ? "answer-step" : "answer-step extra"});
        }
    }
    // The wrong turns on top: the answer's step out of the vertex, thick red.
    for (const Inset& inset : insets) {
        for (const WrongTurn& t : inset.turns) {
            if (const auto step = steps(t.at, t.answer_to)) {
                io::svg::arrow(out, step->line,
                               {io::svg::kAnswerInk, 2.8, 4.5, step->along_edge ? "" : "5 3", "wrong-turn"});
            }
        }
    }
    out += "</g>\n";
}

void paint_answer_polygons(std::string& out, const DrawnDcel& g, const CounterexampleDrawing& in,
                           const ReferenceCycles& ref) {
    const io::svg::StepLines steps(g);
    out += "<g id=\"answer-regions\" fill-rule=\"evenodd\">\n";
    // A polygon the answer lists twice (its rings the same up to order,
    // rotation and direction) is salmon the second time, as cycles are brown.
    std::set<std::vector<std::vector<Index>>> drawn_polygons;
    for (const auto& polygon : in.answer_polygons) {
        if (polygon.empty()) continue;
        std::vector<std::vector<Index>> canonical_rings;
        canonical_rings.reserve(polygon.size());
        for (const auto& ring : polygon) canonical_rings.push_back(canonical_ring(ring));
        std::vector<std::vector<Index>> key = canonical_rings;
        std::sort(key.begin(), key.end());
        const bool repeat = !drawn_polygons.insert(std::move(key)).second;
        bool all_match = !repeat;
        std::optional<Index> face;
        std::string d;
        std::string outline;
        for (std::size_t r = 0; r < polygon.size(); ++r) {
            const auto& ring = polygon[r];
            const auto match = ref.face_of_ring.find(canonical_rings[r]);
            if (match == ref.face_of_ring.end()) all_match = false;
            if (!face && match != ref.face_of_ring.end()) face = match->second;
            Polyline drawn;
            for (std::size_t i = 0; i < ring.size(); ++i) {
                const auto step = steps(ring[i], ring[(i + 1) % ring.size()]);
                if (!step) continue;
                drawn.insert(drawn.end(), step->line.begin(), step->line.end() - 1);
                outline += "<path d=\"" + io::svg::path_data(step->line) + "\" stroke=\"#202020\" fill=\"none\"" +
                           (step->along_edge ? "" : " stroke-dasharray=\"5 3\"") + "/>";
            }
            if (drawn.size() > 2) d += io::svg::path_data(drawn, true);
        }
        const bool good = all_match && face;
        out += "<path class=\"answer-region";
        out += good ? "" : " extra";
        out += "\" d=\"" + d + "\" fill=\"";
        out += good ? io::svg::face_fill(*face) : "#f4a582";
        out += "\" fill-opacity=\"0.8\"/>" + outline + "\n";
    }
    out += "</g>\n";
}

// The reference's half-edges, dashed where their cycle is missing from the answer.
io::svg::HalfEdgeStyle reference_style(const DrawnDcel& g, const ReferenceCycles& ref,
                                       const std::map<std::vector<Index>, std::size_t>& answer_cycles, bool cycles_given) {
    return [&g, &ref, &answer_cycles, cycles_given](HalfEdgeId h) -> std::optional<ArrowStyle> {
        const bool missing = cycles_given && !answer_cycles.contains(ref.cycle_of_half_edge[h.index()]);
        return ArrowStyle{io::svg::face_ink(g.dcel().face(h).index()), missing ? 1.8 : 1.3, 4.5, missing ? "4 3" : "",
                          missing ? "half-edge missing" : "half-edge"};
    };
}

void ring_vertex(std::string& out, Xy at, const char* colour) {
    out += "<circle class=\"tag-ring\" cx=\"" + io::svg::num(at.x) + "\" cy=\"" + io::svg::num(at.y) +
           "\" r=\"9\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\"/>\n";
}

std::string page(double width, double height, const std::string& title, const std::string& body) {
    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + io::svg::num(width) + "\" height=\"" +
                      io::svg::num(height) + "\" viewBox=\"0 0 " + io::svg::num(width) + " " + io::svg::num(height) +
                      "\">\n";
    out += "<title>" + io::svg::escape(title) + "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    out += "<g font-family=\"" + std::string(io::svg::kMonoFont) + "\">\n" + body + "</g>\n</svg>\n";
    return out;
}

std::string shortened(const std::string& s, std::size_t max) { return s.size() <= max ? s : s.substr(0, max - 3) + "..."; }

// The page when there is no reference to draw: the title and why.
std::string nothing_to_draw(const std::string& title) {
    std::string body;
    io::svg::text(body, {kPad, 24}, title, 14, io::svg::kNoteInk, "start", true);
    io::svg::text(body, {kPad, 46}, "nothing to draw: no reference DCEL was given", kFont);
    return page(std::max(420.0, io::svg::text_width(title, 14) + 2 * kPad), 60, title, body);
}

// The vertices where the answer's next differs from the reference's: the
// first kMaxInsets (in answer order) get an inset, the others are listed.
struct Insets {
    std::vector<Inset> drawn;
    std::vector<Index> uninset;
};

Insets collect_insets(const Dcel& d, const std::vector<std::vector<Index>>& answer_cycles) {
    Insets out;
    for (const WrongTurn& t : wrong_turns(d, answer_cycles)) {
        auto it = std::find_if(out.drawn.begin(), out.drawn.end(), [&](const Inset& i) { return i.vertex == t.at; });
        if (it != out.drawn.end()) {
            it->turns.push_back(t);
        } else if (out.drawn.size() < kMaxInsets) {
            out.drawn.push_back({t.at, static_cast<char>('A' + out.drawn.size()), {t}});
        } else if (std::find(out.uninset.begin(), out.uninset.end(), t.at) == out.uninset.end()) {
            out.uninset.push_back(t.at);
        }
    }
    return out;
}

std::string subtitle_of(const CounterexampleDrawing& in, std::size_t insets) {
    return "left: " + in.reference_name + "; right: " + shortened(in.answer_name, 60) +
           (insets == 0   ? ""
            : insets == 1 ? "; A: where their next differ (inset below)"
                          : "; A, B, ...: where their next differ (insets below)");
}

// The title, the subtitle, each panel's name and frame.
void paint_headers(std::string& body, const CounterexampleDrawing& in, const std::string& title, const std::string& subtitle,
                   double top, const Panel& left, const Panel& right) {
    io::svg::text(body, {kPad, 22}, title, 14, io::svg::kNoteInk, "start", true);
    io::svg::text(body, {kPad, 42}, subtitle, kFont);
    io::svg::text(body, {left.area.x, top + 12}, in.reference_name, 12, io::svg::kReferenceInk, "start", true);
    io::svg::text(body, {right.area.x, top + 12}, shortened(in.answer_name, 60), 12, io::svg::kAnswerInk, "start", true);
    for (const Panel* p : {&left, &right}) {
        body += "<rect class=\"panel-frame\" x=\"" + io::svg::num(p->area.x) + "\" y=\"" + io::svg::num(p->area.y) +
                "\" width=\"" + io::svg::num(p->area.w) + "\" height=\"" + io::svg::num(p->area.h) +
                "\" fill=\"none\" stroke=\"#d0d0d0\"/>\n";
    }
}

// Left: the reference, its half-edges dashed where the answer lacks their
// cycle. Right: the answer's regions and cycles over the reference's edges.
// Both: a ring around each vertex with an inset.
void paint_panels(std::string& body, const CounterexampleDrawing& in, const ReferenceCycles& ref, const Panel& left,
                  const Panel& right, const std::vector<Inset>& insets) {
    std::map<std::vector<Index>, std::size_t> answer_cycles;
    for (const auto& c : in.answer_cycles) ++answer_cycles[canonical(c)];
    body += "<g id=\"reference\">\n";
    io::svg::paint_faces(body, *left.drawn);
    io::svg::paint_edges(body, *left.drawn);
    io::svg::paint_half_edges(body, *left.drawn,
                              reference_style(*left.drawn, ref, answer_cycles, !in.answer_cycles.empty()));
    io::svg::paint_vertices(body, *left.drawn);
    body += "</g>\n<g id=\"answer\">\n";
    io::svg::paint_edges(body, *right.drawn);
    if (!in.answer_polygons.empty()) paint_answer_polygons(body, *right.drawn, in, ref);
    paint_answer_cycles(body, *right.drawn, in, ref, insets);
    io::svg::paint_vertices(body, *right.drawn);
    if (in.answer_cycles.empty() && in.answer_polygons.empty()) {
        io::svg::text(body, {right.area.x + 10, right.area.y + 20}, "(no answer given)", kFont, io::svg::kAnswerInk);
    }
    for (const Inset& inset : insets) {
        ring_vertex(body, left.drawn->at(VertexId(inset.vertex)), io::svg::kAnswerInk);
        ring_vertex(body, right.drawn->at(VertexId(inset.vertex)), io::svg::kAnswerInk);
    }
    body += "</g>\n";
}

// The panels' labels, the tags first, then the vertex ids, then the face
// ids; returns those that found no room.
std::vector<std::string> label_panels(LabelLayout& labels, const Panel& left, const Panel& right,
                                      const std::vector<Inset>& insets) {
    io::svg::block_drawing(labels, *left.drawn);
    io::svg::block_drawing(labels, *right.drawn);
    std::vector<std::string> left_out;
    for (const Inset& inset : insets) {
        for (const Panel* p : {&left, &right}) {
            if (!labels.place(p->drawn->at(VertexId(inset.vertex)), 10, std::string(1, inset.tag), p->area,
                              {io::svg::kAnswerInk, 13, false, "label tag"})) {
                left_out.emplace_back(1, inset.tag);
            }
        }
    }
    for (const Panel* p : {&left, &right}) {
        const auto v = io::svg::label_vertices(labels, *p->drawn, p->area);
        left_out.insert(left_out.end(), v.begin(), v.end());
    }
    const auto f = io::svg::label_faces(labels, *left.drawn, left.area);
    left_out.insert(left_out.end(), f.begin(), f.end());
    return left_out;
}

// The width of a row of (at most three) insets.
double insets_width(std::size_t insets) {
    return kPad + static_cast<double>(std::min<std::size_t>(3, insets)) * (kInsetWidth + 12);
}

// The insets in rows from y down, as many to a row as the page is wide
// (at least three); returns the y under the last row.
double paint_inset_rows(std::string& body, LabelLayout& labels, const std::vector<Inset>& insets, const Panel& right,
                        const std::vector<std::vector<Index>>& answer_cycles, double y, double page_width,
                        std::vector<std::string>& left_out) {
    const auto per_row = std::max<std::size_t>(1, static_cast<std::size_t>((page_width - kPad) / (kInsetWidth + 12)));
    double row_height = 0;
    for (std::size_t i = 0; i < insets.size(); ++i) {
        const Xy at{kPad + static_cast<double>(i % per_row) * (kInsetWidth + 12), y};
        const double h = paint_inset(body, labels, insets[i], *right.drawn, answer_cycles, at, left_out);
        row_height = std::max(row_height, h);
        if (i % per_row == per_row - 1 || i + 1 == insets.size()) {
            y += row_height + 12;
            row_height = 0;
        }
    }
    return y;
}

using Caption = std::vector<std::pair<std::string, const char*>>;  // lines and their colours

// What the two panels show, in the reference's and the answer's colours.
void explain_panels(Caption& caption, const CounterexampleDrawing& in, bool any_inset) {
    caption.emplace_back("left, " + in.reference_name + ": each bounded face tinted, id inside (f0: the unbounded face);",
                         io::svg::kReferenceInk);
    caption.emplace_back("  its half-edges as arrows on their face's side" +
                             std::string(in.answer_cycles.empty() ? "" : "; dashed: cycles the answer does not have"),
                         io::svg::kReferenceInk);
    if (!in.answer_cycles.empty()) {
        caption.emplace_back("right, " + shortened(in.answer_name, 70) + ": its cycles as arrows, in the colour of the",
                             io::svg::kAnswerInk);
        caption.emplace_back("  reference face with the same cycle, brown when the reference has no such cycle",
                             io::svg::kAnswerInk);
        caption.emplace_back("  or the answer repeats it;", io::svg::kAnswerInk);
        caption.emplace_back(any_inset
                                 ? "  thick red: its next where it differs from the reference's (the step out of the vertex)"
                                 : "  its next agrees with the reference's at every step it takes",
                             io::svg::kAnswerInk);
    }
    if (!in.answer_polygons.empty()) {
        caption.emplace_back("right: the answer's regions, tinted like the reference face they match; salmon: no match,",
                             io::svg::kAnswerInk);
        caption.emplace_back("  or a repeat of a region drawn already", io::svg::kAnswerInk);
    }
    if (any_inset) {
        caption.emplace_back("insets: the vertex's edges as a fan in their exact clockwise order (angles not to scale);",
                             io::svg::kNoteInk);
        caption.emplace_back("  black: the edge arrived along; blue: the reference's next; red: the answer's",
                             io::svg::kNoteInk);
    }
}

// The notes: wrong turns without an inset (every one of them, over as many
// lines as it takes), bent edges, the frame's notes, labels left out.
void add_notes(Caption& caption, const std::vector<Index>& uninset, const Panel& left,
               const std::vector<std::string>& left_out) {
    if (!uninset.empty()) {
        std::string line = "wrong turns also at";
        for (std::size_t i = 0; i < uninset.size(); ++i) {
            const std::string item = " " + vertex_name(uninset[i]) + (i + 1 < uninset.size() ? "," : " (no inset)");
            if (line.size() + item.size() > 100) {
                caption.emplace_back(line, io::svg::kNoteInk);
                line = " ";
            }
            line += item;
        }
        caption.emplace_back(line, io::svg::kNoteInk);
    }
    if (left.drawn->bent_edges() > 0) {
        caption.emplace_back("bent edges leave a vertex spread apart, in their exact order, where the frame would draw them",
                             io::svg::kNoteInk);
        caption.emplace_back("  in nearly one direction (every edge is a straight segment)", io::svg::kNoteInk);
    }
    for (const std::string& line : left.frame->note()) caption.emplace_back(line, io::svg::kNoteInk);
    if (!left_out.empty()) {
        std::string list;
        for (std::size_t i = 0; i < left_out.size() && i < 12; ++i) list += (i > 0 ? ", " : "") + left_out[i];
        caption.emplace_back("no room for the labels of " + list + (left_out.size() > 12 ? ", ..." : ""), io::svg::kNoteInk);
    }
}

// The caption from y down, then the coordinate table (small graphs) or a
// note on where the coordinates are; widens `width` to fit. Returns the y
// under it.
double paint_caption(std::string& body, const Caption& caption, const Dcel& d, double y, double& width) {
    for (const auto& [line, colour] : caption) {
        io::svg::text(body, {kPad, y + kLine - 4}, line, kFont, colour);
        width = std::max(width, io::svg::text_width(line, kFont) + 2 * kPad);
        y += kLine;
    }
    if (d.num_vertices() <= 40) {
        const Xy size = io::svg::coordinate_table(body, {kPad, y + 8}, d.points(), kFont);
        width = std::max(width, size.x + 2 * kPad);
        y += 8 + size.y;
    } else {
        io::svg::text(body, {kPad, y + kLine - 4}, "true coordinates: hover over a vertex", kFont);
        y += kLine;
    }
    return y;
}

}  // namespace

// Two panels side by side (the reference, the answer), the insets in rows
// under them, then the caption.
std::string render_counterexample_svg(const CounterexampleDrawing& drawing) {
    const CounterexampleDrawing& in = drawing;
    const std::string title = in.title.empty() ? "counterexample: " + in.answer_name + " against " + in.reference_name
                                               : in.title;
    if (in.reference == nullptr) return nothing_to_draw(title);
    const Dcel& d = *in.reference;
    const ReferenceCycles ref = reference_cycles(d);
    const Insets insets = collect_insets(d, in.answer_cycles);

    const io::svg::FrameKind kind = io::svg::choose_frame(d.points(), kLongest);
    const double top = 58;  // title and subtitle
    Panel left = make_panel(d, kind, {kPad, top + 18});
    Panel right = make_panel(d, kind, {left.area.right() + kGap, top + 18});

    std::string body;
    const std::string subtitle = subtitle_of(in, insets.drawn.size());
    paint_headers(body, in, title, subtitle, top, left, right);
    paint_panels(body, in, ref, left, right, insets.drawn);
    LabelLayout labels;
    std::vector<std::string> left_out = label_panels(labels, left, right, insets.drawn);
    const double width_panels = right.area.right() + kPad;
    const double width_insets = insets_width(insets.drawn.size());
    double y = paint_inset_rows(body, labels, insets.drawn, right, in.answer_cycles,
                                std::max(left.area.bottom(), right.area.bottom()) + 16, std::max(width_panels, width_insets),
                                left_out);
    labels.emit(body);

    Caption caption;
    explain_panels(caption, in, !insets.drawn.empty());
    add_notes(caption, insets.uninset, left, left_out);
    double width = std::max({width_panels, width_insets, io::svg::text_width(subtitle, kFont) + 2 * kPad,
                             io::svg::text_width(title, 14) + 2 * kPad});
    y = paint_caption(body, caption, d, y, width);
    return page(width, y + 10, title, body);
}

}  // namespace dcel::check
