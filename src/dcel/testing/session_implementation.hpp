// The interface a C++ DCEL implements to be driven through an edit session
// (docs/checking.md, "Sessions") by the session helpers
// (check_testing_sessions.hpp): SessionImplementation, its SessionFactory,
// and builders of the step answers. Needs neither GoogleTest nor RapidCheck,
// so the adapter around your DCEL can live with your DCEL; link
// dcel::testing.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dcel/check/session.hpp"
#include "dcel/graph.hpp"

namespace dcel::testing {

// Your DCEL, driven through one session. apply() answers one step: an edit
// with answers::ok() or answers::refused(why), a query with its answer;
// state() gives the face records now (it is asked after every edit and at
// the end).
class SessionImplementation {
public:
    SessionImplementation() = default;
    SessionImplementation(const SessionImplementation&) = delete;
    SessionImplementation& operator=(const SessionImplementation&) = delete;
    SessionImplementation(SessionImplementation&&) = delete;
    SessionImplementation& operator=(SessionImplementation&&) = delete;
    virtual ~SessionImplementation() = default;

    [[nodiscard]] virtual check::StepAnswer apply(const check::SessionStep& step) = 0;
    [[nodiscard]] virtual check::SessionState state() const = 0;
};

// A fresh implementation holding the start graph (protocol ids 0..V-1 are
// its vertices, in order). Called once per session, shrinking included.
using SessionFactory = std::function<std::unique_ptr<SessionImplementation>(const PlanarGraph& start)>;

// The answers a step can have, built from protocol ids.
namespace answers {

inline check::FaceName unbounded_face() { return {}; }
// The face on the left of the half-edge u -> v (or of a longer walk along
// its boundary).
inline check::FaceName face_left_of(Index u, Index v) { return check::FaceName{false, {u, v}}; }
inline check::FaceName face_left_of(std::vector<Index> walk) { return check::FaceName{false, std::move(walk)}; }

// An edit done, or refused (nothing changed; the words are yours).
inline check::StepAnswer ok() { return {}; }
inline check::StepAnswer refused(std::string why) {
    check::StepAnswer a;
    a.kind = check::StepAnswer::Kind::Error;
    a.error = std::move(why);
    return a;
}
// Where a point is (locate; and face_boundary and neighbours at a vertex or
// on an edge).
inline check::StepAnswer at_vertex(Index v) {
    check::StepAnswer a;
    a.kind = check::StepAnswer::Kind::Vertex;
    a.u = v;
    return a;
}
inline check::StepAnswer on_edge(Index u, Index v) {
    check::StepAnswer a;
    a.kind = check::StepAnswer::Kind::Edge;
    a.u = u;
    a.v = v;
    return a;
}
inline check::StepAnswer in_face(check::FaceName f) {
    check::StepAnswer a;
    a.kind = check::StepAnswer::Kind::Face;
    a.face = std::move(f);
    return a;
}
// face_boundary of a point in a face: the face's outer cycle (none for the
// unbounded face) and holes; the face's name is checked too.
inline check::StepAnswer boundary(check::FaceName f, std::optional<std::vector<Index>> outer,
                                  std::vector<std::vector<Index>> holes) {
    check::StepAnswer a;
    a.kind = check::StepAnswer::Kind::Boundary;
    a.face = std::move(f);
    a.face_given = true;
    a.outer = std::move(outer);
    a.holes = std::move(holes);
    return a;
}
// A query your DCEL does not have (a library without stab): the step goes
// unchecked, and a passing run says how many were skipped. Edits cannot be
// skipped.
inline check::StepAnswer skipped(std::string why) {
    check::StepAnswer a;
    a.kind = check::StepAnswer::Kind::Skip;
    a.error = std::move(why);
    return a;
}
// neighbours (a set) or stab (in order along the segment).
inline check::StepAnswer faces(std::vector<check::FaceName> fs) {
    check::StepAnswer a;
    a.kind = check::StepAnswer::Kind::Faces;
    a.faces = std::move(fs);
    return a;
}

}  // namespace answers

}  // namespace dcel::testing
