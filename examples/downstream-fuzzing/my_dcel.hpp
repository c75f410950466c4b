// Stands in for your own DCEL code: replace this file and my_dcel.cpp with
// your library (or link it). It knows nothing of dcel; dcel_adapter.hpp
// converts between the two.
#pragma once

#include <vector>

namespace my_dcel {

struct Point {
    double x;
    double y;
};

struct Edge {
    int u;
    int v;
};

// Every boundary cycle as the vertex ids of its half-edges' origins, in next
// order, where next(u->v) is the half-edge leaving v clockwise after v->u.
std::vector<std::vector<int>> faces(const std::vector<Point>& points, const std::vector<Edge>& edges);

}  // namespace my_dcel
