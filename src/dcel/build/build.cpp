#include "dcel/build.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>

#include "dcel/build/huge_pages.hpp"
#include "dcel/build/input_checks.hpp"
#include "dcel/build/lex_order.hpp"
#include "dcel/build/rank_graph.hpp"
#include "dcel/build/sweep.hpp"
#include "dcel/core/union_find.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::assign_huge;
using detail::check_elements;
using detail::lex_order_checked;
using detail::Linking;
using detail::rank_graph_checked;
using detail::RankGraph;
using detail::reserve_huge;
using detail::sweep_ranks;
using detail::UnionFind;
namespace {

// Frees a vector's memory now (clear() keeps the capacity).
template <class T>
void release(std::vector<T>& v) {
    std::vector<T>().swap(v);
}

}  // namespace

// Friend of Dcel: fills its arrays. One member function per step, in order.
//
// Every step but the last two works on the rank graph (vertices renumbered in
// sweep order, half-edges grouped by origin in slots), where neighbouring
// vertices sit close in memory; only the final writes go to the half-edge ids
// of the input, which may be in any order. Temporaries are freed as soon as
// they are dead, and the DCEL arrays are allocated last, so that the peak
// stays near the size of the result.
class DcelBuilder {
public:
    DcelBuilder(const PlanarGraph& g, const BuildOptions& options) : g_(g), options_(options) {}

    Dcel run() {
        check_elements(g_);                                            // O(V + E)
        rg_ = rank_graph_checked(g_, lex_order_checked(g_.vertices));  // O(V + E log d); sort O(V log V) worst
        find_components();                                             // O((V + E) log V) worst
        find_edges_below();                                            // sweep: O((V + E) log(V + E))
        link_slots();                                                  // O(E), O(E log d) worst
        find_cycles();                                                 // O(E)
        place_components();                                            // O(V)
        number_faces();                                                // O(E)
        write_half_edges();                                            // O(E)
        write_faces();                                                 // O(F + holes log holes)
        copy_points();                                                 // O(V)
        return std::move(d_);
    }

private:
    [[nodiscard]] Index num_slots() const { return rg_.num_slots(); }

    // Union-find on ranks, the smaller root kept (Linking::SmallestRoot), so
    // each component's root is its leftmost vertex. Afterwards component_[r]
    // is the component of rank r; components are numbered in sweep order of
    // their leftmost vertex.
    void find_components() {
        const Index n = rg_.num_vertices();
        std::vector<Index> parents;
        reserve_huge(parents, n);
        UnionFind<Linking::SmallestRoot> sets(n, std::move(parents));
        // cyclic_[root]: an edge inside the root's tree has closed a cycle
        // (kept up to date on roots only, then moved to component numbers).
        assign_huge(cyclic_, n, char{0});
        for (Index r = 0; r < n; ++r) {
            for (Index s = rg_.offset[r]; s < rg_.offset[r + 1]; ++s) {
                if (rg_.target[s] > r) continue;  // each edge once, from its right end
                const Index a = sets.find(r);
                const Index b = sets.find(rg_.target[s]);
                if (a == b) {
                    cyclic_[a] = 1;
                } else {
                    const Index root = sets.link(a, b);
                    const Index absorbed = root == a ? b : a;
                    if (cyclic_[absorbed] != 0) cyclic_[root] = 1;
                }
            }
        }
        sets.flatten();
        component_ = std::move(sets).release();
        number_components();
    }

    // component_[r] is the root of r's component (its leftmost vertex, so no
    // later than r): one ascending pass, in place, turns roots into
    // component numbers and moves cyclic_ from roots to numbers.
    void number_components() {
        for (Index r = 0; r < rg_.num_vertices(); ++r) {
            if (component_[r] == r) {
                cyclic_[leftmost_.size()] = cyclic_[r];  // leftmost_.size() <= r: that entry is done with
                cyclic_count_ += cyclic_[r];
                component_[r] = static_cast<Index>(leftmost_.size());
                leftmost_.push_back(r);
                if (rg_.degree(r) == 0) ++isolated_count_;
            } else {
                component_[r] = component_[component_[r]];
            }
        }
        cyclic_.resize(leftmost_.size());
    }

    // next_slot_[s]: the slot of next(half_edge[s]), the half-edge leaving
    // target(s) just clockwise of the twin. Twins are found from the small
    // ring's side: a slot pointing into a small ring scans it and links both
    // the slot and its twin (when both rings are small, only from the lower
    // rank's side, so each edge is scanned for once); only an edge between
    // two large rings needs binary searches. O(E) with no scattered memory
    // access whatever the input order; O(E log d) at worst. Trees are left
    // out: find_cycles labels them without walking.
    void link_slots() {
        if (cyclic_count_ == 0) return;
        assign_huge(next_slot_, num_slots(), kNoIndex);
        for (Index r = 0; r < rg_.num_vertices(); ++r) {
            if (cyclic_[component_[r]] == 0) continue;
            const bool r_small = rg_.small(r);
            for (Index s = rg_.offset[r]; s < rg_.offset[r + 1]; ++s) {
                const Index t = rg_.target[s];
                if (rg_.small(t)) {
                    if (r_small && t < r) continue;  // linked from t's ring
                    const Index twin_slot = rg_.slot_towards(t, r);
                    next_slot_[s] = rg_.clockwise(t, twin_slot);
                    next_slot_[twin_slot] = rg_.clockwise(r, s);
                } else if (!r_small) {
                    next_slot_[s] = rg_.clockwise(t, rg_.search_towards(t, r));
                }  // else: linked from t's large ring
            }
        }
    }

    // Cycles are found in slot order; cycle_rep_[c] is the smallest half-edge
    // id on cycle c (the one that names it in the result).
    //
    // A tree has exactly one boundary cycle, made of all its half-edges (any
    // rotation system of a tree has one face), so its slots are labelled in
    // ring order with no walk. Walking next() across a large tree jumps
    // between distant rings at every step, a chain of dependent cache misses.
    void find_cycles() {
        assign_huge(cycle_of_slot_, num_slots(), kNoIndex);
        const std::size_t edges = g_.edges.size();
        const std::size_t with_edges = leftmost_.size() - isolated_count_;
        // Euler: a planar embedding has E - V + isolated + 2 * (components with edges) cycles.
        const std::size_t expected = edges + isolated_count_ + 2 * with_edges;
        if (expected >= g_.vertices.size()) cycle_rep_.reserve(expected - g_.vertices.size());
        if (cyclic_count_ < leftmost_.size()) {
            std::vector<Index> tree_cycle(leftmost_.size(), kNoIndex);  // per component
            for (Index r = 0; r < rg_.num_vertices(); ++r) {
                const Index c = component_[r];
                if (cyclic_[c] != 0 || rg_.degree(r) == 0) continue;
                if (tree_cycle[c] == kNoIndex) {
                    tree_cycle[c] = static_cast<Index>(cycle_rep_.size());
                    cycle_rep_.emplace_back(rg_.half_edge[rg_.offset[r]]);
                }
                HalfEdgeId& rep = cycle_rep_[tree_cycle[c]];
                for (Index s = rg_.offset[r]; s < rg_.offset[r + 1]; ++s) {
                    cycle_of_slot_[s] = tree_cycle[c];
                    rep = std::min(rep, rg_.half_edge[s]);
                }
            }
        }
        release(cyclic_);
        for (Index s = 0; s < num_slots(); ++s) {
            if (cycle_of_slot_[s] != kNoIndex) continue;
            const auto c = static_cast<Index>(cycle_rep_.size());
            HalfEdgeId rep = rg_.half_edge[s];
            for (Index x = s; cycle_of_slot_[x] == kNoIndex; x = next_slot_[x]) {
                cycle_of_slot_[x] = c;
                rep = std::min(rep, rg_.half_edge[x]);
            }
            cycle_rep_.push_back(rep);
        }
    }

    // The sweep: rejects crossings (when asked to) and finds, for each
    // component's leftmost vertex, the edge directly below it, as the slot of
    // its left-to-right half-edge. It runs before the cycles are found, so
    // that its memory and theirs are never held at once.
    //
    // When crossings are not checked, only components with a cycle matter:
    // a tree has no bounded face, so it contains nothing, and it adds no
    // face to the others (the face above the first cycle-bearing edge below
    // a point is the face that contains it). So the sweep is skipped for a
    // connected graph and for a forest (every component is then a hole of
    // the unbounded face), and otherwise carries only the edges of
    // components with cycles.
    void find_edges_below() {
        below_.assign(leftmost_.size(), kNoIndex);
        std::vector<char> in_status;
        const bool skip = !options_.check_crossings && (leftmost_.size() <= 1 || cyclic_count_ == 0);
        if (!skip && !options_.check_crossings && cyclic_count_ < leftmost_.size()) {
            assign_huge(in_status, rg_.num_vertices(), char{0});
            for (Index r = 0; r < rg_.num_vertices(); ++r) in_status[r] = cyclic_[component_[r]];
        }
        if (skip) return;
        std::vector<char> wanted;
        assign_huge(wanted, rg_.num_vertices(), char{0});
        for (const Index r : leftmost_) wanted[r] = 1;
        std::vector<Index> below;
        assign_huge(below, rg_.num_vertices(), kNoIndex);
        sweep_ranks(rg_, g_, wanted, below, options_.check_crossings, in_status);
        for (Index c = 0; c < leftmost_.size(); ++c) below_[c] = below[leftmost_[c]];
    }

    // The outer cycle of a component passes through its leftmost vertex, on
    // the side of the wedge that contains the direction west. A component
    // lies in the face just above the edge below its leftmost vertex; if that
    // edge's upper side is the outer boundary of another component, that
    // component's container is ours too (it has a smaller leftmost vertex,
    // so it was placed already).
    void place_components() {
        const auto components = static_cast<Index>(leftmost_.size());
        is_outer_cycle_.assign(cycle_rep_.size(), 0);
        outer_cycle_.assign(components, kNoIndex);
        for (Index c = 0; c < components; ++c) {
            const Index r = leftmost_[c];
            const Index first = rg_.offset[r];
            const Index degree = rg_.degree(r);
            if (degree == 0) continue;  // an isolated vertex
            // All directions at the leftmost vertex point into x >= 0; the
            // last one in [0, pi) (or the very last) borders the wedge
            // through west.
            Index k = 0;
            while (k < degree && angular_half(rg_.point[r], rg_.point[rg_.target[first + k]]) == 0) ++k;
            outer_cycle_[c] = cycle_of_slot_[first + (k + degree - 1) % degree];
            is_outer_cycle_[outer_cycle_[c]] = 1;
        }
        // Containers are face numbers, known only after number_faces(): for
        // now, a cycle (kNoIndex: the unbounded face).
        container_cycle_.assign(components, kNoIndex);
        for (Index c = 0; c < components; ++c) {
            const Index s = below_[c];
            if (s == kNoIndex) continue;
            const Index cycle = cycle_of_slot_[s];  // the slot's half-edge runs left to right: face above
            // The edge's right end is in the component whose outer boundary it may be.
            container_cycle_[c] = is_outer_cycle_[cycle] != 0 ? container_cycle_[component_[rg_.target[s]]] : cycle;
        }
        release(below_);
        release(rg_.point);
        release(rg_.target);
        release(component_);
    }

    // Every cycle that is not the outer boundary of its component bounds a
    // face of its own; faces are numbered after the unbounded face in order
    // of their smallest half-edge. Those half-edges are marked in a bitmap
    // of H bits, small enough to stay in cache where an array of H ids would
    // not on shuffled input, and a face's number is the count of marks up
    // to its half-edge: a running count per word plus a popcount. O(E).
    void number_faces() {
        release(next_slot_);
        const std::size_t words = num_slots() / 64 + 1;
        std::vector<std::uint64_t> named(words, 0);
        for (Index c = 0; c < cycle_rep_.size(); ++c) {
            const Index h = cycle_rep_[c].index();
            if (is_outer_cycle_[c] == 0) named[h / 64] |= std::uint64_t{1} << (h % 64);
        }
        std::vector<Index> faces_before(words);  // faces numbered below word w's first half-edge
        face_outer_.reserve(1 + cycle_rep_.size() - (leftmost_.size() - isolated_count_));
        face_outer_.assign(1, HalfEdgeId());  // the unbounded face has no outer cycle
        for (std::size_t w = 0; w < words; ++w) {
            faces_before[w] = static_cast<Index>(face_outer_.size());
            for (std::uint64_t bits = named[w]; bits != 0; bits &= bits - 1) {
                face_outer_.emplace_back(static_cast<Index>(64 * w + static_cast<unsigned>(std::countr_zero(bits))));
            }
        }
        face_of_cycle_.assign(cycle_rep_.size(), kNoIndex);
        for (Index c = 0; c < cycle_rep_.size(); ++c) {
            if (is_outer_cycle_[c] != 0) continue;
            const Index h = cycle_rep_[c].index();
            const std::uint64_t below = named[h / 64] & ((std::uint64_t{1} << (h % 64)) - 1);
            face_of_cycle_[c] = faces_before[h / 64] + static_cast<Index>(std::popcount(below));
        }
        for (Index c = 0; c < leftmost_.size(); ++c) {
            const Index container = container_cycle_[c] == kNoIndex ? 0 : face_of_cycle_[container_cycle_[c]];
            container_cycle_[c] = container;  // now a face number
            if (outer_cycle_[c] != kNoIndex) face_of_cycle_[outer_cycle_[c]] = container;
        }
    }

    // next(u->v) = the half-edge leaving v just clockwise of v->u: walking
    // each ring, the twin of slot s's half-edge is followed by the half-edge
    // of the slot clockwise of s, and preceded by the twin of the one
    // counterclockwise of s.
    //
    // The DCEL arrays are indexed by input half-edge ids, which may be in
    // any order relative to the rings: written directly, every slot would
    // cost four cache misses on shuffled input. So unless the ids follow
    // the slots (slots_follow_ids), what each slot gives is first written,
    // in ring order, to one of about H / 8192 buckets of consecutive
    // half-edge ids (sequential streams), and then applied bucket by bucket,
    // each bucket's lines of the four arrays in cache. Every id occurs once,
    // so bucket b is exactly the records for ids b * 8192 .. and needs no
    // counting pass. Origins come from the input edges in order.
    void write_half_edges() {
        const Index h_count = num_slots();
        assign_huge(d_.out_, rg_.num_vertices());
        if (slots_follow_ids()) {
            assign_huge(d_.next_, h_count);
            assign_huge(d_.prev_, h_count);
            assign_huge(d_.face_, h_count);
            for_each_slot([&](const HalfEdgeRecord& x) { apply(x); });
            release_slot_arrays();
        } else {
            constexpr unsigned kBucketBits = 13;  // 8192 ids: 128 KiB of the four arrays
            std::vector<HalfEdgeRecord> records;
            assign_huge(records, h_count);
            std::vector<Index> fill((h_count >> kBucketBits) + 1);
            for (Index b = 0; b < fill.size(); ++b) fill[b] = b << kBucketBits;
            for_each_slot([&](const HalfEdgeRecord& x) { records[fill[x.h.index() >> kBucketBits]++] = x; });
            release_slot_arrays();
            assign_huge(d_.next_, h_count);
            assign_huge(d_.prev_, h_count);
            assign_huge(d_.face_, h_count);
            for (const HalfEdgeRecord& x : records) apply(x);
        }
        assign_huge(d_.origin_, h_count);
        for (Index h = 0; h < h_count; h += 2) {  // half-edge 2k runs along edge k from u to v
            d_.origin_[h] = g_.edges[h / 2].u;
            d_.origin_[h + 1] = g_.edges[h / 2].v;
        }
    }

    // What one slot gives the DCEL arrays.
    struct HalfEdgeRecord {
        HalfEdgeId h;
        HalfEdgeId twin_next;  // next(twin(h))
        HalfEdgeId prev;       // prev(h)
        FaceId face;           // face(h)
    };

    // Calls emit with each slot's record, in ring order, and sets d_.out_.
    template <class Emit>
    void for_each_slot(Emit emit) {
        for (Index r = 0; r < rg_.num_vertices(); ++r) {
            HalfEdgeId out;
            for (Index s = rg_.offset[r]; s < rg_.offset[r + 1]; ++s) {
                const HalfEdgeId h = rg_.half_edge[s];
                emit(HalfEdgeRecord{h, rg_.half_edge[rg_.clockwise(r, s)], twin(rg_.half_edge[rg_.counterclockwise(r, s)]),
                                    FaceId(face_of_cycle_[cycle_of_slot_[s]])});
                out = std::min(out, h);
            }
            d_.out_[rg_.vertex[r].index()] = out;
        }
    }

    void apply(const HalfEdgeRecord& x) {
        d_.next_[twin(x.h).index()] = x.twin_next;
        d_.prev_[x.h.index()] = x.prev;
        d_.face_[x.h.index()] = x.face;
    }

    void release_slot_arrays() {
        release(cycle_of_slot_);
        release(rg_.half_edge);
        release(rg_.offset);
    }

    // Whether consecutive slots mostly hold nearby half-edge ids (chains,
    // polygons, nested shapes, edges listed along the sweep): then writing
    // the arrays in slot order touches a few lines at a time, and the
    // buckets would only cost their 16 bytes per half-edge. O(E), one
    // sequential read.
    [[nodiscard]] bool slots_follow_ids() const {
        constexpr Index kNear = 64;  // ids: four cache lines of an array
        Index far = 0;
        for (Index s = 1; s < num_slots(); ++s) {
            const Index a = rg_.half_edge[s - 1].index();
            const Index b = rg_.half_edge[s].index();
            far += (a > b ? a - b : b - a) > kNear ? 1 : 0;
        }
        return far <= num_slots() / 16;
    }

    // The result keeps its own copy of the points.
    void copy_points() {
        reserve_huge(d_.points_, g_.vertices.size());
        d_.points_.assign(g_.vertices.begin(), g_.vertices.end());
    }

    // One pass in face order; only faces with two or more holes or isolated
    // vertices need their lists sorted.
    void write_faces() {
        std::vector<FaceRecord>().swap(d_.faces_);
        d_.faces_.reserve(face_outer_.size());
        for (const HalfEdgeId outer : face_outer_) d_.faces_.push_back(FaceRecord{outer, {}, {}});
        release(face_outer_);
        std::vector<Index> crowded;  // faces given a second hole or isolated vertex
        for (Index c = 0; c < leftmost_.size(); ++c) {
            FaceRecord& f = d_.faces_[container_cycle_[c]];
            if (f.inner.size() + f.isolated.size() == 1) crowded.push_back(container_cycle_[c]);
            if (outer_cycle_[c] == kNoIndex) {
                f.isolated.push_back(rg_.vertex[leftmost_[c]]);
            } else {
                f.inner.push_back(cycle_rep_[outer_cycle_[c]]);
            }
        }
        for (const Index i : crowded) {
            FaceRecord& f = d_.faces_[i];
            std::sort(f.inner.begin(), f.inner.end());
            std::sort(f.isolated.begin(), f.isolated.end());
        }
    }

    const PlanarGraph& g_;
    BuildOptions options_;
    Dcel d_;
    RankGraph rg_;

    std::vector<Index> component_;        // per rank
    std::vector<Index> leftmost_;         // per component: the rank of its leftmost vertex
    std::vector<Index> below_;            // per component: the slot below its leftmost vertex, or kNoIndex
    std::size_t isolated_count_ = 0;      // components without edges
    std::vector<char> cyclic_;            // per component: has a cycle, see find_components; until find_cycles
    std::size_t cyclic_count_ = 0;        // components with a cycle
    std::vector<Index> next_slot_;        // per slot
    std::vector<Index> cycle_of_slot_;    // per slot
    std::vector<HalfEdgeId> cycle_rep_;   // per cycle: its smallest half-edge
    std::vector<char> is_outer_cycle_;    // per cycle
    std::vector<Index> outer_cycle_;      // per component; kNoIndex when isolated
    std::vector<Index> container_cycle_;  // per component: see place_components, then number_faces
    std::vector<Index> face_of_cycle_;    // per cycle
    std::vector<HalfEdgeId> face_outer_;  // per face: its outer cycle's smallest half-edge (null: unbounded)
};

Dcel build(const PlanarGraph& graph, const BuildOptions& options) { return DcelBuilder(graph, options).run(); }

}  // namespace dcel
