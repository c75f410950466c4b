#include "support/dump_edits.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <utility>
#include <vector>

namespace dcel::fuzz {
namespace {

// The command's target: an element that exists, whatever the number.
Index target(double v, std::size_t count) { return static_cast<Index>(wrap_index(v, count)); }

// The value written: any id, in range or not; negative (or not an id) is null.
Index value(double v) {
    if (!(v >= 0 && v < static_cast<double>(kNoIndex)) || std::floor(v) != v) return kNoIndex;
    return static_cast<Index>(v);
}

template <class Id>
Id swapped(Id x, Index a, Index b) {
    if (x.index() == a) return Id(b);
    if (x.index() == b) return Id(a);
    return x;
}

void renumber_half_edges(DcelDump& d, Index a, Index b) {
    for (HalfEdgeRecord& r : d.half_edges) {
        r.twin = swapped(r.twin, a, b);
        r.next = swapped(r.next, a, b);
        r.prev = swapped(r.prev, a, b);
    }
    std::swap(d.half_edges[a], d.half_edges[b]);
    for (HalfEdgeId& h : d.vertex_out) h = swapped(h, a, b);
    for (FaceDump& f : d.faces) {
        f.outer = swapped(f.outer, a, b);
        for (HalfEdgeId& h : f.inner) h = swapped(h, a, b);
    }
}

void renumber_vertices(DcelDump& d, Index a, Index b) {
    std::swap(d.vertices[a], d.vertices[b]);
    if (!d.vertex_out.empty()) std::swap(d.vertex_out[a], d.vertex_out[b]);
    for (HalfEdgeRecord& r : d.half_edges) r.origin = swapped(r.origin, a, b);
    for (FaceDump& f : d.faces) {
        for (VertexId& v : f.isolated) v = swapped(v, a, b);
    }
}

void renumber_faces(DcelDump& d, Index a, Index b) {
    std::swap(d.faces[a], d.faces[b]);
    for (HalfEdgeRecord& r : d.half_edges) r.face = swapped(r.face, a, b);
}

template <class T>
void erase_at(std::vector<T>& v, double i) {
    if (!v.empty()) v.erase(v.begin() + target(i, v.size()));
}

}  // namespace

std::string apply_edit(DcelDump& d, TokenReader& in) {
    const Token t = in.next();
    std::vector<double> args;
    while (in.peek().kind == Token::Kind::Number && args.size() < 2) args.push_back(in.next().number);
    if (t.kind != Token::Kind::Word) return "";
    const std::string_view w = t.word;
    auto arg = [&](std::size_t i) { return i < args.size() ? args[i] : 0.0; };
    const std::size_t nv = d.vertices.size();
    const std::size_t nh = d.half_edges.size();
    const std::size_t nf = d.faces.size();

    if (nh != 0 && (w == "next" || w == "prev" || w == "twin")) {
        HalfEdgeRecord& r = d.half_edges[target(arg(0), nh)];
        HalfEdgeId& field = w == "next" ? r.next : w == "prev" ? r.prev : r.twin;
        field = HalfEdgeId(value(arg(1)));
    } else if (nh != 0 && w == "origin") {
        d.half_edges[target(arg(0), nh)].origin = VertexId(value(arg(1)));
    } else if (nh != 0 && w == "face") {
        d.half_edges[target(arg(0), nh)].face = FaceId(value(arg(1)));
    } else if (nf != 0 && w == "outer") {
        d.faces[target(arg(0), nf)].outer = HalfEdgeId(value(arg(1)));
    } else if (nf != 0 && w == "inner") {
        d.faces[target(arg(0), nf)].inner.emplace_back(value(arg(1)));
    } else if (nf != 0 && w == "uninner") {
        erase_at(d.faces[target(arg(0), nf)].inner, arg(1));
    } else if (nf != 0 && w == "isolated") {
        d.faces[target(arg(0), nf)].isolated.emplace_back(value(arg(1)));
    } else if (nf != 0 && w == "unisolated") {
        erase_at(d.faces[target(arg(0), nf)].isolated, arg(1));
    } else if (nv != 0 && !d.vertex_out.empty() && w == "out") {
        d.vertex_out[target(arg(0), nv)] = HalfEdgeId(value(arg(1)));
    } else if (w == "noout") {
        d.vertex_out.clear();
    } else if (nv != 0 && (w == "x" || w == "y")) {
        Point& p = d.vertices[target(arg(0), nv)];
        (w == "x" ? p.x : p.y) = arg(1);
    } else if (nh != 0 && w == "swapnext") {
        const Index a = target(arg(0), nh);
        const Index b = target(arg(1), nh);
        const HalfEdgeId na = d.half_edges[a].next;
        const HalfEdgeId nb = d.half_edges[b].next;
        d.half_edges[a].next = nb;
        d.half_edges[b].next = na;
        if (nb.index() < nh) d.half_edges[nb.index()].prev = HalfEdgeId(a);
        if (na.index() < nh) d.half_edges[na.index()].prev = HalfEdgeId(b);
    } else if (nh != 0 && w == "swaphalf") {
        renumber_half_edges(d, target(arg(0), nh), target(arg(1), nh));
    } else if (nv != 0 && w == "swapvertex") {
        renumber_vertices(d, target(arg(0), nv), target(arg(1), nv));
    } else if (nf != 0 && w == "swapface") {
        renumber_faces(d, target(arg(0), nf), target(arg(1), nf));
    } else if (w == "addvertex") {
        d.vertices.push_back({arg(0), arg(1)});
        if (!d.vertex_out.empty()) d.vertex_out.emplace_back();
    } else if (w == "addface") {
        d.faces.push_back(FaceDump{HalfEdgeId(value(arg(0))), {}, {}});
    } else if (w == "dropface") {
        if (nf != 0) d.faces.pop_back();
    } else {
        return "";
    }
    std::ostringstream s;
    s << " " << w;
    for (const double a : args) s << " " << a;
    return s.str();
}

}  // namespace dcel::fuzz
