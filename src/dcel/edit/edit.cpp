// The edits of edit.hpp. DcelEditor is the friend of Dcel that changes its
// arrays; like DcelBuilder it keeps one member function per step.
//
// Topology changes are made by splicing half-edges into and out of the
// rotation at a vertex (insert_after, and its inverse inline): next and prev
// are only ever set together (link), so they cannot drift apart. Face records
// are then repaired by walking the cycles that changed; geometry decides what
// each new cycle is (exact area signs, exact winding numbers).
#include "dcel/edit.hpp"

#include <algorithm>
#include "dcel/contracts.hpp"

#include "dcel/edit/edit_checks.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/area.hpp"
#include "dcel/geometry/segments.hpp"
#include "dcel/geometry/winding.hpp"
#include "dcel/locate.hpp"
#include "dcel/query/rotation.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::polygon_area_sign;
using detail::strictly_inside_segment;
using detail::winding_number;

class DcelEditor {
public:
    explicit DcelEditor(Dcel& d) : d_(d) {}

    Change split_edge(EdgeId e, Point p);
    Change add_edge(VertexId u, VertexId v);
    Change add_edge_to_point(VertexId u, Point p);
    Change add_vertex(Point p);
    Change remove_edge(EdgeId e);
    Change remove_isolated_vertex(VertexId v);
    Change merge_collinear_edges(VertexId v);

private:
    // ---- Raw access
    [[nodiscard]] HalfEdgeId next(HalfEdgeId h) const { return d_.next(h); }
    [[nodiscard]] HalfEdgeId prev(HalfEdgeId h) const { return d_.prev(h); }
    [[nodiscard]] static HalfEdgeId twin(HalfEdgeId h) { return Dcel::twin(h); }
    [[nodiscard]] VertexId origin(HalfEdgeId h) const { return d_.origin(h); }
    [[nodiscard]] VertexId target(HalfEdgeId h) const { return d_.target(h); }
    [[nodiscard]] Point point(VertexId v) const { return d_.point(v); }
    [[nodiscard]] FaceRecord& record(FaceId f) {
        DCEL_EXPECTS(f.index() < d_.faces_.size());
        return d_.faces_[f.index()];
    }
    [[nodiscard]] std::size_t degree(VertexId v) const {
        std::size_t n = 0;
        if (!d_.out(v).is_null()) {
            for ([[maybe_unused]] const HalfEdgeId h : d_.around_origin_cw(d_.out(v))) ++n;
        }
        return n;
    }
    [[nodiscard]] static std::string edges_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " edge" : " edges"); }
    // next(a) = b and prev(b) = a, always together (pmp's set_next_halfedge).
    void link(HalfEdgeId a, HalfEdgeId b) {
        DCEL_EXPECTS(a.index() < d_.next_.size() && b.index() < d_.prev_.size());
        d_.next_[a.index()] = b;
        d_.prev_[b.index()] = a;
    }
    void set_out(VertexId v, HalfEdgeId h) {
        DCEL_EXPECTS(v.index() < d_.out_.size() && (h.is_null() || d_.origin(h) == v));
        d_.out_[v.index()] = h;
    }

    // ---- Growing: each appends at the end of its arrays
    VertexId append_vertex(Point p);                           // no edges, listed in no face yet
    HalfEdgeId append_edge(VertexId u, VertexId v, FaceId f);  // u->v and v->u, linked to each other
    FaceId append_face(HalfEdgeId outer);
    // Puts x (leaving origin(r)) into the rotation just clockwise of r.
    void insert_after(HalfEdgeId x, HalfEdgeId r);

    // ---- Cycles (walks are capped by the Orbit iterator)
    [[nodiscard]] bool on_cycle(HalfEdgeId start, HalfEdgeId wanted) const;
    [[nodiscard]] std::vector<HalfEdgeId> sorted_cycle(HalfEdgeId start) const;
    void relabel_cycle(HalfEdgeId start, FaceId f);
    [[nodiscard]] Sign area_sign(HalfEdgeId start) const;
    [[nodiscard]] bool encloses(HalfEdgeId start, Point p) const;

    // ---- Face records
    void erase_isolated(FaceId f, VertexId v);
    void replace_in_record(FaceId f, HalfEdgeId from, HalfEdgeId to);
    Change connect(VertexId u, VertexId v, bool v_is_new);
    FaceId split_face(FaceId f, HalfEdgeId x);
    void join_cycles(FaceId f, HalfEdgeId x);
    void move_enclosed(FaceId from, FaceId to, HalfEdgeId boundary, HalfEdgeId skip);

    // ---- remove_edge's four cases
    struct Removal;
    IdChange<FaceId> merge_faces_across(const Removal& r);
    void remove_lone_edge(const Removal& r);
    void remove_dangling_edge(const Removal& r, bool u_end);
    void remove_bridge(const Removal& r);

    // ---- Shrinking: swap with last; each returns the id that moved, or null
    EdgeId remove_edge_slot(EdgeId e);
    VertexId remove_vertex_slot(VertexId v);
    FaceId remove_face_slot(FaceId f);

    Dcel& d_;
};

// ------------------------------------------------------------------ helpers

VertexId DcelEditor::append_vertex(Point p) {
    d_.points_.push_back(p);
    d_.out_.emplace_back();
    return VertexId(static_cast<Index>(d_.points_.size() - 1));
}

HalfEdgeId DcelEditor::append_edge(VertexId u, VertexId v, FaceId f) {
    const HalfEdgeId x(static_cast<Index>(d_.origin_.size()));
    d_.origin_.insert(d_.origin_.end(), {u, v});
    d_.next_.resize(d_.next_.size() + 2);
    d_.prev_.resize(d_.prev_.size() + 2);
    d_.face_.insert(d_.face_.end(), {f, f});
    link(x, twin(x));
    link(twin(x), x);
    return x;
}

FaceId DcelEditor::append_face(HalfEdgeId outer) {
    d_.faces_.push_back(FaceRecord{outer, {}, {}});
    return FaceId(static_cast<Index>(d_.faces_.size() - 1));
}

void DcelEditor::insert_after(HalfEdgeId x, HalfEdgeId r) {
    // Clockwise around the vertex: r, x, s. cw(h) = next(twin(h)).
    const HalfEdgeId s = next(twin(r));
    link(twin(r), x);
    link(twin(x), s);
}

bool DcelEditor::on_cycle(HalfEdgeId start, HalfEdgeId wanted) const {
    for (const HalfEdgeId h : d_.cycle(start)) {
        if (h == wanted) return true;
    }
    return false;
}

std::vector<HalfEdgeId> DcelEditor::sorted_cycle(HalfEdgeId start) const {
    std::vector<HalfEdgeId> out;
    for (const HalfEdgeId h : d_.cycle(start)) out.push_back(h);
    std::sort(out.begin(), out.end());
    return out;
}

void DcelEditor::relabel_cycle(HalfEdgeId start, FaceId f) {
    for (const HalfEdgeId h : d_.cycle(start)) d_.face_[h.index()] = f;
}

Sign DcelEditor::area_sign(HalfEdgeId start) const {
    return polygon_area_sign([&](auto&& f) {
        for (const HalfEdgeId h : d_.cycle(start)) f(point(origin(h)), point(target(h)));
    });
}

bool DcelEditor::encloses(HalfEdgeId start, Point p) const {
    return winding_number(p, [&](auto&& f) {
               for (const HalfEdgeId h : d_.cycle(start)) f(point(origin(h)), point(target(h)));
           }) != 0;
}

void DcelEditor::erase_isolated(FaceId f, VertexId v) {
    auto& iso = record(f).isolated;
    const auto it = std::find(iso.begin(), iso.end(), v);
    DCEL_ASSERT(it != iso.end() && "an isolated end of a clear segment lies in the segment's face");
    if (it != iso.end()) iso.erase(it);
}

void DcelEditor::replace_in_record(FaceId f, HalfEdgeId from, HalfEdgeId to) {
    FaceRecord& r = record(f);
    if (r.outer == from) r.outer = to;
    std::replace(r.inner.begin(), r.inner.end(), from, to);
}

// ------------------------------------------------------------------ adding

Change DcelEditor::split_edge(EdgeId e, Point p) {
    constexpr std::string_view kEdit = "split_edge";
    detail::require_edge(d_, e, kEdit);
    detail::require_finite(p, kEdit);
    const HalfEdgeId h = half_edge_of(e, 0);  // a -> b
    const HalfEdgeId t = twin(h);             // b -> a
    const VertexId b = target(h);
    if (!strictly_inside_segment(point(origin(h)), point(b), p)) {
        detail::refuse(kEdit, "the point " + format_point(p) + " is not exactly on edge " + detail::describe(d_, e) +
                                  " strictly between its ends");
    }
    // Before: P -> h -> X at b, and Q -> t -> Y. After: h = a->w, n0 = w->b,
    // n1 = b->w, t = w->a, with P -> h -> n0 -> X and Q -> n1 -> t -> Y.
    // At a degree-1 b, X = t and Q = h: the walk turns at b through n0 -> n1.
    HalfEdgeId x = next(h);
    HalfEdgeId q = prev(t);
    const VertexId w = append_vertex(p);
    const HalfEdgeId n0 = append_edge(w, b, d_.face(h));
    const HalfEdgeId n1 = twin(n0);
    d_.face_[n1.index()] = d_.face(t);
    if (x == t) {
        x = n1;
        q = n0;
    }
    d_.origin_[t.index()] = w;
    link(h, n0);
    link(n0, x);
    link(q, n1);
    link(n1, t);
    set_out(w, n0);
    if (d_.out(b) == t) set_out(b, n1);
    Change c;
    c.vertices.added = w;
    c.edges.added = edge_of(n0);
    c.edges.added_from = e;
    return c;
}

Change DcelEditor::add_edge(VertexId u, VertexId v) {
    constexpr std::string_view kEdit = "add_edge";
    detail::require_vertex(d_, u, kEdit);
    detail::require_vertex(d_, v, kEdit);
    if (u == v) detail::refuse(kEdit, "an edge needs two different vertices, but both ends are " + u.str());
    if (!d_.out(u).is_null()) {
        for (const HalfEdgeId h : d_.around_origin_cw(d_.out(u))) {
            if (target(h) == v) {
                detail::refuse(
                    kEdit, u.str() + " and " + v.str() + " are already joined by edge " + detail::describe(d_, edge_of(h)));
            }
        }
    }
    detail::require_segment_clear(d_, u, point(v), v, kEdit);
    return connect(u, v, false);
}

Change DcelEditor::add_edge_to_point(VertexId u, Point p) {
    constexpr std::string_view kEdit = "add_edge_to_point";
    detail::require_vertex(d_, u, kEdit);
    detail::require_finite(p, kEdit);
    detail::require_point_free(d_, p, kEdit);
    detail::require_segment_clear(d_, u, p, VertexId(), kEdit);
    const VertexId w = append_vertex(p);
    Change c = connect(u, w, true);
    c.vertices.added = w;
    return c;
}

Change DcelEditor::add_vertex(Point p) {
    constexpr std::string_view kEdit = "add_vertex";
    detail::require_finite(p, kEdit);
    detail::require_point_free(d_, p, kEdit);
    const Location where = locate_by_scan(d_, p);  // a face: p is at no vertex and on no edge
    const VertexId w = append_vertex(p);
    record(where.face).isolated.push_back(w);
    Change c;
    c.vertices.added = w;
    return c;
}

// Adds the edge u-v once the checks passed. v may be a fresh vertex (listed
// in no face yet).
Change DcelEditor::connect(VertexId u, VertexId v, bool v_is_new) {
    const bool u_alone = d_.out(u).is_null();
    const bool v_alone = d_.out(v).is_null();
    // The wedges the new edge enters at each end, found before anything changes.
    HalfEdgeId r_u;
    HalfEdgeId r_v;
    if (!u_alone) r_u = detail::wedge_after(d_, u, {point(u), point(v)});
    if (!v_alone) r_v = detail::wedge_after(d_, v, {point(v), point(u)});
    const FaceId f = !u_alone   ? d_.face(next(twin(r_u)))
                     : !v_alone ? d_.face(next(twin(r_v)))
                                : face_of_isolated_vertex(d_, u);
    const bool same_cycle = !u_alone && !v_alone && on_cycle(next(twin(r_u)), next(twin(r_v)));

    const HalfEdgeId x = append_edge(u, v, f);
    if (u_alone) {
        erase_isolated(f, u);
        set_out(u, x);
    } else {
        insert_after(x, r_u);
    }
    if (v_alone) {
        if (!v_is_new) erase_isolated(f, v);
        set_out(v, twin(x));
    } else {
        insert_after(twin(x), r_v);
    }
    Change c;
    c.edges.added = edge_of(x);
    if (u_alone && v_alone) {
        record(f).inner.push_back(x);  // a lone edge: a new hole of f
    } else if (same_cycle) {
        c.faces.added = split_face(f, x);
        c.faces.added_from = f;
    } else if (!u_alone && !v_alone) {
        join_cycles(f, x);
    }  // else one end was alone: its cycle just grew
    return c;
}

// The new edge x cut one cycle of f in two: cycle(x) and cycle(twin(x)).
FaceId DcelEditor::split_face(FaceId f, HalfEdgeId x) {
    const HalfEdgeId y = twin(x);
    const HalfEdgeId old_outer = record(f).outer;
    HalfEdgeId new_outer;  // the outer cycle of the new face
    HalfEdgeId rest;       // what stays f's: its outer cycle or one of its holes
    if (!old_outer.is_null() && (on_cycle(x, old_outer) || on_cycle(y, old_outer))) {
        // f's outer boundary split: both parts are counterclockwise; the new
        // face takes the one on the left of x.
        new_outer = x;
        rest = y;
        record(f).outer = y;
    } else {
        // A hole's boundary (or a cycle of the unbounded face) split: the part
        // with positive area is the region the edge closed off; the other
        // part is still a hole of f, and replaces the old entry.
        new_outer = area_sign(x) == Sign::Positive ? x : y;
        rest = twin(new_outer);
        const std::vector<HalfEdgeId> cx = sorted_cycle(x);
        const std::vector<HalfEdgeId> cy = sorted_cycle(y);
        for (HalfEdgeId& h : record(f).inner) {
            if (std::binary_search(cx.begin(), cx.end(), h) || std::binary_search(cy.begin(), cy.end(), h)) {
                h = rest;
                break;
            }
        }
    }
    const FaceId g = append_face(new_outer);
    relabel_cycle(new_outer, g);
    move_enclosed(f, g, new_outer, rest);
    return g;
}

// Moves the holes and isolated vertices of `from` that lie inside the cycle
// `boundary` to face `to`. `skip` names a hole that touches the boundary
// (it stays). O(|boundary| * count) worst case; a bounding box rejects most.
void DcelEditor::move_enclosed(FaceId from, FaceId to, HalfEdgeId boundary, HalfEdgeId skip) {
    Point lo = point(origin(boundary));
    Point hi = lo;
    for (const HalfEdgeId h : d_.cycle(boundary)) {
        const Point p = point(origin(h));
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    auto inside = [&](Point p) { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && encloses(boundary, p); };
    std::vector<HalfEdgeId> holes_kept;
    std::vector<HalfEdgeId> holes_moved;
    for (const HalfEdgeId h : record(from).inner) {
        (h != skip && inside(point(origin(h))) ? holes_moved : holes_kept).push_back(h);
    }
    std::vector<VertexId> isolated_kept;
    std::vector<VertexId> isolated_moved;
    for (const VertexId v : record(from).isolated) (inside(point(v)) ? isolated_moved : isolated_kept).push_back(v);
    record(from).inner = std::move(holes_kept);
    record(from).isolated = std::move(isolated_kept);
    // Filled through the conditional operator above, which cppcheck does not follow.
    // cppcheck-suppress knownEmptyContainer
    for (const HalfEdgeId h : holes_moved) relabel_cycle(h, to);
    FaceRecord& target_record = record(to);
    target_record.inner.insert(target_record.inner.end(), holes_moved.begin(), holes_moved.end());
    target_record.isolated.insert(target_record.isolated.end(), isolated_moved.begin(), isolated_moved.end());
}

// The new edge x joined two cycles of f into cycle(x): the record keeps one
// entry for it (the outer one, if either was f's outer cycle).
void DcelEditor::join_cycles(FaceId f, HalfEdgeId x) {
    const std::vector<HalfEdgeId> merged = sorted_cycle(x);
    FaceRecord& r = record(f);
    std::erase_if(r.inner, [&](HalfEdgeId h) { return std::binary_search(merged.begin(), merged.end(), h); });
    if (r.outer.is_null() || !std::binary_search(merged.begin(), merged.end(), r.outer)) r.inner.push_back(x);
}

// ------------------------------------------------------------------ removing

// The four cases of remove_edge, told apart by the faces on e's two sides
// and the degrees of its ends. Each relinks the cycles and fixes the face
// records; remove_edge then frees the edge's slot.
struct DcelEditor::Removal {
    HalfEdgeId h, t;  // u -> v and v -> u
    VertexId u, v;
    HalfEdgeId h_next, h_prev, t_next, t_prev;
};

Change DcelEditor::remove_edge(EdgeId e) {
    detail::require_edge(d_, e, "remove_edge");
    Removal r;
    r.h = half_edge_of(e, 0);
    r.t = twin(r.h);
    r.u = origin(r.h);
    r.v = origin(r.t);
    r.h_next = next(r.h);
    r.h_prev = prev(r.h);
    r.t_next = next(r.t);
    r.t_prev = prev(r.t);
    const bool u_end = r.t_next == r.h;  // u has no other edge
    const bool v_end = r.h_next == r.t;
    Change c;
    if (d_.face(r.h) != d_.face(r.t)) {
        c.faces = merge_faces_across(r);
    } else if (u_end && v_end) {
        remove_lone_edge(r);
    } else if (u_end || v_end) {
        remove_dangling_edge(r, u_end);
    } else {
        remove_bridge(r);
    }
    c.edges.removed = e;
    c.edges.moved = remove_edge_slot(e);
    return c;
}

// Two faces meet along the edge; neither end can be of degree 1. Their two
// cycles become one; the faces merge into the smaller id.
IdChange<FaceId> DcelEditor::merge_faces_across(const Removal& r) {
    const FaceId fh = d_.face(r.h);
    const FaceId ft = d_.face(r.t);
    const FaceId keep = std::min(fh, ft);
    const FaceId gone = std::max(fh, ft);
    const bool h_outer = !record(fh).outer.is_null() && on_cycle(r.h, record(fh).outer);
    const bool t_outer = !record(ft).outer.is_null() && on_cycle(r.t, record(ft).outer);
    auto drop_entry = [&](FaceId f, HalfEdgeId on) {
        const std::vector<HalfEdgeId> cyc = sorted_cycle(on);
        std::erase_if(record(f).inner, [&](HalfEdgeId x) { return std::binary_search(cyc.begin(), cyc.end(), x); });
    };
    if (!h_outer) drop_entry(fh, r.h);
    if (!t_outer) drop_entry(ft, r.t);
    link(r.h_prev, r.t_next);
    link(r.t_prev, r.h_next);
    const HalfEdgeId merged = r.h_next;
    FaceRecord absorbed = std::move(record(gone));
    record(gone) = FaceRecord{};
    FaceRecord& kept = record(keep);
    // When both cycles were outer boundaries, two bounded faces meet and
    // the merged cycle is the outer boundary. Otherwise one of them was a
    // hole of the face outside, and the face it enclosed opens into it:
    // the outside face's outer boundary stays, the merged cycle is a hole.
    HalfEdgeId outer_from_gone;
    if (h_outer && t_outer) {
        kept.outer = merged;
    } else {
        const FaceId outside = h_outer ? ft : fh;
        if (outside == gone) {
            kept.outer = absorbed.outer;
            outer_from_gone = absorbed.outer;
        }
        kept.inner.push_back(merged);
    }
    kept.inner.insert(kept.inner.end(), absorbed.inner.begin(), absorbed.inner.end());
    kept.isolated.insert(kept.isolated.end(), absorbed.isolated.begin(), absorbed.isolated.end());
    relabel_cycle(merged, keep);
    if (!outer_from_gone.is_null()) relabel_cycle(outer_from_gone, keep);
    for (const HalfEdgeId x : absorbed.inner) relabel_cycle(x, keep);
    if (d_.out(r.u) == r.h) set_out(r.u, r.t_next);
    if (d_.out(r.v) == r.t) set_out(r.v, r.h_next);
    IdChange<FaceId> faces;
    faces.removed = gone;
    faces.merged_into = keep;
    faces.moved = remove_face_slot(gone);
    return faces;
}

// A lone edge: its 2-cycle was a hole of its face; both ends become isolated.
void DcelEditor::remove_lone_edge(const Removal& r) {
    FaceRecord& rec = record(d_.face(r.h));
    std::erase_if(rec.inner, [&](HalfEdgeId x) { return x == r.h || x == r.t; });
    rec.isolated.insert(rec.isolated.end(), {r.u, r.v});
    set_out(r.u, {});
    set_out(r.v, {});
}

// A dangling edge: the cycle shortens, the free end becomes isolated.
void DcelEditor::remove_dangling_edge(const Removal& r, bool u_end) {
    const FaceId f = d_.face(r.h);
    const VertexId end = u_end ? r.u : r.v;
    const HalfEdgeId survivor = u_end ? r.h_next : r.t_next;
    if (u_end) {
        link(r.t_prev, r.h_next);
    } else {
        link(r.h_prev, r.t_next);
    }
    replace_in_record(f, r.h, survivor);
    replace_in_record(f, r.t, survivor);
    record(f).isolated.push_back(end);
    set_out(end, {});
    const VertexId other = u_end ? r.v : r.u;
    if (d_.out(other) == r.h || d_.out(other) == r.t) set_out(other, survivor);
}

// A bridge: the cycle splits into A (through h_next, around v's side) and B
// (through t_next). A component breaks off and becomes a hole of the face.
void DcelEditor::remove_bridge(const Removal& r) {
    const FaceId f = d_.face(r.h);
    const HalfEdgeId outer = record(f).outer;
    const bool is_outer = !outer.is_null() && on_cycle(r.h, outer);
    std::vector<HalfEdgeId> old_cycle;
    if (!is_outer) old_cycle = sorted_cycle(r.h);
    link(r.t_prev, r.h_next);
    link(r.h_prev, r.t_next);
    if (is_outer) {
        // One part still bounds f from outside (positive area); the other is
        // the component that broke off inside f.
        const bool a_outside = area_sign(r.h_next) == Sign::Positive;
        record(f).outer = a_outside ? r.h_next : r.t_next;
        record(f).inner.push_back(a_outside ? r.t_next : r.h_next);
    } else {
        for (HalfEdgeId& x : record(f).inner) {
            if (std::binary_search(old_cycle.begin(), old_cycle.end(), x)) {
                x = r.h_next;
                break;
            }
        }
        record(f).inner.push_back(r.t_next);
    }
    if (d_.out(r.u) == r.h) set_out(r.u, r.t_next);
    if (d_.out(r.v) == r.t) set_out(r.v, r.h_next);
}

Change DcelEditor::remove_isolated_vertex(VertexId v) {
    constexpr std::string_view kEdit = "remove_isolated_vertex";
    detail::require_vertex(d_, v, kEdit);
    if (const std::size_t n = degree(v); n != 0) {
        detail::refuse(kEdit, detail::describe(d_, v) + " has " + edges_text(n) + "; remove them first (remove_edge)");
    }
    erase_isolated(face_of_isolated_vertex(d_, v), v);
    Change c;
    c.vertices.removed = v;
    c.vertices.moved = remove_vertex_slot(v);
    return c;
}

Change DcelEditor::merge_collinear_edges(VertexId v) {
    constexpr std::string_view kEdit = "merge_collinear_edges";
    detail::require_vertex(d_, v, kEdit);
    if (const std::size_t n = degree(v); n != 2) {
        detail::refuse(kEdit, detail::describe(d_, v) + " has " + edges_text(n) + "; merging needs exactly two");
    }
    const HalfEdgeId h1 = d_.out(v);
    const HalfEdgeId h2 = next(twin(h1));
    const VertexId a = target(h1);
    const VertexId b = target(h2);
    if (!strictly_inside_segment(point(a), point(b), point(v))) {
        detail::refuse(kEdit, detail::describe(d_, v) + " is not exactly on the segment from " + detail::describe(d_, a) +
                                  " to " + detail::describe(d_, b) + ", so its two edges are not one straight line");
    }
    const EdgeId keep = std::min(edge_of(h1), edge_of(h2));
    const EdgeId drop = std::max(edge_of(h1), edge_of(h2));
    const HalfEdgeId hk = edge_of(h1) == keep ? h1 : h2;  // v -> far end of the kept edge
    const HalfEdgeId hd = edge_of(h1) == keep ? h2 : h1;  // v -> far_d
    const HalfEdgeId tk = twin(hk);
    const HalfEdgeId td = twin(hd);
    const VertexId far_d = target(hd);
    // Before: tk -> hd -> B and A -> td -> hk (at v of degree 2). After: hk
    // starts at far_d, so tk -> B and A -> hk; at a degree-1 far_d, tk -> hk.
    const HalfEdgeId b_next = next(hd);
    const HalfEdgeId a_prev = prev(td);
    d_.origin_[hk.index()] = far_d;
    if (b_next == td) {
        link(tk, hk);
    } else {
        link(tk, b_next);
        link(a_prev, hk);
    }
    if (d_.out(far_d) == td) set_out(far_d, hk);
    set_out(v, {});
    replace_in_record(d_.face(hd), hd, tk);
    replace_in_record(d_.face(td), td, hk);
    Change c;
    c.edges.removed = drop;
    c.edges.merged_into = keep;
    c.edges.moved = remove_edge_slot(drop);
    c.vertices.removed = v;
    c.vertices.moved = remove_vertex_slot(v);
    return c;
}

// ------------------------------------------------------------------ slots

EdgeId DcelEditor::remove_edge_slot(EdgeId e) {
    const EdgeId last(static_cast<Index>(d_.num_edges() - 1));
    if (e != last) {
        auto moved = [&](HalfEdgeId h) { return edge_of(h) == last ? half_edge_of(e, h.index() & 1U) : h; };
        for (unsigned side = 0; side < 2; ++side) {
            const Index from = half_edge_of(last, side).index();
            const Index to = half_edge_of(e, side).index();
            d_.origin_[to] = d_.origin_[from];
            d_.face_[to] = d_.face_[from];
            d_.next_[to] = moved(d_.next_[from]);
            d_.prev_[to] = moved(d_.prev_[from]);
        }
        for (unsigned side = 0; side < 2; ++side) {
            const HalfEdgeId to = half_edge_of(e, side);
            const HalfEdgeId from = half_edge_of(last, side);
            link(prev(to), to);
            link(to, next(to));
            if (d_.out(origin(to)) == from) set_out(origin(to), to);
            replace_in_record(d_.face(to), from, to);
        }
    }
    for (auto* column : {&d_.next_, &d_.prev_}) column->resize(column->size() - 2);
    d_.origin_.resize(d_.origin_.size() - 2);
    d_.face_.resize(d_.face_.size() - 2);
    return e != last ? last : EdgeId();
}

VertexId DcelEditor::remove_vertex_slot(VertexId v) {
    const VertexId last(static_cast<Index>(d_.num_vertices() - 1));
    if (v != last) {
        const HalfEdgeId out = d_.out(last);
        if (out.is_null()) {
            auto& iso = record(face_of_isolated_vertex(d_, last)).isolated;
            std::replace(iso.begin(), iso.end(), last, v);
        } else {
            for (const HalfEdgeId h : d_.around_origin_cw(out)) d_.origin_[h.index()] = v;
        }
        d_.points_[v.index()] = d_.points_[last.index()];
        d_.out_[v.index()] = out;
    }
    d_.points_.pop_back();
    d_.out_.pop_back();
    return v != last ? last : VertexId();
}

FaceId DcelEditor::remove_face_slot(FaceId f) {
    const FaceId last(static_cast<Index>(d_.num_faces() - 1));
    if (f != last) {
        record(f) = std::move(record(last));
        const FaceRecord& r = record(f);
        if (!r.outer.is_null()) relabel_cycle(r.outer, f);
        for (const HalfEdgeId h : r.inner) relabel_cycle(h, f);
    }
    d_.faces_.pop_back();
    return f != last ? last : FaceId();
}

// ------------------------------------------------------------------ public

Change split_edge(Dcel& d, EdgeId e, Point p) { return DcelEditor(d).split_edge(e, p); }
Change add_edge(Dcel& d, VertexId u, VertexId v) { return DcelEditor(d).add_edge(u, v); }
Change add_edge_to_point(Dcel& d, VertexId u, Point p) { return DcelEditor(d).add_edge_to_point(u, p); }
Change add_vertex(Dcel& d, Point p) { return DcelEditor(d).add_vertex(p); }
Change remove_edge(Dcel& d, EdgeId e) { return DcelEditor(d).remove_edge(e); }
Change remove_isolated_vertex(Dcel& d, VertexId v) { return DcelEditor(d).remove_isolated_vertex(v); }
Change merge_collinear_edges(Dcel& d, VertexId v) { return DcelEditor(d).merge_collinear_edges(v); }

}  // namespace dcel
