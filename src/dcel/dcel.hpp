// Dcel: the doubly connected edge list of a planar straight-line graph.
//
// Conventions, fixed once here:
//  - Half-edges come in twin pairs: twin(h) = h ^ 1, and input edge k owns
//    half-edges 2k (u->v) and 2k+1 (v->u).
//  - face(h) is the face on the left of h. Boundary cycles follow next().
//  - next(u->v) is the half-edge leaving v immediately clockwise from v->u;
//    at a vertex of degree 1, next(u->v) = v->u.
//  - Face 0 is the unbounded face: it has no outer cycle. Every other face has
//    exactly one outer cycle (counterclockwise) and any number of inner cycles
//    (holes: clockwise outer boundaries of the components directly inside it).
//  - An isolated vertex has no outgoing half-edge and is listed in the face
//    that contains it.
//
// The store only holds records and answers navigation; build() (build.hpp)
// makes one from a PlanarGraph and validate() (validate.hpp) checks one.
#pragma once

#include <cstddef>
#include <iterator>
#include <vector>

#include "dcel/contracts.hpp"
#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel {

struct FaceRecord {
    HalfEdgeId outer;                // null for the unbounded face
    std::vector<HalfEdgeId> inner;   // one half-edge of each hole's cycle
    std::vector<VertexId> isolated;  // isolated vertices inside this face
};

class Dcel;

// A walk that starts at a half-edge and steps until it comes back: a face
// cycle (by next or prev) or the half-edges around a vertex. Usable in
// range-for; the walk is capped at the number of half-edges.
enum class OrbitStep { Next, Prev, ClockwiseAroundOrigin, CounterclockwiseAroundOrigin };

class OrbitIterator {
public:
    using value_type = HalfEdgeId;
    using difference_type = std::ptrdiff_t;
    OrbitIterator() = default;
    OrbitIterator(const Dcel* dcel, HalfEdgeId start, OrbitStep step)
        : dcel_(dcel), start_(start), at_(start), step_(step) {}
    HalfEdgeId operator*() const { return at_; }
    OrbitIterator& operator++();
    OrbitIterator operator++(int) {
        OrbitIterator old = *this;
        ++*this;
        return old;
    }
    bool operator==(std::default_sentinel_t) const { return at_.is_null(); }

private:
    const Dcel* dcel_ = nullptr;
    HalfEdgeId start_;
    HalfEdgeId at_;
    OrbitStep step_ = OrbitStep::Next;
    std::size_t steps_ = 0;
};

class Orbit {
public:
    Orbit(const Dcel& dcel, HalfEdgeId start, OrbitStep step) : dcel_(&dcel), start_(start), step_(step) {}
    [[nodiscard]] OrbitIterator begin() const { return {dcel_, start_, step_}; }
    [[nodiscard]] std::default_sentinel_t end() const { return {}; }

private:
    const Dcel* dcel_;
    HalfEdgeId start_;
    OrbitStep step_;
};

class Dcel {
public:
    static constexpr FaceId kUnboundedFace{0};

    Dcel() { faces_.emplace_back(); }  // the empty subdivision: one unbounded face

    // ---- Sizes
    [[nodiscard]] std::size_t num_vertices() const { return points_.size(); }
    [[nodiscard]] std::size_t num_half_edges() const { return origin_.size(); }
    [[nodiscard]] std::size_t num_edges() const { return origin_.size() / 2; }
    [[nodiscard]] std::size_t num_faces() const { return faces_.size(); }

    // ---- Navigators
    // Every id argument must name an element of this DCEL (DCEL_EXPECTS,
    // checked in debug, sanitizer and fuzz builds; see contracts.hpp).
    [[nodiscard]] VertexId origin(HalfEdgeId h) const {
        DCEL_EXPECTS(h.index() < origin_.size());
        return origin_[h.index()];
    }
    [[nodiscard]] VertexId target(HalfEdgeId h) const {
        DCEL_EXPECTS(h.index() < origin_.size());
        return origin_[twin(h).index()];
    }
    [[nodiscard]] HalfEdgeId next(HalfEdgeId h) const {
        DCEL_EXPECTS(h.index() < next_.size());
        return next_[h.index()];
    }
    [[nodiscard]] HalfEdgeId prev(HalfEdgeId h) const {
        DCEL_EXPECTS(h.index() < prev_.size());
        return prev_[h.index()];
    }
    [[nodiscard]] FaceId face(HalfEdgeId h) const {
        DCEL_EXPECTS(h.index() < face_.size());
        return face_[h.index()];
    }
    [[nodiscard]] static HalfEdgeId twin(HalfEdgeId h) { return dcel::twin(h); }

    [[nodiscard]] Point point(VertexId v) const {
        DCEL_EXPECTS(v.index() < points_.size());
        return points_[v.index()];
    }
    // One outgoing half-edge (the smallest id after build); null when isolated.
    [[nodiscard]] HalfEdgeId out(VertexId v) const {
        DCEL_EXPECTS(v.index() < out_.size());
        return out_[v.index()];
    }

    [[nodiscard]] HalfEdgeId outer(FaceId f) const { return record(f).outer; }
    [[nodiscard]] const std::vector<HalfEdgeId>& inner(FaceId f) const { return record(f).inner; }
    [[nodiscard]] const std::vector<VertexId>& isolated(FaceId f) const { return record(f).isolated; }
    [[nodiscard]] bool is_unbounded(FaceId f) const { return record(f).outer.is_null(); }

    // ---- Walks (each is a range of half-edges)
    // The boundary cycle through h, forwards (next) or backwards (prev).
    [[nodiscard]] Orbit cycle(HalfEdgeId h) const { return {*this, h, OrbitStep::Next}; }
    [[nodiscard]] Orbit cycle_reversed(HalfEdgeId h) const { return {*this, h, OrbitStep::Prev}; }
    // The half-edges leaving the origin of h, clockwise (next(twin(h))) or
    // counterclockwise (twin(prev(h))). A null h gives an empty walk.
    [[nodiscard]] Orbit around_origin_cw(HalfEdgeId h) const { return {*this, h, OrbitStep::ClockwiseAroundOrigin}; }
    [[nodiscard]] Orbit around_origin_ccw(HalfEdgeId h) const { return {*this, h, OrbitStep::CounterclockwiseAroundOrigin}; }

    // ---- Whole arrays, read-only (for dumps, validation and bulk queries)
    [[nodiscard]] const std::vector<Point>& points() const { return points_; }
    [[nodiscard]] const std::vector<VertexId>& origins() const { return origin_; }
    [[nodiscard]] const std::vector<HalfEdgeId>& next_links() const { return next_; }
    // The rest of the arrays, for bindings that hand them out without copying
    // (the Python module's numpy views): prev(h), face(h) and out(v).
    [[nodiscard]] const std::vector<HalfEdgeId>& prev_links() const { return prev_; }
    [[nodiscard]] const std::vector<FaceId>& left_faces() const { return face_; }
    [[nodiscard]] const std::vector<HalfEdgeId>& out_links() const { return out_; }

private:
    [[nodiscard]] const FaceRecord& record(FaceId f) const {
        DCEL_EXPECTS(f.index() < faces_.size());
        return faces_[f.index()];
    }

    friend class DcelBuilder;  // build.cpp fills the arrays
    friend class DcelEditor;   // edit.cpp changes them in place

    std::vector<Point> points_;      // point(v): the coordinates, as given
    std::vector<HalfEdgeId> out_;    // out(v): origin(out(v)) == v, or null if isolated
    std::vector<VertexId> origin_;   // origin(h); target(h) = origin(twin(h))
    std::vector<HalfEdgeId> next_;   // next(h): a permutation; origin(next(h)) == target(h)
    std::vector<HalfEdgeId> prev_;   // prev(h): the inverse permutation of next
    std::vector<FaceId> face_;       // face(h): constant along each next-cycle
    std::vector<FaceRecord> faces_;  // faces_[0] is the unbounded face
};

inline OrbitIterator& OrbitIterator::operator++() {
    switch (step_) {
        case OrbitStep::Next: at_ = dcel_->next(at_); break;
        case OrbitStep::Prev: at_ = dcel_->prev(at_); break;
        case OrbitStep::ClockwiseAroundOrigin: at_ = dcel_->next(Dcel::twin(at_)); break;
        case OrbitStep::CounterclockwiseAroundOrigin: at_ = Dcel::twin(dcel_->prev(at_)); break;
    }
    if (at_ == start_ || ++steps_ >= dcel_->num_half_edges()) at_ = HalfEdgeId();
    return *this;
}

}  // namespace dcel
