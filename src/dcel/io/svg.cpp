#include "dcel/io/svg.hpp"

#include <algorithm>

#include "dcel/io/svg_canvas.hpp"
#include "dcel/io/svg_drawing.hpp"
#include "dcel/io/svg_frame.hpp"

namespace dcel::io {
namespace {

using svg::Box;
using svg::Xy;

constexpr double kLongest = 640;  // px along the longer side of the drawing
constexpr double kMargin = 44;    // around the drawing: room for labels
constexpr double kPad = 12;
constexpr double kLine = 15;  // caption line height
constexpr double kFont = 11;

std::string count(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

svg::FrameKind frame_kind(const std::vector<Point>& points, SvgFrame f) {
    if (f == SvgFrame::Exact) return svg::FrameKind::Exact;
    if (f == SvgFrame::Normalised) return svg::FrameKind::Normalised;
    return svg::choose_frame(points, kLongest);
}

// The vertices' points, then the marks' (each mark's a, then its b): the
// frame places them all, so a mark outside the drawing widens it.
std::vector<Point> framed_points(const Dcel& d, const std::vector<SvgMark>& marks) {
    std::vector<Point> points = d.points();
    for (const SvgMark& m : marks) {
        points.push_back(m.a);
        if (m.b) points.push_back(*m.b);
    }
    return points;
}

// The marks in red, their labels placed with the others'.
void draw_marks(std::string& out, svg::LabelLayout& labels, const svg::Frame& frame, std::size_t first,
                const std::vector<SvgMark>& marks, const Box& panel) {
    if (marks.empty()) return;
    out += "<g id=\"marks\">\n";
    std::size_t i = first;
    for (const SvgMark& m : marks) {
        const Xy a = frame.at(i++);
        Xy where = a;
        if (m.b) {
            const Xy b = frame.at(i++);
            svg::arrow(out, {a, b}, {svg::kAnswerInk, 2.2, 0, "6 3", "mark"});
            where = {(a.x + b.x) / 2, (a.y + b.y) / 2};
        } else {
            out += "<circle class=\"mark\" cx=\"" + svg::num(a.x) + "\" cy=\"" + svg::num(a.y) +
                   "\" r=\"6\" fill=\"none\" stroke=\"" + svg::kAnswerInk + "\" stroke-width=\"2\"/>\n";
        }
        if (!m.label.empty()) (void)labels.place(where, 8, m.label, panel, {svg::kAnswerInk, 11, false, "label mark-label"});
    }
    out += "</g>\n";
}

void draw_highlights(std::string& out, const svg::DrawnDcel& g, const std::vector<std::vector<Index>>& cycles) {
    if (cycles.empty()) return;
    const svg::StepLines steps(g);
    out += "<g id=\"highlight\" opacity=\"0.9\">\n";
    for (const auto& cycle : cycles) {
        for (std::size_t i = 0; i < cycle.size(); ++i) {
            const auto step = steps(cycle[i], cycle[(i + 1) % cycle.size()]);
            if (!step) continue;
            svg::arrow(out, step->line, {svg::kAnswerInk, 2.6, 9, step->along_edge ? "" : "5 3", "highlight"});
        }
    }
    out += "</g>\n";
}

// The drawing, then its labels (vertex ids, and face ids unless turned
// off); returns the labels that found no room.
std::vector<std::string> paint_drawing(std::string& body, const svg::DrawnDcel& g, const svg::Frame& frame, const Box& panel,
                                       const SvgOptions& options) {
    svg::paint_faces(body, g);
    svg::paint_edges(body, g);
    svg::paint_half_edges(body, g, svg::by_face_colour(g));
    draw_highlights(body, g, options.highlight_cycles);
    svg::paint_vertices(body, g);

    svg::LabelLayout labels;
    svg::block_drawing(labels, g);
    std::vector<std::string> left_out = svg::label_vertices(labels, g, panel, options.vertex_names);
    draw_marks(body, labels, frame, g.dcel().num_vertices(), options.marks, panel);
    if (options.face_ids) {
        const auto faces = svg::label_faces(labels, g, panel);
        left_out.insert(left_out.end(), faces.begin(), faces.end());
    }
    labels.emit(body);
    return left_out;
}

// The caption: the counts, what the marks mean, bent edges, the frame's
// notes, where the coordinates are, and the labels left out.
std::vector<std::string> caption_of(const svg::DrawnDcel& g, const svg::Frame& frame, const SvgOptions& options, bool table,
                                    const std::vector<std::string>& left_out) {
    const Dcel& dcel = g.dcel();
    std::vector<std::string> caption;
    caption.push_back(count(dcel.num_vertices(), "vertex", "vertices") + ", " + count(dcel.num_edges(), "edge", "edges") +
                      ", " + count(dcel.num_faces() - 1, "bounded face", "bounded faces") +
                      (options.face_ids ? " (tinted, ids inside; f0 is the unbounded face)" : " (tinted)"));
    caption.emplace_back("arrows: half-edges, on the side of their face; rings: isolated vertices" +
                         std::string(options.highlight_cycles.empty() ? "" : "; red: highlighted cycles"));
    if (!options.marks.empty()) caption.push_back("red: " + options.marks_caption);
    if (g.bent_edges() > 0) {
        caption.push_back(count(g.bent_edges(), "edge is", "edges are") +
                          " drawn bent: where the frame would draw edges of a vertex in nearly one");
        caption.emplace_back(
            "  direction, they leave it spread apart in their exact order (each edge is a straight segment)");
    }
    for (const std::string& line : frame.note()) caption.push_back(line);
    if (!table) caption.emplace_back("true coordinates: hover over a vertex");
    if (!left_out.empty()) {
        std::string list;
        for (std::size_t i = 0; i < left_out.size() && i < 12; ++i) list += (i > 0 ? ", " : "") + left_out[i];
        if (left_out.size() > 12) list += ", and " + std::to_string(left_out.size() - 12) + " more";
        caption.push_back("no room for the labels of " + list);
    }
    return caption;
}

// The whole document: the body (drawing and table), then the title and the
// caption from caption_top down.
std::string page(double width, double height, const std::string& title, const std::string& body,
                 const std::vector<std::string>& caption, double caption_top) {
    std::string out;
    out.reserve(body.size() + 4096);
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + svg::num(width) + "\" height=\"" + svg::num(height) +
           "\" viewBox=\"0 0 " + svg::num(width) + " " + svg::num(height) + "\">\n";
    out += "<title>" + svg::escape(title) + "</title>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    out += body;
    out += "<g id=\"caption\" font-family=\"" + std::string(svg::kMonoFont) + "\">\n";
    if (!title.empty()) svg::text(out, {kPad, 22}, title, 14, svg::kNoteInk, "start", true);
    for (std::size_t i = 0; i < caption.size(); ++i) {
        svg::text(out, {kPad, caption_top + kLine * static_cast<double>(i + 1) - 4}, caption[i], kFont);
    }
    out += "</g>\n</svg>\n";
    return out;
}

}  // namespace

// The drawing in a panel, the coordinate table beside it (small graphs),
// the caption under both.
std::string render_svg(const Dcel& dcel, const SvgOptions& options) {
    const std::vector<Point> points = framed_points(dcel, options.marks);
    svg::Frame frame(points, frame_kind(points, options.frame));
    const Xy size = frame.size(kLongest);
    const double top = options.title.empty() ? kPad : 36;
    const Box panel{kPad, top, size.x + 2 * kMargin, size.y + 2 * kMargin};
    frame.place({panel.x + kMargin, panel.y + kMargin, size.x, size.y});
    const svg::DrawnDcel g(dcel, frame);

    std::string body;
    const std::vector<std::string> left_out = paint_drawing(body, g, frame, panel, options);
    const bool table = dcel.num_vertices() > 0 && dcel.num_vertices() <= options.max_table_vertices;
    Xy table_size{0, 0};
    if (table)
        table_size = svg::coordinate_table(body, {panel.right() + 16, panel.y + 8}, dcel.points(), kFont,
                                           options.vertex_names);
    const std::vector<std::string> caption = caption_of(g, frame, options, table, left_out);

    double width = std::max(panel.right() + (table ? 16 + table_size.x : 0) + kPad, 420.0);
    for (const std::string& line : caption) width = std::max(width, svg::text_width(line, kFont) + 2 * kPad);
    const double caption_top = std::max(panel.bottom(), panel.y + 8 + table_size.y) + 10;
    const double height = caption_top + static_cast<double>(caption.size()) * kLine + 8;
    return page(width, height, options.title, body, caption, caption_top);
}

}  // namespace dcel::io
