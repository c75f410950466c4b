// Internal to the answer trials (answer_spellings.hpp): the facts about
// the graph each step needs, small helpers, and steps 2 to 4, one file each:
// answer_respell.cpp (meaning kept), answer_corrupt.cpp (meaning maybe
// changed, the oracle says), answer_write.cpp (the text).
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "dcel/check/answer.hpp"
#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"
#include "oracles/answer_meaning.hpp"
#include "support/answer_spellings.hpp"

namespace dcel::test_support::spell {

using oracle::IdPolygon;
using oracle::IdRing;

// "[0, 1, 2]", for the story.
inline std::string list_text(const std::vector<Index>& vs) {
    std::string s = "[";
    for (std::size_t i = 0; i < vs.size(); ++i) s += (i == 0 ? "" : ", ") + std::to_string(vs[i]);
    return s + "]";
}

// Fisher-Yates from the choices: choices of 0 leave the order as it is.
template <class T>
void shuffle(std::vector<T>& v, Choices& c) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[i - 1 - c.below(i)]);
}

// Rotated to start at a chosen element (0: as it is).
template <class T>
void rotate(std::vector<T>& v, Choices& c) {
    if (!v.empty()) std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(c.below(v.size())), v.end());
}

template <class T>
T pick(const std::vector<T>& v, Choices& c) {
    return v[c.below(v.size())];
}

// ---- Shared facts about the graph

struct Facts {
    const oracle::AnswerJudge& judge;
    std::vector<std::vector<Index>> neighbours;  // per vertex
    std::vector<std::pair<Index, Index>> edges;
    // Edges with one face on both sides (lone edges, dangles, bridges), by
    // the oracle's faces.
    std::vector<std::pair<Index, Index>> lone_edges;

    explicit Facts(const oracle::AnswerJudge& j) : judge(j) {
        const PlanarGraph& g = judge.graph();
        neighbours.resize(g.vertices.size());
        for (std::size_t k = 0; k < g.edges.size(); ++k) {
            const Index u = g.edges[k].u.index(), v = g.edges[k].v.index();
            neighbours[u].push_back(v);
            neighbours[v].push_back(u);
            edges.emplace_back(u, v);
            if (judge.left_face(2 * static_cast<Index>(k)) == judge.left_face(2 * static_cast<Index>(k) + 1)) {
                lone_edges.emplace_back(u, v);
            }
        }
    }
    [[nodiscard]] Index vertex_count() const { return static_cast<Index>(judge.graph().vertices.size()); }
    // An id in [0, V]: V names no vertex.
    [[nodiscard]] Index any_id(Choices& c) const { return static_cast<Index>(c.below(vertex_count() + 1)); }
};

// The same cyclic walk, from its element `at`.
inline IdRing rotated_to(const IdRing& ring, std::size_t at) {
    IdRing r(ring.begin() + static_cast<std::ptrdiff_t>(at), ring.end());
    r.insert(r.end(), ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(at));
    return r;
}

// ---- Step 2: the same meaning in other words (answer_respell.cpp)

// Polygons and rings: ring splits and joins at a vertex, excursions,
// degenerate holes, hole, ring and polygon order, rotations, and
// reversals where `any_direction` (the rings kind, or --unoriented).
void respell_regions(const Facts& f, std::vector<IdPolygon>& polygons, bool rings_kind, bool any_direction, Choices& c,
                     std::string& story);
// A dump: outer, inner and vertex_out naming other half-edges of their
// cycles and vertices, inner and isolated lists reordered, vertex_out left out.
void respell_dump(DcelDump& d, Choices& c, std::string& story);

// ---- Step 3: one corruption (answer_corrupt.cpp)

void corrupt_faces(const Facts& f, std::vector<IdRing>& cycles, Choices& c, std::string& story);
void corrupt_regions(const Facts& f, std::vector<IdPolygon>& polygons, bool rings_kind, bool oriented, Choices& c,
                     std::string& story);
void corrupt_dump(DcelDump& d, Choices& c, std::string& story);

// ---- Step 4: the text (answer_write.cpp)

[[nodiscard]] std::string faces_text(const std::vector<IdRing>& cycles, const TrialSetup& s, Choices& c, std::string& story);
[[nodiscard]] std::string regions_text(const PlanarGraph& g, const std::vector<IdPolygon>& polygons, const TrialSetup& s,
                                       Choices& c, std::string& story);
[[nodiscard]] std::string dump_text(const DcelDump& d, const check::Conventions& conventions, Choices& c,
                                    std::string& story);

}  // namespace dcel::test_support::spell
