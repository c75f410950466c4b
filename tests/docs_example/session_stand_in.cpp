// my_session for the docs example's session test: the reference's answers,
// replayed (each step runs the whole session so far again with
// dcel::check::run_reference_session, which is slow and right), so that the
// example's tests have an implementation to pass; built with
// DOCS_EXAMPLE_REFUSES_AXIS_PARALLEL it also refuses every horizontal or
// vertical add_edge, a bug the tests must catch.
#include <optional>
#include <utility>

#include "my_session.hpp"

namespace {

class Replayed : public dcel::testing::SessionImplementation {
public:
    explicit Replayed(const dcel::PlanarGraph& start) {
        so_far_.start = start;
        state_ = dcel::check::run_reference_session(so_far_).state;
    }

    dcel::check::StepAnswer apply(const dcel::check::SessionStep& s) override {
#ifdef DOCS_EXAMPLE_REFUSES_AXIS_PARALLEL
        if (s.op == dcel::check::StepOp::AddEdge) {
            const std::optional<dcel::Point> p = point(s.u), q = point(s.v);
            if (p && q && (p->x == q->x || p->y == q->y)) return dcel::testing::answers::refused("axis-parallel");
        }
#endif
        so_far_.steps.push_back(s);
        dcel::check::ReferenceRun run = dcel::check::run_reference_session(so_far_);
        state_ = std::move(run.state);
        return run.steps.back();
    }

    dcel::check::SessionState state() const override { return state_; }

private:
    [[nodiscard]] std::optional<dcel::Point> point(dcel::Index v) const {
        if (!state_.points || v >= state_.points->size()) return std::nullopt;
        return (*state_.points)[v];
    }

    dcel::check::Session so_far_;
    dcel::check::SessionState state_;
};

}  // namespace

std::unique_ptr<dcel::testing::SessionImplementation> my_session(const dcel::PlanarGraph& start) {
    return std::make_unique<Replayed>(start);
}
