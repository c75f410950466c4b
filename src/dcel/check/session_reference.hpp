// Internal to dcel::check: a session running on the reference DCEL, step by
// step, with the protocol's names kept apart from the DCEL's own ids (the
// DCEL renumbers on removal: the last vertex moves into the freed id; the
// protocol never does, so two maps follow every Change). Used to write the
// reference's answer and, step by step beside an answer, to compare.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dcel/change.hpp"
#include "dcel/check/session.hpp"
#include "dcel/dcel.hpp"
#include "dcel/location.hpp"

namespace dcel::check::detail {

class ReferenceSession {
public:
    // Throws InvalidInput when the start graph is not valid.
    explicit ReferenceSession(const PlanarGraph& start);

    // Runs one step: an edit changes the DCEL (or is refused: {"error"} and
    // nothing changes); a query is answered.
    [[nodiscard]] StepAnswer apply(const SessionStep& s);
    // The face records and the points by protocol id, now.
    [[nodiscard]] SessionState state() const;

    // The face an answer names (a walk of two or more vertices along its
    // boundary with the face on the left; null for the unbounded face), or
    // nothing, with `why` saying what is wrong with the name.
    [[nodiscard]] std::optional<FaceId> face_named(const FaceName& f, std::string& why) const;

    [[nodiscard]] const Dcel& dcel() const { return d_; }
    // The protocol id of a DCEL vertex, and the DCEL vertex of a protocol id
    // (nothing for an id that never was or was removed); how many protocol
    // ids were handed out so far.
    [[nodiscard]] Index protocol_id(VertexId v) const { return proto_of_[v.index()]; }
    [[nodiscard]] std::optional<VertexId> vertex_of(Index p) const {
        if (p >= ref_of_.size() || ref_of_[p] == kNoIndex) return std::nullopt;
        return VertexId(ref_of_[p]);
    }
    [[nodiscard]] Index protocol_ids() const { return static_cast<Index>(ref_of_.size()); }

private:
    [[nodiscard]] Index proto(VertexId v) const { return proto_of_[v.index()]; }
    [[nodiscard]] VertexId vertex(Index p) const;
    [[nodiscard]] std::optional<HalfEdgeId> find_half_edge(Index pu, Index pv) const;
    [[nodiscard]] HalfEdgeId half_edge(Index pu, Index pv) const;
    [[nodiscard]] std::vector<Index> cycle(HalfEdgeId start) const;
    [[nodiscard]] FaceName name(FaceId f) const;
    void follow(const Change& c);
    StepAnswer edit(const SessionStep& s);
    [[nodiscard]] StepAnswer query(const SessionStep& s) const;
    [[nodiscard]] StepAnswer located(const Location& l) const;

    Dcel d_;
    std::vector<Index> ref_of_;    // protocol id -> DCEL vertex id (kNoIndex: removed)
    std::vector<Index> proto_of_;  // DCEL vertex id -> protocol id
};

}  // namespace dcel::check::detail
