// Judging one run of the foreign command against the reference DCEL: agrees,
// or fails in one of five ways. Two failures are "the same" when shrinking
// may trade one for the other (see same_failure).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dcel/check/answer.hpp"
#include "dcel/check/session.hpp"
#include "dcel/dcel.hpp"
#include "dcel/diff/options.hpp"
#include "dcel/diff/process.hpp"

namespace dcel::diff {

enum class FailureKind : std::uint8_t {
    Crash,        // killed by a signal (or /bin/sh exited with 128 + its number)
    NonZeroExit,  // exited with a status other than 0
    Timeout,      // no answer within the case's time limit: a hang
    Unparsable,   // stdout is no answer of the expected kind (empty, garbage, too large)
    WrongAnswer,  // an answer that differs from the reference
    Refused,      // {"refused": "message"}: the implementation refused a graph the reference accepts
};

[[nodiscard]] std::string_view failure_name(FailureKind k);  // "crash", "non-zero exit", ...

struct Outcome {
    bool agrees = true;
    // {"skip": "reason"}: the graph is outside what the implementation
    // promises (agrees is true: not a failure; counted by reason).
    bool skipped = false;
    std::string skip_reason;
    FailureKind kind = FailureKind::WrongAnswer;
    std::string what;      // one line: the exit status, the parse error, the first difference, the refusal
    check::Report report;  // the differences, for a wrong answer
    ProcessResult run;     // what the command did (a crash reported by sh as Signalled)
    check::AnswerKind answer_kind = check::AnswerKind::Faces;  // how the answer was read
    // For drawing: the answer as vertex cycles (faces, dump) or as polygons of
    // vertex rings (polygons, rings); empty when it could not be read.
    std::vector<std::vector<Index>> answer_cycles;
    std::vector<std::vector<std::vector<Index>>> answer_polygons;
    // Sessions: the state was given as boundary cycles only, so where holes
    // and isolated vertices lie went unchecked.
    bool cycles_only = false;
    // Sessions: query steps the answer skipped ({"skip": ...}), by operation.
    std::array<std::size_t, check::kStepOpCount> skipped_steps{};
};

// How a run reads answers: --answer and the conventions, and, when the kind
// is detected, which kinds ambiguous shapes (a bare list of id lists, an
// empty list) agreed as so far, so a failure is judged as the likeliest.
struct AnswerJudging {
    AnswerOptions options;
    std::array<std::size_t, check::kAnswerKindCount> agreed_as{};
};

[[nodiscard]] Outcome judge(const Dcel& reference, const ProcessResult& run, const ProcessLimits& limits,
                            AnswerJudging& judging);

// A session's run (docs/checking.md, "Sessions"): as judge, with the answer
// read as a session's and compared with the reference running the session.
[[nodiscard]] Outcome judge_session(const check::Session& session, const ProcessResult& run, const ProcessLimits& limits);

// The protocol's own answers (docs/checking.md): {"skip": "reason"} for a
// graph outside the implementation's domain, {"refused": "message"} for one
// it refuses. Anything else: nothing.
struct ProtocolReply {
    bool skip = false;  // otherwise a refusal
    std::string text;   // the reason or the message
};
[[nodiscard]] std::optional<ProtocolReply> protocol_reply(std::string_view out);

// The class of a failure, what shrinking keeps and what groups start from:
// "wrong-answer/<family>" (the family of its first difference: "cycles" for
// wrong-next, reversed-cycle, missing-cycle, extra-cycle and
// wrong-orientation; "names" for vertex-count, not-a-vertex, not-an-edge and
// wrong-point; "faces" for wrong-hole, wrong-outer-boundary,
// wrong-isolated-vertex, missing-face and extra-polygon; "invariants" for
// broken-invariant), "crash/11", "exit/3: <the error line of stderr,
// numbers masked>", "timeout", "unparsable", "refused: <message, numbers
// masked>".
[[nodiscard]] std::string failure_class(const Outcome& o);

// Both failures, of the same class: shrinking may take one for the other.
[[nodiscard]] bool same_failure(const Outcome& a, const Outcome& b);

// "wrong answer (reversed-cycle)", "crash (signal 11)", "non-zero exit (status 1)", "timeout", "refused".
[[nodiscard]] std::string failure_label(const Outcome& o);

// A wrong answer's kinds of difference, sorted and joined by '+'
// ("missing-cycle+reversed-cycle"); "" for other failures.
[[nodiscard]] std::string difference_kinds(const Outcome& o);

// At most max_bytes of a program's output, escaped as every message is
// (dcel::escape_for_message), and how long it was when it is cut.
[[nodiscard]] std::string printable(std::string_view text, std::size_t max_bytes);

}  // namespace dcel::diff
