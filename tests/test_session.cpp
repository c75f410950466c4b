// Sessions (check/session.hpp): the protocol's documents, the reference
// running a session, and comparing another implementation's answers with it.
// Expected answers are worked out by hand from the pictures in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "dcel/check/report.hpp"
#include "dcel/check/session.hpp"
#include "dcel/error.hpp"

namespace dcel {
namespace {

using check::compare_session;
using check::read_session;
using check::read_session_answer;
using check::Report;

// A 4x4 square 0 1 2 3 with the isolated vertex 4 at (3, 1):
//
//   3 (0,4) ----- 2 (4,4)
//     |             |
//     |          4  |      (3, 1)
//   0 (0,0) ----- 1 (4,0)
//
// Steps: the diagonal 0-2 splits the square (4 lies below it, y < x, in the
// lower triangle); queries; the diagonal removed (the triangles merge and 4
// is in the square again); 4 removed; a new vertex at (2, 2), which takes id
// 5, not 4; an edge to vertex 9, which does not exist (refused); the
// boundary of the face around (1, 1).
constexpr const char* kSession = R"({"vertices": [[0, 0], [4, 0], [4, 4], [0, 4], [3, 1]],
  "edges": [[0, 1], [1, 2], [2, 3], [3, 0]],
  "steps": [{"add_edge": {"from": 0, "to": 2}},
            {"locate": {"at": [3, 1]}},
            {"locate": {"at": [1, 3]}},
            {"locate": {"at": [2, 2]}},
            {"neighbours": {"at": [1, 3]}},
            {"remove_edge": {"edge": [2, 0]}},
            {"remove_isolated_vertex": {"vertex": 4}},
            {"add_vertex": {"at": [2, 2]}},
            {"add_edge": {"from": 5, "to": 9}},
            {"face_boundary": {"at": [1, 1]}},
            {"stab": {"from": [-1, 2], "to": [5, 2]}}]})";

// The answers, by hand: the upper triangle 0 2 3 is the face left of 2->3;
// the lower one, 0 1 2, left of 0->1; (2, 2) is on the diagonal; the upper
// triangle's neighbours are the lower one and the unbounded face; the stab
// crosses the unbounded face, the square, the unbounded face.
constexpr const char* kRight = R"({"steps": [
    {"ok": true}, {"vertex": 4}, {"face": [2, 3]}, {"edge": [0, 2]}, {"faces": [[0, 1], null]},
    {"ok": true}, {"ok": true}, {"ok": true}, {"error": "no vertex 9"},
    {"outer": [1, 2, 3, 0], "holes": []}, {"faces": [null, [3, 0], null]}],
  "state": {"faces": [{"outer": null, "holes": [[0, 3, 2, 1]], "isolated": []},
                      {"outer": [2, 3, 0, 1], "holes": [], "isolated": [5]}],
            "vertices": [[0, 0], [4, 0], [4, 4], [0, 4], null, [2, 2]]}})";

Report compare(const char* session, const std::string& answer) {
    return compare_session(read_session(session), read_session_answer(answer));
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

bool has(const Report& r, check::DifferenceKind k) {
    return std::any_of(r.differences.begin(), r.differences.end(), [&](const check::Difference& d) { return d.kind == k; });
}

TEST(Session, TheAnswerWorkedOutByHandAgrees) {
    const Report r = compare(kSession, kRight);
    EXPECT_TRUE(r.agrees()) << check::report_text(r);
}

TEST(Session, TheReferencesOwnAnswerAgreesAndReadsBack) {
    const check::Session s = read_session(kSession);
    EXPECT_EQ(read_session(check::write_session(s)).steps.size(), s.steps.size());
    for (const bool each : {false, true}) {
        const std::string answer = check::reference_session_answer(s, each);
        const Report r = compare_session(s, read_session_answer(answer));
        EXPECT_TRUE(r.agrees()) << answer << check::report_text(r);
    }
}

TEST(Session, ARefusalTheReferenceDoesNotMakeIsADifferenceAndTheOtherWayRound) {
    Report r = compare(kSession, replaced(kRight, R"({"ok": true}, {"vertex": 4})", R"({"error": "no"}, {"vertex": 4})"));
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongRefusal));
    EXPECT_EQ(r.first_wrong_step, 0U);
    r = compare(kSession, replaced(kRight, R"({"error": "no vertex 9"})", R"({"ok": true})"));
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongRefusal));
    EXPECT_EQ(r.first_wrong_step, 8U);
}

TEST(Session, QueriesAreComparedByWhatTheyNameNotHow) {
    // The upper triangle named by another of its half-edges, and by a walk.
    EXPECT_TRUE(compare(kSession, replaced(kRight, R"({"face": [2, 3]})", R"({"face": [0, 2, 3]})")).agrees());
    // The diagonal named the other way round.
    EXPECT_TRUE(compare(kSession, replaced(kRight, R"({"edge": [0, 2]})", R"({"edge": [2, 0]})")).agrees());
    // The wrong triangle; a name that is no half-edge; the hole's parent for a point.
    Report r = compare(kSession, replaced(kRight, R"({"face": [2, 3]})", R"({"face": [0, 1]})"));
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongQueryAnswer));
    EXPECT_EQ(r.first_wrong_step, 2U);
    r = compare(kSession, replaced(kRight, R"({"face": [2, 3]})", R"({"face": [3, 2]})"));  // the unbounded side
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongQueryAnswer));
    r = compare(kSession, replaced(kRight, R"({"face": [2, 3]})", R"({"face": [1, 3]})"));  // no such edge
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongQueryAnswer));
    r = compare(kSession, replaced(kRight, R"({"faces": [[0, 1], null]})", R"({"faces": [[0, 1]]})"));
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongQueryAnswer));
    r = compare(kSession, replaced(kRight, R"({"faces": [null, [3, 0], null]})", R"({"faces": [null, [3, 0]]})"));
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongQueryAnswer));
}

TEST(Session, AVertexInTheWrongFaceIsAPlacementDifference) {
    // A hole and an isolated vertex are placed by face: the cycles alone
    // cannot tell. Here the isolated vertex 5 left in the unbounded face.
    const std::string wrong = replaced(
        replaced(kRight, R"("holes": [[0, 3, 2, 1]], "isolated": [])", R"("holes": [[0, 3, 2, 1]], "isolated": [5])"),
        R"("holes": [], "isolated": [5])", R"("holes": [], "isolated": [])");
    const Report r = compare(kSession, wrong);
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongIsolatedVertex));
    // The same state as boundary cycles only: accepted, with a warning.
    const std::string cycles = R"({"steps": [
        {"ok": true}, {"vertex": 4}, {"face": [2, 3]}, {"edge": [0, 2]}, {"faces": [[0, 1], null]},
        {"ok": true}, {"ok": true}, {"ok": true}, {"error": "x"},
        {"outer": [1, 2, 3, 0], "holes": []}, {"faces": [null, [3, 0], null]}],
      "state": {"faces": [[0, 3, 2, 1], [1, 2, 3, 0]]}})";
    const Report c = compare(kSession, cycles);
    EXPECT_TRUE(c.agrees()) << check::report_text(c);
    EXPECT_TRUE(std::any_of(c.notes.begin(), c.notes.end(),
                            [](const std::string& n) { return n.find("went unchecked") != std::string::npos; }));
}

TEST(Session, CyclesAreComparedUpToRotationAndByDirection) {
    Report r = compare(kSession, replaced(kRight, R"("outer": [2, 3, 0, 1])", R"("outer": [0, 1, 2, 3, 0])"));
    EXPECT_TRUE(r.agrees()) << check::report_text(r);  // rotated, and closed
    r = compare(kSession, replaced(kRight, R"("outer": [2, 3, 0, 1])", R"("outer": [0, 3, 2, 1])"));
    EXPECT_TRUE(has(r, check::DifferenceKind::ReversedCycle));
    EXPECT_EQ(r.first_wrong_step, 11U);  // the state at the end
    r = compare(kSession, replaced(kRight, R"([2, 2]]}})", R"([2, 3]]}})"));
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongPoint));
}

TEST(Session, ProtocolIdsAreNeverReused) {
    const check::ReferenceRun run = check::run_reference_session(read_session(kSession));
    ASSERT_TRUE(run.state.points.has_value());
    ASSERT_EQ(run.state.points->size(), 6U);  // ids 0..5, 4 removed
    EXPECT_FALSE((*run.state.points)[4].has_value());
    EXPECT_EQ((*run.state.points)[5], (Point{2, 2}));
}

TEST(Session, BadDocumentsAreRefusedWithTheirPlace) {
    auto message = [](const char* text) {
        try {
            (void)read_session(text);
        } catch (const InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message(R"({"vertices": [], "edges": [], "steps": [{"jump": {}}]})").find("unknown operation \"jump\""),
              std::string::npos);
    EXPECT_NE(message(R"({"vertices": [], "edges": [], "steps": [{"add_edge": {"from": 0}}]})").find("missing key \"to\""),
              std::string::npos);
    EXPECT_NE(message(R"({"vertices": [], "edges": []})").find("missing key \"steps\""), std::string::npos);
    EXPECT_THROW((void)read_session_answer(R"({"steps": [{"ok": true, "error": "both"}]})"), InvalidInput);
}

}  // namespace
}  // namespace dcel

namespace dcel {
namespace {

check::Report compare_texts(const std::string& session, const std::string& answer) {
    return check::compare_session(check::read_session(session), check::read_session_answer(answer));
}

// A triangle; an isolated vertex added far out; a point located inside.
constexpr const char* kTriangle =
    R"({"vertices": [[0, 0], [4, 0], [0, 4]], "edges": [[0, 1], [1, 2], [2, 0]],)"
    R"( "steps": [{"locate": {"at": [1, 1]}}, {"add_vertex": {"at": [9, 9]}}, {"face_boundary": {"at": [1, 1]}}]})";

TEST(Session, TooFewStepAnswersAreWrongFromTheFirstMissing) {
    // Steps 0 and 1 answered right, step 2 not at all: the first wrong step is 2, not 0.
    const check::Report r = compare_texts(kTriangle, R"({"steps": [{"face": [0, 1]}, {"ok": true}]})");
    EXPECT_FALSE(r.agrees());
    EXPECT_EQ(r.first_wrong_step, 2U);
}

TEST(Session, ABoundarysFaceNameIsCheckedWhenGivenEvenAsNull) {
    const std::string right =
        R"({"steps": [{"face": [0, 1]}, {"ok": true}, {"face": [1, 2], "outer": [0, 1, 2], "holes": []}]})";
    EXPECT_TRUE(compare_texts(kTriangle, right).agrees());
    const std::string unnamed = R"({"steps": [{"face": [0, 1]}, {"ok": true}, {"outer": [0, 1, 2], "holes": []}]})";
    EXPECT_TRUE(compare_texts(kTriangle, unnamed).agrees());
    // null names the unbounded face: wrong for a point inside the triangle.
    const std::string null_name =
        R"({"steps": [{"face": [0, 1]}, {"ok": true}, {"face": null, "outer": [0, 1, 2], "holes": []}]})";
    const check::Report r = compare_texts(kTriangle, null_name);
    EXPECT_FALSE(r.agrees());
    EXPECT_EQ(r.first_wrong_step, 2U);
}

TEST(Session, AnEmptyListOfFacesIsAStateOfCyclesOnly) {
    // No edge at all: no cycle, and a record list would have the unbounded
    // face. Read as cycles, it agrees with the warning that placement went unchecked.
    const std::string session = R"({"vertices": [[0, 0]], "edges": [], "steps": [{"add_vertex": {"at": [1, 1]}}]})";
    const check::Report r = compare_texts(session, R"({"steps": [{"ok": true}], "state": {"faces": []}})");
    EXPECT_TRUE(r.agrees()) << check::report_text(r);
    ASSERT_FALSE(r.notes.empty());
    EXPECT_NE(r.notes.back().find("boundary cycles only"), std::string::npos);
}

TEST(Session, TheStepsPictureMarksTheStepOverTheStateBeforeIt) {
    const check::Session s = check::read_session(kTriangle);
    const std::string svg = check::render_session_step_svg(s, 2, "title");
    EXPECT_NE(svg.find("class=\"mark\""), std::string::npos);
    EXPECT_NE(svg.find("step 2, face_boundary"), std::string::npos);
    // Vertex 3 (the one step 1 added) is drawn: the state before step 2.
    EXPECT_NE(svg.find(">3<"), std::string::npos);
    // The end state: nothing in red.
    EXPECT_EQ(check::render_session_step_svg(s, 3, "title").find("class=\"mark\""), std::string::npos);
}

}  // namespace
}  // namespace dcel

namespace dcel {
namespace {

bool has_kind(const check::Report& r, check::DifferenceKind k) {
    return std::any_of(r.differences.begin(), r.differences.end(), [&](const check::Difference& d) { return d.kind == k; });
}

// A triangle and the vertex 3 added at (1, 1), inside it.
constexpr const char* kAdd =
    R"({"vertices": [[0, 0], [4, 0], [0, 4]], "edges": [[0, 1], [1, 2], [2, 0]], "steps": [{"add_vertex": {"at": [1, 1]}}]})";
constexpr const char* kAddState =
    R"({"faces": [{"outer": null, "holes": [[0, 2, 1]], "isolated": []}, {"outer": [0, 1, 2], "holes": [], "isolated": [3]}])";

std::string add_answer(const std::string& state) { return R"({"steps": [{"ok": true}], "state": )" + state + "}"; }

TEST(Session, StatesAreComparedCycleByCycleAndFaceByFace) {
    EXPECT_TRUE(compare_texts(kAdd, add_answer(std::string(kAddState) + "}")).agrees());
    // The points, when given: a wrong one, a missing one.
    check::Report r = compare_texts(
        kAdd, add_answer(std::string(kAddState) + R"(, "vertices": [[0, 0], [4, 0], [0, 4], [1, 2]]})"));
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::WrongPoint));
    r = compare_texts(kAdd, add_answer(std::string(kAddState) + R"(, "vertices": [[0, 0], [4, 0], [0, 4]]})"));
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::WrongPoint));
    // A cycle walked backwards; one missing; one that is no cycle.
    r = compare_texts(
        kAdd,
        add_answer(
            R"({"faces": [{"outer": null, "holes": [[0, 1, 2]], "isolated": []}, {"outer": [0, 1, 2], "holes": [], "isolated": [3]}]})"));
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::ReversedCycle));
    r = compare_texts(
        kAdd,
        add_answer(
            R"({"faces": [{"outer": null, "holes": [], "isolated": []}, {"outer": [0, 1, 2], "holes": [], "isolated": [3]}]})"));
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::MissingCycle));
    r = compare_texts(
        kAdd,
        add_answer(
            R"({"faces": [{"outer": null, "holes": [[0, 2, 1], [0, 3]], "isolated": []}, {"outer": [0, 1, 2], "holes": [], "isolated": [3]}]})"));
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::ExtraCycle));
    // Two records with one outer boundary; an outer boundary given as a hole.
    r = compare_texts(
        kAdd,
        add_answer(
            R"({"faces": [{"outer": null, "holes": [[0, 2, 1]], "isolated": []}, {"outer": [0, 1, 2], "holes": [], "isolated": [3]}, {"outer": [1, 2, 0], "holes": [], "isolated": []}]})"));
    EXPECT_FALSE(r.agrees());
    r = compare_texts(kAdd, add_answer(R"({"faces": [{"outer": null, "holes": [[0, 2, 1], [0, 1, 2]], "isolated": [3]}]})"));
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::WrongOuterBoundary));
    // A hole in the wrong face.
    r = compare_texts(
        kAdd,
        add_answer(
            R"({"faces": [{"outer": null, "holes": [], "isolated": []}, {"outer": [0, 1, 2], "holes": [[0, 2, 1]], "isolated": [3]}]})"));
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::WrongHole));
    // No state at all: the steps alone are checked, and the report says so.
    r = compare_texts(kAdd, R"({"steps": [{"ok": true}]})");
    EXPECT_TRUE(r.agrees());
    ASSERT_FALSE(r.notes.empty());
    EXPECT_NE(r.notes.front().find("no state"), std::string::npos);
}

TEST(Session, AnEditAnsweredAsAQueryAndAQueryAsAnotherKindAreWrong) {
    check::Report r = compare_texts(kAdd, R"({"steps": [{"vertex": 3}], "state": )" + std::string(kAddState) + "}}");
    EXPECT_TRUE(has_kind(r, check::DifferenceKind::WrongQueryAnswer)) << check::report_text(r);
    // Every query answered with the wrong kind of answer.
    const std::string session =
        R"({"vertices": [[0, 0], [4, 0], [0, 4]], "edges": [[0, 1], [1, 2], [2, 0]], "steps": [)"
        R"({"locate": {"at": [1, 1]}}, {"face_boundary": {"at": [1, 1]}}, {"neighbours": {"at": [1, 1]}},)"
        R"( {"stab": {"from": [-1, 1], "to": [5, 1]}}, {"locate": {"at": [0, 0]}}, {"locate": {"at": [2, 0]}}]})";
    r = compare_texts(
        session,
        R"({"steps": [{"ok": true}, {"face": [0, 1]}, {"face": [0, 1]}, {"vertex": 0}, {"edge": [0, 1]}, {"vertex": 0}]})");
    EXPECT_EQ(r.first_wrong_step, 0U);
    std::size_t wrong = 0;
    for (const check::Difference& d : r.differences) wrong += d.kind == check::DifferenceKind::WrongQueryAnswer ? 1 : 0;
    EXPECT_EQ(wrong, 6U) << check::report_text(r);
    // The right answers, with other names for the same things.
    r = compare_texts(session, R"({"steps": [{"face": [1, 2, 0]}, {"outer": [1, 2, 0], "holes": []}, {"faces": [null]},)"
                               R"( {"faces": [null, [2, 0], [0, 1], null]}, {"vertex": 0}, {"edge": [1, 0]}]})");
    EXPECT_TRUE(r.agrees()) << check::report_text(r);
}

TEST(Session, AQueryMayBeSkippedAndIsThenUncheckedButAnEditMayNot) {
    // Steps 1 (locate) and 10 (stab) skipped: nothing else is wrong, so the
    // answer agrees, with a note that counts them.
    std::string answer = replaced(kRight, R"({"vertex": 4})", R"({"skip": "no point location here"})");
    answer = replaced(answer, R"({"faces": [null, [3, 0], null]})", R"({"skip": "no stab"})");
    Report r = compare(kSession, answer);
    EXPECT_TRUE(r.agrees()) << check::report_text(r);
    ASSERT_FALSE(r.notes.empty());
    EXPECT_NE(r.notes.back().find("skipped 1 locate step, 1 stab step"), std::string::npos) << r.notes.back();
    // A skipped query does not hide a wrong one after it.
    r = compare(kSession, replaced(answer, R"({"face": [2, 3]})", R"({"face": [0, 1]})"));
    EXPECT_TRUE(has(r, check::DifferenceKind::WrongQueryAnswer));
    EXPECT_EQ(r.first_wrong_step, 2U);
    // An edit cannot be skipped (the states after it would part), even one
    // the reference refuses.
    for (const char* edit : {R"({"ok": true}, {"vertex": 4})", R"({"error": "no vertex 9"})"}) {
        const std::string skipped = std::string(edit).find("error") != std::string::npos
                                        ? R"({"skip": "later"})"
                                        : R"({"skip": "later"}, {"vertex": 4})";
        r = compare(kSession, replaced(kRight, edit, skipped));
        ASSERT_FALSE(r.agrees()) << edit;
        EXPECT_NE(r.differences.front().message.find("skips an edit (later)"), std::string::npos)
            << r.differences.front().message;
    }
    // The skip reads back as written, and its reason must be a string.
    EXPECT_EQ(check::write_step_answer(check::read_session_answer(R"({"steps": [{"skip": "why"}]})").steps[0]),
              R"({"skip": "why"})");
    EXPECT_THROW((void)read_session_answer(R"({"steps": [{"skip": true}]})"), InvalidInput);
    EXPECT_THROW((void)read_session_answer(R"({"steps": [{"skip": "a", "vertex": 1}]})"), InvalidInput);
}

TEST(Session, BadAnswersAreRefusedWithTheirPlace) {
    for (const char* bad : {R"({"steps": [{}]})", R"({"steps": [{"ok": false}]})", R"({"steps": [{"face": [1]}]})",
                            R"({"steps": [{"holes": []}]})", R"({"steps": [], "state": {"vertices": []}})",
                            R"({"steps": [], "state": {"faces": [[0, 1], {"outer": null}]}})",
                            R"({"steps": [], "state": {"faces": [{"holes": []}]}})", R"({"steps": [{"edge": [1, 2, 3]}]})",
                            R"({"steps": [], "state": {"faces": [], "vertices": [[1]]}})", R"([])"}) {
        EXPECT_THROW((void)check::read_session_answer(bad), InvalidInput) << bad;
    }
    for (const char* bad :
         {R"({"vertices": [], "edges": [], "steps": [{"add_vertex": {"at": [1, 2, 3]}}]})",
          R"({"vertices": [], "edges": [], "steps": [{"add_vertex": {"at": [1, 2]}, "locate": {"at": [1, 2]}}]})",
          R"({"vertices": [], "edges": [], "steps": [{"remove_edge": {"edge": [0]}}]})",
          R"({"vertices": [], "edges": [], "steps": [{"add_vertex": {"at": [1, 2]}}], "each_step": 1})",
          R"({"vertices": [], "edges": [], "steps": {}})"}) {
        EXPECT_THROW((void)check::read_session(bad), InvalidInput) << bad;
    }
}

TEST(Session, EveryStepIsWrittenAndReadBackAndDescribed) {
    const std::string text =
        R"({"vertices": [[0, 0], [4, 0], [0, 4]], "edges": [[0, 1], [1, 2], [2, 0]], "steps": [)"
        R"({"split_edge": {"edge": [0, 1], "at": [2, 0]}}, {"add_vertex": {"at": [1, 1]}}, {"add_edge": {"from": 3, "to": 4}},)"
        R"( {"add_edge_to_point": {"from": 4, "to": [1, 2]}}, {"remove_edge": {"edge": [4, 5]}}, {"remove_isolated_vertex": {"vertex": 5}},)"
        R"( {"remove_edge": {"edge": [3, 4]}}, {"merge_collinear_edges": {"vertex": 3}}, {"locate": {"at": [1, 1]}}, {"face_boundary": {"at": [1, 1]}},)"
        R"( {"neighbours": {"at": [1, 1]}}, {"stab": {"from": [-1, 1], "to": [5, 1]}}], "each_step": true})";
    const check::Session s = check::read_session(text);
    ASSERT_EQ(s.steps.size(), 12U);
    EXPECT_TRUE(s.each_step);
    EXPECT_EQ(check::write_session(check::read_session(check::write_session(s))), check::write_session(s));
    for (const check::SessionStep& step : s.steps) EXPECT_FALSE(check::describe_step(step).empty());
    // The reference's own answer, with a state after every edit, agrees with itself.
    const std::string answer = check::reference_session_answer(s, true);
    EXPECT_TRUE(check::compare_session(s, check::read_session_answer(answer)).agrees());
    const check::ReferenceRun run = check::run_reference_session(s, true);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_NE(run.steps[i].kind, check::StepAnswer::Kind::Error) << i;
}

}  // namespace
}  // namespace dcel
