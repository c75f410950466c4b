// What an answer of each kind means, and whether it is the right one,
// decided without dcel::check: the judge of the answer-spelling property
// (properties/prop_answer_spellings.cpp) and of the answer fuzz harness.
//
// Answers come in their plain spelling: vertex ids from 0, faces on the
// left, every ring or cycle a cyclic walk (no closing repeat: [a, b, c]
// steps a->b, b->c, c->a). Whatever else an answer's text may say is the
// spelling's business (tests/support/answer_spellings.hpp).
//
//   faces     right when the multiset of cycles, each up to rotation, is
//             the reference DCEL's (reference_dcel.hpp) boundary cycles.
//   polygons  A polygon means a point set: the sum of its rings' winding
//   rings     numbers, a number per face of the graph. Every step of a ring
//             must be an edge. Each ring with a nonzero area is first turned
//             to its role's direction (shells and the rings kind
//             counterclockwise, holes clockwise; with `oriented` a ring that
//             runs the other way makes the answer wrong instead); a ring of
//             zero area is taken as written. The winding numbers are worked
//             out on the dual graph, not at sample points: start at 0 in the
//             unbounded face and cross each edge, from its right face to its
//             left one, adding how many more times the rings walk it forwards
//             than backwards (exact, and no point inside a face is needed).
//             Right when the multiset of these functions is exactly the
//             reference's: for polygons, one per bounded face f, 1 on f and
//             0 elsewhere; for rings, 1 on f and on every face its outer
//             boundary encloses (the faces that cannot reach the unbounded
//             face without crossing an edge with f on exactly one side).
//   dump      right when it has the graph's points (compared as doubles,
//             so -0.0 is 0.0), judge_dump (dump_judge.hpp) finds it the
//             correct DCEL of its own geometry, and its edges (one per twin
//             pair) are the graph's.
//
// Built on the reference DCEL, the exact areas and the dump judge of this
// folder; nothing from src/dcel/check, build, query or geometry.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "dcel/dump.hpp"
#include "dcel/graph.hpp"
#include "oracles/reference_dcel.hpp"

namespace dcel::oracle {

using IdRing = std::vector<Index>;      // a cyclic walk of vertex ids; an id >= V names no vertex
using IdPolygon = std::vector<IdRing>;  // the shell first, then the holes

enum class RegionKind { Polygons, Rings };

struct AnswerVerdict {
    bool right = true;
    std::string why;  // what is wrong, when not right
};

class AnswerJudge {
public:
    explicit AnswerJudge(const PlanarGraph& g);

    [[nodiscard]] AnswerVerdict faces(const std::vector<IdRing>& cycles) const;
    // `oriented`: polygons whose rings must run in their role's direction.
    [[nodiscard]] AnswerVerdict regions(const std::vector<IdPolygon>& polygons, RegionKind kind, bool oriented) const;
    [[nodiscard]] AnswerVerdict dump(const DcelDump& d) const;

    [[nodiscard]] const PlanarGraph& graph() const { return g_; }
    // The half-edge u->v (2k for edge k's u->v, 2k+1 back), or kNoIndex.
    [[nodiscard]] Index half_edge(Index u, Index v) const;
    // The face on the left of half-edge h in the reference DCEL (0: unbounded).
    [[nodiscard]] Index left_face(Index h) const { return left_[h]; }
    [[nodiscard]] Index face_count() const { return static_cast<Index>(reference_.outer_cycle.size()); }
    // Twice the signed area of a ring of vertex ids (all < V), exactly: its sign.
    [[nodiscard]] int area_sign(const IdRing& ring) const;

private:
    // The winding number per face of a chain (a count per edge: forwards
    // minus backwards).
    [[nodiscard]] std::vector<long> winding(const std::vector<long>& chain) const;
    [[nodiscard]] std::vector<long> filled(Index f) const;

    PlanarGraph g_;
    HalfEdgeGraph h_;
    ReferenceDcel reference_;
    std::map<std::pair<Index, Index>, Index> by_ends_;
    std::vector<Index> left_;                                          // per half-edge
    std::vector<std::vector<std::pair<Index, Index>>> dual_;           // per face: (edge, face across it)
    std::vector<std::vector<long>> polygon_meanings_, ring_meanings_;  // sorted
    std::vector<IdRing> cycles_;                                       // canonical, sorted
};

}  // namespace dcel::oracle
