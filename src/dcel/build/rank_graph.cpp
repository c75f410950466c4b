#include "dcel/build/rank_graph.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include "dcel/build/huge_pages.hpp"
#include "dcel/build/ring_sort.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::detail {

void throw_same_direction(const PlanarGraph& g, VertexId v, HalfEdgeId a, HalfEdgeId b) {
    const EdgeId lo = std::min(edge_of(a), edge_of(b));
    const EdgeId hi = std::max(edge_of(a), edge_of(b));
    const VertexId ta = graph_target(g, a);
    if (ta == graph_target(g, b)) {
        throw InvalidInput(InputErrorKind::DuplicateEdge,
                           "edges " + std::to_string(lo.index()) + " and " + std::to_string(hi.index()) +
                               " both join vertices " + std::to_string(std::min(v, ta).index()) + " and " +
                               std::to_string(std::max(v, ta).index()) + "; remove one of them",
                           {v, ta}, {lo, hi});
    }
    throw InvalidInput(InputErrorKind::Overlap,
                       describe_edge(g, lo) + " and " + describe_edge(g, hi) + " overlap: both leave vertex " +
                           std::to_string(v.index()) + " in the same direction; merge them into one chain of edges",
                       {v}, {lo, hi});
}

namespace {

// Groups the half-edges by the rank of their origin (offset, half_edge,
// target), in O(V + E). A plain counting sort would scatter every half-edge
// to a random slot when the input is in random order; instead the
// half-edges are first partitioned into about 1024 groups of consecutive
// ranks (1024 sequential output streams), and each group is then counted
// and scattered within its own small range of slots.
void group_by_origin(const PlanarGraph& g, std::vector<Index> rank, RankGraph& rg) {
    const auto n = static_cast<Index>(g.vertices.size());
    const auto m = static_cast<Index>(g.edges.size());
    unsigned shift = 0;
    while ((static_cast<std::uint64_t>(n) >> shift) > 1024) ++shift;
    const Index groups = (n >> shift) + 1;

    struct Record {
        Index origin = 0;
        Index target = 0;
        HalfEdgeId half_edge;
    };
    std::vector<Record> records;
    assign_huge(records, 2 * static_cast<std::size_t>(m));
    {
        // The ranks of each edge's ends, read once (scattered reads when the
        // input is in random order) and then streamed twice.
        std::vector<std::pair<Index, Index>> ends;
        assign_huge(ends, m);
        std::vector<Index> start(groups + 1, 0);
        for (Index k = 0; k < m; ++k) {
            const Index ru = rank[g.edges[k].u.index()];
            const Index rv = rank[g.edges[k].v.index()];
            ends[k] = {ru, rv};
            ++start[(ru >> shift) + 1];
            ++start[(rv >> shift) + 1];
        }
        std::vector<Index>().swap(rank);
        for (Index b = 0; b < groups; ++b) start[b + 1] += start[b];
        for (Index k = 0; k < m; ++k) {
            const auto [ru, rv] = ends[k];
            records[start[ru >> shift]++] = Record{ru, rv, HalfEdgeId(2 * k)};
            records[start[rv >> shift]++] = Record{rv, ru, HalfEdgeId(2 * k + 1)};
        }
    }

    assign_huge(rg.offset, n + std::size_t{1}, Index{0});
    for (const Record& r : records) ++rg.offset[r.origin + 1];
    for (Index r = 0; r < n; ++r) rg.offset[r + 1] += rg.offset[r];
    assign_huge(rg.half_edge, records.size());
    assign_huge(rg.target, records.size());
    // Within a group, records keep their input order, as in a counting sort.
    std::vector<Index> fill;
    reserve_huge(fill, n);
    fill.assign(rg.offset.begin(), rg.offset.end() - 1);
    for (const Record& r : records) {
        const Index s = fill[r.origin]++;
        rg.half_edge[s] = r.half_edge;
        rg.target[s] = r.target;
    }
}

// The first pair of half-edges that leave a vertex in one direction, for
// the smallest such vertex id, so that the error is the one
// sort_rings_checked reports.
struct SameDirection {
    VertexId vertex;
    HalfEdgeId a;
    HalfEdgeId b;
    void note(VertexId v, HalfEdgeId first, HalfEdgeId second) {
        if (v >= vertex) return;  // a null vertex is larger than every id
        vertex = v;
        a = first;
        b = second;
    }
};

// A ring of two, sorted in place: no round trip through RingEntry.
inline void sort_two_in_place(RankGraph& rg, Index r, SameDirection& same) {
    const Index first = rg.offset[r];
    const Index t0 = rg.target[first];
    const Index t1 = rg.target[first + 1];
    const HalfEdgeId h0 = rg.half_edge[first];
    const HalfEdgeId h1 = rg.half_edge[first + 1];
    const PairOrder order = order_pair(rg.point[r], rg.point[t0], h0, rg.point[t1], h1);
    if (order.swap) {
        rg.target[first] = t1;
        rg.target[first + 1] = t0;
        rg.half_edge[first] = h1;
        rg.half_edge[first + 1] = h0;
    }
    if (order.same_direction) same.note(rg.vertex[r], h0, h1);  // throw_same_direction orders the pair itself
}

// A larger ring, sorted on a contiguous copy of its targets' points (`ring`,
// reused from vertex to vertex) and written back.
inline void sort_on_copy(RankGraph& rg, Index r, std::vector<RingEntry>& ring, SameDirection& same) {
    const Index first = rg.offset[r];
    const Index degree = rg.offset[r + 1] - first;
    ring.resize(degree);
    for (Index i = 0; i < degree; ++i) {
        // Field by field: building a whole RingEntry on the stack and
        // copying it stalls on store forwarding.
        const Index t = rg.target[first + i];
        ring[i].target = rg.point[t];
        ring[i].half_edge = rg.half_edge[first + i];
        ring[i].payload = t;
    }
    const std::size_t same_at = sort_ring(rg.point[r], ring);
    for (Index i = 0; i < degree; ++i) {
        rg.half_edge[first + i] = ring[i].half_edge;
        rg.target[first + i] = ring[i].payload;
    }
    if (same_at < ring.size()) same.note(rg.vertex[r], ring[same_at].half_edge, ring[same_at + 1].half_edge);
}

}  // namespace

RankGraph rank_graph_checked(const PlanarGraph& g, LexOrder&& lex) {
    const auto n = static_cast<Index>(g.vertices.size());
    RankGraph rg;
    rg.vertex = std::move(lex.vertex_of_rank);
    rg.point = std::move(lex.point_of_rank);

    group_by_origin(g, std::move(lex.rank_of_vertex), rg);

    std::vector<RingEntry> ring;
    SameDirection same;
    for (Index r = 0; r < n; ++r) {
        const Index degree = rg.degree(r);
        if (degree == 2) {
            sort_two_in_place(rg, r, same);
        } else if (degree > 2) {
            sort_on_copy(rg, r, ring, same);
        }
    }
    if (!same.vertex.is_null()) throw_same_direction(g, same.vertex, same.a, same.b);
    return rg;
}

Index RankGraph::search_towards(Index t, Index r) const {
    const Point centre = point[t];
    const Point back = point[r];
    Index lo = offset[t];  // the lower bound of `back` in the ring
    Index hi = offset[t + 1];
    while (lo < hi) {
        const Index mid = lo + (hi - lo) / 2;
        if (compare_angle(centre, point[target[mid]], back) == Sign::Negative) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo;
}

RankGraph rank_graph_from_rings(const PlanarGraph& g, std::span<const VertexId> lex_order,
                                std::span<const Index> ring_offset, std::span<const HalfEdgeId> ring) {
    const auto n = static_cast<Index>(g.vertices.size());
    RankGraph rg;
    rg.vertex.assign(lex_order.begin(), lex_order.end());
    std::vector<Index> rank(n);
    for (Index r = 0; r < n; ++r) rank[rg.vertex[r].index()] = r;
    rg.point.resize(n);
    rg.offset.assign(n + 1, 0);
    for (Index r = 0; r < n; ++r) {
        const Index v = rg.vertex[r].index();
        rg.point[r] = g.vertices[v];
        rg.offset[r + 1] = rg.offset[r] + (ring_offset[v + 1] - ring_offset[v]);
    }
    rg.half_edge.resize(ring.size());
    rg.target.resize(ring.size());
    for (Index r = 0; r < n; ++r) {
        const Index v = rg.vertex[r].index();
        for (Index i = ring_offset[v]; i < ring_offset[v + 1]; ++i) {
            const Index s = rg.offset[r] + (i - ring_offset[v]);
            rg.half_edge[s] = ring[i];
            rg.target[s] = rank[graph_target(g, ring[i]).index()];
        }
    }
    return rg;
}

}  // namespace dcel::detail
