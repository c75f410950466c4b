// Running a foreign command under a time limit, for `dcel diff` (POSIX).
//
// The command runs as `/bin/sh -c COMMAND` in a process group of its own, so
// a timeout kills everything it started (a shell, an interpreter, their
// children). What escapes the group (setsid, a daemon's double fork) comes
// back to dcel, a child subreaper, when its parent dies, and is killed and
// reaped once the run ends (or dcel is interrupted). Its stdin is written
// while its stdout and stderr are read, all through poll(), so a child that
// never reads its input, or fills a pipe before reading, cannot deadlock us.
// What it prints is capped, so garbage cannot exhaust our memory.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace dcel::diff {

// The most processes of the command run at once by one `dcel diff --jobs N`
// (N workers; the process layer records each one's group).
inline constexpr std::size_t kMaxJobs = 64;

// The command could not be run at all: no pipe, no /bin/sh, poll failing,
// or /bin/sh saying the command is not found or not executable.
class ProcessError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ProcessLimits {
    std::chrono::milliseconds timeout{5000};         // per run (per exchange with a stream): --timeout-ms
    std::size_t max_output = std::size_t{64} << 20;  // stdout bytes; beyond is a failure
};

enum class ProcessEnd : std::uint8_t {
    Exited,          // exit_status holds the status
    Signalled,       // signal holds the signal number
    TimedOut,        // killed, with its process group, at the deadline
    OutputTooLarge,  // killed after printing more than max_output bytes
};

struct ProcessResult {
    ProcessEnd end = ProcessEnd::Exited;
    int exit_status = 0;
    int signal = 0;
    std::string out;       // stdout, at most max_output bytes
    std::string err_tail;  // the last few KiB of stderr
};

// "exit status 3", "killed by signal 11 (Segmentation fault)", "no answer
// within 3000 ms", "more than 67108864 bytes on stdout".
[[nodiscard]] std::string describe_end(const ProcessResult& r, const ProcessLimits& limits);

// Runs COMMAND once with `input` on its stdin (then closed) and waits for it
// to exit, to time out, or to print too much.
[[nodiscard]] ProcessResult run_command(const std::string& command, std::string_view input, const ProcessLimits& limits);

// COMMAND kept running: one line in, one line out, per exchange. Started on
// the first exchange; after a failure (exit, signal, timeout, a line longer
// than max_output) the process is gone and the next exchange starts anew.
class StreamProcess {
public:
    StreamProcess(std::string command, ProcessLimits limits) : command_(std::move(command)), limits_(limits) {}
    StreamProcess(const StreamProcess&) = delete;
    StreamProcess& operator=(const StreamProcess&) = delete;
    ~StreamProcess();

    struct Reply {
        bool answered = false;  // line holds the answer (without its '\n')
        std::string line;
        ProcessResult failure;  // when not answered: how the process ended
    };
    // Writes `line` (which must not contain '\n') and a '\n', then waits for
    // the next non-blank line of output, at most `timeout` (the limits' by default).
    [[nodiscard]] Reply exchange(std::string_view line);
    [[nodiscard]] Reply exchange(std::string_view line, std::chrono::milliseconds timeout);

    // Closes its stdin, gives it a moment to exit, then kills its group.
    void stop();
    // How many times the command was started.
    [[nodiscard]] std::size_t starts() const { return starts_; }

private:
    void start();

    std::string command_;
    ProcessLimits limits_;
    int pid_ = -1;
    int in_ = -1, out_ = -1, err_ = -1;
    std::string pending_;  // output read past the last answer line
    std::size_t starts_ = 0;
};

}  // namespace dcel::diff
