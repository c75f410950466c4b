// Sessions and their answers as JSON (session.hpp; docs/checking.md,
// "Sessions"), read with the strict pull parser: every error names its
// place, nothing is trusted, and a document costs a few bytes per number.
#include <array>
#include <string>

#include "dcel/check/session.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/json_reader.hpp"
#include "dcel/io/json_writer.hpp"

namespace dcel::check {

namespace {

using io::JsonReader;
using io::JsonType;
using io::JsonWriter;

constexpr std::array<std::string_view, kStepOpCount> kOpNames{"split_edge",
                                                              "add_vertex",
                                                              "add_edge",
                                                              "add_edge_to_point",
                                                              "remove_edge",
                                                              "remove_isolated_vertex",
                                                              "merge_collinear_edges",
                                                              "locate",
                                                              "face_boundary",
                                                              "neighbours",
                                                              "stab"};

constexpr std::string_view kOpList =
    "split_edge, add_vertex, add_edge, add_edge_to_point, remove_edge, remove_isolated_vertex, "
    "merge_collinear_edges, locate, face_boundary, neighbours, stab";

// ---- Writing

void point(JsonWriter& w, Point p) {
    w.raw('[');
    if (!w.number(p.x)) io::fail_not_finite("a step's point", p.x);
    w.raw(", ");
    if (!w.number(p.y)) io::fail_not_finite("a step's point", p.y);
    w.raw(']');
}

void pair(JsonWriter& w, Index u, Index v) {
    w.raw('[');
    w.index(u);
    w.raw(", ");
    w.index(v);
    w.raw(']');
}

void step(JsonWriter& w, const SessionStep& s) {
    w.raw("{\"");
    w.raw(step_op_name(s.op));
    w.raw("\": {");
    switch (s.op) {
        case StepOp::SplitEdge:
            w.raw("\"edge\": ");
            pair(w, s.u, s.v);
            w.raw(", \"at\": ");
            point(w, s.p);
            break;
        case StepOp::AddVertex:
        case StepOp::Locate:
        case StepOp::FaceBoundary:
        case StepOp::Neighbours:
            w.raw("\"at\": ");
            point(w, s.p);
            break;
        case StepOp::AddEdge:
            w.raw("\"from\": ");
            w.index(s.u);
            w.raw(", \"to\": ");
            w.index(s.v);
            break;
        case StepOp::AddEdgeToPoint:
            w.raw("\"from\": ");
            w.index(s.u);
            w.raw(", \"to\": ");
            point(w, s.p);
            break;
        case StepOp::RemoveEdge:
            w.raw("\"edge\": ");
            pair(w, s.u, s.v);
            break;
        case StepOp::RemoveIsolatedVertex:
        case StepOp::MergeCollinearEdges:
            w.raw("\"vertex\": ");
            w.index(s.u);
            break;
        case StepOp::Stab:
            w.raw("\"from\": ");
            point(w, s.p);
            w.raw(", \"to\": ");
            point(w, s.q);
            break;
    }
    w.raw("}}");
}

// ---- Reading a session

Point read_point(JsonReader& r) {
    r.begin_array("a point [x, y]");
    double xy[2] = {0, 0};
    std::uint64_t n = 0;
    while (r.next_element()) {
        if (n < 2) {
            xy[n] = r.read_double("a coordinate");
        } else {
            r.skip_value();
        }
        ++n;
    }
    if (n != 2) r.fail_arity("a point [x, y]", n);
    return {xy[0], xy[1]};
}

std::pair<Index, Index> read_pair(JsonReader& r, std::string_view what) {
    r.begin_array(what);
    Index ids[2] = {kNoIndex, kNoIndex};
    std::uint64_t n = 0;
    while (r.next_element()) {
        if (n < 2) {
            ids[n] = r.read_index("vertex id");
        } else {
            r.skip_value();
        }
        ++n;
    }
    if (n != 2) r.fail_arity(what, n);
    return {ids[0], ids[1]};
}

// The operand object of a step: its known keys, each once, all required.
SessionStep read_operands(JsonReader& r, StepOp op) {
    SessionStep s;
    s.op = op;
    static constexpr std::array<std::string_view, 6> kKeys{"edge", "at", "from", "to", "vertex", "point"};
    r.begin_object("the step's operands, an object");
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        switch (k) {
            case 0: std::tie(s.u, s.v) = read_pair(r, "an edge [u, v]"); break;
            case 1:
            case 5: s.p = read_point(r); break;
            case 2:
                if (op == StepOp::Stab) {
                    s.p = read_point(r);
                } else {
                    s.u = r.read_index("vertex id");
                }
                break;
            case 3:
                if (op == StepOp::Stab) {
                    s.q = read_point(r);
                } else if (op == StepOp::AddEdgeToPoint) {
                    s.p = read_point(r);
                } else {
                    s.v = r.read_index("vertex id");
                }
                break;
            default: s.u = r.read_index("vertex id"); break;
        }
    }
    auto need = [&](std::size_t bit, std::string_view key) {
        if ((seen & (std::uint64_t{1} << bit)) == 0)
            r.fail_missing_key(key, "the operands of " + std::string(step_op_name(op)));
    };
    switch (op) {
        case StepOp::SplitEdge: need(0, "edge"), need(1, "at"); break;
        case StepOp::AddVertex:
        case StepOp::Locate:
        case StepOp::FaceBoundary:
        case StepOp::Neighbours:
            if ((seen & 0b100010U) == 0) need(1, "at");
            break;
        case StepOp::AddEdge:
        case StepOp::AddEdgeToPoint:
        case StepOp::Stab: need(2, "from"), need(3, "to"); break;
        case StepOp::RemoveEdge: need(0, "edge"); break;
        case StepOp::RemoveIsolatedVertex:
        case StepOp::MergeCollinearEdges: need(4, "vertex"); break;
    }
    return s;
}

SessionStep read_step(JsonReader& r) {
    r.begin_object("a step {\"operation\": {operands}}");
    if (!r.next_member()) r.fail(InputErrorKind::Shape, "a step needs its operation: one of " + std::string(kOpList));
    std::optional<StepOp> op;
    for (std::size_t i = 0; i < kOpNames.size(); ++i) {
        if (r.key() == kOpNames[i]) op = static_cast<StepOp>(i);
    }
    if (!op) {
        r.fail(InputErrorKind::Shape,
               "unknown operation " + quote_for_message(r.key()) + ": expected one of " + std::string(kOpList));
    }
    SessionStep s = read_operands(r, *op);
    if (r.next_member()) r.fail(InputErrorKind::Shape, "a step has one operation; give each step its own object");
    return s;
}

// ---- Reading an answer

std::vector<Index> read_ids(JsonReader& r, std::string_view what) {
    std::vector<Index> ids;
    r.begin_array(what);
    while (r.next_element()) ids.push_back(r.read_index("vertex id"));
    return ids;
}

FaceName read_face_name(JsonReader& r) {
    FaceName f;
    if (r.peek() == JsonType::Null) {
        r.skip_value();
        return f;
    }
    f.unbounded = false;
    f.walk = read_ids(r, "a face: null (the unbounded face) or [u, v, ...], a walk of its boundary with it on the left");
    if (f.walk.size() < 2) {
        r.fail(InputErrorKind::Shape,
               "a face is named by at least two vertices: a half-edge [u, v] with the face on its left");
    }
    return f;
}

FaceRecord read_face_record(JsonReader& r) {
    static constexpr std::array<std::string_view, 3> kKeys{"outer", "holes", "isolated"};
    FaceRecord rec;
    r.begin_object(R"(a face {"outer": cycle or null, "holes": [cycle, ...], "isolated": [v, ...]})");
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        if (k == 0) {
            if (r.peek() == JsonType::Null) {
                r.skip_value();
            } else {
                rec.outer = read_ids(r, "a cycle [v, ...]");
            }
        } else if (k == 1) {
            r.begin_array("an array of cycles");
            while (r.next_element()) rec.holes.push_back(read_ids(r, "a cycle [v, ...]"));
        } else {
            rec.isolated = read_ids(r, "an array of vertex ids");
        }
    }
    if ((seen & 1U) == 0) r.fail_missing_key("outer", "a face record (null for the unbounded face)");
    return rec;
}

SessionState read_state(JsonReader& r) {
    static constexpr std::array<std::string_view, 2> kKeys{"faces", "vertices"};
    SessionState st;
    r.begin_object(R"(a state {"faces": [...], "vertices": [...]})");
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        if (k == 0) {
            r.begin_array("an array of faces");
            // An empty list is of cycles: records always have the unbounded face.
            st.cycles_only = true;
            bool decided = false;
            while (r.next_element()) {
                const bool record = r.peek() == JsonType::Object;
                if (!decided) {
                    st.cycles_only = !record;
                    decided = true;
                } else if (record == st.cycles_only) {
                    r.fail(InputErrorKind::Shape, "faces given both as records and as cycles; use one form");
                }
                if (record) {
                    st.faces.push_back(read_face_record(r));
                } else {
                    st.cycles.push_back(read_ids(r, "a cycle [v, ...] or a face record"));
                }
            }
        } else {
            std::vector<std::optional<Point>> points;
            r.begin_array("an array of points by vertex id (null: removed)");
            while (r.next_element()) {
                if (r.peek() == JsonType::Null) {
                    r.skip_value();
                    points.emplace_back();
                } else {
                    points.emplace_back(read_point(r));
                }
            }
            st.points = std::move(points);
        }
    }
    if ((seen & 1U) == 0) r.fail_missing_key("faces", R"(a state {"faces": [...]})");
    return st;
}

StepAnswer read_step_answer(JsonReader& r, std::optional<SessionState>& state) {
    static constexpr std::array<std::string_view, 10> kKeys{"ok",    "error", "vertex", "edge",  "face",
                                                            "outer", "holes", "faces",  "state", "skip"};
    StepAnswer a;
    r.begin_object("a step's answer, an object");
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        switch (k) {
            case 0:
                if (r.peek() != JsonType::True) r.fail_type("true");
                r.skip_value();
                break;
            case 1: a.error = r.read_string("the refusal's message, a string"); break;
            case 2: a.u = r.read_index("vertex id"); break;
            case 3: std::tie(a.u, a.v) = read_pair(r, "an edge [u, v]"); break;
            case 4:
                a.face = read_face_name(r);
                a.face_given = true;
                break;
            case 5:
                if (r.peek() == JsonType::Null) {
                    r.skip_value();
                } else {
                    a.outer = read_ids(r, "the outer cycle [v, ...], or null for the unbounded face");
                }
                break;
            case 6:
                r.begin_array("an array of holes");
                while (r.next_element()) a.holes.push_back(read_ids(r, "a hole [v, ...]"));
                break;
            case 7:
                r.begin_array("an array of faces");
                while (r.next_element()) a.faces.push_back(read_face_name(r));
                break;
            case 8: state = read_state(r); break;
            default: a.error = r.read_string("why the query is skipped, a string"); break;
        }
    }
    const auto has = [&](std::size_t bit) { return (seen & (std::uint64_t{1} << bit)) != 0; };
    const int kinds = static_cast<int>(has(0)) + static_cast<int>(has(1)) + static_cast<int>(has(2)) +
                      static_cast<int>(has(3)) + static_cast<int>(has(7)) + static_cast<int>(has(9)) +
                      static_cast<int>(has(4) || has(5) || has(6));
    if (kinds != 1) {
        r.fail(InputErrorKind::Shape,
               R"(a step's answer is one of {"ok": true}, {"error": "..."}, {"vertex": v}, )"
               R"({"edge": [u, v]}, {"face": ...}, {"outer": ..., "holes": [...]}, {"faces": [...]}, {"skip": "..."})");
    }
    if (has(0)) a.kind = StepAnswer::Kind::Ok;
    if (has(1)) a.kind = StepAnswer::Kind::Error;
    if (has(2)) a.kind = StepAnswer::Kind::Vertex;
    if (has(3)) a.kind = StepAnswer::Kind::Edge;
    if (has(7)) a.kind = StepAnswer::Kind::Faces;
    if (has(9)) a.kind = StepAnswer::Kind::Skip;
    if (has(4)) a.kind = StepAnswer::Kind::Face;
    if (has(5) || has(6)) {
        a.kind = StepAnswer::Kind::Boundary;
        if (!has(5)) r.fail_missing_key("outer", "a face's boundary (null for the unbounded face)");
    }
    return a;
}

}  // namespace

std::string_view step_op_name(StepOp op) { return kOpNames[static_cast<std::size_t>(op)]; }

bool is_query(StepOp op) {
    return op == StepOp::Locate || op == StepOp::FaceBoundary || op == StepOp::Neighbours || op == StepOp::Stab;
}

bool creates_vertex(StepOp op) { return op == StepOp::SplitEdge || op == StepOp::AddVertex || op == StepOp::AddEdgeToPoint; }

std::string describe_step(const SessionStep& s) {
    std::string name(step_op_name(s.op));
    const auto edge = [&] { return "[" + std::to_string(s.u) + ", " + std::to_string(s.v) + "]"; };
    switch (s.op) {
        case StepOp::SplitEdge: return name + " " + edge() + " at " + format_point(s.p);
        case StepOp::AddVertex:
        case StepOp::Locate:
        case StepOp::FaceBoundary:
        case StepOp::Neighbours: return name + " at " + format_point(s.p);
        case StepOp::AddEdge: return name + " from " + std::to_string(s.u) + " to " + std::to_string(s.v);
        case StepOp::AddEdgeToPoint: return name + " from " + std::to_string(s.u) + " to " + format_point(s.p);
        case StepOp::RemoveEdge: return name + " " + edge();
        case StepOp::RemoveIsolatedVertex:
        case StepOp::MergeCollinearEdges: return name + " " + std::to_string(s.u);
        case StepOp::Stab: return name + " from " + format_point(s.p) + " to " + format_point(s.q);
    }
    return name;
}

std::string write_session(const Session& s) {
    std::string graph = io::write_graph(s.start);  // {"vertices": ..., "edges": ...}\n
    while (!graph.empty() && (graph.back() == '\n' || graph.back() == '}')) graph.pop_back();
    std::string out;
    JsonWriter w(out);
    w.raw(graph);
    w.raw(", \"steps\": [");
    for (std::size_t i = 0; i < s.steps.size(); ++i) {
        if (i != 0) w.raw(", ");
        step(w, s.steps[i]);
    }
    w.raw(s.each_step ? "], \"each_step\": true}\n" : "]}\n");
    w.flush();
    return out;
}

Session read_session(std::string_view text) {
    Session s;
    s.start = io::read_graph(text);  // the graph's own keys; "steps" is ignored there
    JsonReader r(text);
    static constexpr std::array<std::string_view, 2> kKeys{"steps", "each_step"};
    r.begin_object(R"(a session {"vertices": [...], "edges": [...], "steps": [...]})");
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        if (k == 1) {
            const JsonType t = r.peek();
            if (t != JsonType::True && t != JsonType::False) r.fail_type("true or false");
            s.each_step = t == JsonType::True;
            r.skip_value();
            continue;
        }
        r.begin_array("an array of steps");
        while (r.next_element()) s.steps.push_back(read_step(r));
    }
    if ((seen & 1U) == 0) r.fail_missing_key("steps", R"(a session {"vertices": [...], "edges": [...], "steps": [...]})");
    r.end_document();
    return s;
}

SessionAnswer read_session_answer(std::string_view text) {
    SessionAnswer a;
    JsonReader r(text);
    static constexpr std::array<std::string_view, 2> kKeys{"steps", "state"};
    r.begin_object(R"(a session's answer {"steps": [...], "state": {...}})");
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        if (k == 0) {
            r.begin_array("an array of step answers");
            while (r.next_element()) {
                std::optional<SessionState> state;
                a.steps.push_back(read_step_answer(r, state));
                a.states.push_back(std::move(state));
            }
        } else {
            a.state = read_state(r);
        }
    }
    if ((seen & 1U) == 0) r.fail_missing_key("steps", R"(a session's answer {"steps": [...], "state": {...}})");
    r.end_document();
    return a;
}

}  // namespace dcel::check
