// validate() accepts every DCEL that build() makes, and rejects every
// single-field corruption of one, and a hole moved to another face with its
// records kept consistent: this shows the checkers can fail.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "dcel/validate.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

RC_GTEST_PROP(Validate, prop_accepts_every_built_dcel, ()) {
    const GraphCase c = *graphs();
    const CheckResult v = validate(build(c.graph));
    RC_ASSERT(!v.has_value());
}

// The corruptions. Each one is guaranteed to break an invariant:
//  - a new next(h) (prev(h) left alone): prev(new next(h)) is not h;
//  - a new prev(h): next(new prev(h)) is not h;
//  - a new twin(h): twin(new twin) is not h, or twin(h) = h;
//  - a new face(h): face(next(h)) differs (every cycle has length >= 2);
//  - a new origin(h): origin(h) no longer equals the target of prev(h);
//  - a vertex's out: a half-edge that does not leave it;
//  - a face record: an inner cycle dropped, or moved to another face, or
//    listed twice, or its outer cycle replaced by another cycle's half-edge;
//  - an isolated vertex dropped from its face, or moved to another face
//    (then it lies in a face that does not contain it).
enum class Corruption {
    Next,
    Prev,
    Twin,
    Face,
    Origin,
    VertexOut,
    DropInner,
    MoveInner,
    RepeatCycle,
    ReplaceOuter,
    DropIsolated,
    MoveIsolated
};

std::string name(Corruption c) {
    static const char* const kNames[] = {"next",         "prev",          "twin",          "face",
                                         "origin",       "vertex-out",    "drop-inner",    "move-inner",
                                         "repeat-cycle", "replace-outer", "drop-isolated", "move-isolated"};
    return kNames[static_cast<int>(c)];
}

// Another value in [0, n) than `not_this` (n >= 2).
Index other_than(Index not_this, Index n) {
    const auto k = static_cast<Index>(*rc::gen::inRange<Index>(0, n - 1));
    return k >= not_this ? k + 1 : k;
}

RC_GTEST_PROP(Validate, prop_rejects_every_single_field_corruption, ()) {
    const GraphCase c = *graphs();
    const DcelDump clean = to_dump(build(c.graph));
    DcelDump d = clean;
    const auto halves = static_cast<Index>(d.half_edges.size());
    const auto faces = static_cast<Index>(d.faces.size());
    const auto vertices = static_cast<Index>(d.vertices.size());
    // What this DCEL offers to corrupt.
    std::vector<Corruption> options;
    std::vector<Index> with_inner, bounded, with_isolated;
    for (Index f = 0; f < faces; ++f) {
        if (!d.faces[f].inner.empty()) with_inner.push_back(f);
        if (!d.faces[f].outer.is_null()) bounded.push_back(f);
        if (!d.faces[f].isolated.empty()) with_isolated.push_back(f);
    }
    if (halves > 0) {
        options.insert(options.end(), {Corruption::Next, Corruption::Prev, Corruption::Twin, Corruption::Face,
                                       Corruption::Origin, Corruption::VertexOut, Corruption::RepeatCycle});
    }
    if (!with_inner.empty()) options.push_back(Corruption::DropInner);
    if (!with_inner.empty() && faces > 1) options.push_back(Corruption::MoveInner);
    if (!bounded.empty()) options.push_back(Corruption::ReplaceOuter);
    if (!with_isolated.empty()) options.push_back(Corruption::DropIsolated);
    if (!with_isolated.empty() && faces > 1) options.push_back(Corruption::MoveIsolated);
    RC_PRE(!options.empty());  // only the empty graph offers nothing
    const Corruption what = *rc::gen::elementOf(options);
    RC_CLASSIFY(true, name(what));

    const Index h = halves > 0 ? *rc::gen::inRange<Index>(0, halves) : 0;
    switch (what) {
        case Corruption::Next: d.half_edges[h].next = HalfEdgeId(other_than(d.half_edges[h].next.index(), halves)); break;
        case Corruption::Prev: d.half_edges[h].prev = HalfEdgeId(other_than(d.half_edges[h].prev.index(), halves)); break;
        case Corruption::Twin: d.half_edges[h].twin = HalfEdgeId(other_than(d.half_edges[h].twin.index(), halves)); break;
        case Corruption::Face:  // faces + 1 allows an out-of-range face when there is only one
            d.half_edges[h].face = FaceId(other_than(d.half_edges[h].face.index(), faces + 1));
            break;
        case Corruption::Origin:
            d.half_edges[h].origin = VertexId(other_than(d.half_edges[h].origin.index(), vertices));
            break;
        case Corruption::VertexOut:  // twin(h) leaves the other end of h
            d.vertex_out[d.half_edges[h].origin.index()] = d.half_edges[h].twin;
            break;
        case Corruption::DropInner: {
            auto& inner = d.faces[*rc::gen::elementOf(with_inner)].inner;
            inner.erase(inner.begin() + *rc::gen::inRange<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(inner.size())));
            break;
        }
        case Corruption::MoveInner: {
            const Index f = *rc::gen::elementOf(with_inner);
            const Index g = other_than(f, faces);
            d.faces[g].inner.push_back(d.faces[f].inner.back());
            d.faces[f].inner.pop_back();
            break;
        }
        case Corruption::RepeatCycle: d.faces[*rc::gen::inRange<Index>(0, faces)].inner.push_back(HalfEdgeId(h)); break;
        case Corruption::ReplaceOuter: {
            const Index f = *rc::gen::elementOf(bounded);
            // A half-edge of another cycle: walk the outer cycle and pick outside it.
            std::vector<char> on_cycle(halves, 0);
            HalfEdgeId x = d.faces[f].outer;
            do {
                on_cycle[x.index()] = 1;
                x = d.half_edges[x.index()].next;
            } while (x != d.faces[f].outer);
            std::vector<Index> elsewhere;
            for (Index k = 0; k < halves; ++k) {
                if (on_cycle[k] == 0) elsewhere.push_back(k);
            }
            RC_ASSERT(!elsewhere.empty());  // the twins of a bounded face's outer cycle lie on other cycles
            d.faces[f].outer = HalfEdgeId(*rc::gen::elementOf(elsewhere));
            break;
        }
        case Corruption::DropIsolated: d.faces[*rc::gen::elementOf(with_isolated)].isolated.pop_back(); break;
        case Corruption::MoveIsolated: {
            const Index f = *rc::gen::elementOf(with_isolated);
            const Index g = other_than(f, faces);
            d.faces[g].isolated.push_back(d.faces[f].isolated.back());
            d.faces[f].isolated.pop_back();
            break;
        }
    }
    RC_ASSERT(!(d.half_edges == clean.half_edges && d.faces == clean.faces && d.vertex_out == clean.vertex_out));
    RC_ASSERT(validate(d).has_value());
}

// A hole moved to another face with every record kept consistent: the cycle
// (a component's outer boundary) is listed by the other face and its
// half-edges name it. Only the hole-placement checker can see this.
RC_GTEST_PROP(Validate, prop_rejects_a_hole_moved_to_another_face, ()) {
    const GraphCase c = *graphs();
    DcelDump d = to_dump(build(c.graph));
    const auto faces = static_cast<Index>(d.faces.size());
    std::vector<Index> with_inner;
    for (Index f = 0; f < faces; ++f) {
        if (!d.faces[f].inner.empty()) with_inner.push_back(f);
    }
    RC_PRE(!with_inner.empty() && faces > 1);  // a hole, and a face to move it to
    const Index f = *rc::gen::elementOf(with_inner);
    const Index g = other_than(f, faces);
    auto& inner = d.faces[f].inner;
    const auto k = *rc::gen::inRange<std::size_t>(0, inner.size());
    const HalfEdgeId hole = inner[k];
    inner.erase(inner.begin() + static_cast<std::ptrdiff_t>(k));
    d.faces[g].inner.push_back(hole);
    HalfEdgeId x = hole;
    do {
        d.half_edges[x.index()].face = FaceId(g);
        x = d.half_edges[x.index()].next;
    } while (x != hole);
    const CheckResult v = validate(d);
    RC_ASSERT(v.has_value());
    RC_ASSERT(v->invariant == Invariant::HolePlacement);
}

}  // namespace
}  // namespace dcel::props
