// compare(): an answer of any kind against the reference, under the
// conventions, with notes on what was assumed and on conventions that would
// make the answer agree.
#include "dcel/check/answer.hpp"

#include <algorithm>
#include <string>

#include "dcel/check/collector.hpp"
#include "dcel/check/cycles.hpp"
#include "dcel/format.hpp"

namespace dcel::check {

namespace {

// Faces: a repeated first vertex dropped, 1-based ids shifted, cycles
// reversed for faces on the right; then matched like compare_faces.
bool needs_rewriting(const CycleList& answer, const Conventions& c) {
    if (c.one_based || c.face_on_right || c.isolated_cycles) return true;
    for (std::size_t i = 0; i < answer.size(); ++i) {
        const std::span<const Index> cycle = answer[i];
        if (cycle.size() >= 2 && cycle.front() == cycle.back()) return true;
    }
    return false;
}

// --isolated-as-cycles: the one-vertex cycles [v] of the answer are exactly
// the isolated vertices, each once.
void match_isolated(const Dcel& reference, const std::vector<std::pair<Index, std::size_t>>& singles,
                    detail::Collector& out) {
    const Index n = reference.num_vertices();
    std::vector<char> listed(n, 0);
    for (const auto& [v, i] : singles) {
        const std::string cycle = "answer cycle " + std::to_string(i) + " [" + std::to_string(v) + "]";
        if (v >= n) {
            if (out.wants(DifferenceKind::VertexCount)) {
                out.add(DifferenceKind::VertexCount, cycle + " names vertex " + std::to_string(v) + ", but the graph has " +
                                                         std::to_string(n) + " vertices");
            }
        } else if (!reference.out(VertexId(v)).is_null()) {
            if (out.wants(DifferenceKind::WrongIsolatedVertex)) {
                out.add(DifferenceKind::WrongIsolatedVertex,
                        cycle + " is a one-vertex cycle, but v" + std::to_string(v) +
                            " has edges: only an isolated vertex is written so (--isolated-as-cycles)",
                        {v});
            }
        } else if (listed[v]++ != 0 && out.wants(DifferenceKind::WrongIsolatedVertex)) {
            out.add(DifferenceKind::WrongIsolatedVertex,
                    cycle + " lists the isolated vertex v" + std::to_string(v) + " again", {v});
        }
    }
    for (Index v = 0; v < n; ++v) {
        if (listed[v] != 0 || !reference.out(VertexId(v)).is_null()) continue;
        if (out.wants(DifferenceKind::WrongIsolatedVertex)) {
            out.add(DifferenceKind::WrongIsolatedVertex,
                    "the isolated vertex v" + std::to_string(v) + " " + format_point(reference.point(VertexId(v))) +
                        " has no one-vertex cycle [" + std::to_string(v) + "] in the answer (--isolated-as-cycles)",
                    {v});
        }
    }
}

Report compare_cycles(const Dcel& reference, const CycleList& answer, const Conventions& c) {
    detail::Collector out;
    if (!needs_rewriting(answer, c)) {
        // As given: no copy (an answer may hold millions of cycles).
        const detail::Reference ref(reference);
        (void)detail::match_cycles(ref, detail::AnswerCycles{&answer, {}}, out);
        return std::move(out).finish();
    }
    CycleList list;
    std::vector<std::size_t> numbering;
    std::vector<std::pair<Index, std::size_t>> singles;  // --isolated-as-cycles: (vertex, answer cycle)
    std::size_t closed = 0;
    for (std::size_t i = 0; i < answer.size(); ++i) {
        const std::span<const Index> given = answer[i];
        std::vector<Index> vs(given.begin(), given.end());
        if (c.one_based && std::find(vs.begin(), vs.end(), Index{0}) != vs.end()) {
            if (out.wants(DifferenceKind::VertexCount)) {
                out.add(DifferenceKind::VertexCount, "answer cycle " + std::to_string(i) + " " + detail::cycle_text(vs) +
                                                         " names vertex 0, but with --one-based ids count from 1");
            }
            continue;
        }
        if (c.one_based) {
            for (Index& v : vs) --v;
        }
        if (vs.size() >= 2 && vs.front() == vs.back()) {  // open, a cycle never steps from a vertex to itself
            vs.pop_back();
            ++closed;
        }
        if (c.isolated_cycles && vs.size() == 1) {  // an isolated vertex, written as its own cycle
            singles.push_back({vs.front(), i});
            continue;
        }
        if (c.face_on_right && !vs.empty()) std::reverse(vs.begin() + 1, vs.end());
        list.ids.insert(list.ids.end(), vs.begin(), vs.end());
        list.end_cycle();
        numbering.push_back(i);
    }
    const detail::Reference ref(reference);
    detail::AnswerCycles labels{&list, {}, &numbering};
    (void)detail::match_cycles(ref, labels, out);
    if (c.isolated_cycles) match_isolated(reference, singles, out);
    Report report = std::move(out).finish();
    if (closed != 0) {
        report.notes.push_back(std::to_string(closed) + (closed == 1 ? " cycle repeats its" : " cycles repeat their") +
                               " first vertex at the end: read as closed");
    }
    if (c.one_based) report.notes.push_back("ids read as counting from 1 (--one-based); messages count from 0");
    if (c.face_on_right) {
        report.notes.push_back("cycles read with faces on the right (--face-on right); messages show them reversed");
    }
    return report;
}

// A dump under the conventions, rewritten into the reference's: ids from 0
// (a 0 in a 1-based dump is its null), faces on the left.
DcelDump normalised(const DcelDump& in, const Conventions& c) {
    DcelDump d = in;
    if (c.one_based) {
        auto shift = [](auto& id) {
            using Id = std::decay_t<decltype(id)>;
            id = id.is_null() || id.index() == 0 ? Id() : Id(id.index() - 1);
        };
        for (HalfEdgeId& h : d.vertex_out) shift(h);
        for (HalfEdgeRecord& r : d.half_edges) {
            shift(r.origin);
            shift(r.twin);
            shift(r.next);
            shift(r.prev);
            shift(r.face);
        }
        for (FaceDump& f : d.faces) {
            shift(f.outer);
            for (HalfEdgeId& h : f.inner) shift(h);
            for (VertexId& v : f.isolated) shift(v);
        }
    }
    if (c.face_on_right) {
        // Each half-edge turned around: it starts where its twin starts, and
        // the cycles run backwards (next and prev swap); every face keeps its
        // half-edges. Left as is where a twin is out of range (validation
        // reports that).
        const std::size_t n = d.half_edges.size();
        auto twin_of = [&](HalfEdgeId h) { return h.index() < n ? d.half_edges[h.index()].twin : HalfEdgeId(); };
        std::vector<HalfEdgeRecord> turned = d.half_edges;
        for (std::size_t h = 0; h < n; ++h) {
            const HalfEdgeId t = d.half_edges[h].twin;
            if (t.index() < n) turned[h].origin = d.half_edges[t.index()].origin;
            std::swap(turned[h].next, turned[h].prev);
        }
        d.half_edges = std::move(turned);
        for (HalfEdgeId& h : d.vertex_out) {
            if (const HalfEdgeId t = twin_of(h); !t.is_null()) h = t;
        }
    }
    return d;
}

Report compare_under(const Dcel& reference, const Answer& a, const Conventions& c) {
    switch (a.kind) {
        case AnswerKind::Faces: return compare_cycles(reference, a.cycles, c);
        case AnswerKind::Dump: {
            Report r = compare_dump(reference, c.one_based || c.face_on_right ? normalised(a.dump, c) : a.dump);
            if (c.one_based) r.notes.push_back("ids read as counting from 1 (--one-based); messages count from 0");
            if (c.face_on_right) r.notes.push_back("half-edges read with faces on the right (--face-on right)");
            return r;
        }
        case AnswerKind::Polygons: return compare_polygons(reference, a.regions, c);
        case AnswerKind::Rings: return compare_rings(reference, a.regions, c);
        case AnswerKind::EvenOdd: return compare_even_odd(reference, a.regions, c);
    }
    return {};
}

}  // namespace

std::optional<std::string> convention_hint(const Dcel& reference, const Answer& a, const Conventions& c) {
    struct Toggle {
        bool applies = false;
        Conventions conventions;
        const char* note = "";
    };
    Conventions right = c, based = c, loose = c, singles = c, unattached = c;
    right.face_on_right = !c.face_on_right;
    based.one_based = !c.one_based;
    loose.unoriented = true;
    singles.isolated_cycles = !c.isolated_cycles;
    unattached.holes_unattached = !c.holes_unattached;
    const bool regions = a.kind == AnswerKind::Polygons || a.kind == AnswerKind::Rings || a.kind == AnswerKind::EvenOdd;
    const bool ids = !regions || !a.regions.by_points;
    const Toggle toggles[] = {
        {a.kind != AnswerKind::Rings, right,
         c.face_on_right ? "the answer agrees without --face-on right: it keeps faces on the left"
                         : "the answer agrees with --face-on right: it keeps each face on the right of its half-edges"},
        {ids, based,
         c.one_based ? "the answer agrees without --one-based: its ids count from 0"
                     : "the answer agrees with --one-based: its ids count from 1"},
        {a.kind == AnswerKind::Polygons && !c.unoriented, loose,
         "the answer agrees with --unoriented: its rings run either way, which GeoJSON allows readers to accept"},
        {a.kind == AnswerKind::Faces, singles,
         c.isolated_cycles ? "the answer agrees without --isolated-as-cycles: it lists no one-vertex cycles"
                           : "the answer agrees with --isolated-as-cycles: it writes each isolated vertex as a "
                             "one-vertex cycle [v]"},
        {a.kind == AnswerKind::Polygons, unattached,
         c.holes_unattached ? "the answer agrees without --holes-unattached: it attaches holes to their polygons"
                            : "the answer agrees with --holes-unattached: every ring is a polygon of its own and "
                              "holes are never attached (GEOS/JTS polygonize without holes, Turf)"},
    };
    for (const Toggle& t : toggles) {
        if (t.applies && compare_under(reference, a, t.conventions).agrees()) return std::string(t.note);
    }
    if (a.kind == AnswerKind::Polygons) {
        Answer as_even_odd = a;
        as_even_odd.kind = AnswerKind::EvenOdd;
        if (compare_under(reference, as_even_odd, c).agrees()) {
            return std::string(
                "the answer agrees as even-odd regions (--answer even-odd): it has the faces inside an odd number of "
                "boundaries only");
        }
    }
    return std::nullopt;
}

std::string reference_answer(const Dcel& reference, AnswerKind kind) {
    std::string out;
    write_reference_answer(reference, kind, [&out](std::string_view text) { out.append(text); });
    return out;
}

Report compare(const Dcel& reference, const Answer& answer, const Conventions& conventions) {
    Report report = compare_under(reference, answer, conventions);
    if (!report.agrees()) {
        if (std::optional<std::string> hint = convention_hint(reference, answer, conventions)) {
            report.notes.push_back(std::move(*hint));
        }
    }
    // A kind named by the answer's own key needs no note; a shape does.
    if (!answer.detected_from.empty() && answer.detected_from.rfind("an object with", 0) != 0) {
        report.notes.insert(report.notes.begin(), "answer kind " + std::string(answer_kind_name(answer.kind)) +
                                                      ", detected from " + answer.detected_from);
    }
    return report;
}

}  // namespace dcel::check
