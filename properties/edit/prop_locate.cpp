// Properties of the queries on maps grown by random edits: the trapezoidal
// map answers exactly as the scan does (at grid points, which hit vertices,
// edges and faces), the scan's faces agree with build() placing the point,
// and every stabbing walk passes the brute-force checks of
// tests/oracles/stab_walk.hpp.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>  // after gtest.h, which it needs

#include "dcel/locate.hpp"
#include "dcel/stab.hpp"
#include "edit_steps.hpp"
#include "oracles/stab_walk.hpp"

namespace dcel::props {
namespace {

Dcel grown_map() {
    const int which = *rc::gen::inRange(0, 3);
    const std::vector<Step> steps = *script(growing_step());
    Dcel d = build(start_map(which));
    for (const Step& s : steps) {
        const Resolved r = resolve(d, s);
        if (!r.applicable) continue;
        try {
            (void)apply(d, s, r);
        } catch (const TopologyError&) {
        }
    }
    return d;
}

rc::Gen<Point> half_grid_point() {
    return rc::gen::map(rc::gen::pair(rc::gen::inRange(-2, 2 * kGrid + 3), rc::gen::inRange(-2, 2 * kGrid + 3)),
                        [](std::pair<int, int> ij) {
                            return Point{ij.first / 2.0, ij.second / 2.0};
                        });
}

RC_GTEST_PROP(LocateProperties, prop_locator_agrees_with_scan, ()) {
    const Dcel d = grown_map();
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const PointLocator fast(d, seed);
    const auto queries = *rc::gen::container<std::vector<Point>>(half_grid_point());
    for (const Point p : queries) {
        const Location scan = locate_by_scan(d, p);
        RC_ASSERT(fast.locate(p) == scan);
        if (scan.kind != Location::Kind::Face) continue;
        PlanarGraph g = to_graph(d);
        g.vertices.push_back(p);
        const Dcel r = build(g);
        const FaceId f = face_of_isolated_vertex(r, VertexId(static_cast<Index>(g.vertices.size() - 1)));
        RC_ASSERT(scan.face == (r.is_unbounded(f) ? Dcel::kUnboundedFace : d.face(r.outer(f))));
    }
}

RC_GTEST_PROP(StabProperties, prop_stab_matches_brute_force, ()) {
    const Dcel d = grown_map();
    const auto segments = *rc::gen::container<std::vector<std::pair<Point, Point>>>(
        rc::gen::pair(half_grid_point(), half_grid_point()));
    for (const auto& [a, b] : segments) {
        const std::vector<StabPiece> pieces = stab_segment(d, a, b);
        const std::string problem = oracle::check_walk(d, a, b, pieces);
        if (!problem.empty()) RC_FAIL(problem);
    }
}

}  // namespace
}  // namespace dcel::props
