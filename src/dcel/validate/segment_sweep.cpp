#include "dcel/validate/segment_sweep.hpp"

#include <algorithm>
#include <iterator>
#include <memory_resource>
#include <set>
#include <utility>

#include "dcel/geometry/predicates.hpp"

namespace dcel::detail {
namespace {

// An edge as the sweep sees it: from its lex-smaller end to the other. The
// status holds these by value, so that its search reads the points from the
// tree's nodes and not through the edge ids.
struct Segment {
    Point left;
    Point right;
    VertexId left_vertex;
    VertexId right_vertex;
    Index edge = kNoIndex;
};

Segment segment_of(const PlanarGraph& g, Index k) {
    const GraphEdge& e = g.edges[k];
    const Point pu = g.vertices[e.u.index()];
    const Point pv = g.vertices[e.v.index()];
    return lex_less(pu, pv) ? Segment{pu, pv, e.u, e.v, k} : Segment{pv, pu, e.v, e.u, k};
}

// p lies inside s (on it, and not an end). Points on one line come in lex
// order along it, so "between the ends" needs no arithmetic.
bool inside(const Segment& s, Point p) {
    return lex_less(s.left, p) && lex_less(p, s.right) && orient2d(s.left, s.right, p) == Sign::Zero;
}

// The order of the status, bottom to top, for two segments that are both
// cut by the sweep line and do not meet but at a shared end. Their order
// is the same wherever both are cut, so it is decided where the one that
// starts later starts: that point is above or below the other one (on it,
// it would lie inside it). Two that start together are ordered by turn.
// Such segments are never equal unless they run the same way from one point.
//
// A point is compared with a segment cut by the sweep line through it (the
// point lies above, on or below it), for the search that locates an event.
struct StatusOrder {
    using is_transparent = void;  // lower_bound takes a point

    bool operator()(const Segment& s, const Segment& t) const {
        if (s.left == t.left) return orient2d(s.left, s.right, t.right) == Sign::Positive;
        if (lex_less(s.left, t.left)) return orient2d(s.left, s.right, t.left) == Sign::Positive;
        return orient2d(t.left, t.right, s.left) == Sign::Negative;
    }
    bool operator()(const Segment& s, Point p) const {  // s passes below p
        return orient2d(s.left, s.right, p) == Sign::Positive;
    }
    bool operator()(Point p, const Segment& s) const {  // p is below s
        return orient2d(s.left, s.right, p) == Sign::Negative;
    }
};

using Status = std::pmr::set<Segment, StatusOrder>;

class SegmentSweep {
public:
    SegmentSweep(const PlanarGraph& g, std::span<const VertexId> order, std::span<const char> wanted, bool find_contact)
        : g_(g), order_(order), wanted_(wanted), find_contact_(find_contact), status_(StatusOrder{}, &pool_) {
        group_edges();
        where_.resize(starting_.size());
        active_.assign(starting_.size(), 0);
        answers_.below.resize(wanted.empty() ? 0 : g.vertices.size());
    }

    SweepAnswers run() {
        for (Index r = 0; r < order_.size() && !answers_.contact; ++r) visit(r);
        return std::move(answers_);
    }

private:
    // The edges by the rank (the place in the sweep order) of their left
    // end, in slots: starting_[starts_at_[r] .. starts_at_[r + 1]) start at
    // the vertex of rank r, by edge id. ending_ lists the slots of the edges
    // by the rank of their right end, likewise. So the sweep reads the edges
    // about in the order it meets them, whatever the input's numbering.
    void group_edges() {
        const std::size_t n = order_.size();
        const auto m = static_cast<Index>(g_.edges.size());
        std::vector<Index> rank(n);
        for (Index r = 0; r < n; ++r) rank[order_[r].index()] = r;
        starts_at_.assign(n + 1, 0);
        ends_at_.assign(n + 1, 0);
        for (Index k = 0; k < m; ++k) {
            const Segment s = segment_of(g_, k);
            ++starts_at_[rank[s.left_vertex.index()] + 1];
            ++ends_at_[rank[s.right_vertex.index()] + 1];
        }
        for (std::size_t r = 0; r < n; ++r) {
            starts_at_[r + 1] += starts_at_[r];
            ends_at_[r + 1] += ends_at_[r];
        }
        starting_.resize(m);
        ending_.resize(m);
        std::vector<Index> next_start(starts_at_.begin(), starts_at_.end() - 1);
        std::vector<Index> next_end(ends_at_.begin(), ends_at_.end() - 1);
        for (Index k = 0; k < m; ++k) {
            const Segment s = segment_of(g_, k);
            const Index slot = next_start[rank[s.left_vertex.index()]]++;
            starting_[slot] = s;
            ending_[next_end[rank[s.right_vertex.index()]]++] = slot;
        }
    }

    // One event: the edges ending at the vertex of rank r leave the status,
    // the vertex is located among the rest (and checked against the edge
    // just above it), the edges starting there enter, and the pairs of edges
    // that have just become neighbours are tested.
    void visit(Index r) {
        const VertexId v = order_[r];
        const Point p = g_.vertices[v.index()];
        const bool any_ended = remove_ending(r);
        const auto above = status_.lower_bound(p);  // the first edge not below p
        const auto below = above == status_.begin() ? status_.end() : std::prev(above);
        if (find_contact_ && above != status_.end() && inside(*above, p)) {
            return report(SweepContact::Kind::VertexInside, above->edge, kNoIndex, v);
        }
        if (!answers_.below.empty() && wanted_[v.index()] != 0 && below != status_.end()) {
            answers_.below[v.index()] = EdgeId(below->edge);
        }
        if (!insert_starting(r) || !find_contact_) return;
        if (starts_at_[r + 1] == starts_at_[r]) {  // nothing started here
            if (any_ended && below != status_.end() && above != status_.end()) test_pair(*below, *above);
            return;
        }
        // The new edges lie between `below` and `above`: nothing else passes
        // through p (that was just checked), and they all start at p.
        const auto lowest_new = below == status_.end() ? status_.begin() : std::next(below);
        const auto highest_new = std::prev(above);
        if (below != status_.end()) test_pair(*below, *lowest_new);
        if (!answers_.contact && above != status_.end()) test_pair(*highest_new, *above);
    }

    // Returns whether any edge ended at the vertex of rank r.
    bool remove_ending(Index r) {
        for (Index i = ends_at_[r]; i < ends_at_[r + 1]; ++i) {
            const Index slot = ending_[i];
            if (active_[slot] == 0) continue;  // it never entered (see insert_starting)
            status_.erase(where_[slot]);
            active_[slot] = 0;
        }
        return ends_at_[r + 1] > ends_at_[r];
    }

    // Returns false when a contact was found (two edges leaving the vertex
    // the same way).
    bool insert_starting(Index r) {
        for (Index slot = starts_at_[r]; slot < starts_at_[r + 1]; ++slot) {
            const Segment& s = starting_[slot];
            const auto [it, fresh] = status_.insert(s);
            if (!fresh) {
                if (!find_contact_) continue;  // an invalid drawing: leave it out
                test_pair(*it, s);
                if (!answers_.contact) report(SweepContact::Kind::SameSegment, it->edge, s.edge, VertexId());
                return false;
            }
            where_[slot] = it;
            active_[slot] = 1;
        }
        return true;
    }

    // Reports how edges a and b meet, if improperly: a crossing, else an end
    // of one inside the other (a's ends first, left end first), else the
    // same two ends.
    void test_pair(const Segment& s, const Segment& t) {
        const Index a = s.edge;
        const Index b = t.edge;
        const Sign s_left = orient2d(s.left, s.right, t.left);
        const Sign s_right = orient2d(s.left, s.right, t.right);
        const Sign t_left = orient2d(t.left, t.right, s.left);
        const Sign t_right = orient2d(t.left, t.right, s.right);
        if (s_left != Sign::Zero && s_left == -s_right && t_left != Sign::Zero && t_left == -t_right) {
            return report(SweepContact::Kind::Crossing, a, b, VertexId());
        }
        if (inside(t, s.left)) return report(SweepContact::Kind::VertexInside, b, a, s.left_vertex);
        if (inside(t, s.right)) return report(SweepContact::Kind::VertexInside, b, a, s.right_vertex);
        if (inside(s, t.left)) return report(SweepContact::Kind::VertexInside, a, b, t.left_vertex);
        if (inside(s, t.right)) return report(SweepContact::Kind::VertexInside, a, b, t.right_vertex);
        if (s.left == t.left && s.right == t.right) report(SweepContact::Kind::SameSegment, a, b, VertexId());
    }

    void report(SweepContact::Kind kind, Index edge, Index other, VertexId vertex) {
        answers_.contact = SweepContact{kind, EdgeId(edge), EdgeId(other), vertex};
    }

    const PlanarGraph& g_;
    std::span<const VertexId> order_;
    std::span<const char> wanted_;
    bool find_contact_;
    std::vector<Index> starts_at_;                 // by rank, see group_edges
    std::vector<Segment> starting_;                // by slot
    std::vector<Index> ends_at_;                   // by rank
    std::vector<Index> ending_;                    // slots
    std::pmr::unsynchronized_pool_resource pool_;  // the status's nodes, reused as edges come and go
    Status status_;
    std::vector<Status::iterator> where_;  // by slot, while active
    std::vector<char> active_;             // by slot: in the status now
    SweepAnswers answers_;
};

}  // namespace

std::vector<VertexId> sweep_order(const PlanarGraph& g) {
    std::vector<VertexId> order(g.vertices.size());
    for (Index v = 0; v < order.size(); ++v) order[v] = VertexId(v);
    std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) {
        const Point pa = g.vertices[a.index()];
        const Point pb = g.vertices[b.index()];
        if (lex_less(pa, pb)) return true;
        if (lex_less(pb, pa)) return false;
        return a < b;
    });
    return order;
}

SweepAnswers sweep_segments(const PlanarGraph& g, std::span<const VertexId> order, std::span<const char> wanted,
                            bool find_contact) {
    return SegmentSweep(g, order, wanted, find_contact).run();
}

}  // namespace dcel::detail
