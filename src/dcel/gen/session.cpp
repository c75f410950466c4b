#include "dcel/gen/session.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

#include "dcel/build.hpp"
#include "dcel/check/session_reference.hpp"
#include "dcel/error.hpp"
#include "dcel/gen/rng.hpp"

namespace dcel::gen {

namespace {

using check::Session;
using check::SessionStep;
using check::StepOp;

// ---- Generating

// How often each operation is drawn, in StepOp order: edits that change
// faces most, then the queries.
constexpr std::uint64_t kWeights[check::kStepOpCount] = {
    12,  // split_edge
    8,   // add_vertex
    22,  // add_edge
    10,  // add_edge_to_point
    12,  // remove_edge
    4,   // remove_isolated_vertex
    4,   // merge_collinear_edges
    10,  // locate
    6,   // face_boundary
    6,   // neighbours
    6,   // stab
};

StepOp draw_op(Rng& rng) {
    std::uint64_t total = 0;
    for (const std::uint64_t w : kWeights) total += w;
    std::uint64_t pick = rng.below(total);
    for (std::size_t i = 0; i < check::kStepOpCount; ++i) {
        if (pick < kWeights[i]) return static_cast<StepOp>(i);
        pick -= kWeights[i];
    }
    return StepOp::Locate;
}

class StepDrawer {
public:
    StepDrawer(const check::detail::ReferenceSession& ref, Rng& rng) : ref_(ref), d_(ref.dcel()), rng_(rng) {}

    SessionStep draw(StepOp op) {
        SessionStep s;
        s.op = op;
        switch (op) {
            case StepOp::SplitEdge: {
                const HalfEdgeId h = half_edge();
                if (h.is_null()) return any_vertex_step(s);
                s.u = id(d_.origin(h));
                s.v = id(d_.target(h));
                s.p = point_on(h);
                break;
            }
            case StepOp::AddVertex: s.p = interesting_point(); break;
            case StepOp::AddEdge: pair_on_a_face(s); break;
            case StepOp::AddEdgeToPoint:
                s.u = vertex();
                s.p = interesting_point();
                break;
            case StepOp::RemoveEdge: {
                // Half the time a bridge or dangling edge (the same face on
                // both sides), when there is one: its removal makes a new
                // hole or new isolated vertices.
                const HalfEdgeId h = rng_.chance(1, 2) ? bridge() : half_edge();
                if (h.is_null()) return any_vertex_step(s);
                s.u = id(d_.origin(h));
                s.v = id(d_.target(h));
                break;
            }
            case StepOp::RemoveIsolatedVertex: s.u = vertex_where([&](VertexId v) { return d_.out(v).is_null(); }); break;
            case StepOp::MergeCollinearEdges: s.u = vertex_where([&](VertexId v) { return degree(v) == 2; }); break;
            case StepOp::Locate:
            case StepOp::FaceBoundary:
            case StepOp::Neighbours: s.p = query_point(); break;
            case StepOp::Stab:
                s.p = query_point();
                s.q = query_point();
                break;
        }
        return s;
    }

    // A step of the kind `op` that the reference most likely refuses, each
    // edit in its own way: a split at an end of the edge or just off it, a
    // vertex or an edge end exactly at a vertex, an edge between any two
    // vertices (it often crosses one, or exists), an edge from a vertex to
    // itself, the removal of an edge that is not there, of a vertex that has
    // edges, a merge at a vertex that is not between two others, an id that
    // never was. Queries are never refused; they come as drawn.
    SessionStep draw_refused(StepOp op) {
        SessionStep s = draw(op);
        if (is_query(s.op) || d_.num_vertices() == 0) return s;
        if (rng_.chance(1, 10)) {  // an id that never was
            s.u = ref_.protocol_ids() + static_cast<Index>(rng_.below(3));
            if (s.op == StepOp::AddVertex) s.op = StepOp::RemoveIsolatedVertex;
            return s;
        }
        const Point at_vertex = point(VertexId(static_cast<Index>(rng_.below(d_.num_vertices()))));
        switch (s.op) {
            case StepOp::SplitEdge:
                if (const std::optional<VertexId> a = ref_.vertex_of(s.u)) {
                    s.p = rng_.chance(1, 2) ? point(*a) : Point{s.p.x, std::nextafter(s.p.y, 1e308)};
                }
                break;
            case StepOp::AddVertex:
            case StepOp::AddEdgeToPoint: s.p = at_vertex; break;
            case StepOp::AddEdge:
                s.u = vertex();
                s.v = rng_.chance(1, 4) ? s.u : vertex();
                break;
            case StepOp::RemoveEdge:
                s.u = vertex();
                s.v = vertex();
                break;
            case StepOp::RemoveIsolatedVertex: s.u = vertex_where([&](VertexId v) { return !d_.out(v).is_null(); }); break;
            case StepOp::MergeCollinearEdges: s.u = vertex_where([&](VertexId v) { return degree(v) != 2; }); break;
            default: break;
        }
        return s;
    }

private:
    // A step on some vertex when the DCEL has no edge to draw from.
    SessionStep any_vertex_step(SessionStep s) {
        s.op = StepOp::AddVertex;
        s.p = interesting_point();
        return s;
    }

    [[nodiscard]] Index id(VertexId v) const { return ref_.protocol_id(v); }

    [[nodiscard]] std::size_t degree(VertexId v) const {
        std::size_t n = 0;
        for (const HalfEdgeId h : d_.around_origin_cw(d_.out(v))) {
            (void)h;
            ++n;
        }
        return n;
    }

    HalfEdgeId half_edge() {
        if (d_.num_half_edges() == 0) return {};
        return HalfEdgeId(static_cast<Index>(rng_.below(d_.num_half_edges())));
    }

    // A half-edge whose twin has the same face, or any half-edge when none has.
    HalfEdgeId bridge() {
        std::vector<HalfEdgeId> bridges;
        for (Index h = 0; h < d_.num_half_edges(); ++h) {
            if (d_.face(HalfEdgeId(h)) == d_.face(twin(HalfEdgeId(h)))) bridges.push_back(HalfEdgeId(h));
        }
        return bridges.empty() ? half_edge() : rng_.pick(bridges);
    }

    // A protocol id: mostly a live vertex, sometimes one that is not (a
    // removed or never created id), which the reference refuses.
    Index vertex() {
        if (d_.num_vertices() == 0 || rng_.chance(1, 40)) return static_cast<Index>(rng_.below(ref_.protocol_ids() + 2));
        return id(VertexId(static_cast<Index>(rng_.below(d_.num_vertices()))));
    }

    template <class Pred>
    Index vertex_where(Pred ok) {
        std::vector<Index> fits;
        for (Index v = 0; v < d_.num_vertices(); ++v) {
            if (ok(VertexId(v))) fits.push_back(id(VertexId(v)));
        }
        return fits.empty() ? vertex() : rng_.pick(fits);
    }

    // Two vertices of one face (its boundary cycles and isolated vertices),
    // most often: an edge that splits the face, maybe around its holes.
    void pair_on_a_face(SessionStep& s) {
        s.u = vertex();
        s.v = vertex();
        if (d_.num_faces() == 0 || rng_.chance(1, 5)) return;
        const FaceId f(static_cast<Index>(rng_.below(d_.num_faces())));
        std::vector<Index> on;
        if (!d_.is_unbounded(f)) {
            for (const HalfEdgeId h : d_.cycle(d_.outer(f))) on.push_back(id(d_.origin(h)));
        }
        for (const HalfEdgeId start : d_.inner(f)) {
            for (const HalfEdgeId h : d_.cycle(start)) on.push_back(id(d_.origin(h)));
        }
        for (const VertexId v : d_.isolated(f)) on.push_back(id(v));
        if (on.size() < 2) return;
        s.u = rng_.pick(on);
        s.v = rng_.pick(on);
    }

    [[nodiscard]] Point point(VertexId v) const { return d_.point(v); }

    // A point on h at a dyadic fraction k / 2^m of its length: exact when
    // the sums round nowhere (small integers, long edges of large integers),
    // which is what makes the split legal; the reference decides.
    Point point_on(HalfEdgeId h) {
        const Point a = point(d_.origin(h)), b = point(d_.target(h));
        const int m = static_cast<int>(rng_.between(1, 5));
        const double t = std::ldexp(static_cast<double>(2 * rng_.below(std::uint64_t{1} << (m - 1)) + 1), -m);
        return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    }

    // The extent of the points, for offsets of the right magnitude.
    [[nodiscard]] double extent() const {
        double lo = 0, hi = 0;
        bool first = true;
        for (const Point p : d_.points()) {
            for (const double c : {p.x, p.y}) {
                lo = first ? c : std::min(lo, c);
                hi = first ? c : std::max(hi, c);
                first = false;
            }
        }
        const double e = hi - lo;
        return std::isfinite(e) && e > 0 ? e : 4.0;
    }

    // A power of two near a fraction of the extent: offsets that keep the
    // coordinates in their class and round nowhere near small integers.
    double step_size() {
        int exp = 0;
        (void)std::frexp(extent(), &exp);
        return std::ldexp(1.0, exp - static_cast<int>(rng_.between(1, 4)));
    }

    Point interesting_point() {
        if (d_.num_vertices() == 0)
            return {static_cast<double>(rng_.between(-4, 4)), static_cast<double>(rng_.between(-4, 4))};
        const Point a = point(VertexId(static_cast<Index>(rng_.below(d_.num_vertices()))));
        const double h = step_size();
        switch (rng_.below(4)) {
            case 0: return {a.x + h, a.y};  // beside a vertex: next to horizontal edges
            case 1: return {a.x, a.y + h};  // above it: next to vertical edges
            case 2: {                       // between two vertices
                const Point b = point(VertexId(static_cast<Index>(rng_.below(d_.num_vertices()))));
                return {a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
            }
            default:
                return {a.x + static_cast<double>(rng_.between(-3, 3)) * h,
                        a.y + static_cast<double>(rng_.between(-3, 3)) * h};
        }
    }

    // Where queries look: at a vertex, on an edge (vertical ones too), just
    // beside edges (inside faces and holes), and far out.
    Point query_point() {
        const std::uint64_t where = rng_.below(10);
        if (where == 0 && d_.num_vertices() > 0) return point(VertexId(static_cast<Index>(rng_.below(d_.num_vertices()))));
        if (where == 1 && d_.num_half_edges() > 0) return point_on(half_edge());
        if (where <= 4 && d_.num_half_edges() > 0) {
            // Just left of a half-edge's middle: inside the face on its left.
            const HalfEdgeId h = half_edge();
            const Point a = point(d_.origin(h)), b = point(d_.target(h));
            const Point m{a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
            const double s = std::ldexp(1.0, -static_cast<int>(rng_.between(4, 12)));
            return {m.x - (b.y - a.y) * s, m.y + (b.x - a.x) * s};
        }
        if (where == 5) {
            const double far = extent() * 4;
            return {rng_.chance(1, 2) ? far : -far, static_cast<double>(rng_.between(-2, 2))};
        }
        return interesting_point();
    }

    const check::detail::ReferenceSession& ref_;
    const Dcel& d_;
    Rng& rng_;
};

bool valid_graph(const PlanarGraph& g) {
    try {
        (void)build(g);
        return true;
    } catch (const InvalidInput&) {
        return false;
    }
}

// ---- Shrinking

// Which steps created a vertex (accepted split_edge, add_vertex,
// add_edge_to_point), and its protocol id.
std::vector<Index> created_ids(const Session& s) {
    std::vector<Index> created(s.steps.size(), kNoIndex);
    check::detail::ReferenceSession ref(s.start);
    for (std::size_t i = 0; i < s.steps.size(); ++i) {
        const Index before = ref.protocol_ids();
        const check::StepAnswer a = ref.apply(s.steps[i]);
        if (a.kind != check::StepAnswer::Kind::Error && ref.protocol_ids() > before) created[i] = before;
    }
    return created;
}

bool names(const SessionStep& s, Index v) {
    switch (s.op) {
        case StepOp::SplitEdge:
        case StepOp::RemoveEdge:
        case StepOp::AddEdge: return s.u == v || s.v == v;
        case StepOp::AddEdgeToPoint:
        case StepOp::RemoveIsolatedVertex:
        case StepOp::MergeCollinearEdges: return s.u == v;
        default: return false;
    }
}

// Protocol id v is gone: the steps that name it are dropped from `from` on,
// and every id above it moves down one.
void forget_id(Session& s, Index v, std::size_t from) {
    std::vector<SessionStep> kept(s.steps.begin(), s.steps.begin() + static_cast<std::ptrdiff_t>(from));
    for (std::size_t i = from; i < s.steps.size(); ++i) {
        SessionStep step = s.steps[i];
        if (names(step, v)) continue;
        for (Index* id : {&step.u, &step.v}) {
            if (*id != kNoIndex && *id > v) --*id;
        }
        kept.push_back(step);
    }
    s.steps = std::move(kept);
}

// s without steps [begin, end): the vertices they created are gone too.
Session without_steps(const Session& s, const std::vector<Index>& created, std::size_t begin, std::size_t end) {
    Session out = s;
    out.steps.erase(out.steps.begin() + static_cast<std::ptrdiff_t>(begin),
                    out.steps.begin() + static_cast<std::ptrdiff_t>(end));
    // Forget the created ids from the highest, so the lower ones stay put.
    for (std::size_t i = end; i-- > begin;) {
        if (created[i] != kNoIndex) forget_id(out, created[i], begin);
    }
    return out;
}

Session without_start_vertex(const Session& s, Index v) {
    Session out = s;
    out.start.vertices.erase(out.start.vertices.begin() + v);
    std::vector<GraphEdge> edges;
    for (GraphEdge e : s.start.edges) {
        if (e.u.index() == v || e.v.index() == v) continue;
        if (e.u.index() > v) e.u = VertexId(e.u.index() - 1);
        if (e.v.index() > v) e.v = VertexId(e.v.index() - 1);
        edges.push_back(e);
    }
    out.start.edges = std::move(edges);
    forget_id(out, v, 0);
    return out;
}

// s without start vertex v of degree two, its neighbours a and b joined
// instead (a polygon one corner smaller); nothing when v has not degree two
// or a and b are joined already. The new edge may cross another: the
// candidate's start graph is then not valid, and next() skips it.
std::optional<Session> smoothed(const Session& s, Index v) {
    std::vector<Index> ends;
    for (const GraphEdge& e : s.start.edges) {
        if (e.u.index() == v) ends.push_back(e.v.index());
        if (e.v.index() == v) ends.push_back(e.u.index());
    }
    if (ends.size() != 2 || ends[0] == ends[1]) return std::nullopt;
    for (const GraphEdge& e : s.start.edges) {
        if ((e.u.index() == ends[0] && e.v.index() == ends[1]) || (e.u.index() == ends[1] && e.v.index() == ends[0])) {
            return std::nullopt;
        }
    }
    Session with = s;
    with.start.edges.push_back({VertexId(ends[0]), VertexId(ends[1])});
    return without_start_vertex(with, v);
}

// Every point of the session, the start graph's then the steps' (p and q).
std::vector<Point> all_points(const Session& s) {
    std::vector<Point> ps = s.start.vertices;
    for (const SessionStep& step : s.steps) {
        ps.push_back(step.p);
        ps.push_back(step.q);
    }
    return ps;
}

std::optional<Session> with_points(const Session& s, const std::optional<PlanarGraph>& moved) {
    if (!moved) return std::nullopt;
    Session out = s;
    const std::size_t n = s.start.vertices.size();
    std::copy(moved->vertices.begin(), moved->vertices.begin() + static_cast<std::ptrdiff_t>(n), out.start.vertices.begin());
    for (std::size_t i = 0; i < out.steps.size(); ++i) {
        out.steps[i].p = moved->vertices[n + 2 * i];
        out.steps[i].q = moved->vertices[n + 2 * i + 1];
    }
    return out;
}

// The exact maps of every point at once (gen::apply on a graph of all the
// points and no edges, which only checks that nothing rounds).
void coordinate_candidates(const Session& s, std::vector<Session>& out) {
    PlanarGraph points;
    points.vertices = all_points(s);
    double biggest = 0;
    bool integral = true;
    for (const Point p : points.vertices) {
        biggest = std::max({biggest, std::fabs(p.x), std::fabs(p.y)});
        integral = integral && std::trunc(p.x) == p.x && std::trunc(p.y) == p.y;
    }
    if (biggest == 0) return;
    int exp = 0;
    (void)std::frexp(biggest, &exp);
    // Every coordinate rounded onto a grid of 2^k steps across the largest,
    // as integers (k = 1 first: the coarsest; exact, since dividing by a power
    // of two rounds nothing here). Rounding moves points, so a candidate may
    // have a crossing (next() skips it) or no longer fail (it is not taken).
    // These come last out of `out`, so they are tried first.
    std::vector<Session> grids;
    if (!integral || biggest > 64) {
        for (int k = 1; k <= 12; ++k) {
            Session c = s;
            const auto snap = [&](Point& p) {
                // (+ 0.0: a -0 becomes 0, the plainer spelling)
                p = {std::nearbyint(std::ldexp(p.x, k - exp)) + 0.0, std::nearbyint(std::ldexp(p.y, k - exp)) + 0.0};
            };
            for (Point& p : c.start.vertices) snap(p);
            for (SessionStep& step : c.steps) {
                snap(step.p);
                snap(step.q);
            }
            grids.push_back(std::move(c));
        }
    }
    // Towards magnitudes of a few units: scale by 2^-k (or up from tiny).
    const int target = integral ? std::min(exp, 4) : 4;
    if (exp != target) {
        if (auto c = with_points(s, apply(points, Transform::ScalePow2, target - exp))) out.push_back(std::move(*c));
    }
    if (!s.start.vertices.empty()) {
        const Point o = s.start.vertices.front();
        if (o.x != 0 && o.x == -o.y) {
            if (auto c = with_points(s, apply(points, Transform::Translate, static_cast<std::int64_t>(-o.x)))) {
                out.push_back(std::move(*c));
            }
        }
    }
    out.insert(out.end(), std::make_move_iterator(grids.rbegin()), std::make_move_iterator(grids.rend()));
}

// How hard the coordinates are to read: for each, the bits of its
// significand and how far its exponent is from that of a small integer.
std::uint64_t coordinate_cost(const Session& s) {
    std::uint64_t cost = 0;
    const auto add = [&](double x) {
        if (x == 0 || !std::isfinite(x)) return;
        int exp = 0;
        double m = std::fabs(std::frexp(x, &exp));  // in [0.5, 1)
        std::uint64_t bits = 0;
        while (m != 0 && bits < 64) {  // significant bits after the binary point
            m = m * 2 - std::trunc(m * 2);
            ++bits;
        }
        cost += bits + static_cast<std::uint64_t>(std::abs(exp - 2));
    };
    for (const Point p : all_points(s)) {
        add(p.x);
        add(p.y);
    }
    return cost;
}

// s with its first k steps folded into the start graph: the reference's
// state after them becomes the start (the protocol ids stay, so the later
// steps name the same vertices), and the steps are the rest. Then the start
// graph's own candidates can drop what those steps built. Nothing when a
// vertex was removed by then (its id would leave a gap in the start).
std::optional<Session> folded(const Session& s, std::size_t k) {
    check::detail::ReferenceSession ref(s.start);
    for (std::size_t i = 0; i < k; ++i) (void)ref.apply(s.steps[i]);
    const Dcel& d = ref.dcel();
    if (d.num_vertices() != ref.protocol_ids()) return std::nullopt;
    Session out;
    out.each_step = s.each_step;
    out.start.vertices.resize(d.num_vertices());
    for (Index v = 0; v < d.num_vertices(); ++v) out.start.vertices[ref.protocol_id(VertexId(v))] = d.point(VertexId(v));
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        out.start.edges.push_back({VertexId(ref.protocol_id(d.origin(h))), VertexId(ref.protocol_id(d.target(h)))});
    }
    out.steps.assign(s.steps.begin() + static_cast<std::ptrdiff_t>(k), s.steps.end());
    return out;
}

}  // namespace

check::Session generate_session(const SessionParams& params) {
    Session s;
    s.start = generate(params.graph);
    if (params.coordinates) {
        if (std::optional<PlanarGraph> mapped = to_coordinate_class(s.start, *params.coordinates, params.seed)) {
            s.start = std::move(*mapped);
        }
    }
    Rng rng(params.seed ^ 0x5e5510eULL);
    check::detail::ReferenceSession ref(s.start);
    constexpr int kTries = 8;
    // Each step: about one in eight drawn to be refused (the reference's
    // refusals are checked too: an implementation must refuse them as well),
    // the others a few tries at an accepted one. Bounded, in case the graph
    // leaves nothing to do but refusals.
    for (std::size_t draws = 0; s.steps.size() < params.steps && draws < 20 * params.steps + 20; ++draws) {
        const StepOp op = draw_op(rng);
        if (rng.chance(1, 8)) {
            const SessionStep step = StepDrawer(ref, rng).draw_refused(op);
            (void)ref.apply(step);  // refused, most likely; applied when not
            s.steps.push_back(step);
            continue;
        }
        SessionStep step;
        bool accepted = false;
        for (int t = 0; t < kTries && !accepted; ++t) {
            step = StepDrawer(ref, rng).draw(op);
            accepted = ref.apply(step).kind != check::StepAnswer::Kind::Error;  // a refusal changes nothing
        }
        if (accepted) s.steps.push_back(step);
    }
    return s;
}

SessionShrinkCandidates::SessionShrinkCandidates(check::Session s) : s_(std::move(s)), created_(created_ids(s_)) {}

// Runs of halving length over n items, as (begin, end): the candidates of
// one stage, numbered by index_. False when index_ is past the last.
bool SessionShrinkCandidates::run_at(std::size_t n, std::size_t& begin, std::size_t& end) const {
    std::size_t i = index_;
    for (std::size_t run = std::max<std::size_t>(n, 1); n > 0; run /= 2) {
        const std::size_t count = (n + run - 1) / run;
        if (i < count) {
            begin = i * run;
            end = std::min(n, begin + run);
            return true;
        }
        i -= count;
        if (run == 1) break;
    }
    return false;
}

std::optional<check::Session> SessionShrinkCandidates::next() {
    for (;;) {
        std::optional<Session> c = candidate();
        if (!c) return std::nullopt;
        if (valid_graph(c->start)) return c;
    }
}

// The next candidate of the current stage, or of the next stage when this
// one is done; nothing after the last.
std::optional<check::Session> SessionShrinkCandidates::candidate() {
    const std::size_t n = s_.steps.size();
    for (;;) {
        std::size_t begin = 0, end = 0;
        switch (stage_) {
            case 0:  // prefixes: the steps after the first half, three quarters, ... dropped
                if (keep_ < n) {
                    const std::size_t keep = keep_;
                    keep_ = keep_ == 0 ? std::max<std::size_t>(n / 2, 1) : keep_ + std::max<std::size_t>((n - keep_) / 2, 1);
                    return without_steps(s_, created_, keep, n);
                }
                break;
            case 1:  // runs of steps anywhere
                if (run_at(n, begin, end)) {
                    ++index_;
                    return without_steps(s_, created_, begin, end);
                }
                break;
            case 2:  // the first steps folded into the start graph, the most first
                if (index_ < n) {
                    const std::size_t k = n - index_++;
                    if (std::optional<Session> c = folded(s_, k)) return c;
                    continue;
                }
                break;
            case 3:  // runs of start edges
                if (run_at(s_.start.edges.size(), begin, end)) {
                    ++index_;
                    Session c = s_;
                    c.start.edges.erase(c.start.edges.begin() + static_cast<std::ptrdiff_t>(begin),
                                        c.start.edges.begin() + static_cast<std::ptrdiff_t>(end));
                    return c;
                }
                break;
            case 4:  // runs of start vertices, with their edges and the steps naming them
                if (run_at(s_.start.vertices.size(), begin, end)) {
                    ++index_;
                    Session c = s_;
                    for (std::size_t v = end; v-- > begin;) c = without_start_vertex(c, static_cast<Index>(v));
                    return c;
                }
                break;
            case 5:  // start vertices of degree two smoothed away, one at a time
                if (index_ < s_.start.vertices.size()) {
                    if (std::optional<Session> c = smoothed(s_, static_cast<Index>(index_++))) return c;
                    continue;
                }
                break;
            case 6:  // exact maps of every coordinate
                if (index_ == 0) {
                    ++index_;
                    coordinate_candidates(s_, maps_);
                }
                while (!maps_.empty()) {
                    Session c = std::move(maps_.back());
                    maps_.pop_back();
                    // Only a simpler one: taking candidates that are not
                    // (the same points again, or a scaling undone by a
                    // rounding) could go round for ever.
                    if (coordinate_cost(c) < coordinate_cost(s_)) return c;
                }
                break;
            default: return std::nullopt;
        }
        ++stage_;
        index_ = 0;
    }
}

std::vector<check::Session> session_shrink_candidates(const check::Session& s) {
    std::vector<Session> out;
    SessionShrinkCandidates candidates(s);
    while (std::optional<Session> c = candidates.next()) out.push_back(std::move(*c));
    return out;
}

GreedySessionShrink shrink_session_greedily(check::Session s, const std::function<bool(const check::Session&)>& still_fails,
                                            const std::function<bool()>& stop) {
    GreedySessionShrink out{std::move(s)};
    for (bool moved = true; moved;) {
        moved = false;
        SessionShrinkCandidates candidates(out.session);
        while (std::optional<Session> c = candidates.next()) {
            if (stop()) {
                out.stopped = true;
                return out;
            }
            ++out.tried;
            if (still_fails(*c)) {
                out.session = std::move(*c);
                ++out.taken;
                moved = true;
                break;
            }
        }
    }
    return out;
}

}  // namespace dcel::gen
