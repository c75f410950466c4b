#include "dcel/build/sweep.hpp"

#include <algorithm>
#include <utility>
#include "dcel/contracts.hpp"

#include "dcel/build/huge_pages.hpp"
#include "dcel/build/status_list.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/geometry/segments.hpp"

namespace dcel::detail {
namespace {

// An edge as the sweep sees it, from its left (lexicographically smaller)
// endpoint to its right one; ranks are indexes into RankGraph::point.
struct Span {
    Index left;
    Index right;
    Index start_slot;  // the slot of the half-edge left -> right
    Index edge;        // the input edge id, for messages
};

[[noreturn]] void throw_vertex_on_edge(const PlanarGraph& g, VertexId v, EdgeId e) {
    // A vertex inside an edge is an overlap when one of its own edges runs
    // along that edge; otherwise it is a T-junction.
    const GraphEdge& ge = g.edges[e.index()];
    const Point a = g.vertices[ge.u.index()];
    const Point b = g.vertices[ge.v.index()];
    for (Index k = 0; k < g.edges.size(); ++k) {
        const GraphEdge& other = g.edges[k];
        if (k == e.index() || (other.u != v && other.v != v)) continue;
        const VertexId w = other.u == v ? other.v : other.u;
        const Point pw = g.vertices[w.index()];
        if (orient2d(a, b, pw) == Sign::Zero && segment_contact(a, b, g.vertices[v.index()], pw) == Contact::Overlap) {
            const EdgeId lo = EdgeId(std::min(k, e.index()));
            const EdgeId hi = EdgeId(std::max(k, e.index()));
            throw InvalidInput(InputErrorKind::Overlap,
                               describe_edge(g, lo) + " and " + describe_edge(g, hi) +
                                   " overlap along a collinear stretch; merge them into one chain of edges",
                               {v}, {lo, hi});
        }
    }
    throw InvalidInput(InputErrorKind::VertexOnEdge,
                       describe_vertex(g, v) + " lies inside " + describe_edge(g, e) + "; split edge " +
                           std::to_string(e.index()) + " at vertex " + std::to_string(v.index()),
                       {v}, {e});
}

class Sweep {
public:
    Sweep(const RankGraph& rg, const PlanarGraph& g, bool check, std::span<const char> in_status)
        : rg_(rg), g_(g), check_(check), in_status_(in_status), status_(static_cast<Index>(g.edges.size())) {
        assign_huge(node_of_slot_, rg.num_slots(), kNoIndex);
        reserve_huge(spans_, g.edges.size() + std::size_t{1});  // touched only up to the ids made
    }

    // One event per vertex, in rank order: O(degree) list work, plus, when
    // no edge arrives from the left, a walk of a few steps from the previous
    // vertex's place (near_hint) or else one O(log n) search, plus O(1)
    // predicate calls for the checks.
    void run(std::span<const char> wanted, std::span<Index> below) {
        for (Index r = 0; r < rg_.num_vertices(); ++r) visit(r, wanted, below);
    }

private:
    [[nodiscard]] Point left(Index e) const { return rg_.point[spans_[e].left]; }
    [[nodiscard]] Point right(Index e) const { return rg_.point[spans_[e].right]; }
    // Edge e passes below p: p is to the left of e, looking from left to right.
    [[nodiscard]] bool below_point(Index e, Point p) const { return orient2d(left(e), right(e), p) == Sign::Positive; }

    // Where an edge's status node is recorded: in the slot at its right end
    // when that ring is small (found by a scan of it, next door in memory),
    // else in the slot at its left end (found from the right end by a scan
    // or search of the left end's ring). Either way both ends reach it
    // through memory near them, never through the input's edge ids.
    [[nodiscard]] Index home_of_starting(Index r, Index s) const {
        const Index t = rg_.target[s];
        return rg_.small(t) ? rg_.slot_towards(t, r) : s;
    }
    [[nodiscard]] Index home_of_ending(Index r, Index s) const {
        return rg_.small(r) ? s : rg_.slot_towards(rg_.target[s], r);
    }

    // Where a vertex sits in the status: the active edges just below and just
    // above it (kNone past either end).
    struct Place {
        Index below = StatusList::kNone;
        Index above = StatusList::kNone;
    };
    // The edges a vertex put into the status: the lowest (kNone when none
    // started there) and the top one, the highest of them or, when none
    // started, the edge below the vertex.
    struct Inserted {
        Index lowest = StatusList::kNone;
        Index top = StatusList::kNone;
    };

    // Every step is called once per vertex and inlined (members of a class
    // in this file): splitting the event into named steps costs no call.
    void visit(Index r, std::span<const char> wanted, std::span<Index> below_out) {
        if (!in_status_.empty() && in_status_[r] == 0) {
            if (wanted[r] != 0) locate_only(r, below_out);
            return;
        }
        const Point p = rg_.point[r];
        Place place;
        const bool any_ending = remove_ending(r, place);
        // `above` must be the first active edge not below p (what a search
        // would find). The candidates are that exactly when `below` is below
        // p and `above` is not; otherwise, and when nothing ended here, search.
        if (!any_ending || (place.below != StatusList::kNone && !below_point(place.below, p)) ||
            (place.above != StatusList::kNone && below_point(place.above, p))) {
            locate(p, place.below, place.above);
        }
        if (check_ && place.above != StatusList::kNone && orient2d(left(place.above), right(place.above), p) == Sign::Zero) {
            throw_vertex_on_edge(g_, rg_.vertex[r], EdgeId(spans_[place.above].edge));
        }
        if (wanted[r] != 0) below_out[r] = place.below == StatusList::kNone ? kNoIndex : spans_[place.below].start_slot;
        const Inserted added = insert_starting(r, place.below);
        hint_ = added.top != StatusList::kNone ? added.top : place.above;
        if (check_) check_new_neighbours(place, added, any_ending);
    }

    // Edges ending at r leave the status. In a consistent status they are
    // adjacent: their neighbours below and above, set in `place`, are the
    // candidates for r's place. Returns whether any edge ended here.
    bool remove_ending(Index r, Place& place) {
        bool any_ending = false;
        for (Index s = rg_.offset[r]; s < rg_.offset[r + 1]; ++s) {
            if (rg_.target[s] >= r) continue;
            const Index e = node_of_slot_[home_of_ending(r, s)];
            if (e == kNoIndex || !status_.contains(e)) continue;
            // Each edge leaves once, at its right end, so the node recorded for
            // it is still its own, though ids are reused.
            DCEL_ASSERT(spans_[e].right == r && spans_[e].left == rg_.target[s]);
            if (!any_ending) {
                Index lo = e;
                Index hi = e;
                while (status_.prev(lo) != StatusList::kNone && spans_[status_.prev(lo)].right == r) lo = status_.prev(lo);
                while (status_.next(hi) != StatusList::kNone && spans_[status_.next(hi)].right == r) hi = status_.next(hi);
                place.below = status_.prev(lo);
                place.above = status_.next(hi);
                any_ending = true;
            }
            status_.erase(e);
        }
        return any_ending;
    }

    // The slot of the lowest edge starting at r. The ring lists directions
    // counterclockwise from east, so the starting edges in the lower
    // half-plane (the ring's second half) are the lowest. Edges ending here
    // point into (pi/2, 3pi/2] and starting ones into (-pi/2, pi/2], so the
    // ending ones form one run of the ring, and the starting edges after it
    // are exactly those in the lower half: the split is found from ranks
    // alone when anything ends here.
    [[nodiscard]] Index lowest_starting_slot(Index r) const {
        const Index ring_begin = rg_.offset[r];
        const Index ring_end = rg_.offset[r + 1];
        Index split = ring_end;
        for (Index s = ring_end; s > ring_begin; --s) {
            if (rg_.target[s - 1] < r) break;
            split = s - 1;
        }
        if (split == ring_begin) {  // nothing ends here
            const Point p = rg_.point[r];
            while (split < ring_end && angular_half(p, rg_.point[rg_.target[split]]) == 0) ++split;
        }
        return split;
    }

    // Edges starting at r enter the status bottom to top, just above `below`:
    // from the lowest starting slot to the ring's end, then round from its
    // beginning.
    Inserted insert_starting(Index r, Index below) {
        Inserted added{StatusList::kNone, below};
        auto insert = [&](Index s) {
            if (rg_.target[s] < r) return;
            const Index edge = edge_of(rg_.half_edge[s]).index();
            const Index e = status_.insert_above(added.top);
            node_of_slot_[home_of_starting(r, s)] = e;
            if (e >= spans_.size()) spans_.resize(e + std::size_t{1});
            spans_[e] = Span{r, rg_.target[s], s, edge};
            if (added.lowest == StatusList::kNone) added.lowest = e;
            added.top = e;
        };
        const Index split = lowest_starting_slot(r);
        for (Index s = split; s < rg_.offset[r + 1]; ++s) insert(s);
        for (Index s = rg_.offset[r]; s < split; ++s) insert(s);
        return added;
    }

    // The pairs of edges that became neighbours in the status at this
    // vertex: the new edges' outer neighbours, or, when nothing started
    // here, the two edges that the ending ones separated.
    void check_new_neighbours(const Place& place, const Inserted& added, bool any_ending) const {
        if (added.lowest == StatusList::kNone) {
            if (any_ending && place.below != StatusList::kNone && place.above != StatusList::kNone) {
                check_pair(place.below, place.above);
            }
        } else {
            if (place.below != StatusList::kNone) check_pair(place.below, added.lowest);
            if (place.above != StatusList::kNone) check_pair(added.top, place.above);
        }
    }

    // The adjacent pair of active edges (below, above) with `below` below p
    // and `above` not (kNone past either end): near the previous vertex's
    // place if possible, else by a search.
    void locate(Point p, Index& below, Index& above) const {
        if (near_hint(p, below, above)) return;
        above = status_.first_not_below([&](Index e) { return below_point(e, p); });
        below = above == StatusList::kNone ? status_.last() : status_.prev(above);
    }

    // A vertex whose edges stay out of the status (see sweep_ranks): only
    // the edge below it is looked up.
    void locate_only(Index r, std::span<Index> below_out) {
        Index below = StatusList::kNone;
        Index above = StatusList::kNone;
        locate(rg_.point[r], below, above);
        below_out[r] = below == StatusList::kNone ? kNoIndex : spans_[below].start_slot;
        hint_ = above != StatusList::kNone ? above : below;
    }

    // The place of p found from the node the previous vertex left in hint_,
    // within a few steps along the status: the pair (below, above) of
    // neighbours with `below` below p and `above` not (kNone past either
    // end). In a status partitioned by below_point there is exactly one such
    // pair, the one the full search finds; consecutive vertices of nested
    // polygons and of edges that share a column meet it in one or two
    // orient2d calls. Returns false (nothing set) when the walk runs out.
    bool near_hint(Point p, Index& below, Index& above) const {
        constexpr int kSteps = 12;
        Index h = hint_;
        if (h == StatusList::kNone || !status_.contains(h)) return false;
        if (below_point(h, p)) {
            for (int step = 0; step < kSteps; ++step) {
                const Index n = status_.next(h);
                if (n == StatusList::kNone || !below_point(n, p)) {
                    below = h;
                    above = n;
                    return true;
                }
                h = n;
            }
        } else {
            for (int step = 0; step < kSteps; ++step) {
                const Index b = status_.prev(h);
                if (b == StatusList::kNone || below_point(b, p)) {
                    below = b;
                    above = h;
                    return true;
                }
                h = b;
            }
        }
        return false;
    }

    // Throws when the edges of nodes ns and nt meet other than at a shared
    // endpoint.
    void check_pair(Index ns, Index nt) const {
        const Index s = spans_[ns].edge;
        const Index t = spans_[nt].edge;
        const Point a_left = left(ns);
        const Point a_right = right(ns);
        const Point b_left = left(nt);
        const Point b_right = right(nt);
        switch (segment_contact(a_left, a_right, b_left, b_right)) {
            case Contact::None:
            case Contact::SharedEndpoint: return;
            case Contact::Crossing: {
                const EdgeId lo = EdgeId(std::min(s, t));
                const EdgeId hi = EdgeId(std::max(s, t));
                throw InvalidInput(
                    InputErrorKind::Crossing,
                    describe_edge(g_, lo) + " and " + describe_edge(g_, hi) + " cross; split both at their crossing point",
                    {}, {lo, hi});
            }
            case Contact::Touch:
            case Contact::Overlap: {
                // Name a vertex that lies inside the other segment.
                const std::pair<Index, Index> cases[] = {{ns, nt}, {nt, ns}};
                for (const auto& [seg, other] : cases) {
                    for (const Index v : {spans_[seg].left, spans_[seg].right}) {
                        if (strictly_inside_segment(left(other), right(other), rg_.point[v])) {
                            throw_vertex_on_edge(g_, rg_.vertex[v], EdgeId(spans_[other].edge));
                        }
                    }
                }
                throw InvalidInput(InputErrorKind::Overlap,
                                   describe_edge(g_, EdgeId(s)) + " and " + describe_edge(g_, EdgeId(t)) + " overlap", {},
                                   {EdgeId(s), EdgeId(t)});
            }
        }
    }

    // Status node ids are handed out by the list, which reuses the ids of
    // erased nodes: the spans and the list touch memory for the most edges
    // active at once, and recently active edges sit close in memory whatever
    // the input order.
    const RankGraph& rg_;
    const PlanarGraph& g_;
    bool check_;
    std::span<const char> in_status_;  // empty: every edge enters the status
    std::vector<Index> node_of_slot_;  // see home_of_starting
    std::vector<Span> spans_;          // by node id
    StatusList status_;
    Index hint_ = StatusList::kNone;  // a node near the previous vertex, see near_hint
};

}  // namespace

void sweep_ranks(const RankGraph& rg, const PlanarGraph& graph, std::span<const char> wanted, std::span<Index> below,
                 bool check_intersections, std::span<const char> in_status) {
    DCEL_ASSERT(in_status.empty() || !check_intersections);
    Sweep(rg, graph, check_intersections, in_status).run(wanted, below);
}

std::vector<EdgeId> sweep(const SweepInput& in, bool check_intersections) {
    const PlanarGraph& g = in.graph;
    const RankGraph rg = rank_graph_from_rings(g, in.lex_order, in.ring_offset, in.ring);
    const Index n = rg.num_vertices();
    std::vector<char> wanted(n);
    for (Index r = 0; r < n; ++r) wanted[r] = in.wanted[rg.vertex[r].index()];
    std::vector<Index> below_slot(n, kNoIndex);
    sweep_ranks(rg, g, wanted, below_slot, check_intersections);
    std::vector<EdgeId> below(n);
    for (Index r = 0; r < n; ++r) {
        if (below_slot[r] != kNoIndex) below[rg.vertex[r].index()] = edge_of(rg.half_edge[below_slot[r]]);
    }
    return below;
}

}  // namespace dcel::detail
