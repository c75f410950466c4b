// The smallest user of the installed library through pkg-config, with no
// CMake: a triangle with an isolated vertex inside. Worked out by hand:
// V = 4, E = 3, C = 2 components, so V - E + F = 1 + C gives F = 2 (the
// unbounded face and the triangle), and the triangle (0,0), (4,0), (0,4) has
// area 8 and holds vertex 3.
#include <cstdio>
#include <cstdlib>

#include "dcel/build.hpp"
#include "dcel/queries.hpp"

int main() {
    using dcel::VertexId;
    const dcel::PlanarGraph g{{{0, 0}, {4, 0}, {0, 4}, {1, 1}},
                              {{VertexId(0), VertexId(1)}, {VertexId(1), VertexId(2)}, {VertexId(2), VertexId(0)}}};
    const dcel::Dcel d = dcel::build(g);
    // Half-edge 0 runs (0,0) -> (4,0), counterclockwise around the triangle.
    const dcel::FaceId triangle = d.face(dcel::HalfEdgeId(0));
    const bool ok = d.num_faces() == 2 && dcel::face_area(d, triangle).value == 8.0 && d.isolated(triangle).size() == 1 &&
                    d.isolated(triangle)[0] == VertexId(3);
    std::puts(ok ? "pkg-config consumer: dcel works" : "pkg-config consumer: FAILED");
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
