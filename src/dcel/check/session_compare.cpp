// compare_session: an implementation's answers to a session against the
// reference running the same session beside them, step by step (the face an
// answer names is looked up in the reference's DCEL as it is at that step),
// then the state: the boundary cycles (each up to rotation), then, face by
// face, its holes and isolated vertices, and the points.
#include <algorithm>
#include <array>
#include <map>
#include <string>

#include "dcel/check/collector.hpp"
#include "dcel/check/cycles.hpp"
#include "dcel/check/session.hpp"
#include "dcel/check/session_reference.hpp"
#include "dcel/format.hpp"

namespace dcel::check {

namespace {

using Cycle = std::vector<Index>;

// The rotation of a cycle that is smallest lexicographically (the two-pointer
// minimum rotation, O(n)): two cycles are the same walk exactly when these
// agree.
Cycle canonical(const Cycle& c) {
    const std::size_t n = c.size();
    std::size_t i = 0, j = 1, k = 0;
    while (i < n && j < n && k < n) {
        const Index a = c[(i + k) % n], b = c[(j + k) % n];
        if (a == b) {
            ++k;
            continue;
        }
        if (a > b) {
            i += k + 1;
        } else {
            j += k + 1;
        }
        if (i == j) ++j;
        k = 0;
    }
    const std::size_t start = n == 0 ? 0 : std::min(i, j) % n;
    Cycle out(n);
    for (std::size_t t = 0; t < n; ++t) out[t] = c[(start + t) % n];
    return out;
}

// The same walk backwards: a cycle with its face on the other side.
Cycle reversed(const Cycle& c) {
    Cycle r(c);
    if (r.size() > 1) std::reverse(r.begin() + 1, r.end());
    return canonical(r);
}

// A repeated first vertex at the end is read as closing the cycle.
Cycle opened(Cycle c) {
    if (c.size() >= 2 && c.front() == c.back()) c.pop_back();
    return c;
}

std::string text(const Cycle& c) { return detail::cycle_text(c); }

std::string step_label(std::size_t i, const SessionStep& s) {
    return "step " + std::to_string(i) + " (" + describe_step(s) + ")";
}

std::string face_text(const FaceName& f) {
    return f.unbounded ? std::string("the unbounded face") : "the face left of " + text(f.walk);
}

class SessionComparison {
public:
    SessionComparison(const Session& s, const SessionAnswer& a) : session_(s), answer_(a), ref_(s.start) {}

    Report run() {
        const std::size_t n = session_.steps.size();
        std::size_t found = 0;  // differences found so far
        for (std::size_t i = 0; i < n; ++i) {
            const SessionStep& step = session_.steps[i];
            // A query is answered against the DCEL as it is before it runs
            // (queries change nothing, so that is also after).
            const StepAnswer expected = ref_.apply(step);
            if (i < answer_.steps.size()) compare_step(i, step, expected, answer_.steps[i]);
            if (i < answer_.states.size() && answer_.states[i]) {
                compare_state(*answer_.states[i], ref_.state(), "after " + step_label(i, step));
            }
            note_first(found, i);
        }
        // Too few step answers: the first step without one is the first wrong
        // (too many: the answers of the steps there are may all be right).
        if (answer_.steps.size() != n && out_.wants(DifferenceKind::WrongQueryAnswer)) {
            out_.add(DifferenceKind::WrongQueryAnswer, "the answer has " + std::to_string(answer_.steps.size()) +
                                                           " step answers; the session has " + std::to_string(n) + " steps");
        }
        if (answer_.steps.size() < n) note_first(found, answer_.steps.size());
        if (answer_.state) compare_state(*answer_.state, ref_.state(), "at the end");
        note_first(found, n);
        Report report = std::move(out_).finish();
        report.first_wrong_step = first_;
        if (!answer_.state && !has_any_state()) {
            report.notes.emplace_back("the answer gives no state: only the steps' answers were checked");
        }
        if (const std::string skips = skipped_text(); !skips.empty()) {
            report.notes.push_back("the answer skipped " + skips + " ({\"skip\": ...}): unchecked");
        }
        if (cycles_only_) {
            report.notes.emplace_back(
                "the state gives boundary cycles only: where holes and isolated vertices lie went unchecked (give "
                "face records {\"outer\", \"holes\", \"isolated\"} to have it checked)");
        }
        return report;
    }

private:
    void note_first(std::size_t& found, std::size_t step) {
        const std::size_t now = out_.count();
        if (now != found && !first_) first_ = step;
        found = now;
    }

    // "3 stab steps, 1 locate step", or "" when nothing was skipped.
    [[nodiscard]] std::string skipped_text() const {
        std::string out;
        for (std::size_t op = 0; op < kStepOpCount; ++op) {
            if (skipped_[op] == 0) continue;
            if (!out.empty()) out += ", ";
            out += std::to_string(skipped_[op]) + " " + std::string(step_op_name(static_cast<StepOp>(op))) +
                   (skipped_[op] == 1 ? " step" : " steps");
        }
        return out;
    }

    [[nodiscard]] bool has_any_state() const {
        return std::any_of(answer_.states.begin(), answer_.states.end(), [](const auto& s) { return s.has_value(); });
    }

    void compare_step(std::size_t i, const SessionStep& step, const StepAnswer& expected, const StepAnswer& got) {
        if (got.kind == StepAnswer::Kind::Skip) {
            if (is_query(step.op)) {
                ++skipped_[static_cast<std::size_t>(step.op)];
            } else {
                wrong(i, step,
                      "the answer skips an edit (" + escape_for_message(got.error, 200) +
                          "); only queries may be skipped, since the states after an edit would part");
            }
            return;
        }
        const bool ref_refused = expected.kind == StepAnswer::Kind::Error;
        const bool refused = got.kind == StepAnswer::Kind::Error;
        if (ref_refused != refused) {
            if (out_.wants(DifferenceKind::WrongRefusal)) {
                out_.add(DifferenceKind::WrongRefusal,
                         step_label(i, step) + ": " +
                             (ref_refused ? "the answer accepts it; the reference refuses it: " +
                                                escape_for_message(expected.error, 200)
                                          : "the answer refuses it (" + escape_for_message(got.error, 200) +
                                                "); the reference accepts it"));
            }
            return;
        }
        if (ref_refused) return;  // both refuse, each in its own words
        if (!is_query(step.op)) {
            if (got.kind != StepAnswer::Kind::Ok)
                wrong(i, step, "an edit's answer is {\"ok\": true} or {\"error\": \"...\"}");
            return;
        }
        compare_query(i, step, expected, got);
    }

    void wrong(std::size_t i, const SessionStep& step, const std::string& what) {
        if (out_.wants(DifferenceKind::WrongQueryAnswer)) {
            out_.add(DifferenceKind::WrongQueryAnswer, step_label(i, step) + ": " + what);
        }
    }

    // The face id of a name, the reference's or the answer's; nothing (and
    // a difference) when the answer's name names no face.
    std::optional<FaceId> face_of(std::size_t i, const SessionStep& step, const FaceName& f) {
        std::string why;
        std::optional<FaceId> face = ref_.face_named(f, why);
        if (!face) wrong(i, step, "the answer names a face by " + text(f.walk) + ", but " + why);
        return face;
    }

    void compare_query(std::size_t i, const SessionStep& step, const StepAnswer& expected, const StepAnswer& got) {
        // A point on a vertex or an edge: every query but stab answers where it is.
        if (expected.kind == StepAnswer::Kind::Vertex || expected.kind == StepAnswer::Kind::Edge) {
            compare_location(i, step, expected, got);
            return;
        }
        switch (step.op) {
            case StepOp::Locate: compare_location(i, step, expected, got); break;
            case StepOp::FaceBoundary: compare_boundary(i, step, expected, got); break;
            case StepOp::Neighbours: compare_faces(i, step, expected, got, false); break;
            case StepOp::Stab: compare_faces(i, step, expected, got, true); break;
            default: break;
        }
    }

    void compare_location(std::size_t i, const SessionStep& step, const StepAnswer& expected, const StepAnswer& got) {
        const std::string want = location_text(expected);
        if (got.kind != expected.kind) {
            wrong(i, step, "the answer says " + location_text(got) + "; the reference: " + want);
            return;
        }
        if (expected.kind == StepAnswer::Kind::Vertex && got.u != expected.u) {
            wrong(i, step, "the answer says vertex " + std::to_string(got.u) + "; the reference: " + want);
        } else if (expected.kind == StepAnswer::Kind::Edge &&
                   !((got.u == expected.u && got.v == expected.v) || (got.u == expected.v && got.v == expected.u))) {
            wrong(i, step, "the answer says edge " + text({got.u, got.v}) + "; the reference: " + want);
        } else if (expected.kind == StepAnswer::Kind::Face) {
            const std::optional<FaceId> g = face_of(i, step, got.face);
            std::string unused;
            if (g && g != ref_.face_named(expected.face, unused)) {
                wrong(i, step, "the answer says " + face_text(got.face) + "; the reference: " + want);
            }
        }
    }

    static std::string location_text(const StepAnswer& a) {
        switch (a.kind) {
            case StepAnswer::Kind::Vertex: return "vertex " + std::to_string(a.u);
            case StepAnswer::Kind::Edge: return "edge " + text({a.u, a.v});
            case StepAnswer::Kind::Face:
            case StepAnswer::Kind::Boundary: return face_text(a.face);
            case StepAnswer::Kind::Faces: return "a list of faces";
            case StepAnswer::Kind::Ok: return "ok";
            case StepAnswer::Kind::Error: return "an error";
            case StepAnswer::Kind::Skip: return "a skip";
        }
        return "?";
    }

    void compare_boundary(std::size_t i, const SessionStep& step, const StepAnswer& expected, const StepAnswer& got) {
        if (got.kind != StepAnswer::Kind::Boundary) {
            wrong(i, step,
                  "the answer says " + location_text(got) + "; the reference gives the boundary of " +
                      face_text(expected.face));
            return;
        }
        if (got.face_given) {  // the face's name is optional in a boundary; when given (null too), it must be right
            const std::optional<FaceId> g = face_of(i, step, got.face);
            std::string unused;
            if (g && g != ref_.face_named(expected.face, unused)) {
                wrong(i, step,
                      "the answer names " + face_text(got.face) + "; the reference's face is " + face_text(expected.face));
            }
        }
        const bool outer_ok = got.outer.has_value() == expected.outer.has_value() &&
                              (!got.outer || canonical(opened(*got.outer)) == canonical(*expected.outer));
        if (!outer_ok) {
            wrong(i, step,
                  "the outer boundary is " + (got.outer ? text(*got.outer) : std::string("null")) +
                      "; the reference's: " + (expected.outer ? text(*expected.outer) : std::string("null")));
        }
        if (sorted_canonical(got.holes) != sorted_canonical(expected.holes)) {
            wrong(i, step, "the holes are " + cycles_text(got.holes) + "; the reference's: " + cycles_text(expected.holes));
        }
    }

    static std::vector<Cycle> sorted_canonical(const std::vector<Cycle>& cs) {
        std::vector<Cycle> out;
        out.reserve(cs.size());
        for (const Cycle& c : cs) out.push_back(canonical(opened(c)));
        std::sort(out.begin(), out.end());
        return out;
    }

    static std::string cycles_text(const std::vector<Cycle>& cs) {
        constexpr std::size_t kShown = 6;
        std::string s = "[";
        for (std::size_t i = 0; i < cs.size() && i < kShown; ++i) s += (i == 0 ? "" : ", ") + text(cs[i]);
        if (cs.size() > kShown) s += ", ... (" + std::to_string(cs.size()) + " in all)";
        return s + "]";
    }

    // Neighbours (a set) or stab (in order, consecutive repeats merged).
    void compare_faces(std::size_t i, const SessionStep& step, const StepAnswer& expected, const StepAnswer& got,
                       bool ordered) {
        if (got.kind != StepAnswer::Kind::Faces) {
            wrong(i, step, "the answer says " + location_text(got) + "; the reference gives a list of faces");
            return;
        }
        std::vector<FaceId> want, have;
        std::string unused;
        for (const FaceName& f : expected.faces) want.push_back(*ref_.face_named(f, unused));
        for (const FaceName& f : got.faces) {
            const std::optional<FaceId> g = face_of(i, step, f);
            if (!g) return;
            if (!ordered || have.empty() || have.back() != *g) have.push_back(*g);
        }
        if (!ordered) {
            std::sort(have.begin(), have.end());
            have.erase(std::unique(have.begin(), have.end()), have.end());
            std::sort(want.begin(), want.end());
        }
        if (have != want) {
            wrong(i, step,
                  std::string(ordered ? "the faces in order are " : "the neighbours are ") + names_text(got.faces) +
                      "; the reference's: " + names_text(expected.faces));
        }
    }

    static std::string names_text(const std::vector<FaceName>& fs) {
        constexpr std::size_t kShown = 8;
        std::string s = "[";
        for (std::size_t i = 0; i < fs.size() && i < kShown; ++i) {
            s += (i == 0 ? "" : ", ") + (fs[i].unbounded ? std::string("null") : text(fs[i].walk));
        }
        if (fs.size() > kShown) s += ", ... (" + std::to_string(fs.size()) + " in all)";
        return s + "]";
    }

    // ---- States

    void compare_state(const SessionState& got, const SessionState& want, const std::string& when) {
        if (got.points) compare_points(*got.points, *want.points, when);
        std::vector<Cycle> want_cycles, got_cycles;
        for (const FaceRecord& f : want.faces) {
            if (f.outer) want_cycles.push_back(*f.outer);
            want_cycles.insert(want_cycles.end(), f.holes.begin(), f.holes.end());
        }
        if (got.cycles_only) {
            cycles_only_ = true;
            got_cycles = got.cycles;
        } else {
            for (const FaceRecord& f : got.faces) {
                if (f.outer) got_cycles.push_back(*f.outer);
                got_cycles.insert(got_cycles.end(), f.holes.begin(), f.holes.end());
            }
        }
        const bool cycles_agree = compare_cycles(got_cycles, want_cycles, when);
        if (!got.cycles_only && cycles_agree) compare_records(got.faces, want.faces, when);
    }

    void compare_points(const std::vector<std::optional<Point>>& got, const std::vector<std::optional<Point>>& want,
                        const std::string& when) {
        const std::size_t n = std::max(got.size(), want.size());
        for (std::size_t v = 0; v < n; ++v) {
            const std::optional<Point> g = v < got.size() ? got[v] : std::nullopt;
            const std::optional<Point> w = v < want.size() ? want[v] : std::nullopt;
            const bool same = g.has_value() == w.has_value() && (!g || (g->x == w->x && g->y == w->y));
            if (same || !out_.wants(DifferenceKind::WrongPoint)) continue;
            out_.add(DifferenceKind::WrongPoint, when + ", vertex " + std::to_string(v) + " is " +
                                                     (g ? "at " + format_point(*g) : std::string("absent")) +
                                                     " in the answer; in the reference " +
                                                     (w ? "at " + format_point(*w) : std::string("absent (removed)")));
        }
    }

    // The cycles as multisets up to rotation; true when they agree.
    bool compare_cycles(const std::vector<Cycle>& got, const std::vector<Cycle>& want, const std::string& when) {
        std::map<Cycle, long> balance;  // > 0: the reference has more; < 0: the answer
        for (const Cycle& c : want) ++balance[canonical(c)];
        std::vector<Cycle> extra;
        for (const Cycle& c : got) {
            const Cycle k = canonical(opened(c));
            if (auto it = balance.find(k); it != balance.end() && it->second > 0) {
                --it->second;
            } else {
                extra.push_back(k);
            }
        }
        bool agree = extra.empty();
        for (const Cycle& c : extra) {
            const Cycle back = reversed(c);
            if (auto it = balance.find(back); it != balance.end() && it->second > 0) {
                --it->second;
                if (out_.wants(DifferenceKind::ReversedCycle)) {
                    out_.add(
                        DifferenceKind::ReversedCycle,
                        when + ", the answer's cycle " + text(c) + " is the reference's " + text(back) + " walked backwards",
                        c);
                }
            } else if (out_.wants(DifferenceKind::ExtraCycle)) {
                out_.add(DifferenceKind::ExtraCycle,
                         when + ", the answer's cycle " + text(c) + " is no boundary cycle of the reference", c);
            }
        }
        for (const auto& [c, n] : balance) {
            for (long k = 0; k < n; ++k) {
                agree = false;
                if (out_.wants(DifferenceKind::MissingCycle)) {
                    out_.add(DifferenceKind::MissingCycle,
                             when + ", the reference's cycle " + text(c) + " is missing from the answer", c);
                }
            }
        }
        return agree;
    }

    // With the same cycles: each face, known by its outer cycle (none for the
    // unbounded face), must have the reference's holes and isolated vertices.
    void compare_records(const std::vector<FaceRecord>& got, const std::vector<FaceRecord>& want, const std::string& when) {
        std::map<std::optional<Cycle>, const FaceRecord*> by_outer;
        for (const FaceRecord& f : got) {
            const std::optional<Cycle> key = f.outer ? std::optional<Cycle>(canonical(opened(*f.outer))) : std::nullopt;
            if (!by_outer.emplace(key, &f).second && out_.wants(DifferenceKind::WrongOuterBoundary)) {
                out_.add(DifferenceKind::WrongOuterBoundary,
                         when + ", two faces of the answer have the outer boundary " + (f.outer ? text(*f.outer) : "null"));
            }
        }
        for (const FaceRecord& f : want) {
            const std::optional<Cycle> key = f.outer ? std::optional<Cycle>(canonical(*f.outer)) : std::nullopt;
            const std::string which = f.outer ? "the face with outer boundary " + text(*f.outer) : "the unbounded face";
            const auto it = by_outer.find(key);
            if (it == by_outer.end()) {
                if (out_.wants(DifferenceKind::WrongOuterBoundary)) {
                    std::string what = when;
                    what += ", the answer has no face record for ";
                    what += which;
                    what += " (its outer cycle is listed as a hole)";
                    out_.add(DifferenceKind::WrongOuterBoundary, std::move(what));
                }
                continue;
            }
            if (sorted_canonical(it->second->holes) != sorted_canonical(f.holes) && out_.wants(DifferenceKind::WrongHole)) {
                std::string what = when;
                what += ", " + which + " has the holes ";
                what += cycles_text(it->second->holes) + " in the answer; ";
                what += cycles_text(f.holes) + " in the reference";
                out_.add(DifferenceKind::WrongHole, std::move(what));
            }
            std::vector<Index> a = it->second->isolated, b = f.isolated;
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            if (a != b && out_.wants(DifferenceKind::WrongIsolatedVertex)) {
                std::string what = when;
                what += ", " + which + " has the isolated vertices ";
                what += text(a) + " in the answer; ";
                what += text(b) + " in the reference";
                out_.add(DifferenceKind::WrongIsolatedVertex, std::move(what));
            }
        }
    }

    const Session& session_;
    const SessionAnswer& answer_;
    detail::ReferenceSession ref_;
    detail::Collector out_;
    bool cycles_only_ = false;
    std::array<std::size_t, kStepOpCount> skipped_{};  // query steps skipped, by operation
    std::optional<std::size_t> first_;
};

}  // namespace

Report compare_session(const Session& s, const SessionAnswer& answer) { return SessionComparison(s, answer).run(); }

}  // namespace dcel::check
