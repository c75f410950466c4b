// compare_dump: a whole DCEL dump against the reference. The points first,
// then validate_all() on the dump's own terms, then its next-cycles and face
// records against the reference, identified by vertex pairs and cycles.
#include <algorithm>
#include <string>

#include "dcel/check/collector.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/cycles.hpp"
#include "dcel/check/dump_faces.hpp"
#include "dcel/format.hpp"
#include "dcel/validate.hpp"

namespace dcel::check {

namespace {

void compare_points(const Dcel& reference, const DcelDump& answer, detail::Collector& out) {
    const std::size_t want = reference.num_vertices();
    const std::size_t got = answer.vertices.size();
    if (want != got) {
        out.add(DifferenceKind::VertexCount,
                "the answer has " + std::to_string(got) + " vertices, the graph " + std::to_string(want));
    }
    for (std::size_t v = 0; v < std::min(want, got); ++v) {  // before validation: no 32-bit count assumed
        const Point p = reference.points()[v];
        const Point q = answer.vertices[v];
        if (p == q || !out.wants(DifferenceKind::WrongPoint)) continue;
        out.add(DifferenceKind::WrongPoint,
                "v" + std::to_string(v) + " is at " + format_point(q) + " in the answer, at " + format_point(p) +
                    " in the graph",
                {static_cast<Index>(v)});
    }
}

}  // namespace

Report compare_dump(const Dcel& reference, const DcelDump& answer) {
    detail::Collector out;
    compare_points(reference, answer, out);

    // The walks below need every id in range and next a permutation.
    bool walkable = true;
    for (const Violation& v : validate_all(answer)) {
        if (v.invariant == Invariant::References || v.invariant == Invariant::NextPrev) walkable = false;
        if (!out.wants(DifferenceKind::BrokenInvariant)) continue;
        std::vector<Index> vertices;
        for (const VertexId x : v.vertices) {
            if (x.index() < reference.num_vertices()) vertices.push_back(x.index());  // drawable on the graph
        }
        out.add(DifferenceKind::BrokenInvariant, "[" + std::string(to_string(v.invariant)) + "] " + v.message,
                std::move(vertices));
    }
    if (!walkable) return std::move(out).finish();

    const detail::Reference ref(reference);
    const detail::DumpCycles cycles = detail::dump_cycles(answer);
    const detail::AnswerCycles labels{&cycles.cycles, cycles.through};
    const detail::CycleMatch match = detail::match_cycles(ref, labels, out);
    detail::compare_face_records(ref, answer, cycles, match, out);
    return std::move(out).finish();
}

}  // namespace dcel::check
