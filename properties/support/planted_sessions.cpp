#include "support/planted_sessions.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/location.hpp"
#include "oracles/exact.hpp"
#include "oracles/nested_rings.hpp"

namespace dcel::props::planted {
namespace {

using check::FaceName;
using check::SessionState;
using check::SessionStep;
using check::StepAnswer;
using check::StepOp;
namespace answers = testing::answers;

using Cycle = std::vector<Index>;
using ProtocolEdge = std::pair<Index, Index>;  // a half-edge u -> v by protocol ids

// The subdivision of the current graph, from scratch: dcel::build of the
// live vertices (compacted) and edges, its cycles and face records by
// protocol ids. The records start as build's and may then be changed by a
// planted bug (adjust_records).
struct Picture {
    struct Record {
        std::optional<std::size_t> outer;  // a cycle index
        std::vector<std::size_t> holes;
        std::vector<Index> isolated;  // protocol ids
    };

    std::vector<Index> protocol;  // compact vertex -> protocol id
    Dcel d;
    std::map<ProtocolEdge, HalfEdgeId> half_edge;
    std::vector<std::size_t> cycle_of;               // half-edge -> cycle
    std::vector<std::vector<HalfEdgeId>> cycles;     // in next order
    std::vector<bool> is_outer;                      // the cycle is a bounded face's outer cycle
    std::vector<Record> records;                     // per face of d
    std::optional<oracle::NestedRings> outer_rings;  // for point location, made when first asked

    Picture(std::vector<Index> ids, const PlanarGraph& g) : protocol(std::move(ids)), d(build(g)) {
        for (Index h = 0; h < d.num_half_edges(); ++h) {
            half_edge[{protocol[d.origin(HalfEdgeId(h)).index()], protocol[d.target(HalfEdgeId(h)).index()]}] = HalfEdgeId(
                h);
        }
        cycle_of.assign(d.num_half_edges(), kNoIndex);
        for (Index h = 0; h < d.num_half_edges(); ++h) {
            if (cycle_of[h] != kNoIndex) continue;
            auto& c = cycles.emplace_back();
            for (const HalfEdgeId x : d.cycle(HalfEdgeId(h))) {
                cycle_of[x.index()] = cycles.size() - 1;
                c.push_back(x);
            }
        }
        is_outer.assign(cycles.size(), false);
        for (Index f = 0; f < d.num_faces(); ++f) {
            Record& r = records.emplace_back();
            if (!d.is_unbounded(FaceId(f))) {
                r.outer = cycle_of[d.outer(FaceId(f)).index()];
                is_outer[*r.outer] = true;
            }
            for (const HalfEdgeId h : d.inner(FaceId(f))) r.holes.push_back(cycle_of[h.index()]);
            for (const VertexId v : d.isolated(FaceId(f))) r.isolated.push_back(protocol[v.index()]);
        }
    }

    [[nodiscard]] Index id(VertexId v) const { return protocol[v.index()]; }
    [[nodiscard]] Point point(HalfEdgeId h) const { return d.point(d.origin(h)); }
    [[nodiscard]] std::optional<HalfEdgeId> find(ProtocolEdge e) const {
        const auto it = half_edge.find(e);
        return it == half_edge.end() ? std::nullopt : std::optional<HalfEdgeId>(it->second);
    }
    [[nodiscard]] FaceId face_of_cycle(std::size_t c) const { return d.face(cycles[c].front()); }
    [[nodiscard]] ProtocolEdge key(std::size_t c) const {
        return {id(d.origin(cycles[c].front())), id(d.target(cycles[c].front()))};
    }
    [[nodiscard]] Cycle vertices(std::size_t c) const {
        Cycle out;
        for (const HalfEdgeId h : cycles[c]) out.push_back(id(d.origin(h)));
        return out;
    }
    // A face's protocol name: the first half-edge of its outer cycle.
    [[nodiscard]] FaceName name(FaceId f) const {
        if (d.is_unbounded(f)) return answers::unbounded_face();
        const HalfEdgeId h = d.outer(f);
        return answers::face_left_of(id(d.origin(h)), id(d.target(h)));
    }
    [[nodiscard]] std::vector<Point> ring(std::size_t c) const {
        std::vector<Point> out;
        for (const HalfEdgeId h : cycles[c]) out.push_back(point(h));
        return out;
    }

    // The face whose interior holds p, a point on no edge: the innermost
    // bounded face whose outer cycle winds around it.
    [[nodiscard]] FaceId face_around(Point p) {
        if (!outer_rings) {
            outer_rings.emplace();
            for (Index f = 0; f < d.num_faces(); ++f) {
                if (!d.is_unbounded(FaceId(f))) outer_rings->add(ring(cycle_of[d.outer(FaceId(f)).index()]), f, 0);
            }
        }
        const Index f = outer_rings->innermost_around(p);
        return f == kNoIndex ? Dcel::kUnboundedFace : FaceId(f);
    }

    // At a vertex, inside an edge, or in a face, by scanning.
    [[nodiscard]] Location locate(Point p) {
        for (Index v = 0; v < d.num_vertices(); ++v) {
            if (d.point(VertexId(v)) == p) return Location::at_vertex(VertexId(v));
        }
        for (Index e = 0; e < d.num_edges(); ++e) {
            const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
            if (oracle::strictly_on_segment(point(h), point(twin(h)), p)) return Location::on_edge(EdgeId(e));
        }
        return Location::in_face(face_around(p));
    }
};

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

class BruteForceSession : public testing::SessionImplementation {
public:
    explicit BruteForceSession(const PlanarGraph& start) {
        for (const Point p : start.vertices) {
            points_.emplace_back(p);
            adj_.emplace_back();
        }
        for (const GraphEdge& e : start.edges) connect(e.u.index(), e.v.index());
        rebuild();
    }

    StepAnswer apply(const SessionStep& s) override {
        if (check::is_query(s.op)) return query(s);
        std::string why = check_edit(s);
        if (why.empty()) why = refusal(s);
        if (!why.empty()) return answers::refused(std::string(check::step_op_name(s.op)) + ": " + why);
        const Index created = edit(s);
        rebuild();
        after_edit(s, created);
        adjust_records(*picture_);
        return answers::ok();
    }

    [[nodiscard]] SessionState state() const override {
        SessionState st;
        for (const Picture::Record& r : picture_->records) {
            check::FaceRecord& f = st.faces.emplace_back();
            if (r.outer) f.outer = cycle_text(*picture_, *r.outer);
            for (const std::size_t c : r.holes) f.holes.push_back(cycle_text(*picture_, c));
            f.isolated = r.isolated;
        }
        st.points = points_;
        return st;
    }

protected:
    // ---- The hooks of the planted bugs.

    // A reason to refuse an edit the checks accept, or "".
    [[nodiscard]] virtual std::string refusal(const SessionStep& /*s*/) const { return ""; }
    // After each accepted edit, the picture rebuilt (created: the new
    // vertex's id, or kNoIndex).
    virtual void after_edit(const SessionStep& /*s*/, Index /*created*/) {}
    // May change the face records before anything reads them.
    virtual void adjust_records(Picture& /*p*/) {}
    // A cycle as it is answered: its vertices in next order.
    [[nodiscard]] virtual Cycle cycle_text(const Picture& p, std::size_t c) const { return p.vertices(c); }
    // Where locate, face_boundary and neighbours find a point.
    [[nodiscard]] virtual Location locate(Picture& p, Point at) const { return p.locate(at); }

    [[nodiscard]] Picture& picture() const { return *picture_; }
    [[nodiscard]] Point at(Index v) const { return *points_[v]; }
    [[nodiscard]] const std::set<Index>& neighbours_of(Index v) const { return adj_[v]; }

    // Connected components by protocol id (removed vertices: kNoIndex).
    [[nodiscard]] std::vector<Index> components() const {
        std::vector<Index> label(points_.size(), kNoIndex);
        for (Index v = 0; v < points_.size(); ++v) {
            if (!points_[v] || label[v] != kNoIndex) continue;
            std::vector<Index> stack{v};
            label[v] = v;
            while (!stack.empty()) {
                const Index x = stack.back();
                stack.pop_back();
                for (const Index y : adj_[x]) {
                    if (label[y] == kNoIndex) {
                        label[y] = v;
                        stack.push_back(y);
                    }
                }
            }
        }
        return label;
    }

private:
    [[nodiscard]] bool live(Index v) const { return v < points_.size() && points_[v].has_value(); }
    [[nodiscard]] bool joined(Index u, Index v) const { return adj_[u].count(v) != 0; }

    void connect(Index u, Index v) {
        adj_[u].insert(v);
        adj_[v].insert(u);
    }
    void disconnect(Index u, Index v) {
        adj_[u].erase(v);
        adj_[v].erase(u);
    }
    Index add_point(Point p) {
        points_.emplace_back(p);
        adj_.emplace_back();
        return static_cast<Index>(points_.size() - 1);
    }

    // ---- Checking an edit, by brute force over every vertex and edge.

    // p is at no vertex and inside no edge: "" or why not.
    [[nodiscard]] std::string free_point(Point p) const {
        if (!finite(p)) return "the point is not finite";
        for (Index v = 0; v < points_.size(); ++v) {
            if (!live(v)) continue;
            if (at(v) == p) return "the point is vertex " + std::to_string(v);
            for (const Index w : adj_[v]) {
                if (v < w && oracle::strictly_on_segment(at(v), at(w), p)) return "the point is inside an edge";
            }
        }
        return "";
    }

    // The segment from vertex u to q (vertex v's point, or a new point)
    // meets the graph at u (and v) only.
    [[nodiscard]] std::string clear_segment(Index u, Point q, Index v) const {
        const Point p = at(u);
        for (Index a = 0; a < points_.size(); ++a) {
            if (!live(a)) continue;
            if (a != u && a != v && oracle::strictly_on_segment(p, q, at(a))) return "the segment passes through a vertex";
            for (const Index b : adj_[a]) {
                if (a > b) continue;
                const oracle::Meeting m = oracle::meeting(p, q, at(a), at(b));
                if (m != oracle::Meeting::None && m != oracle::Meeting::SharedEndpoint) {
                    return "the segment crosses, touches or overlaps an edge";
                }
            }
        }
        return "";
    }

    // "" when the edit is legal, else why not.
    [[nodiscard]] std::string check_edit(const SessionStep& s) const {
        switch (s.op) {
            case StepOp::SplitEdge:
                if (!live(s.u) || !live(s.v) || !joined(s.u, s.v)) return "no such edge";
                if (!finite(s.p) || !oracle::strictly_on_segment(at(s.u), at(s.v), s.p)) return "not strictly on the edge";
                return "";
            case StepOp::AddVertex: return free_point(s.p);
            case StepOp::AddEdge:
                if (!live(s.u) || !live(s.v)) return "no such vertex";
                if (s.u == s.v) return "an edge needs two vertices";
                if (joined(s.u, s.v)) return "joined already";
                return clear_segment(s.u, at(s.v), s.v);
            case StepOp::AddEdgeToPoint: {
                if (!live(s.u)) return "no such vertex";
                std::string why = free_point(s.p);
                return why.empty() ? clear_segment(s.u, s.p, kNoIndex) : why;
            }
            case StepOp::RemoveEdge: return live(s.u) && live(s.v) && joined(s.u, s.v) ? "" : "no such edge";
            case StepOp::RemoveIsolatedVertex:
                if (!live(s.u)) return "no such vertex";
                return adj_[s.u].empty() ? "" : "the vertex has edges";
            case StepOp::MergeCollinearEdges: {
                if (!live(s.u)) return "no such vertex";
                if (adj_[s.u].size() != 2) return "the vertex has not two edges";
                const Index a = *adj_[s.u].begin(), b = *adj_[s.u].rbegin();
                return oracle::strictly_on_segment(at(a), at(b), at(s.u)) ? "" : "the vertex is not between its neighbours";
            }
            default: return "not an edit";
        }
    }

    // Makes a legal edit; the id of the vertex it creates, or kNoIndex.
    Index edit(const SessionStep& s) {
        switch (s.op) {
            case StepOp::SplitEdge: {
                const Index w = add_point(s.p);
                disconnect(s.u, s.v);
                connect(s.u, w);
                connect(w, s.v);
                return w;
            }
            case StepOp::AddVertex: return add_point(s.p);
            case StepOp::AddEdge: connect(s.u, s.v); return kNoIndex;
            case StepOp::AddEdgeToPoint: {
                const Index w = add_point(s.p);
                connect(s.u, w);
                return w;
            }
            case StepOp::RemoveEdge: disconnect(s.u, s.v); return kNoIndex;
            case StepOp::RemoveIsolatedVertex: points_[s.u].reset(); return kNoIndex;
            case StepOp::MergeCollinearEdges: {
                const Index a = *adj_[s.u].begin(), b = *adj_[s.u].rbegin();
                disconnect(s.u, a);
                disconnect(s.u, b);
                connect(a, b);
                points_[s.u].reset();
                return kNoIndex;
            }
            default: return kNoIndex;
        }
    }

    // The faces from scratch.
    void rebuild() {
        std::vector<Index> protocol, compact(points_.size(), kNoIndex);
        PlanarGraph g;
        for (Index v = 0; v < points_.size(); ++v) {
            if (!live(v)) continue;
            compact[v] = static_cast<Index>(protocol.size());
            protocol.push_back(v);
            g.vertices.push_back(at(v));
        }
        for (Index u = 0; u < points_.size(); ++u) {
            for (const Index v : adj_[u]) {
                if (u < v) g.edges.push_back({VertexId(compact[u]), VertexId(compact[v])});
            }
        }
        picture_ = std::make_unique<Picture>(std::move(protocol), g);
    }

    // ---- Queries, by brute force.

    [[nodiscard]] StepAnswer located(const Picture& p, const Location& l) const {
        switch (l.kind) {
            case Location::Kind::Vertex: return answers::at_vertex(p.id(l.vertex));
            case Location::Kind::Edge: {
                const HalfEdgeId h = half_edge_of(l.edge, 0);
                return answers::on_edge(p.id(p.d.origin(h)), p.id(p.d.target(h)));
            }
            case Location::Kind::Face: return answers::in_face(p.name(l.face));
        }
        return {};
    }

    [[nodiscard]] StepAnswer query(const SessionStep& s) const {
        Picture& p = picture();
        if (s.op == StepOp::Stab) {
            std::vector<FaceName> names;
            for (const FaceId f : stab(p, s.p, s.q)) names.push_back(p.name(f));
            return answers::faces(std::move(names));
        }
        const Location l = locate(p, s.p);
        if (s.op == StepOp::Locate || l.kind != Location::Kind::Face) return located(p, l);
        const Picture::Record& r = p.records[l.face.index()];
        if (s.op == StepOp::FaceBoundary) {
            std::optional<Cycle> outer;
            if (r.outer) outer = cycle_text(p, *r.outer);
            std::vector<Cycle> holes;
            for (const std::size_t c : r.holes) holes.push_back(cycle_text(p, c));
            return answers::boundary(p.name(l.face), std::move(outer), std::move(holes));
        }
        // neighbours: the faces across the edges of the face's cycles.
        std::vector<FaceId> seen;
        std::vector<std::size_t> cycles = r.holes;
        if (r.outer) cycles.push_back(*r.outer);
        for (const std::size_t c : cycles) {
            for (const HalfEdgeId h : p.cycles[c]) {
                const FaceId g = p.d.face(twin(h));
                if (g != l.face && std::find(seen.begin(), seen.end(), g) == seen.end()) seen.push_back(g);
            }
        }
        std::vector<FaceName> names;
        for (const FaceId g : seen) names.push_back(p.name(g));
        return answers::faces(std::move(names));
    }

    // The face just beside the edge e, on the side of `toward`.
    static FaceId side_of(const Picture& p, EdgeId e, Point toward) {
        const HalfEdgeId h = half_edge_of(e, 0);
        return oracle::orientation(p.point(h), p.point(twin(h)), toward) > 0 ? p.d.face(h) : p.d.face(twin(h));
    }

    // The face just beside vertex w in the direction of `toward` (which is
    // along no edge of w): the face left of the last of w's edges before
    // that direction, counterclockwise.
    static FaceId wedge(Picture& p, VertexId w, Point toward) {
        const Point c = p.d.point(w);
        if (p.d.out(w).is_null()) return p.face_around(c);  // isolated: the face it lies in
        std::optional<HalfEdgeId> before, last;
        for (const HalfEdgeId h : p.d.around_origin_ccw(p.d.out(w))) {
            const Point t = p.d.point(p.d.target(h));
            if (!last || oracle::angle_order(c, p.d.point(p.d.target(*last)), t) < 0) last = h;
            if (oracle::angle_order(c, t, toward) < 0 &&
                (!before || oracle::angle_order(c, p.d.point(p.d.target(*before)), t) < 0)) {
                before = h;
            }
        }
        return p.d.face(before ? *before : *last);
    }

    // The faces of the open stretches of a -> b, in order, repeats merged;
    // a stretch along an edge gives none. a == b: the face a lies in, if any.
    static std::vector<FaceId> stab(Picture& p, Point a, Point b) {
        if (a == b) {
            const Location l = p.locate(a);
            if (l.kind == Location::Kind::Face) return {l.face};
            return {};
        }
        struct Cut {
            enum class Kind { End, Vertex, Crossing } kind;
            Index id;  // the vertex or the edge crossed
        };
        std::map<oracle::Rational, Cut> cuts{{oracle::Rational(0), {Cut::Kind::End, kNoIndex}},
                                             {oracle::Rational(1), {Cut::Kind::End, kNoIndex}}};
        std::vector<std::pair<oracle::Rational, oracle::Rational>> along;
        for (Index v = 0; v < p.d.num_vertices(); ++v) {
            const Point q = p.d.point(VertexId(v));
            if (q == a) cuts[oracle::Rational(0)] = {Cut::Kind::Vertex, v};
            if (q == b) cuts[oracle::Rational(1)] = {Cut::Kind::Vertex, v};
            if (oracle::strictly_on_segment(a, b, q)) cuts[oracle::parameter_of_point(a, b, q)] = {Cut::Kind::Vertex, v};
        }
        for (Index e = 0; e < p.d.num_edges(); ++e) {
            const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
            const Point u = p.point(h), v = p.point(twin(h));
            const oracle::Meeting m = oracle::meeting(a, b, u, v);
            if (m == oracle::Meeting::Crossing) {
                cuts[oracle::parameter_of_crossing(a, b, u, v)] = {Cut::Kind::Crossing, e};
            } else if (m == oracle::Meeting::Overlap || m == oracle::Meeting::Same) {
                const oracle::Rational tu = oracle::parameter_of_point(a, b, u), tv = oracle::parameter_of_point(a, b, v);
                along.emplace_back(std::min(tu, tv), std::max(tu, tv));
            }
        }
        std::vector<FaceId> faces;
        for (auto it = cuts.begin(); std::next(it) != cuts.end(); ++it) {
            const oracle::Rational& t0 = it->first;
            const oracle::Rational& t1 = std::next(it)->first;
            const bool on_edge = std::any_of(along.begin(), along.end(),
                                             [&](const auto& in) { return in.first <= t0 && t1 <= in.second; });
            if (on_edge) continue;
            FaceId f;
            const Cut& cut = it->second;
            if (cut.kind == Cut::Kind::Vertex) {
                f = wedge(p, VertexId(cut.id), b);
            } else if (cut.kind == Cut::Kind::Crossing) {
                f = side_of(p, EdgeId(cut.id), b);
            } else {  // a itself, at no vertex
                const Location l = p.locate(a);
                f = l.kind == Location::Kind::Edge ? side_of(p, l.edge, b) : l.face;
            }
            if (faces.empty() || faces.back() != f) faces.push_back(f);
        }
        return faces;
    }

    std::vector<std::optional<Point>> points_;  // by protocol id; none once removed
    std::vector<std::set<Index>> adj_;          // by protocol id
    std::unique_ptr<Picture> picture_;
};

// ---- The planted bugs.

class HolesStay : public BruteForceSession {
public:
    using BruteForceSession::BruteForceSession;

protected:
    void after_edit(const SessionStep& s, Index /*created*/) override {
        if (s.op != StepOp::AddEdge) return;
        const Picture& p = picture();
        const HalfEdgeId hl = *p.find({s.u, s.v}), hr = *p.find({s.v, s.u});
        const FaceId fl = p.d.face(hl), fr = p.d.face(hr);
        if (fl == fr) return;  // no face split: two cycles joined, or a dangling edge
        const bool outer_l = p.is_outer[p.cycle_of[hl.index()]], outer_r = p.is_outer[p.cycle_of[hr.index()]];
        FaceId fresh = fl, old = fr;  // the old face's outer split: the new face is the part left of u -> v
        if (!(outer_l && outer_r)) {  // a hole's cycle split: the new face is the part closed off
            fresh = outer_l ? fl : fr;
            old = outer_l ? fr : fl;
        }
        std::optional<ProtocolEdge> old_key;
        if (!p.d.is_unbounded(old)) old_key = p.key(p.cycle_of[p.d.outer(old).index()]);
        const Picture::Record& r = p.records[fresh.index()];
        for (const std::size_t c : r.holes) add(Stuck{false, p.key(c), kNoIndex, old_key});
        for (const Index v : r.isolated) add(Stuck{true, {}, v, old_key});
    }

    // Every stuck hole and isolated vertex moves back into the old face,
    // while the old face's half-edge and the hole (or vertex) are there.
    void adjust_records(Picture& p) override {
        std::vector<Stuck> kept;
        std::set<std::size_t> moved_holes;
        std::set<Index> moved_vertices;
        for (const Stuck& s : stuck_) {
            std::optional<HalfEdgeId> old_h;
            if (s.old_face) {
                old_h = p.find(*s.old_face);
                if (!old_h) continue;  // the old face's half-edge is gone: the entry with it
            }
            const FaceId stay = old_h ? p.d.face(*old_h) : Dcel::kUnboundedFace;
            if (s.isolated) {
                if (moved_vertices.count(s.vertex) != 0 || !move_isolated(p, s.vertex, stay)) continue;
                moved_vertices.insert(s.vertex);
            } else {
                const std::optional<HalfEdgeId> h = p.find(s.hole);
                if (!h) continue;
                const std::size_t c = p.cycle_of[h->index()];
                if (p.is_outer[c] || moved_holes.count(c) != 0) continue;
                move_hole(p, c, stay);
                moved_holes.insert(c);
            }
            kept.push_back(s);
        }
        stuck_ = std::move(kept);
    }

private:
    struct Stuck {
        bool isolated;
        ProtocolEdge hole;                     // a half-edge of the hole's cycle
        Index vertex;                          // the isolated vertex
        std::optional<ProtocolEdge> old_face;  // a half-edge of the old face's outer cycle; none: unbounded
    };

    void add(const Stuck& s) {
        const bool already = std::any_of(stuck_.begin(), stuck_.end(), [&](const Stuck& t) {
            return t.isolated == s.isolated && (s.isolated ? t.vertex == s.vertex : t.hole == s.hole);
        });
        if (!already) stuck_.push_back(s);  // already stale: stays where it was left
    }

    static bool move_isolated(Picture& p, Index v, FaceId to) {
        for (Picture::Record& r : p.records) {
            const auto it = std::find(r.isolated.begin(), r.isolated.end(), v);
            if (it == r.isolated.end()) continue;
            r.isolated.erase(it);
            p.records[to.index()].isolated.push_back(v);
            return true;
        }
        return false;  // no longer isolated
    }

    static void move_hole(Picture& p, std::size_t c, FaceId to) {
        for (Picture::Record& r : p.records) {
            const auto it = std::find(r.holes.begin(), r.holes.end(), c);
            if (it == r.holes.end()) continue;
            r.holes.erase(it);
            p.records[to.index()].holes.push_back(c);
            return;
        }
    }

    std::vector<Stuck> stuck_;
};

class StaleOuter : public BruteForceSession {
public:
    using BruteForceSession::BruteForceSession;

protected:
    // A bridge removed where the part holding the step's first end broke
    // off inside the face whose outer boundary is the other end's part.
    void after_edit(const SessionStep& s, Index /*created*/) override {
        if (s.op != StepOp::RemoveEdge || neighbours_of(s.u).empty() || neighbours_of(s.v).empty()) return;
        const std::vector<Index> component = components();
        if (component[s.u] == component[s.v]) return;  // not a bridge
        const Picture& p = picture();
        for (std::size_t c = 0; c < p.cycles.size(); ++c) {
            if (p.is_outer[c] || component[p.vertices(c).front()] != component[s.u]) continue;
            const FaceId f = p.face_of_cycle(c);  // u's part: a hole of f
            if (p.d.is_unbounded(f)) return;
            const std::size_t outer = p.cycle_of[p.d.outer(f).index()];
            if (component[p.vertices(outer).front()] == component[s.v]) swapped_.emplace_back(p.key(outer), p.key(c));
            return;
        }
    }

    void adjust_records(Picture& p) override {
        std::vector<std::pair<ProtocolEdge, ProtocolEdge>> kept;
        for (const auto& [outer_key, hole_key] : swapped_) {
            const std::optional<HalfEdgeId> o = p.find(outer_key), h = p.find(hole_key);
            if (!o || !h) continue;
            const std::size_t oc = p.cycle_of[o->index()], hc = p.cycle_of[h->index()];
            if (!p.is_outer[oc]) continue;
            Picture::Record& r = p.records[p.face_of_cycle(oc).index()];
            const auto it = std::find(r.holes.begin(), r.holes.end(), hc);
            if (r.outer != oc || it == r.holes.end()) continue;
            *it = oc;  // planted: the two swapped
            r.outer = hc;
            kept.emplace_back(outer_key, hole_key);
        }
        swapped_ = std::move(kept);
    }

private:
    std::vector<std::pair<ProtocolEdge, ProtocolEdge>> swapped_;  // (the real outer cycle, the new hole)
};

class LocateVertical : public BruteForceSession {
public:
    using BruteForceSession::BruteForceSession;

protected:
    [[nodiscard]] Location locate(Picture& p, Point at) const override {
        const Location l = BruteForceSession::locate(p, at);
        if (l.kind != Location::Kind::Edge) return l;
        HalfEdgeId h = half_edge_of(l.edge, 0);
        const Point a = p.point(h), b = p.point(twin(h));
        if (a.x != b.x) return l;
        if (a.y > b.y) h = twin(h);
        return Location::in_face(p.d.face(h));  // planted: the face left of the edge walked upwards
    }
};

class LocateIgnoresHoles : public BruteForceSession {
public:
    using BruteForceSession::BruteForceSession;

protected:
    [[nodiscard]] Location locate(Picture& p, Point at) const override {
        const Location l = BruteForceSession::locate(p, at);
        if (l.kind != Location::Kind::Face) return l;
        std::optional<FaceId> best;
        oracle::Rational best_area;
        for (Index f = 0; f < p.d.num_faces(); ++f) {
            if (p.d.is_unbounded(FaceId(f))) continue;
            const std::vector<Point> ring = p.ring(p.cycle_of[p.d.outer(FaceId(f)).index()]);
            const oracle::Rational area = oracle::twice_area(ring);
            // planted: the largest face around the point, its holes not looked at
            if ((!best || area > best_area) && oracle::winding_number(at, ring) != 0) {
                best = FaceId(f);
                best_area = area;
            }
        }
        return Location::in_face(best ? *best : Dcel::kUnboundedFace);
    }
};

class SplitTwin : public BruteForceSession {
public:
    using BruteForceSession::BruteForceSession;

protected:
    void after_edit(const SessionStep& s, Index created) override {
        if (s.op == StepOp::SplitEdge) splits_.push_back({s.u, created, s.v});
        std::erase_if(splits_, [&](const Split& x) { return neighbours_of(x.w) != std::set<Index>{x.u, x.v}; });
    }

    // planted: v -> u as before the split, on the cycle through v -> w -> u.
    [[nodiscard]] Cycle cycle_text(const Picture& p, std::size_t c) const override {
        Cycle cycle = p.vertices(c);
        for (const Split& s : splits_) {
            const std::size_t n = cycle.size();
            for (std::size_t i = 0; i < n; ++i) {
                if (cycle[i] == s.v && cycle[(i + 1) % n] == s.w && cycle[(i + 2) % n] == s.u) {
                    cycle.erase(cycle.begin() + static_cast<std::ptrdiff_t>((i + 1) % n));
                    break;
                }
            }
        }
        return cycle;
    }

private:
    struct Split {
        Index u, w, v;
    };
    std::vector<Split> splits_;
};

class RefusesCollinear : public BruteForceSession {
public:
    using BruteForceSession::BruteForceSession;

protected:
    [[nodiscard]] std::string refusal(const SessionStep& s) const override {
        if (s.op != StepOp::AddEdge) return "";
        const Point p = at(s.u), q = at(s.v);
        return p.x == q.x || p.y == q.y ? "an axis-parallel edge is not supported" : "";
    }
};

}  // namespace

SessionPtr right_session(const PlanarGraph& start) { return std::make_unique<BruteForceSession>(start); }
SessionPtr holes_stay_session(const PlanarGraph& start) { return std::make_unique<HolesStay>(start); }
SessionPtr stale_outer_session(const PlanarGraph& start) { return std::make_unique<StaleOuter>(start); }
SessionPtr locate_vertical_session(const PlanarGraph& start) { return std::make_unique<LocateVertical>(start); }
SessionPtr locate_ignores_holes_session(const PlanarGraph& start) { return std::make_unique<LocateIgnoresHoles>(start); }
SessionPtr split_twin_session(const PlanarGraph& start) { return std::make_unique<SplitTwin>(start); }
SessionPtr refuses_collinear_session(const PlanarGraph& start) { return std::make_unique<RefusesCollinear>(start); }

}  // namespace dcel::props::planted
