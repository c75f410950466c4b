// The picture of one step of a session (session.hpp): the reference's state
// before the step, its vertices labelled with their protocol ids, and the
// step in red over it.
#include <optional>
#include <string>

#include "dcel/check/session.hpp"
#include "dcel/check/session_reference.hpp"
#include "dcel/io/svg.hpp"

namespace dcel::check {

namespace {

// The point of protocol vertex p in the state, when it is there.
std::optional<Point> point_of(const detail::ReferenceSession& ref, Index p) {
    const std::optional<VertexId> v = ref.vertex_of(p);
    if (!v) return std::nullopt;
    return ref.dcel().point(*v);
}

// The step as marks: the segment of an edge added, removed or stabbed (from
// its first end), the point of a split, a new vertex, a query, or the vertex
// a step removes. Nothing for a name the state does not have.
std::vector<io::SvgMark> marks_of(const detail::ReferenceSession& ref, const SessionStep& s) {
    const std::string op(step_op_name(s.op));
    std::vector<io::SvgMark> marks;
    const auto segment = [&](std::optional<Point> a, std::optional<Point> b) {
        if (a && b) marks.push_back({*a, *b, op});
    };
    switch (s.op) {
        case StepOp::AddEdge:
        case StepOp::RemoveEdge: segment(point_of(ref, s.u), point_of(ref, s.v)); break;
        case StepOp::AddEdgeToPoint: segment(point_of(ref, s.u), s.p); break;
        case StepOp::Stab: segment(s.p, s.q); break;
        case StepOp::RemoveIsolatedVertex:
        case StepOp::MergeCollinearEdges:
            if (const std::optional<Point> p = point_of(ref, s.u)) marks.push_back({*p, std::nullopt, op});
            break;
        case StepOp::SplitEdge:
        case StepOp::AddVertex:
        case StepOp::Locate:
        case StepOp::FaceBoundary:
        case StepOp::Neighbours: marks.push_back({s.p, std::nullopt, op}); break;
    }
    return marks;
}

}  // namespace

std::string render_session_step_svg(const Session& s, std::size_t k, const std::string& title) {
    detail::ReferenceSession ref(s.start);
    for (std::size_t i = 0; i < k && i < s.steps.size(); ++i) (void)ref.apply(s.steps[i]);
    io::SvgOptions options;
    options.title = title;
    const Dcel& d = ref.dcel();
    for (Index v = 0; v < d.num_vertices(); ++v)
        options.vertex_names.push_back(std::to_string(ref.protocol_id(VertexId(v))));
    if (k < s.steps.size()) {
        options.marks = marks_of(ref, s.steps[k]);
        options.marks_caption = "step " + std::to_string(k) + ", " + describe_step(s.steps[k]) +
                                ", over the reference's state before it (vertex labels: the session's ids)";
    }
    return io::render_svg(d, options);
}

}  // namespace dcel::check
