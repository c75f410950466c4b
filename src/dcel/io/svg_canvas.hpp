// SVG drawing primitives shared by the pictures (io/svg.cpp for `dcel
// render`, check/counterexample_svg.cpp for counterexamples): numbers and
// escaping, colours, polylines drawn as arrows beside their line, and a label
// layout that never lets two labels overlap. Internal; screen coordinates
// (y grows downwards) in px.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "dcel/ids.hpp"

namespace dcel::io::svg {

struct Xy {
    double x = 0;
    double y = 0;
};

struct Box {
    double x = 0;
    double y = 0;
    double w = 0;
    double h = 0;
    [[nodiscard]] double right() const { return x + w; }
    [[nodiscard]] double bottom() const { return y + h; }
    [[nodiscard]] Xy centre() const { return {x + w / 2, y + h / 2}; }
    [[nodiscard]] bool overlaps(const Box& o) const {
        return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
    }
    [[nodiscard]] bool contains(const Box& o) const {
        return o.x >= x && o.y >= y && o.right() <= right() && o.bottom() <= bottom();
    }
    [[nodiscard]] bool contains(Xy p) const { return p.x >= x && p.y >= y && p.x <= right() && p.y <= bottom(); }
};

// Numbers with two decimals (px); XML text and attribute escaping.
[[nodiscard]] std::string num(double v);
[[nodiscard]] std::string escape(std::string_view s);
// A double in its shortest round-trip form ("-0", "1e-300", "268947842").
[[nodiscard]] std::string exact_number(double v);

// Colours: each face its tint (fill) and ink (arrows, labels), the unbounded
// face grey; the reference's and the answer's marks.
[[nodiscard]] std::string face_fill(Index f);
[[nodiscard]] std::string face_ink(Index f);
inline constexpr const char* kAnswerInk = "#d7191c";     // the answer where it differs: red
inline constexpr const char* kReferenceInk = "#2166ac";  // the reference's choice: blue (red and blue
                                                         // stay apart for colour-blind readers)
inline constexpr const char* kNoteInk = "#303030";

// Text metrics of the label and note fonts: monospace, so a box computed
// from the character count holds the text in any renderer.
inline constexpr const char* kMonoFont = "DejaVu Sans Mono, Menlo, Consolas, monospace";
inline constexpr double kCharWidth = 0.61;  // DejaVu Sans Mono's advance, per em (0.602), and a little room
[[nodiscard]] inline double text_width(std::string_view text, double font) {
    return static_cast<double>(text.size()) * kCharWidth * font;
}

// A line of text at (x, baseline y) in the monospace font.
void text(std::string& out, Xy at, std::string_view s, double font, const char* colour = kNoteInk,
          const char* anchor = "start", bool bold = false);

using Polyline = std::vector<Xy>;

[[nodiscard]] double length(const Polyline& line);
// The polyline moved `d` px to its left as seen in the plane (y up).
[[nodiscard]] Polyline offset_left(const Polyline& line, double d);
// The polyline without its first `start` and last `end` px (empty if nothing is left).
[[nodiscard]] Polyline trimmed(const Polyline& line, double start, double end);
// "M x y L x y ..." for a path's d attribute.
[[nodiscard]] std::string path_data(const Polyline& line, bool closed = false);

struct ArrowStyle {
    std::string colour;
    double width = 1.3;
    double offset = 4.5;    // px to the left of the line
    std::string dash;       // stroke-dasharray, e.g. "4 3"; empty: solid
    std::string css_class;  // class attribute, for tests and readers
};
// An arrow along the line, beside it (offset) and shortened at both ends so
// that arrows meeting at a vertex stay apart, with its head at the end.
void arrow(std::string& out, const Polyline& line, const ArrowStyle& style);

// Where labels go. Each label is a box with a white background and its text;
// place() never returns a box that overlaps another label's box or a
// blocked box, and keeps it inside the allowed area.
class LabelLayout {
public:
    struct Style {
        std::string colour = "#000000";
        double font = 11;
        bool italic = false;
        std::string css_class = "label";
    };

    // Something a label must not cover (a vertex dot, a legend).
    void block(const Box& b);
    // A line labels should rather not cover (counted, not forbidden).
    void add_line(Xy a, Xy b);

    // Tries, in order, boxes centred on `centres` (e.g. points deep inside a
    // face), then rings of growing radius around `anchor`, preferring spots
    // that cover fewer lines; a leader line joins the box to the anchor when
    // it ends more than a few px away. nullopt when no spot within reach is
    // free (the caller says so in a note).
    std::optional<Box> place(Xy anchor, double clearance, std::string_view label, const Box& allowed, const Style& style,
                             const std::vector<Xy>& centres = {});

    [[nodiscard]] Box box_for(Xy centre, std::string_view label, double font) const;
    void emit(std::string& out) const;

private:
    struct Placed {
        Box box;
        std::string text;
        Style style;
        std::optional<Xy> leader_to;
    };
    [[nodiscard]] bool free(const Box& b) const;
    [[nodiscard]] int lines_covered(const Box& b) const;
    void remember(const Box& b, std::size_t id);
    [[nodiscard]] std::vector<std::size_t> near(const Box& b,
                                                const std::unordered_map<long long, std::vector<std::size_t>>& grid) const;

    static constexpr double kCell = 40;
    std::vector<Box> boxes_;  // placed labels and blocked boxes
    std::unordered_map<long long, std::vector<std::size_t>> box_grid_;
    std::vector<std::pair<Xy, Xy>> lines_;
    std::unordered_map<long long, std::vector<std::size_t>> line_grid_;
    std::vector<Placed> placed_;
};

}  // namespace dcel::io::svg
