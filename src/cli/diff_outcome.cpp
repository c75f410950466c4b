#include "diff_outcome.hpp"

#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"

namespace dcel::cli {

std::string_view failure_name(FailureKind k) {
    switch (k) {
        case FailureKind::Crash: return "crash";
        case FailureKind::NonZeroExit: return "non-zero exit";
        case FailureKind::Timeout: return "timeout";
        case FailureKind::Unparsable: return "unparsable answer";
        case FailureKind::WrongAnswer: return "wrong answer";
    }
    return "?";
}

std::string printable(std::string_view text, std::size_t max_bytes) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    for (const char c : text.substr(0, max_bytes)) {
        const auto b = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += "\\n";
        } else if (b >= 0x20 && b < 0x7f) {
            out += c;
        } else {
            out += "\\x";
            out += kHex[b >> 4U];
            out += kHex[b & 15U];
        }
    }
    if (text.size() > max_bytes) out += "... (" + std::to_string(text.size()) + " bytes in all)";
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

}  // namespace

Outcome judge(const Dcel& reference, const ProcessResult& run, const ProcessLimits& limits) {
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
    check::FacesAnswer answer;
    try {
        answer = io::read_faces_answer(run.out);
    } catch (const InvalidInput& e) {
        return failed(FailureKind::Unparsable,
                      std::string("not a faces answer: ") + e.what() + "; it begins \"" + printable(run.out, 80) + "\"",
                      run);
    }
    Outcome o;
    o.run = run;
    o.report = check::compare_faces(reference, answer);
    if (!o.report.agrees()) {
        o.agrees = false;
        o.kind = FailureKind::WrongAnswer;
        o.what = o.report.differences.front().message;
    }
    return o;
}

bool same_failure(const Outcome& a, const Outcome& b) {
    if (a.agrees || b.agrees || a.kind != b.kind) return false;
    switch (a.kind) {
        case FailureKind::Crash: return a.run.signal == b.run.signal;
        case FailureKind::NonZeroExit: return a.run.exit_status == b.run.exit_status;
        case FailureKind::WrongAnswer: return a.report.differences.front().kind == b.report.differences.front().kind;
        case FailureKind::Timeout:
        case FailureKind::Unparsable: return true;
    }
    return false;
}

std::string failure_label(const Outcome& o) {
    std::string label(failure_name(o.kind));
    switch (o.kind) {
        case FailureKind::Crash: return label + " (signal " + std::to_string(o.run.signal) + ")";
        case FailureKind::NonZeroExit: return label + " (status " + std::to_string(o.run.exit_status) + ")";
        case FailureKind::WrongAnswer:
            return label + " (" + std::string(check::kind_name(o.report.differences.front().kind)) + ")";
        case FailureKind::Timeout:
        case FailureKind::Unparsable: break;
    }
    return label;
}

}  // namespace dcel::cli
