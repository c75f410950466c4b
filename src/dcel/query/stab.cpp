#include "dcel/stab.hpp"

#include <algorithm>

#include "dcel/core/finite.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/line_order.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/geometry/segments.hpp"
#include "dcel/locate.hpp"
#include "dcel/query/rotation.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::DirectedLine;
using detail::Direction;
using detail::LineEvent;
namespace {

// The walk is a loop over states: at a vertex, at the crossing of an edge,
// or inside a face just past the event it entered by. (A loop rather than
// mutual recursion: a line may meet a million things.)
struct State {
    enum class At : unsigned char { Vertex, Crossing, Face, Done };
    At at = At::Done;
    VertexId vertex;
    EdgeId edge;
    FaceId face;  // At::Face: the face; At::Vertex: the face around an isolated vertex, if known
    LineEvent from;

    static State vertex_at(VertexId v, FaceId around) { return {At::Vertex, v, {}, around, {}}; }
    static State crossing(EdgeId e) { return {At::Crossing, {}, e, {}, {}}; }
    static State in_face(FaceId f, LineEvent from) { return {At::Face, {}, {}, f, from}; }
    static State done() { return {}; }
};

// One thing on the line the walk may stop at: a vertex on it, or an edge
// it crosses at an interior point.
struct Stop {
    LineEvent event;
    VertexId vertex;  // a vertex on the line
    EdgeId edge;      // an edge crossed
};

class Walk {
public:
    // A segment walk stops at b; a line walk runs to infinity.
    Walk(const Dcel& d, Point a, Point b, bool segment) : d_(d), line_(a, b), segment_(segment) { collect_stops(); }

    std::vector<StabPiece> run(State s) {
        while (s.at != State::At::Done) {
            switch (s.at) {
                case State::At::Vertex: s = at_vertex(s.vertex, s.face); break;
                case State::At::Crossing: s = at_crossing(s.edge); break;
                case State::At::Face: s = in_face(s.face, s.from); break;
                case State::At::Done: break;
            }
        }
        return std::move(out_);
    }

    // The segment starts inside edge e: crossing it, or running along it.
    State start_inside_edge(EdgeId e) {
        const HalfEdgeId h = half_edge_of(e, 0);
        const Point c = point(d_.origin(h));
        const Point dd = point(d_.target(h));
        if (line_.side(c) != Sign::Zero || line_.side(dd) != Sign::Zero) return State::crossing(e);
        const bool origin_ahead = line_.compare(LineEvent::at(line_.a()), LineEvent::at(c)) == Sign::Negative;
        return run_along(e, origin_ahead ? d_.origin(h) : d_.target(h));
    }

private:
    [[nodiscard]] Point point(VertexId v) const { return d_.point(v); }
    [[nodiscard]] bool before(const LineEvent& x, const LineEvent& y) const { return line_.compare(x, y) == Sign::Negative; }
    [[nodiscard]] bool ends_at(const LineEvent& e) const {
        return segment_ && line_.compare(e, LineEvent::at(line_.b())) == Sign::Zero;
    }

    // Every vertex on the line and every edge it crosses, in order along it:
    // O(V + E) to find them, O(k log k) to sort the k kept. A segment keeps
    // only those from a to b, the walk never looks further. Then the first
    // thing ahead of any position is a binary search away, instead of a scan
    // of the face's boundary that a walk re-entering a large face (the
    // unbounded face of a star it crosses spoke after spoke) repeats each
    // time.
    void collect_stops() {
        const LineEvent a = LineEvent::at(line_.a());
        const LineEvent b = LineEvent::at(line_.b());
        auto keep = [&](const LineEvent& e) { return !segment_ || (!before(e, a) && !before(b, e)); };
        for (Index i = 0; i < d_.num_vertices(); ++i) {
            const VertexId v(i);
            const LineEvent e = LineEvent::at(point(v));
            if (line_.side(point(v)) == Sign::Zero && keep(e)) stops_.push_back({e, v, {}});
        }
        for (Index i = 0; i < d_.num_half_edges(); i += 2) {
            const HalfEdgeId h(i);
            const Point c = point(d_.origin(h));
            const Point dd = point(d_.target(h));
            if (to_int(line_.side(c)) * to_int(line_.side(dd)) >= 0) continue;
            const LineEvent e = LineEvent::cut(c, dd);
            if (keep(e)) stops_.push_back({e, {}, edge_of(h)});
        }
        // Stops are at distinct points of the line: two edges crossing it at
        // one point, or an edge crossing it at a vertex, would cross.
        std::sort(stops_.begin(), stops_.end(), [&](const Stop& x, const Stop& y) { return before(x.event, y.event); });
    }

    // The face entered when crossing edge e (ahead of the crossing).
    [[nodiscard]] FaceId face_ahead_of(EdgeId e) const {
        const HalfEdgeId h = half_edge_of(e, 0);
        const Sign side = line_.ahead_side(point(d_.origin(h)), point(d_.target(h)));
        return d_.face(side == Sign::Positive ? h : Dcel::twin(h));
    }
    [[nodiscard]] LineEvent crossing_of(EdgeId e) const {
        const HalfEdgeId h = half_edge_of(e, 0);
        return LineEvent::cut(point(d_.origin(h)), point(d_.target(h)));
    }

    // Along edge e towards its end `ahead`; stops when b lies inside the edge.
    State run_along(EdgeId e, VertexId ahead) {
        out_.push_back(StabPiece::along_edge(e));
        if (segment_ && line_.compare(LineEvent::at(line_.b()), LineEvent::at(point(ahead))) == Sign::Negative) {
            return State::done();
        }
        return State::vertex_at(ahead, {});
    }

    State at_vertex(VertexId v, FaceId around) {
        out_.push_back(StabPiece::at(v));
        const LineEvent here = LineEvent::at(point(v));
        if (ends_at(here)) return State::done();
        if (d_.out(v).is_null()) return State::in_face(around.is_null() ? face_of_isolated_vertex(d_, v) : around, here);
        const Direction dir{line_.a(), line_.b()};
        const HalfEdgeId along = detail::outgoing_in_direction(d_, v, dir);
        if (!along.is_null()) return run_along(edge_of(along), d_.target(along));
        const HalfEdgeId r = detail::wedge_after(d_, v, dir);
        return State::in_face(d_.face(d_.next(Dcel::twin(r))), here);
    }

    State at_crossing(EdgeId e) {
        out_.push_back(StabPiece::across(e));
        if (ends_at(crossing_of(e))) return State::done();
        return State::in_face(face_ahead_of(e), crossing_of(e));
    }

    // Inside face f just past `from`: the next stop, which lies on f's
    // boundary or is an isolated vertex in f (the open stretch up to it
    // meets nothing, so it stays in f), unless the segment ends first.
    State in_face(FaceId f, const LineEvent& from) {
        out_.push_back(StabPiece::in_face(f));
        const auto next = std::upper_bound(stops_.begin(), stops_.end(), from,
                                           [&](const LineEvent& x, const Stop& y) { return before(x, y.event); });
        if (segment_ && (next == stops_.end() || line_.compare(LineEvent::at(line_.b()), next->event) == Sign::Negative)) {
            return State::done();  // b lies inside f
        }
        if (next == stops_.end()) return State::done();  // the line runs to infinity inside f
        return next->event.crossing ? State::crossing(next->edge) : State::vertex_at(next->vertex, f);
    }

    const Dcel& d_;
    DirectedLine line_;
    bool segment_;
    std::vector<Stop> stops_;
    std::vector<StabPiece> out_;
};

std::vector<StabPiece> reversed_tail(std::vector<StabPiece> v) {
    std::reverse(v.begin(), v.end());
    v.pop_back();  // the shared start piece
    return v;
}

}  // namespace

std::vector<StabPiece> stab_segment(const Dcel& d, Point a, Point b) {
    detail::require_finite(a, "stab_segment");
    detail::require_finite(b, "stab_segment");
    const Location start = locate_by_scan(d, a);
    if (a == b) {
        switch (start.kind) {
            case Location::Kind::Face: return {StabPiece::in_face(start.face)};
            case Location::Kind::Edge: return {StabPiece::across(start.edge)};
            case Location::Kind::Vertex: return {StabPiece::at(start.vertex)};
        }
    }
    Walk walk(d, a, b, true);
    switch (start.kind) {
        case Location::Kind::Face: return walk.run(State::in_face(start.face, LineEvent::at(a)));
        case Location::Kind::Edge: return walk.run(walk.start_inside_edge(start.edge));
        case Location::Kind::Vertex: return walk.run(State::vertex_at(start.vertex, {}));
    }
    return {};
}

std::vector<StabPiece> stab_line(const Dcel& d, Point a, Point b, HalfEdgeId cut) {
    detail::require_finite(a, "stab_line");
    detail::require_finite(b, "stab_line");
    if (a == b) {
        throw InvalidInput(InputErrorKind::BadCoordinate,
                           "stab_line: a line needs two different points, but both are " + format_point(a));
    }
    if (cut.is_null() || cut.index() >= d.num_half_edges()) {
        throw InvalidInput(InputErrorKind::BadIndex, "stab_line: there is no half-edge " + cut.str());
    }
    const Point c = d.point(d.origin(cut));
    const Point e = d.point(d.target(cut));
    const Sign sc = orient2d(a, b, c);
    const Sign se = orient2d(a, b, e);
    if (to_int(sc) * to_int(se) > 0) {
        throw TopologyError("stab_line: the line through " + format_point(a) + " and " + format_point(b) +
                            " does not meet the edge of " + cut.str() + " from " + format_point(c) + " to " +
                            format_point(e));
    }
    Walk forward(d, a, b, false);
    Walk backward(d, b, a, false);
    std::vector<StabPiece> ahead;
    std::vector<StabPiece> behind;
    const State start = to_int(sc) * to_int(se) < 0 ? State::crossing(edge_of(cut))
                                                    : State::vertex_at(sc == Sign::Zero ? d.origin(cut) : d.target(cut), {});
    ahead = forward.run(start);
    behind = backward.run(start);
    std::vector<StabPiece> out = reversed_tail(std::move(behind));
    out.insert(out.end(), ahead.begin(), ahead.end());
    return out;
}

std::vector<StabPiece> stab_line(const Dcel& d, Point a, Point b) {
    detail::require_finite(a, "stab_line");
    detail::require_finite(b, "stab_line");
    if (a == b) {
        throw InvalidInput(InputErrorKind::BadCoordinate,
                           "stab_line: a line needs two different points, but both are " + format_point(a));
    }
    for (Index i = 0; i < d.num_half_edges(); i += 2) {
        const HalfEdgeId h(i);
        if (to_int(orient2d(a, b, d.point(d.origin(h)))) * to_int(orient2d(a, b, d.point(d.target(h)))) <= 0) {
            return stab_line(d, a, b, h);
        }
    }
    // No edge on the line: it lies in the unbounded face, meeting only
    // isolated vertices of that face.
    for (Index i = 0; i < d.num_vertices(); ++i) {
        const VertexId v(i);
        if (orient2d(a, b, d.point(v)) != Sign::Zero) continue;
        Walk forward(d, a, b, false);
        Walk backward(d, b, a, false);
        const State start = State::vertex_at(v, Dcel::kUnboundedFace);
        std::vector<StabPiece> out = reversed_tail(backward.run(start));
        const std::vector<StabPiece> ahead = forward.run(start);
        out.insert(out.end(), ahead.begin(), ahead.end());
        return out;
    }
    return {StabPiece::in_face(Dcel::kUnboundedFace)};
}

std::vector<FaceId> faces_in_order(const std::vector<StabPiece>& pieces) {
    std::vector<FaceId> out;
    for (const StabPiece& p : pieces) {
        if (p.kind == StabPiece::Kind::Face) out.push_back(p.face);
    }
    return out;
}

}  // namespace dcel
