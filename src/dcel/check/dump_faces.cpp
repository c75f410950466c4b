#include "dcel/check/dump_faces.hpp"

#include <algorithm>
#include <string>

namespace dcel::check::detail {

DumpCycles dump_cycles(const DcelDump& d) {
    DumpCycles c;
    const auto halves = static_cast<Index>(d.half_edges.size());
    c.cycle_of.assign(halves, kNoIndex);
    for (Index h = 0; h < halves; ++h) {
        if (c.cycle_of[h] != kNoIndex) continue;
        const auto k = static_cast<Index>(c.cycles.size());
        c.through.emplace_back(h);
        Index x = h;
        do {  // next is a permutation, so the walk comes back to h
            c.cycle_of[x] = k;
            c.cycles.ids.push_back(d.half_edges[x].origin.index());
            x = d.half_edges[x].next.index();
        } while (x != h);
        c.cycles.end_cycle();
    }
    return c;
}

namespace {

// Which face record names a cycle, and how.
struct Role {
    Index face = kNoIndex;
    bool outer = false;
};

class FaceComparison {
public:
    FaceComparison(const Reference& ref, const DcelDump& answer, const DumpCycles& cycles, const CycleMatch& match,
                   Collector& out)
        : ref_(ref),
          d_(ref.dcel()),
          answer_(answer),
          cycles_(cycles),
          match_(match),
          out_(out),
          labels_{&cycles.cycles, cycles.through} {}

    void run() {
        reference_roles();
        answer_roles();
        map_faces();
        compare_cycles();
        compare_isolated();
    }

private:
    void reference_roles() {
        ref_role_.assign(ref_.cycle_count(), {});
        for (Index f = 0; f < d_.num_faces(); ++f) {
            const HalfEdgeId outer = d_.outer(FaceId(f));
            if (!outer.is_null()) ref_role_[ref_.cycle_of(outer)] = {f, true};
            for (const HalfEdgeId h : d_.inner(FaceId(f))) ref_role_[ref_.cycle_of(h)] = {f, false};
        }
    }

    // The first record naming each answer cycle; validate() reports a cycle
    // named twice or not at all (face-records).
    void answer_roles() {
        answer_role_.assign(cycles_.cycles.size(), {});
        auto name = [&](HalfEdgeId h, Index f, bool outer) {
            Role& r = answer_role_[cycles_.cycle_of[h.index()]];
            if (r.face == kNoIndex) r = {f, outer};
        };
        for (Index f = 0; f < answer_.faces.size(); ++f) {
            const FaceDump& face = answer_.faces[f];
            if (!face.outer.is_null()) name(face.outer, f, true);
            for (const HalfEdgeId h : face.inner) name(h, f, false);
        }
    }

    // An answer face is the reference face whose outer cycle it has; the one
    // answer face without an outer cycle is the unbounded face.
    void map_faces() {
        face_map_.assign(answer_.faces.size(), kNoIndex);
        std::vector<Index> unbounded;
        for (Index f = 0; f < answer_.faces.size(); ++f) {
            const HalfEdgeId outer = answer_.faces[f].outer;
            if (outer.is_null()) {
                unbounded.push_back(f);
                continue;
            }
            const Index k = cycles_.cycle_of[outer.index()];
            if (match_.status[k] != CycleStatus::Matched) continue;
            const Role r = ref_role_[match_.reference_cycle[k]];
            if (r.outer) face_map_[f] = r.face;
        }
        if (unbounded.size() == 1) {
            face_map_[unbounded[0]] = Dcel::kUnboundedFace.index();
        } else if (out_.wants(DifferenceKind::WrongOuterBoundary)) {
            std::string message;
            if (unbounded.empty()) {
                message = "every answer face has an outer boundary, so none is the unbounded face";
            } else {
                message = "answer faces";
                for (std::size_t i = 0; i < unbounded.size() && i < 8; ++i) message += " f" + std::to_string(unbounded[i]);
                if (unbounded.size() > 8) message += " ...";
                message += " (" + std::to_string(unbounded.size()) +
                           ") have no outer boundary; only the unbounded face lacks one";
            }
            out_.add(DifferenceKind::WrongOuterBoundary, std::move(message));
        }
    }

    [[nodiscard]] std::string reference_face(Index f) const {
        if (f == Dcel::kUnboundedFace.index()) return "the unbounded face";
        return "the face bounded by " + cycle_text(ref_.cycle_vertices(ref_.cycle_of(d_.outer(FaceId(f)))));
    }

    [[nodiscard]] std::string answer_face(Index f) const {
        std::string s = "answer face f" + std::to_string(f);
        const HalfEdgeId outer = answer_.faces[f].outer;
        if (face_map_[f] != kNoIndex) return s + " (" + reference_face(face_map_[f]) + ")";
        if (outer.is_null()) return s + " (no outer boundary)";
        return s + " (outer boundary " + cycle_text(cycles_.cycles[cycles_.cycle_of[outer.index()]]) + ")";
    }

    // A face the comparison could not identify has been reported already (its
    // outer cycle is missing, extra or misplaced, or the unbounded face is not
    // unique); what it contains is not reported again.
    [[nodiscard]] bool known(Index answer_face) const { return face_map_[answer_face] != kNoIndex; }

    void add(DifferenceKind kind, std::string message, std::vector<Index> vertices) {
        out_.add(kind, std::move(message), std::move(vertices));
    }

    // Each reference cycle the answer has must play the same part: the outer
    // boundary of the same face, or a hole of the same face.
    void compare_cycles() {
        for (Index r = 0; r < ref_.cycle_count(); ++r) {
            const Index k = match_.first_match[r];
            if (k == kNoIndex) continue;  // missing: reported with the cycles
            const Role want = ref_role_[r];
            const Role got = answer_role_[k];
            const std::string cycle = labels_.label(k);
            const std::span<const Index> span = cycles_.cycles[k];
            const std::vector<Index> vs(span.begin(), span.end());
            if (want.outer) {
                if (got.face != kNoIndex && got.outer) continue;
                if (!out_.wants(DifferenceKind::WrongOuterBoundary)) continue;
                add(DifferenceKind::WrongOuterBoundary,
                    cycle + " is the outer boundary of " + reference_face(want.face) + " in the reference, but " +
                        (got.face == kNoIndex ? "no answer face lists it"
                                              : "the answer lists it as a hole of " + answer_face(got.face)),
                    vs);
            } else if (got.face != kNoIndex && got.outer) {
                if (!out_.wants(DifferenceKind::WrongOuterBoundary)) continue;
                add(DifferenceKind::WrongOuterBoundary,
                    cycle + " is a hole of " + reference_face(want.face) +
                        " in the reference, but the answer makes it the outer boundary of answer face f" +
                        std::to_string(got.face),
                    vs);
            } else if (got.face == kNoIndex || (known(got.face) && face_map_[got.face] != want.face)) {
                if (!out_.wants(DifferenceKind::WrongHole)) continue;
                add(DifferenceKind::WrongHole,
                    cycle + " is a hole of " + reference_face(want.face) + " in the reference, but " +
                        (got.face == kNoIndex ? "no answer face lists it"
                                              : "the answer puts it in " + answer_face(got.face)),
                    vs);
            }
        }
    }

    void compare_isolated() {
        const auto vertices = static_cast<Index>(std::min(d_.num_vertices(), answer_.vertices.size()));
        std::vector<Index> want(d_.num_vertices(), kNoIndex);
        for (Index f = 0; f < d_.num_faces(); ++f) {
            for (const VertexId v : d_.isolated(FaceId(f))) want[v.index()] = f;
        }
        std::vector<Index> got(vertices, kNoIndex);  // the first answer face listing v
        for (Index f = 0; f < answer_.faces.size(); ++f) {
            for (const VertexId v : answer_.faces[f].isolated) {
                if (v.index() < vertices && got[v.index()] == kNoIndex) got[v.index()] = f;
            }
        }
        for (Index v = 0; v < vertices; ++v) {
            const std::string name = "v" + std::to_string(v);
            if (want[v] == kNoIndex) {
                if (got[v] == kNoIndex || !out_.wants(DifferenceKind::WrongIsolatedVertex)) continue;
                add(DifferenceKind::WrongIsolatedVertex,
                    name + " has edges in the graph, but the answer lists it as isolated in " + answer_face(got[v]), {v});
            } else if (got[v] == kNoIndex || (known(got[v]) && face_map_[got[v]] != want[v])) {
                if (!out_.wants(DifferenceKind::WrongIsolatedVertex)) continue;
                add(DifferenceKind::WrongIsolatedVertex,
                    "isolated vertex " + name + " lies in " + reference_face(want[v]) + " in the reference, but " +
                        (got[v] == kNoIndex ? "no answer face lists it" : "the answer lists it in " + answer_face(got[v])),
                    {v});
            }
        }
    }

    const Reference& ref_;
    const Dcel& d_;
    const DcelDump& answer_;
    const DumpCycles& cycles_;
    const CycleMatch& match_;
    Collector& out_;
    AnswerCycles labels_;
    std::vector<Role> ref_role_;     // per reference cycle
    std::vector<Role> answer_role_;  // per answer cycle
    std::vector<Index> face_map_;    // answer face -> reference face, or kNoIndex
};

}  // namespace

void compare_face_records(const Reference& ref, const DcelDump& answer, const DumpCycles& cycles, const CycleMatch& match,
                          Collector& out) {
    FaceComparison(ref, answer, cycles, match, out).run();
}

}  // namespace dcel::check::detail
