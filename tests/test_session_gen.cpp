// Generated sessions (gen/session.hpp) and their shrinking: every generated
// session's start graph is valid and the reference's own answer agrees with
// it; most steps are accepted; every shrink candidate is a session too.
#include <gtest/gtest.h>

#include "dcel/build.hpp"
#include "dcel/check/report.hpp"
#include "dcel/check/session.hpp"
#include "dcel/gen/session.hpp"

namespace dcel {
namespace {

std::size_t refused(const check::Session& s) {
    const check::ReferenceRun run = check::run_reference_session(s);
    std::size_t n = 0;
    for (const check::StepAnswer& a : run.steps) n += a.kind == check::StepAnswer::Kind::Error ? 1 : 0;
    return n;
}

TEST(SessionGen, SessionsOfEveryFamilyAgreeWithTheReferencesOwnAnswer) {
    std::size_t steps = 0, refusals = 0;
    for (const gen::Family f : gen::all_families()) {
        for (std::uint64_t seed = 0; seed < 6; ++seed) {
            gen::SessionParams p;
            p.graph = {f, seed, 12};
            p.seed = seed;
            p.steps = 20;
            const check::Session s = gen::generate_session(p);
            EXPECT_NO_THROW((void)build(s.start));
            EXPECT_EQ(s.steps.size(), 20U);
            const std::string answer = check::reference_session_answer(s, seed % 2 == 0);
            const check::Report r = check::compare_session(s, check::read_session_answer(answer));
            EXPECT_TRUE(r.agrees()) << check::write_session(s) << check::report_text(r);
            steps += s.steps.size();
            refusals += refused(s);
        }
    }
    // About one step in eight is one the reference refuses, on purpose.
    EXPECT_GT(refusals, steps / 20);
    EXPECT_LT(refusals, steps / 4);
}

TEST(SessionGen, TheSameParametersGiveTheSameSession) {
    gen::SessionParams p;
    p.graph = {gen::Family::NestedPolygons, 3, 16};
    p.seed = 9;
    p.steps = 30;
    EXPECT_EQ(check::write_session(gen::generate_session(p)), check::write_session(gen::generate_session(p)));
}

TEST(SessionGen, ShrinkCandidatesAreSmallerValidSessions) {
    gen::SessionParams p;
    p.graph = {gen::Family::GridWithHoles, 4, 14};
    p.seed = 4;
    p.steps = 12;
    const check::Session s = gen::generate_session(p);
    const auto candidates = gen::session_shrink_candidates(s);
    ASSERT_FALSE(candidates.empty());
    for (const check::Session& c : candidates) {
        EXPECT_NO_THROW((void)build(c.start));
        // Fewer steps (a start graph grown by the steps folded into it at
        // most by the vertices they made), or as many on a smaller start.
        EXPECT_LE(c.steps.size(), s.steps.size());
        if (c.steps.size() == s.steps.size()) {
            EXPECT_LE(c.start.vertices.size(), s.start.vertices.size());
        } else {
            EXPECT_LE(c.start.vertices.size(), s.start.vertices.size() + s.steps.size() - c.steps.size());
        }
        // The reference runs every candidate (refusals allowed).
        EXPECT_NO_THROW((void)check::run_reference_session(c));
    }
}

TEST(SessionGen, ShrinkingKeepsAFailureAndEndsSmall) {
    // "Fails" when the session still adds an edge that the reference
    // accepts: the smallest such session is one add_edge on two start
    // vertices, or, when its ends were made by steps, those steps and it.
    auto adds_an_edge = [](const check::Session& c) {
        const check::ReferenceRun run = check::run_reference_session(c);
        for (std::size_t i = 0; i < c.steps.size(); ++i) {
            if (c.steps[i].op == check::StepOp::AddEdge && run.steps[i].kind == check::StepAnswer::Kind::Ok) return true;
        }
        return false;
    };
    // The first of these sessions that adds an edge (a triangulation leaves
    // few edges to add).
    check::Session s;
    for (std::uint64_t seed = 7; !adds_an_edge(s); ++seed) {
        ASSERT_LT(seed, 40U) << "no session adds an edge";
        gen::SessionParams p;
        p.graph = {gen::Family::Triangulation, seed, 20};
        p.seed = seed;
        p.steps = 24;
        s = gen::generate_session(p);
    }
    const gen::GreedySessionShrink r = gen::shrink_session_greedily(s, adds_an_edge, [] { return false; });
    EXPECT_FALSE(r.stopped);
    EXPECT_LE(r.session.steps.size(), 3U);
    EXPECT_EQ(r.session.start.vertices.size() + r.session.steps.size(), 3U)  // two ends and the edge
        << check::write_session(r.session);
    EXPECT_TRUE(r.session.start.edges.empty());
}

}  // namespace
}  // namespace dcel
