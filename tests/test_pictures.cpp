// The pictures, read back from their SVG text: no two label boxes overlap and
// all lie in the picture; every vertex and face gets its label (or is named
// in the note); a counterexample has an inset for each vertex where the
// answer's next differs, and for no other, and its fan is in the exact
// order. The vertices where the answers differ come from compare_faces'
// report, a different code path from the drawing's own (check/wrong_turns).
// Each SVG is also written to DCEL_PICTURES_DIR, where the ctest
// pictures.png converts it with rsvg-convert.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/counterexample_svg.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/svg.hpp"

namespace {

using dcel::Index;

struct Rect {
    double x, y, w, h;
    std::string text;  // the label's text
};

double number(const std::string& s) { return std::stod(s); }

// Every label: its box and its text.
std::vector<Rect> labels(const std::string& svg) {
    static const std::regex label(
        R"re(<rect class="label-box" x="([-0-9.]+)" y="([-0-9.]+)" width="([0-9.]+)" height="([0-9.]+)"[^>]*/><text[^>]*>([^<]*)</text>)re");
    std::vector<Rect> out;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), label); it != std::sregex_iterator(); ++it) {
        out.push_back({number((*it)[1]), number((*it)[2]), number((*it)[3]), number((*it)[4]), (*it)[5]});
    }
    return out;
}

std::pair<double, double> canvas(const std::string& svg) {
    static const std::regex size(R"re(<svg [^>]*width="([0-9.]+)" height="([0-9.]+)")re");
    std::smatch m;
    EXPECT_TRUE(std::regex_search(svg, m, size));
    return {number(m[1]), number(m[2])};
}

// No two boxes overlap, and all are inside the picture.
void expect_legible_labels(const std::string& svg, const std::string& what) {
    const std::vector<Rect> boxes = labels(svg);
    const auto [width, height] = canvas(svg);
    ASSERT_FALSE(boxes.empty()) << what;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Rect& a = boxes[i];
        EXPECT_TRUE(a.x >= 0 && a.y >= 0 && a.x + a.w <= width && a.y + a.h <= height)
            << what << ": label " << a.text << " outside the picture";
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            const Rect& b = boxes[j];
            const bool overlap = a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
            EXPECT_FALSE(overlap) << what << ": labels " << a.text << " and " << b.text << " overlap";
        }
    }
}

std::set<Index> inset_vertices(const std::string& svg) {
    static const std::regex inset(R"re(<g class="inset" data-vertex="([0-9]+)")re");
    std::set<Index> out;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), inset); it != std::sregex_iterator(); ++it) {
        out.insert(static_cast<Index>(std::stoul((*it)[1])));
    }
    return out;
}

// Per inset vertex, how many wrong turns its text counts there (the one
// drawn and "N more wrong turns here").
std::map<Index, std::size_t> turns_per_inset(const std::string& svg) {
    static const std::regex inset(R"re(<g class="inset" data-vertex="([0-9]+)")re");
    static const std::regex more(R"re(>([0-9]+) more wrong turns? here)re");
    std::map<Index, std::size_t> out;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), inset); it != std::sregex_iterator(); ++it) {
        const auto begin = svg.begin() + (*it).position(0);
        const auto end = svg.begin() +
                         static_cast<std::ptrdiff_t>(svg.find("</g>\n<g class=\"inset\"", (*it).position(0) + 1));
        std::smatch m;
        const std::string text(begin, end > begin ? end : svg.end());
        out[static_cast<Index>(std::stoul((*it)[1]))] = 1 + (std::regex_search(text, m, more) ? std::stoul(m[1]) : 0);
    }
    return out;
}

// The vertices v of the report's wrong-next differences (it reports them in
// the cycles it cannot explain otherwise, not in reversed ones) ("at vU->vV the answer ...").
std::set<Index> wrong_next_vertices(const dcel::check::Report& report) {
    static const std::regex at(R"re(^at v[0-9]+->v([0-9]+) )re");
    std::set<Index> out;
    for (const auto& d : report.differences) {
        std::smatch m;
        if (d.kind == dcel::check::DifferenceKind::WrongNext && std::regex_search(d.message, m, at)) {
            out.insert(static_cast<Index>(std::stoul(m[1])));
        }
    }
    return out;
}

void save(const std::string& name, const std::string& svg) {
    std::ofstream(std::string(DCEL_PICTURES_DIR) + "/" + name + ".svg", std::ios::binary) << svg;
}

const char* const kHeadline =
    R"({"vertices": [[268947842, 268947843], [268947845, 268947846], [-0, -1], [0, 0], [-1, -0]], "edges": [[4, 3], [3, 0], [1, 3], [2, 3]]})";

TEST(Pictures, HeadlineCounterexample) {
    const dcel::PlanarGraph g = dcel::io::read_graph(kHeadline);
    const dcel::Dcel d = dcel::build(g);
    const std::vector<std::vector<Index>> answer = {{4, 3, 1, 3, 0, 3, 2, 3}};  // the atan2 bug's answer
    dcel::check::CounterexampleDrawing drawing{&g, &d};
    drawing.answer_cycles = answer;
    drawing.answer_name = "the command: DCEL_EXAMPLE_BUG=atan2 examples/python/dcel_faces.py";
    drawing.title = "dcel diff: wrong answer (wrong-next), case 129, seed 1";
    const std::string svg = dcel::check::render_counterexample_svg(drawing);
    save("headline-counterexample", svg);
    expect_legible_labels(svg, "headline");
    const std::set<Index> expected = wrong_next_vertices(dcel::check::compare_faces(d, answer));
    EXPECT_EQ(expected, std::set<Index>{3});
    EXPECT_EQ(inset_vertices(svg), expected);
    // Three wrong turns at v3, by hand: the answer goes 4 -> 1, 1 -> 0, 0 -> 2
    // where the reference goes 4 -> 0, 1 -> 2, 0 -> 1 (2 -> 4 agrees); the
    // report lists the same three.
    EXPECT_EQ(turns_per_inset(svg), (std::map<Index, std::size_t>{{3, 3}}));
    EXPECT_EQ(dcel::check::compare_faces(d, answer).differences.size(), 5U);  // 3 wrong-next, a missing and an extra cycle
    // Both names are in the picture.
    EXPECT_NE(svg.find(">the reference (dcel)</text>"), std::string::npos);
    EXPECT_NE(svg.find("the command: DCEL_EXAMPLE_BUG=atan2"), std::string::npos);

    // The fan at v3 in the exact clockwise order. By hand: v4 = (-1, 0) is
    // west, v2 = (0, -1) south, and v0, v1 both north-east, with slopes
    // 268947843/268947842 > 268947846/268947845, so v0 is counterclockwise of
    // v1: clockwise from v4 the order is v0, v1, v2.
    const std::size_t inset = svg.find("<g class=\"inset\"");
    const std::string fan = svg.substr(inset);
    static const std::regex centre(R"re(<circle cx="([0-9.]+)" cy="([0-9.]+)" r="3.2")re");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(fan, m, centre));
    const double cx = number(m[1]), cy = number(m[2]);
    std::map<std::string, double> angle;  // of each spoke label around the centre, y up
    for (const Rect& r : labels(fan)) {
        if (r.text.starts_with("v")) angle[r.text] = std::atan2(-(r.y + r.h / 2 - cy), r.x + r.w / 2 - cx);
    }
    ASSERT_EQ(angle.size(), 4U);
    const auto clockwise_from = [&](const std::string& a, const std::string& b) {
        double t = std::fmod(angle[a] - angle[b], 2 * std::numbers::pi);
        return t < 0 ? t + 2 * std::numbers::pi : t;
    };
    EXPECT_LT(clockwise_from("v4", "v0"), clockwise_from("v4", "v1"));
    EXPECT_LT(clockwise_from("v4", "v1"), clockwise_from("v4", "v2"));
}

// An answer with the counterclockwise neighbour at the given vertices (the
// reference's next elsewhere), as vertex cycles.
std::vector<std::vector<Index>> turned_answer(const dcel::Dcel& d, const std::set<Index>& at) {
    std::vector<Index> next(d.num_half_edges());
    for (Index h = 0; h < d.num_half_edges(); ++h) {
        const dcel::HalfEdgeId he(h);
        next[h] = d.next(he).index();
        if (at.count(d.target(he).index()) != 0) {
            // The half-edge leaving the target just counterclockwise of the twin.
            std::vector<dcel::HalfEdgeId> around;
            for (const dcel::HalfEdgeId x : d.around_origin_ccw(dcel::Dcel::twin(he))) around.push_back(x);
            next[h] = around.size() > 1 ? around[1].index() : dcel::Dcel::twin(he).index();
        }
    }
    std::vector<std::vector<Index>> out;
    std::vector<char> seen(next.size(), 0);
    for (Index h = 0; h < next.size(); ++h) {
        if (seen[h] != 0) continue;
        auto& c = out.emplace_back();
        for (Index x = h; seen[x] == 0; x = next[x]) {
            seen[x] = 1;
            c.push_back(d.origin(dcel::HalfEdgeId(x)).index());
        }
    }
    return out;
}

TEST(Pictures, GeneratedCounterexamples) {
    for (const std::uint64_t seed : {1, 2, 3, 8}) {
        const dcel::PlanarGraph g = dcel::gen::generate({dcel::gen::Family::NearDegenerate, seed, 30});
        const dcel::Dcel d = dcel::build(g);
        // Wrong turns at every vertex of degree 3 or more (where the two
        // neighbours differ).
        std::set<Index> at;
        for (Index v = 0; v < d.num_vertices(); ++v) {
            std::size_t degree = 0;
            for (const dcel::HalfEdgeId h : d.around_origin_cw(d.out(dcel::VertexId(v)))) degree += h.is_null() ? 0 : 1;
            if (degree >= 3) at.insert(v);
        }
        const auto answer = turned_answer(d, at);
        dcel::check::CounterexampleDrawing drawing{&g, &d};
        drawing.answer_cycles = answer;
        drawing.answer_name = "turned at every vertex of degree 3 or more";
        const std::string svg = dcel::check::render_counterexample_svg(drawing);
        const std::string name = "near-degenerate-" + std::to_string(seed) + "-counterexample";
        save(name, svg);
        expect_legible_labels(svg, name);
        // Turning counterclockwise differs from the rule exactly where there
        // are 3 edges or more: the wrong turns are at `at`, by construction.
        const std::set<Index>& wrong = at;
        ASSERT_FALSE(dcel::check::compare_faces(d, answer).agrees()) << name;
        const std::set<Index> insets = inset_vertices(svg);
        EXPECT_EQ(insets.size(), std::min<std::size_t>(6, wrong.size())) << name;
        for (const Index v : insets) EXPECT_EQ(wrong.count(v), 1U) << name << ": an inset at v" << v;
        // At a turned vertex every edge arriving there turns wrong: as many
        // wrong turns as the vertex has edges.
        for (const auto& [v, turns] : turns_per_inset(svg)) {
            std::size_t degree = 0;
            for (const dcel::HalfEdgeId h : d.around_origin_cw(d.out(dcel::VertexId(v)))) degree += h.is_null() ? 0 : 1;
            EXPECT_EQ(turns, degree) << name << ": v" << v;
        }
        // The others are named in the note (which may run over several lines).
        std::string text;
        static const std::regex line(R"re(<text[^>]*>([^<]*)</text>)re");
        for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it) {
            text += (*it)[1].str() + " ";
        }
        const std::size_t note = text.find("wrong turns also at");
        ASSERT_EQ(note == std::string::npos, wrong.size() <= 6) << name;
        const std::string named = note == std::string::npos ? "" : text.substr(note, text.find("(no inset)", note) - note);
        for (const Index v : wrong) {
            if (insets.count(v) != 0) continue;
            EXPECT_TRUE(std::regex_search(named, std::regex("\\bv" + std::to_string(v) + "\\b"))) << name << ": v" << v;
        }
    }
}

// Every vertex id and every face id is labelled, or named in the note.
void expect_all_labelled(const std::string& svg, const dcel::Dcel& d, const std::string& what) {
    std::set<std::string> texts;
    for (const Rect& r : labels(svg)) texts.insert(r.text);
    const std::size_t note = svg.find("no room for the labels of");
    const std::string left_out = note == std::string::npos ? "" : svg.substr(note, svg.find('<', note) - note);
    for (Index v = 0; v < d.num_vertices(); ++v) {
        const std::string id = std::to_string(v);
        EXPECT_TRUE(texts.count(id) != 0 || std::regex_search(left_out, std::regex("\\bv" + id + "\\b")))
            << what << ": v" << id;
    }
    for (Index f = 0; f < d.num_faces(); ++f) {
        const std::string id = "f" + std::to_string(f);
        EXPECT_TRUE(texts.count(id) != 0 || std::regex_search(left_out, std::regex("\\b" + id + "\\b")))
            << what << ": " << id;
    }
}

TEST(Pictures, NearDegenerateRenders) {
    for (const std::uint64_t seed : {1, 2, 3, 5, 7, 8}) {
        const dcel::PlanarGraph g = dcel::gen::generate({dcel::gen::Family::NearDegenerate, seed, 30});
        const dcel::Dcel d = dcel::build(g);
        dcel::io::SvgOptions options;
        options.title = "dcel gen --family near-degenerate --vertices 30 --seed " + std::to_string(seed);
        const std::string svg = dcel::io::render_svg(d, options);
        const std::string name = "near-degenerate-" + std::to_string(seed);
        save(name, svg);
        expect_legible_labels(svg, name);
        expect_all_labelled(svg, d, name);
        // Whatever the frame (points that differ in the last place collapse
        // in the exact one), no two vertices are drawn within 6 px.
        static const std::regex dot(R"re(<circle cx="([-0-9.]+)" cy="([-0-9.]+)" r="[0-9.]+" fill)re");
        std::vector<std::pair<double, double>> at;
        for (auto it = std::sregex_iterator(svg.begin(), svg.end(), dot); it != std::sregex_iterator(); ++it) {
            at.emplace_back(number((*it)[1]), number((*it)[2]));
        }
        ASSERT_EQ(at.size(), d.num_vertices()) << name;
        for (std::size_t i = 0; i < at.size(); ++i) {
            for (std::size_t j = i + 1; j < at.size(); ++j) {
                EXPECT_GE(std::hypot(at[i].first - at[j].first, at[i].second - at[j].second), 6.0)
                    << name << ": v" << i << " and v" << j;
            }
        }
    }
}

TEST(Pictures, FramesAndNotes) {
    const dcel::PlanarGraph g = dcel::io::read_graph(kHeadline);
    const dcel::Dcel d = dcel::build(g);
    dcel::io::SvgOptions exact;
    exact.frame = dcel::io::SvgFrame::Exact;
    const std::string svg = dcel::io::render_svg(d, exact);
    // The exact frame says its scale; v2, v3, v4 fall within a pixel of each
    // other there, so auto chooses the normalised frame.
    // The span, 268947846 - (-1), over 640 px: 100 px = 42023101.1 units.
    EXPECT_NE(svg.find("exact frame: one scale on both axes, 100 px = 4.2e+07 units"), std::string::npos);
    EXPECT_NE(dcel::io::render_svg(d).find("normalised frame"), std::string::npos);
    // The true coordinates: a table for a small graph, a tooltip on each dot.
    EXPECT_NE(svg.find("true coordinates"), std::string::npos);
    EXPECT_NE(svg.find("<title>v0 (268947842, 268947843)</title>"), std::string::npos);
    EXPECT_NE(svg.find("<title>v4 (-1, -0)</title>"), std::string::npos);
}

}  // namespace

namespace {

// A square with a triangle inside it (a hole) and an isolated vertex:
// faces f1 (the square, holed) and f2 (the triangle).
const char* const kSquareHole =
    R"({"vertices": [[0, 0], [10, 0], [10, 10], [0, 10], [3, 3], [7, 3], [5, 7], [8, 8]],
        "edges": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 4]]})";

TEST(Pictures, RegionsAndOddAnswers) {
    const dcel::PlanarGraph g = dcel::io::read_graph(kSquareHole);
    const dcel::Dcel d = dcel::build(g);
    // Regions: the holed square (its hole listed the other way round and from
    // another vertex) and the triangle match; a triangle 0, 1, 2 does not,
    // and the triangle listed again from another vertex is a repeat.
    dcel::check::CounterexampleDrawing regions{&g, &d};
    regions.answer_polygons = {{{0, 1, 2, 3}, {4, 6, 5}}, {{6, 4, 5}}, {{0, 1, 2}}, {{5, 6, 4}}};
    const std::string svg = dcel::check::render_counterexample_svg(regions);
    save("regions", svg);
    expect_legible_labels(svg, "regions");
    const auto count = [](const std::string& text, const std::string& what) {
        std::size_t n = 0;
        for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
        return n;
    };
    const std::size_t matched = count(svg, "class=\"answer-region\" ");
    const std::size_t unmatched = count(svg, "class=\"answer-region extra\"");
    EXPECT_EQ(matched, 2U);
    EXPECT_EQ(unmatched, 2U);
    EXPECT_NE(svg.find("or a repeat of a region drawn already"), std::string::npos);
    EXPECT_TRUE(inset_vertices(svg).empty());

    // Cycles: the square's outer cycle twice (from another vertex the second
    // time): its four steps in face colour once, then brown.
    dcel::check::CounterexampleDrawing twice{&g, &d};
    twice.answer_cycles = {{0, 1, 2, 3}, {2, 3, 0, 1}};
    const std::string twice_svg = dcel::check::render_counterexample_svg(twice);
    EXPECT_EQ(count(twice_svg, "class=\"answer-step\""), 4U);
    EXPECT_EQ(count(twice_svg, "class=\"answer-step extra\""), 4U);
    EXPECT_NE(twice_svg.find("or the answer repeats it"), std::string::npos);

    // A cycle that arrives at v1 along 0 -> 1 and leaves for v6, which is no
    // neighbour of v1: the inset at v1 says so (the reference goes on to v2).
    dcel::check::CounterexampleDrawing odd{&g, &d};
    odd.answer_cycles = {{0, 1, 6}};
    const std::string odd_svg = dcel::check::render_counterexample_svg(odd);
    save("not-a-neighbour", odd_svg);
    expect_legible_labels(odd_svg, "not-a-neighbour");
    EXPECT_EQ(inset_vertices(odd_svg), std::set<Index>{1});
    EXPECT_NE(odd_svg.find("the reference goes on to v2 (next clockwise)"), std::string::npos);
    EXPECT_NE(odd_svg.find("the answer goes on to v6 (not a neighbour)"), std::string::npos);

    // Nothing to draw: said, not crashed.
    const std::string empty = dcel::check::render_counterexample_svg({});
    EXPECT_NE(empty.find("nothing to draw: no reference DCEL was given"), std::string::npos);
}

}  // namespace

namespace {

// render_svg's highlighted cycles (the Python binding's svg(highlight=...)):
// one red arrow per step, drawn along the edge where the step is one and
// dashed straight across where it is not; steps naming a vertex the graph
// does not have are skipped.
TEST(Pictures, HighlightedCycles) {
    const dcel::Dcel d = dcel::build(dcel::io::read_graph(kSquareHole));
    dcel::io::SvgOptions options;
    // The square (4 edges), v4 -> v7 -> v4 (no edge: 2 dashed steps), and a
    // cycle through v99 whose two steps are skipped.
    options.highlight_cycles = {{0, 1, 2, 3}, {4, 7}, {99, 0}};
    const std::string svg = dcel::io::render_svg(d, options);
    const std::size_t group = svg.find("<g id=\"highlight\"");
    ASSERT_NE(group, std::string::npos);
    const std::string highlighted = svg.substr(group, svg.find("</g>\n</g>", group) - group);
    std::size_t arrows = 0, dashed = 0;
    for (std::size_t at = highlighted.find("<g class=\"highlight\">"); at != std::string::npos;
         at = highlighted.find("<g class=\"highlight\">", at + 1)) {
        ++arrows;
        const std::string one = highlighted.substr(at, highlighted.find("</g>", at) - at);
        if (one.find("stroke-dasharray") != std::string::npos) ++dashed;
    }
    EXPECT_EQ(arrows, 6U);
    EXPECT_EQ(dashed, 2U);
    EXPECT_NE(svg.find("red: highlighted cycles"), std::string::npos);
    EXPECT_EQ(dcel::io::render_svg(d).find("highlight"), std::string::npos);
}

}  // namespace
