// Builds a small graph through the installed headers and libraries and checks
// what was worked out by hand:
//   a 4x4 square (0,0)-(4,4) with the diagonal from (0,0) to (4,4),
//   a triangle (3,1), (3.5,1), (3.5,1.5) inside the lower-right half (y < x),
//   an isolated vertex (1,3) in the upper-left half (y > x).
// V = 8, E = 5 + 3 = 8, C = 3 components (square, triangle, lone vertex), so
// Euler's V - E + F = 1 + C gives F = 4: the unbounded face, the two halves
// of the square, the small triangle. The lower-right half has the triangle
// as its hole: area 8 - 0.125 = 7.875; the upper-left half holds the
// isolated vertex and has area 8.
#include <cstdio>
#include <cstdlib>

#include "dcel/build.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/queries.hpp"
#include "dcel/validate.hpp"

namespace {

int failures = 0;

void expect(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "consumer: FAILED: %s\n", what);
        ++failures;
    }
}

}  // namespace

int main() {
    using dcel::VertexId;
    const dcel::PlanarGraph g{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {3, 1}, {3.5, 1}, {3.5, 1.5}, {1, 3}},
                              {{VertexId(0), VertexId(1)},
                               {VertexId(1), VertexId(2)},
                               {VertexId(2), VertexId(3)},
                               {VertexId(3), VertexId(0)},
                               {VertexId(0), VertexId(2)},
                               {VertexId(4), VertexId(5)},
                               {VertexId(5), VertexId(6)},
                               {VertexId(6), VertexId(4)}}};
    const dcel::Dcel d = dcel::build(g);
    expect(!dcel::validate(d).has_value(), "validate() passes");
    expect(d.num_faces() == 4, "4 faces");
    expect(dcel::count_components(d) == 3, "3 components");

    // Edge 0 runs (0,0) -> (4,0): half-edge 0 has the lower-right half on its left.
    const dcel::FaceId lower = d.face(dcel::HalfEdgeId(0));
    expect(d.inner(lower).size() == 1, "the lower-right half has one hole");
    expect(dcel::face_area(d, lower).value == 7.875, "the lower-right half has area 7.875");
    // Edge 3 runs (0,4) -> (0,0): half-edge 6 has the upper-left half on its left.
    const dcel::FaceId upper = d.face(dcel::HalfEdgeId(6));
    expect(d.isolated(upper).size() == 1 && d.isolated(upper)[0] == VertexId(7),
           "the isolated vertex is in the upper-left half");
    expect(dcel::face_area(d, upper).value == 8.0, "the upper-left half has area 8");
    // Edge 5 runs (3,1) -> (3.5,1), counterclockwise around the small triangle.
    expect(dcel::face_area(d, d.face(dcel::HalfEdgeId(10))).value == 0.125, "the small triangle has area 0.125");

    // dcel::gen is exported too: a generated graph builds and validates.
    const dcel::PlanarGraph random = dcel::gen::generate({dcel::gen::Family::NestedPolygons, 7, 40});
    expect(!dcel::validate(dcel::build(random)).has_value(), "a generated graph builds and validates");

    if (failures == 0) std::puts("consumer: dcel package works");
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
