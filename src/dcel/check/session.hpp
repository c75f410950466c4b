// Checking a DCEL's operations, not only its construction: an edit session
// (a start graph and a list of edits and queries, docs/checking.md,
// "Sessions") run by another implementation, its answers read, and compared
// with the reference running the same session.
//
// Names never depend on anyone's internal ids: a vertex keeps its protocol id
// for the whole session (the start graph's vertices are 0..V-1; each vertex a
// step creates takes the next id, ids of removed vertices are never reused);
// an edge is named by its two ends; a face by a half-edge [u, v] with the
// face on its left (or a longer walk of its boundary), the unbounded face by
// null. A step the reference refuses has the answer {"error": "..."}, and the
// session goes on.
//
// Nothing in an answer is trusted; reading is O(size), comparing a state
// O((A + E) log E) for an answer of size A.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dcel/check/compare.hpp"
#include "dcel/dcel.hpp"
#include "dcel/geometry/point.hpp"
#include "dcel/graph.hpp"

namespace dcel::check {

enum class StepOp : std::uint8_t {
    // Edits.
    SplitEdge,             // {"split_edge": {"edge": [u, v], "at": [x, y]}}: a new vertex exactly on the edge
    AddVertex,             // {"add_vertex": {"at": [x, y]}}: a new isolated vertex
    AddEdge,               // {"add_edge": {"from": u, "to": v}}
    AddEdgeToPoint,        // {"add_edge_to_point": {"from": u, "to": [x, y]}}: a new vertex and edge
    RemoveEdge,            // {"remove_edge": {"edge": [u, v]}}
    RemoveIsolatedVertex,  // {"remove_isolated_vertex": {"vertex": v}}
    MergeCollinearEdges,   // {"merge_collinear_edges": {"vertex": v}}: v removed, its two edges one
    // Queries.
    Locate,        // {"locate": {"at": [x, y]}}
    FaceBoundary,  // {"face_boundary": {"at": [x, y]}}
    Neighbours,    // {"neighbours": {"at": [x, y]}}
    Stab,          // {"stab": {"from": [x, y], "to": [x, y]}}
};
inline constexpr std::size_t kStepOpCount = 11;

[[nodiscard]] std::string_view step_op_name(StepOp op);  // "split_edge", ...
[[nodiscard]] bool is_query(StepOp op);
[[nodiscard]] bool creates_vertex(StepOp op);  // split_edge, add_vertex, add_edge_to_point (when accepted)

struct SessionStep {
    StepOp op = StepOp::AddVertex;
    Index u = kNoIndex;  // edge [u, v]; from u; vertex u
    Index v = kNoIndex;  // edge [u, v]; to v
    Point p;             // at; to (add_edge_to_point); from (stab)
    Point q;             // stab: to
};

// "split_edge [2, 5] at (3, 4)", "locate (1, 2)": a step in words.
[[nodiscard]] std::string describe_step(const SessionStep& s);

struct Session {
    PlanarGraph start;
    std::vector<SessionStep> steps;
    // Asks for the state after every edit as well ("each_step": true in the
    // document): the first wrong step is then pinned down exactly.
    bool each_step = false;
};

// The session document, on one line: {"vertices": [...], "edges": [...],
// "steps": [...]} (docs/checking.md, "Sessions").
[[nodiscard]] std::string write_session(const Session& s);
// Throws InvalidInput naming the place.
[[nodiscard]] Session read_session(std::string_view text);

// ---- What the answer says, and what the reference says.

// A face, as an answer names it: null (the unbounded face), or a walk of two
// or more vertices along its boundary with the face on the left.
struct FaceName {
    bool unbounded = true;
    std::vector<Index> walk;
};

// One step's answer.
struct StepAnswer {
    // Skip: {"skip": "why"}, a query the implementation does not have (a
    // library without stab); the step goes unchecked. An edit cannot be
    // skipped (the states after it would part).
    enum class Kind : std::uint8_t { Ok, Error, Vertex, Edge, Face, Boundary, Faces, Skip };
    Kind kind = Kind::Ok;
    std::string error;                        // Error: the implementation's message; Skip: why
    Index u = kNoIndex, v = kNoIndex;         // Vertex: u; Edge: [u, v]
    FaceName face;                            // Face; Boundary (optional in an answer)
    bool face_given = false;                  // an answer's "face" was there (null included)
    std::optional<std::vector<Index>> outer;  // Boundary: the outer cycle; none for the unbounded face
    std::vector<std::vector<Index>> holes;    // Boundary
    std::vector<FaceName> faces;              // Faces: neighbours (a set) or stab (in order)
};

// A face of the state: its outer cycle (none for the unbounded face), holes
// and isolated vertices, by protocol vertex ids.
struct FaceRecord {
    std::optional<std::vector<Index>> outer;
    std::vector<std::vector<Index>> holes;
    std::vector<Index> isolated;
};

// The state after the edits: the face records, or only the boundary cycles
// (which cannot show where holes and isolated vertices are: a report says
// so), and optionally the vertices' points by protocol id (null: removed).
struct SessionState {
    bool cycles_only = false;
    std::vector<FaceRecord> faces;           // when not cycles_only
    std::vector<std::vector<Index>> cycles;  // when cycles_only
    std::optional<std::vector<std::optional<Point>>> points;
};

struct SessionAnswer {
    std::vector<StepAnswer> steps;
    std::vector<std::optional<SessionState>> states;  // --each-step: after each step (edits only)
    std::optional<SessionState> state;                // after the last step
};

// {"steps": [...], "state": {...}}; throws InvalidInput naming the place.
[[nodiscard]] SessionAnswer read_session_answer(std::string_view text);

// ---- The reference: the session run on the reference DCEL.

struct ReferenceRun {
    std::vector<StepAnswer> steps;     // what a right implementation answers, step by step
    std::vector<SessionState> states;  // with each_step: the state after each step
    SessionState state;                // after the last step, with the points by protocol id
};

// Runs the session on the reference. The start graph must be valid (throws
// InvalidInput otherwise); a step the reference refuses is answered
// {"error": ...} and changes nothing. O(total cost of the edits and queries),
// plus O(V + E) per state when every state is kept (`each_step`).
[[nodiscard]] ReferenceRun run_reference_session(const Session& s, bool each_step = false);

// The reference's answer document, as a right implementation prints it
// (states after every edit with each_step).
[[nodiscard]] std::string reference_session_answer(const Session& s, bool each_step = false);

// One step's answer and a state as JSON, one line each, as in an answer.
[[nodiscard]] std::string write_step_answer(const StepAnswer& a);
[[nodiscard]] std::string write_session_state(const SessionState& s);

// The answer against the reference running the same session beside it: step
// by step (a refusal the reference does not make, or the other way round, is
// a wrong-refusal difference; a query answered otherwise, with the face it
// names looked up as the DCEL is at that step, wrong-query-answer), then
// each state the answer gives (cycles, then each face's holes and isolated
// vertices, then the points). Throws InvalidInput when the start graph is
// not valid.
[[nodiscard]] Report compare_session(const Session& s, const SessionAnswer& answer);

// The picture of step k (docs/checking.md, "Sessions"): the reference's state
// before it, the vertices labelled with their session ids, and the step in
// red over it (the edge added or removed, the point split at, added or
// located, the segment stabbed). With k = the number of steps: the state at
// the end and nothing in red. Throws InvalidInput when the start graph is
// not valid.
[[nodiscard]] std::string render_session_step_svg(const Session& s, std::size_t k, const std::string& title);

}  // namespace dcel::check
