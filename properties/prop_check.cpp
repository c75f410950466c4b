// dcel::check: the reference's own answer agrees however it is renumbered,
// shuffled or rotated, and every single corruption of it is reported, with
// the kind of difference the corruption must cause.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <set>

#include "dcel/build.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/dump.hpp"
#include "support/check_helpers.hpp"
#include "support/graph_case.hpp"
#include "support/permutations.hpp"

namespace dcel::props {
namespace {

using check::DifferenceKind;
using test_support::count_kind;
using test_support::faces_answer;

RC_GTEST_PROP(Check, prop_check_renumbered_dump_agrees, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    const check::Report r = check::compare_dump(d, *renumberings(to_dump(d)));
    RC_ASSERT(r.agrees());
}

RC_GTEST_PROP(Check, prop_check_shuffled_faces_agree, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    const check::Report r = check::compare_faces(d, *rewordings(faces_answer(d)));
    RC_ASSERT(r.agrees());
}

std::vector<Index> reversed(const std::vector<Index>& c) { return {c.rbegin(), c.rend()}; }

enum class FacesCorruption { Drop, Repeat, Reverse, SwapNext, VertexBeyond, SingleVertex };

RC_GTEST_PROP(Check, prop_check_reports_every_faces_corruption, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    check::FacesAnswer a = faces_answer(d);
    std::vector<std::size_t> not_own_reverse;  // cycles that differ from their reverse
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (test_support::canonical(reversed(a[i])) != test_support::canonical(a[i])) not_own_reverse.push_back(i);
    }
    std::vector<std::pair<Index, Index>> same_target;  // half-edges a < b into one vertex
    for (Index v = 0; v < d.num_vertices(); ++v) {
        const HalfEdgeId out = d.out(VertexId(v));
        if (out.is_null() || d.next(twin(out)) == out) continue;  // isolated, or degree 1
        same_target.emplace_back(twin(out).index(), twin(d.next(twin(out))).index());
    }
    std::vector<FacesCorruption> options{FacesCorruption::VertexBeyond};
    if (!a.empty()) options.insert(options.end(), {FacesCorruption::Drop, FacesCorruption::Repeat});
    if (!not_own_reverse.empty()) options.push_back(FacesCorruption::Reverse);
    if (!same_target.empty()) options.push_back(FacesCorruption::SwapNext);
    if (d.num_vertices() > 0) options.push_back(FacesCorruption::SingleVertex);
    const FacesCorruption what = *rc::gen::elementOf(options);
    const auto pick = [](std::size_t n) { return *rc::gen::inRange<std::size_t>(0, n); };

    DifferenceKind expected = DifferenceKind::VertexCount;
    std::size_t exactly = 0;  // the exact number of differences, when known
    switch (what) {
        case FacesCorruption::Drop:
            RC_CLASSIFY(true, "drop");
            a.erase(a.begin() + static_cast<std::ptrdiff_t>(pick(a.size())));
            expected = DifferenceKind::MissingCycle, exactly = 1;
            break;
        case FacesCorruption::Repeat:
            RC_CLASSIFY(true, "repeat");
            a.push_back(a[pick(a.size())]);
            expected = DifferenceKind::ExtraCycle, exactly = 1;
            break;
        case FacesCorruption::Reverse: {
            RC_CLASSIFY(true, "reverse");
            auto& cycle = a[not_own_reverse[pick(not_own_reverse.size())]];
            cycle = reversed(cycle);
            expected = DifferenceKind::ReversedCycle, exactly = 1;
            break;
        }
        case FacesCorruption::SwapNext: {
            RC_CLASSIFY(true, "swap-next");
            const auto [x, y] = same_target[pick(same_target.size())];
            std::vector<Index> next = test_support::next_array(d);
            std::swap(next[x], next[y]);
            a = test_support::cycles_of_permutation(d, next);
            expected = DifferenceKind::WrongNext;
            break;
        }
        case FacesCorruption::VertexBeyond:
            RC_CLASSIFY(true, "vertex-beyond");
            a.push_back({static_cast<Index>(d.num_vertices() + pick(1000))});
            expected = DifferenceKind::VertexCount, exactly = 1;
            break;
        case FacesCorruption::SingleVertex:
            RC_CLASSIFY(true, "single-vertex");
            a.push_back({static_cast<Index>(pick(d.num_vertices()))});
            expected = DifferenceKind::NotAnEdge, exactly = 1;
            break;
    }
    const check::Report r = check::compare_faces(d, test_support::shuffled(a, 1));
    RC_LOG() << check::report_text(r);
    RC_ASSERT(!r.agrees());
    RC_ASSERT(count_kind(r, expected) >= 1U);
    RC_ASSERT(r.differences[0].kind == expected);
    if (exactly != 0) RC_ASSERT(r.differences.size() == exactly);
}

enum class DumpCorruption { Next, Twin, Origin, Point, MoveHole, MoveIsolated, DropIsolated, ExtraVertex };

RC_GTEST_PROP(Check, prop_check_reports_every_dump_corruption, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    DcelDump a = to_dump(d);
    const auto halves = static_cast<Index>(a.half_edges.size());
    const auto faces = static_cast<Index>(a.faces.size());
    std::vector<Index> with_inner, with_isolated;
    for (Index f = 0; f < faces; ++f) {
        if (!a.faces[f].inner.empty()) with_inner.push_back(f);
        if (!a.faces[f].isolated.empty()) with_isolated.push_back(f);
    }
    std::vector<DumpCorruption> options{DumpCorruption::ExtraVertex};
    if (halves > 2) options.insert(options.end(), {DumpCorruption::Next, DumpCorruption::Twin});
    if (halves > 0) options.push_back(DumpCorruption::Origin);
    if (!a.vertices.empty()) options.push_back(DumpCorruption::Point);
    if (!with_inner.empty() && faces > 1) options.push_back(DumpCorruption::MoveHole);
    if (!with_isolated.empty() && faces > 1) options.push_back(DumpCorruption::MoveIsolated);
    if (!with_isolated.empty()) options.push_back(DumpCorruption::DropIsolated);
    const DumpCorruption what = *rc::gen::elementOf(options);
    const auto pick = [](Index n) { return *rc::gen::inRange<Index>(0, n); };
    const auto other = [&](Index not_this, Index n) {
        const Index k = pick(n - 1);
        return k >= not_this ? k + 1 : k;
    };

    DifferenceKind expected = DifferenceKind::BrokenInvariant;
    switch (what) {
        case DumpCorruption::Next: {
            RC_CLASSIFY(true, "next");
            auto& h = a.half_edges[pick(halves)];
            h.next = HalfEdgeId(other(h.next.index(), halves));
            break;
        }
        case DumpCorruption::Twin: {
            RC_CLASSIFY(true, "twin");
            auto& h = a.half_edges[pick(halves)];
            h.twin = HalfEdgeId(other(h.twin.index(), halves));
            break;
        }
        case DumpCorruption::Origin: {
            RC_CLASSIFY(true, "origin");
            auto& h = a.half_edges[pick(halves)];
            h.origin = VertexId(other(h.origin.index(), static_cast<Index>(a.vertices.size())));
            break;
        }
        case DumpCorruption::Point: {
            RC_CLASSIFY(true, "point");
            Point& p = a.vertices[pick(static_cast<Index>(a.vertices.size()))];
            p.x = p.x == 0 ? 1 : p.x / 2;  // a different value, and still finite
            expected = DifferenceKind::WrongPoint;
            break;
        }
        case DumpCorruption::MoveHole: {  // with its half-edges' faces, so the records stay consistent
            RC_CLASSIFY(true, "move-hole");
            const Index f = *rc::gen::elementOf(with_inner);
            const Index g = other(f, faces);
            const HalfEdgeId hole = a.faces[f].inner.back();
            a.faces[f].inner.pop_back();
            a.faces[g].inner.push_back(hole);
            HalfEdgeId h = hole;
            do {
                a.half_edges[h.index()].face = FaceId(g);
                h = a.half_edges[h.index()].next;
            } while (h != hole);
            RC_ASSERT(count_kind(check::compare_dump(d, a), DifferenceKind::WrongHole) == 1U);
            break;
        }
        case DumpCorruption::MoveIsolated: {
            RC_CLASSIFY(true, "move-isolated");
            const Index f = *rc::gen::elementOf(with_isolated);
            a.faces[other(f, faces)].isolated.push_back(a.faces[f].isolated.back());
            a.faces[f].isolated.pop_back();
            RC_ASSERT(count_kind(check::compare_dump(d, a), DifferenceKind::WrongIsolatedVertex) == 1U);
            break;
        }
        case DumpCorruption::DropIsolated:
            RC_CLASSIFY(true, "drop-isolated");
            a.faces[*rc::gen::elementOf(with_isolated)].isolated.pop_back();
            RC_ASSERT(count_kind(check::compare_dump(d, a), DifferenceKind::WrongIsolatedVertex) == 1U);
            break;
        case DumpCorruption::ExtraVertex:
            RC_CLASSIFY(true, "extra-vertex");
            a.vertices.push_back({1e300, 1e300});
            if (!a.vertex_out.empty()) a.vertex_out.emplace_back();
            a.faces[0].isolated.emplace_back(static_cast<Index>(a.vertices.size() - 1));
            expected = DifferenceKind::VertexCount;
            break;
    }
    const check::Report r = check::compare_dump(d, test_support::renumbered(a, 3));
    RC_LOG() << check::report_text(r);
    RC_ASSERT(!r.agrees());
    RC_ASSERT(r.differences[0].kind == expected);
}

}  // namespace
}  // namespace dcel::props
