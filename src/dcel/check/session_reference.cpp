// A session run on the reference DCEL (session_reference.hpp): the edits of
// dcel/edit.hpp and the queries of locate.hpp, stab.hpp and queries.hpp; and
// the reference's answer document.
#include <algorithm>
#include <string>

#include "dcel/build.hpp"
#include "dcel/check/session.hpp"
#include "dcel/check/session_reference.hpp"
#include "dcel/edit.hpp"
#include "dcel/error.hpp"
#include "dcel/io/json_writer.hpp"
#include "dcel/locate.hpp"
#include "dcel/queries.hpp"
#include "dcel/stab.hpp"

namespace dcel::check {

namespace detail {

namespace {

StepAnswer refused(std::string why) {
    StepAnswer a;
    a.kind = StepAnswer::Kind::Error;
    a.error = std::move(why);
    return a;
}

bool same_name(const FaceName& a, const FaceName& b) { return a.unbounded == b.unbounded && a.walk == b.walk; }

}  // namespace

ReferenceSession::ReferenceSession(const PlanarGraph& start) : d_(build(start)) {
    const auto n = static_cast<Index>(start.vertices.size());
    ref_of_.resize(n);
    proto_of_.resize(n);
    for (Index v = 0; v < n; ++v) ref_of_[v] = proto_of_[v] = v;
}

StepAnswer ReferenceSession::apply(const SessionStep& s) {
    try {
        return is_query(s.op) ? query(s) : edit(s);
    } catch (const InvalidInput& e) {
        return refused(e.what());
    } catch (const TopologyError& e) {
        return refused(e.what());
    }
}

SessionState ReferenceSession::state() const {
    SessionState st;
    for (Index f = 0; f < d_.num_faces(); ++f) {
        const FaceId face(f);
        FaceRecord rec;
        if (!d_.is_unbounded(face)) rec.outer = cycle(d_.outer(face));
        for (const HalfEdgeId h : d_.inner(face)) rec.holes.push_back(cycle(h));
        for (const VertexId v : d_.isolated(face)) rec.isolated.push_back(proto(v));
        st.faces.push_back(std::move(rec));
    }
    std::vector<std::optional<Point>> points(ref_of_.size());
    for (Index p = 0; p < ref_of_.size(); ++p) {
        if (ref_of_[p] != kNoIndex) points[p] = d_.point(VertexId(ref_of_[p]));
    }
    st.points = std::move(points);
    return st;
}

std::optional<FaceId> ReferenceSession::face_named(const FaceName& f, std::string& why) const {
    if (f.unbounded) return Dcel::kUnboundedFace;
    std::optional<FaceId> face;
    for (std::size_t i = 0; i + 1 < f.walk.size(); ++i) {
        const Index a = f.walk[i], b = f.walk[i + 1];
        const bool known = a < ref_of_.size() && ref_of_[a] != kNoIndex && b < ref_of_.size() && ref_of_[b] != kNoIndex;
        const std::optional<HalfEdgeId> h = known ? find_half_edge(a, b) : std::nullopt;
        if (!h) {
            why = "[" + std::to_string(a) + ", " + std::to_string(b) + "] is no half-edge of the state";
            return std::nullopt;
        }
        if (face && *face != d_.face(*h)) {
            why = "the walk runs along two faces";
            return std::nullopt;
        }
        face = d_.face(*h);
    }
    return face;
}

// The DCEL's vertex for a protocol id; refused when there is none (never
// was, or removed).
VertexId ReferenceSession::vertex(Index p) const {
    if (p >= ref_of_.size() || ref_of_[p] == kNoIndex) {
        throw InvalidInput(InputErrorKind::BadIndex,
                           "vertex " + std::to_string(p) +
                               (p >= ref_of_.size() ? " does not exist" : " was removed earlier in the session"));
    }
    return VertexId(ref_of_[p]);
}

std::optional<HalfEdgeId> ReferenceSession::find_half_edge(Index pu, Index pv) const {
    const VertexId a = vertex(pu), b = vertex(pv);
    for (const HalfEdgeId h : d_.around_origin_cw(d_.out(a))) {
        if (d_.target(h) == b) return h;
    }
    return std::nullopt;
}

HalfEdgeId ReferenceSession::half_edge(Index pu, Index pv) const {
    if (const std::optional<HalfEdgeId> h = find_half_edge(pu, pv)) return *h;
    throw InvalidInput(InputErrorKind::BadIndex,
                       "there is no edge [" + std::to_string(pu) + ", " + std::to_string(pv) + "]");
}

std::vector<Index> ReferenceSession::cycle(HalfEdgeId start) const {
    std::vector<Index> vs;
    for (const HalfEdgeId h : d_.cycle(start)) vs.push_back(proto(d_.origin(h)));
    return vs;
}

// A face's name: null for the unbounded face, else the first half-edge of
// its outer cycle.
FaceName ReferenceSession::name(FaceId f) const {
    FaceName n;
    if (d_.is_unbounded(f)) return n;
    n.unbounded = false;
    const HalfEdgeId h = d_.outer(f);
    n.walk = {proto(d_.origin(h)), proto(d_.target(h))};
    return n;
}

// The protocol maps after an edit: a vertex it added takes the next protocol
// id; a vertex it removed retires its id; the vertex moved into the freed
// DCEL id keeps its protocol id.
void ReferenceSession::follow(const Change& c) {
    const IdChange<VertexId>& v = c.vertices;
    if (!v.removed.is_null()) {
        ref_of_[proto_of_[v.removed.index()]] = kNoIndex;
        if (!v.moved.is_null()) {
            const Index kept = proto_of_[v.moved.index()];
            proto_of_[v.removed.index()] = kept;
            ref_of_[kept] = v.removed.index();
        }
        proto_of_.pop_back();
    }
    if (!v.added.is_null()) {
        const auto p = static_cast<Index>(ref_of_.size());
        ref_of_.push_back(v.added.index());
        proto_of_.resize(std::max<std::size_t>(proto_of_.size(), v.added.index() + 1));
        proto_of_[v.added.index()] = p;
    }
}

StepAnswer ReferenceSession::edit(const SessionStep& s) {
    Change c;
    switch (s.op) {
        case StepOp::SplitEdge: c = split_edge(d_, edge_of(half_edge(s.u, s.v)), s.p); break;
        case StepOp::AddVertex: c = add_vertex(d_, s.p); break;
        case StepOp::AddEdge: c = add_edge(d_, vertex(s.u), vertex(s.v)); break;
        case StepOp::AddEdgeToPoint: c = add_edge_to_point(d_, vertex(s.u), s.p); break;
        case StepOp::RemoveEdge: c = remove_edge(d_, edge_of(half_edge(s.u, s.v))); break;
        case StepOp::RemoveIsolatedVertex: c = remove_isolated_vertex(d_, vertex(s.u)); break;
        case StepOp::MergeCollinearEdges: c = merge_collinear_edges(d_, vertex(s.u)); break;
        default: break;
    }
    follow(c);
    return {};
}

StepAnswer ReferenceSession::located(const Location& l) const {
    StepAnswer a;
    switch (l.kind) {
        case Location::Kind::Vertex:
            a.kind = StepAnswer::Kind::Vertex;
            a.u = proto(l.vertex);
            break;
        case Location::Kind::Edge: {
            a.kind = StepAnswer::Kind::Edge;
            const HalfEdgeId h = half_edge_of(l.edge, 0);
            a.u = proto(d_.origin(h));
            a.v = proto(d_.target(h));
            break;
        }
        case Location::Kind::Face:
            a.kind = StepAnswer::Kind::Face;
            a.face = name(l.face);
            break;
    }
    return a;
}

StepAnswer ReferenceSession::query(const SessionStep& s) const {
    if (s.op == StepOp::Stab) {
        StepAnswer a;
        a.kind = StepAnswer::Kind::Faces;
        for (const FaceId f : faces_in_order(stab_segment(d_, s.p, s.q))) {
            if (a.faces.empty() || !same_name(a.faces.back(), name(f))) a.faces.push_back(name(f));
        }
        return a;
    }
    const Location l = locate_by_scan(d_, s.p);
    if (s.op == StepOp::Locate || l.kind != Location::Kind::Face) return located(l);
    StepAnswer a;
    a.face = name(l.face);
    if (s.op == StepOp::FaceBoundary) {
        a.kind = StepAnswer::Kind::Boundary;
        if (!d_.is_unbounded(l.face)) a.outer = cycle(d_.outer(l.face));
        for (const HalfEdgeId h : d_.inner(l.face)) a.holes.push_back(cycle(h));
    } else {
        a.kind = StepAnswer::Kind::Faces;
        for (const FaceId g : neighbours(d_, l.face)) a.faces.push_back(name(g));
    }
    return a;
}

}  // namespace detail

namespace {

// ---- Writing the reference's answers

void ids(io::JsonWriter& w, const std::vector<Index>& vs) {
    w.begin_array();
    for (const Index v : vs) {
        w.item();
        w.index(v);
    }
    w.end_array();
}

void face_name(io::JsonWriter& w, const FaceName& f) {
    if (f.unbounded) {
        w.null();
    } else {
        ids(w, f.walk);
    }
}

void state(io::JsonWriter& w, const SessionState& st) {
    w.begin_object();
    w.key("faces");
    w.begin_array();
    for (const std::vector<Index>& c : st.cycles) {  // an answer's state of cycles only
        w.item();
        ids(w, c);
    }
    for (const FaceRecord& rec : st.faces) {
        w.item();
        w.begin_object();
        w.key("outer");
        if (rec.outer) {
            ids(w, *rec.outer);
        } else {
            w.null();
        }
        w.key("holes");
        w.begin_array();
        for (const auto& h : rec.holes) {
            w.item();
            ids(w, h);
        }
        w.end_array();
        w.key("isolated");
        ids(w, rec.isolated);
        w.end_object();
    }
    w.end_array();
    if (st.points) {
        w.key("vertices");
        w.begin_array();
        for (const std::optional<Point>& p : *st.points) {
            w.item();
            if (!p) {
                w.null();
                continue;
            }
            w.raw('[');
            (void)w.number(p->x);
            w.raw(", ");
            (void)w.number(p->y);
            w.raw(']');
        }
        w.end_array();
    }
    w.end_object();
}

void step_answer(io::JsonWriter& w, const StepAnswer& a, const SessionState* after) {
    w.begin_object();
    switch (a.kind) {
        case StepAnswer::Kind::Ok:
            w.key("ok");
            w.boolean(true);
            break;
        case StepAnswer::Kind::Error:
            w.key("error");
            w.string(a.error);
            break;
        case StepAnswer::Kind::Skip:
            w.key("skip");
            w.string(a.error);
            break;
        case StepAnswer::Kind::Vertex:
            w.key("vertex");
            w.index(a.u);
            break;
        case StepAnswer::Kind::Edge:
            w.key("edge");
            ids(w, {a.u, a.v});
            break;
        case StepAnswer::Kind::Face:
            w.key("face");
            face_name(w, a.face);
            break;
        case StepAnswer::Kind::Boundary:
            w.key("face");
            face_name(w, a.face);
            w.key("outer");
            if (a.outer) {
                ids(w, *a.outer);
            } else {
                w.null();
            }
            w.key("holes");
            w.begin_array();
            for (const auto& h : a.holes) {
                w.item();
                ids(w, h);
            }
            w.end_array();
            break;
        case StepAnswer::Kind::Faces:
            w.key("faces");
            w.begin_array();
            for (const FaceName& f : a.faces) {
                w.item();
                face_name(w, f);
            }
            w.end_array();
            break;
    }
    if (after != nullptr) {
        w.key("state");
        state(w, *after);
    }
    w.end_object();
}

}  // namespace

ReferenceRun run_reference_session(const Session& s, bool each_step) {
    ReferenceRun run;
    detail::ReferenceSession ref(s.start);
    for (const SessionStep& step : s.steps) {
        run.steps.push_back(ref.apply(step));
        if (each_step) run.states.push_back(ref.state());
    }
    run.state = ref.state();
    return run;
}

std::string write_step_answer(const StepAnswer& a) {
    std::string out;
    io::JsonWriter w(out);
    step_answer(w, a, nullptr);
    w.flush();
    return out;
}

std::string write_session_state(const SessionState& st) {
    std::string out;
    io::JsonWriter w(out);
    state(w, st);
    w.flush();
    return out;
}

std::string reference_session_answer(const Session& s, bool each_step) {
    const ReferenceRun run = run_reference_session(s, each_step);
    std::string out;
    io::JsonWriter w(out);
    w.begin_object();
    w.key("steps");
    w.begin_array();
    for (std::size_t i = 0; i < run.steps.size(); ++i) {
        w.item();
        const bool edit = !is_query(s.steps[i].op);
        step_answer(w, run.steps[i], each_step && edit ? &run.states[i] : nullptr);
    }
    w.end_array();
    w.key("state");
    state(w, run.state);
    w.end_object();
    w.raw('\n');
    w.flush();
    return out;
}

}  // namespace dcel::check
