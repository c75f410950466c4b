#include "dcel/diff/outcome.hpp"

#include <algorithm>

#include "dcel/check/answer_drawing.hpp"
#include "dcel/check/session.hpp"
#include "dcel/diff/failure_class.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/io/json_reader.hpp"

namespace dcel::diff {

std::string_view failure_name(FailureKind k) {
    switch (k) {
        case FailureKind::Crash: return "crash";
        case FailureKind::NonZeroExit: return "non-zero exit";
        case FailureKind::Timeout: return "timeout";
        case FailureKind::Unparsable: return "unparsable answer";
        case FailureKind::WrongAnswer: return "wrong answer";
        case FailureKind::Refused: return "refused";
    }
    return "?";
}

std::string printable(std::string_view text, std::size_t max_bytes) {
    std::string out = escape_for_message(text, max_bytes);
    if (text.size() > max_bytes) out += " (" + std::to_string(text.size()) + " bytes in all)";
    return out;
}

namespace {

// /bin/sh does not always exec its command: when the command is killed by a
// signal, sh itself exits with 128 + the signal number (dash does this).
constexpr int kShellSignalBase = 128;
constexpr int kMaxSignal = 64;

Outcome failed(FailureKind kind, std::string what, const ProcessResult& run) {
    Outcome o;
    o.agrees = false;
    o.kind = kind;
    o.what = std::move(what);
    o.run = run;
    return o;
}

std::string kinds_text(const std::vector<check::AnswerKind>& kinds) {
    std::string s;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        s += i == 0 ? "" : (i + 1 == kinds.size() ? " and " : ", ");
        s += check::answer_kind_name(kinds[i]);
    }
    return s;
}

// How the run ended, before its answer is read: a crash, a timeout, too much
// output, an exit status, nothing printed, or one of the protocol's own
// answers (a skip, a refusal); nothing when there is an answer to read.
std::optional<Outcome> process_outcome(const ProcessResult& run, const ProcessLimits& limits) {
    switch (run.end) {
        case ProcessEnd::Signalled: return failed(FailureKind::Crash, describe_end(run, limits), run);
        case ProcessEnd::TimedOut: return failed(FailureKind::Timeout, describe_end(run, limits), run);
        case ProcessEnd::OutputTooLarge: return failed(FailureKind::Unparsable, describe_end(run, limits), run);
        case ProcessEnd::Exited: break;
    }
    if (run.exit_status > kShellSignalBase && run.exit_status <= kShellSignalBase + kMaxSignal) {
        ProcessResult as_signal = run;
        as_signal.end = ProcessEnd::Signalled;
        as_signal.signal = run.exit_status - kShellSignalBase;
        return failed(FailureKind::Crash,
                      describe_end(as_signal, limits) + " (/bin/sh exit status " + std::to_string(run.exit_status) + ")",
                      as_signal);
    }
    if (run.exit_status != 0) return failed(FailureKind::NonZeroExit, describe_end(run, limits), run);
    if (run.out.find_first_not_of(" \t\r\n") == std::string::npos) {
        return failed(FailureKind::Unparsable,
                      run.out.empty() ? "printed nothing on stdout" : "printed only blanks on stdout", run);
    }
    if (std::optional<ProtocolReply> reply = protocol_reply(run.out)) {
        if (!reply->skip) return failed(FailureKind::Refused, "refused: " + printable(reply->text, 300), run);
        Outcome o;
        o.run = run;
        o.skipped = true;
        o.skip_reason = escape_for_message(reply->text, 120);
        return o;
    }
    return std::nullopt;
}

}  // namespace

Outcome judge(const Dcel& reference, const ProcessResult& run, const ProcessLimits& limits, AnswerJudging& judging) {
    if (std::optional<Outcome> ended = process_outcome(run, limits)) return std::move(*ended);
    const std::optional<check::AnswerKind> given = judging.options.kind;
    check::Answer answer;
    try {
        answer = check::read_answer(run.out, given);
    } catch (const InvalidInput& e) {
        const std::string what = given ? "not a " + std::string(check::answer_kind_name(*given)) + " answer: "
                                       : std::string("not an answer: ");
        return failed(FailureKind::Unparsable, what + e.what() + "; it begins \"" + printable(run.out, 80) + "\"", run);
    }
    // The kinds the shape fits, those that agreed most often so far first.
    std::vector<check::AnswerKind> order = answer.fits;
    std::stable_sort(order.begin(), order.end(), [&](check::AnswerKind a, check::AnswerKind b) {
        return judging.agreed_as[static_cast<std::size_t>(a)] > judging.agreed_as[static_cast<std::size_t>(b)];
    });
    Outcome worst;
    for (std::size_t i = 0; i < order.size(); ++i) {
        check::Answer as = order[i] == answer.kind ? answer : check::read_answer(run.out, order[i]);
        if (!given) as.detected_from.clear();  // the report says what was assumed, below
        check::Report report = check::compare(reference, as, judging.options.conventions);
        if (report.agrees()) {
            ++judging.agreed_as[static_cast<std::size_t>(order[i])];
            Outcome o;
            o.run = run;
            o.answer_kind = order[i];
            return o;
        }
        if (i != 0) continue;
        worst.run = run;
        worst.agrees = false;
        worst.kind = FailureKind::WrongAnswer;
        worst.answer_kind = order[i];
        worst.what = report.differences.front().message;
        worst.answer_cycles = check::drawn_cycles(as, judging.options.conventions);
        worst.answer_polygons = check::drawn_regions(as, reference, judging.options.conventions);
        worst.report = std::move(report);
    }
    if (!given && (order.size() > 1 || answer.detected_from.rfind("an object with", 0) != 0)) {
        worst.report.notes.insert(worst.report.notes.begin(),
                                  order.size() > 1 ? "the answer's shape fits " + kinds_text(order) + "; judged as " +
                                                         std::string(check::answer_kind_name(order.front())) +
                                                         " (--answer KIND says which)"
                                                   : "answer kind " + std::string(check::answer_kind_name(order.front())) +
                                                         ", detected from " + answer.detected_from);
    }
    return worst;
}

Outcome judge_session(const check::Session& session, const ProcessResult& run, const ProcessLimits& limits) {
    if (std::optional<Outcome> ended = process_outcome(run, limits)) return std::move(*ended);
    check::SessionAnswer answer;
    try {
        answer = check::read_session_answer(run.out);
    } catch (const InvalidInput& e) {
        return failed(FailureKind::Unparsable,
                      std::string("not a session's answer: ") + e.what() + "; it begins \"" + printable(run.out, 80) + "\"",
                      run);
    }
    check::Report report = check::compare_session(session, answer);
    Outcome o;
    o.run = run;
    o.cycles_only = answer.state && answer.state->cycles_only;
    for (std::size_t i = 0; i < answer.steps.size() && i < session.steps.size(); ++i) {
        const check::StepOp op = session.steps[i].op;
        if (answer.steps[i].kind == check::StepAnswer::Kind::Skip && check::is_query(op)) {
            ++o.skipped_steps[static_cast<std::size_t>(op)];
        }
    }
    if (report.agrees()) {
        o.report = std::move(report);  // its notes (a state of cycles only) are the run's warnings
        return o;
    }
    o.agrees = false;
    o.kind = FailureKind::WrongAnswer;
    o.what = report.differences.front().message;
    o.report = std::move(report);
    return o;
}

std::optional<ProtocolReply> protocol_reply(std::string_view out) {
    try {
        io::JsonReader r(out);
        if (r.peek() != io::JsonType::Object) return std::nullopt;
        r.begin_object("an object");
        if (!r.next_member()) return std::nullopt;
        const bool skip = r.key() == "skip";
        if ((!skip && r.key() != "refused") || r.peek() != io::JsonType::String) return std::nullopt;
        ProtocolReply reply{skip, r.read_string()};
        if (r.next_member()) return std::nullopt;  // one member, or it is some other answer
        r.end_document();
        return reply;
    } catch (const InvalidInput&) {
        return std::nullopt;  // not JSON at all: read_answer says why
    }
}

std::string difference_kinds(const Outcome& o) {
    if (o.kind != FailureKind::WrongAnswer) return {};
    std::vector<std::string_view> kinds;
    for (const check::Difference& d : o.report.differences) kinds.push_back(check::kind_name(d.kind));
    std::sort(kinds.begin(), kinds.end());
    kinds.erase(std::unique(kinds.begin(), kinds.end()), kinds.end());
    std::string s;
    for (const std::string_view k : kinds) s += (s.empty() ? "" : "+") + std::string(k);
    return s;
}

namespace {

// Wrong answers come in families: what a shrinking wrong answer may turn
// into and still be the same bug (a wrong rotation shows as wrong-next on a
// large graph and as reversed-cycle on a claw), and what it may not (a
// one-vertex cycle for an isolated vertex is another bug, whatever graph
// shows it).
std::string_view difference_family(check::DifferenceKind k) {
    using check::DifferenceKind;
    switch (k) {
        case DifferenceKind::WrongNext:
        case DifferenceKind::ReversedCycle:
        case DifferenceKind::MissingCycle:
        case DifferenceKind::ExtraCycle:
        case DifferenceKind::WrongOrientation: return "cycles";
        case DifferenceKind::VertexCount:
        case DifferenceKind::NotAVertex:
        case DifferenceKind::NotAnEdge:
        case DifferenceKind::WrongPoint: return "names";
        case DifferenceKind::WrongHole:
        case DifferenceKind::WrongOuterBoundary:
        case DifferenceKind::WrongIsolatedVertex:
        case DifferenceKind::MissingFace:
        case DifferenceKind::ExtraPolygon: return "faces";
        case DifferenceKind::BrokenInvariant: return "invariants";
        case DifferenceKind::WrongRefusal: return "refusals";
        case DifferenceKind::WrongQueryAnswer: return "queries";
        case DifferenceKind::UnreadableAnswer: return "unreadable";
    }
    return "?";
}

}  // namespace

std::string failure_class(const Outcome& o) {
    switch (o.kind) {
        case FailureKind::Crash: return "crash/" + std::to_string(o.run.signal);
        case FailureKind::NonZeroExit: {
            const std::string line = message_class(meaningful_line(o.run.err_tail));
            return "exit/" + std::to_string(o.run.exit_status) + (line.empty() ? "" : ": " + line);
        }
        case FailureKind::WrongAnswer:
            return "wrong-answer/" + std::string(difference_family(o.report.differences.front().kind));
        case FailureKind::Timeout: return "timeout";
        case FailureKind::Unparsable: return "unparsable";
        case FailureKind::Refused: {
            const std::optional<ProtocolReply> reply = protocol_reply(o.run.out);
            return "refused: " + message_class(reply ? reply->text : o.what);
        }
    }
    return "?";
}

bool same_failure(const Outcome& a, const Outcome& b) {
    return !a.agrees && !b.agrees && failure_class(a) == failure_class(b);
}

std::string failure_label(const Outcome& o) {
    std::string label(failure_name(o.kind));
    switch (o.kind) {
        case FailureKind::Crash: return label + " (signal " + std::to_string(o.run.signal) + ")";
        case FailureKind::NonZeroExit: return label + " (status " + std::to_string(o.run.exit_status) + ")";
        case FailureKind::WrongAnswer:
            return label + " (" + std::string(check::kind_name(o.report.differences.front().kind)) + ")";
        case FailureKind::Timeout:
        case FailureKind::Unparsable:
        case FailureKind::Refused: break;
    }
    return label;
}

}  // namespace dcel::diff
