#include "dcel/diff/process.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <mutex>
#include <string_view>
#include <thread>

extern char** environ;  // NOLINT: POSIX declares it nowhere else

namespace dcel::diff {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kErrKeep = 4096;               // stderr bytes kept for the report
constexpr std::chrono::milliseconds kGrace{200};     // to drain pipes after an exit
constexpr std::chrono::milliseconds kPollSlice{50};  // to notice an exit while a grandchild holds the pipes

void close_fd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

// The process groups alive now (with --jobs N, up to N workers' commands
// and a shrinker's), so that Ctrl-C or a kill of dcel does not leave a
// hanging command behind: the children have their own group, which the
// terminal's SIGINT does not reach. Mutable and global because the signal
// handler reads it; lock-free atomics, because threads write it.
constexpr std::size_t kMaxLiveGroups = 2 * kMaxJobs + 8;
static_assert(std::atomic<pid_t>::is_always_lock_free, "the signal handler reads live_groups");
// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables)
std::atomic<pid_t> live_groups[kMaxLiveGroups];

// Spawning a child and recording it, and looking for strays, exclude each
// other: between posix_spawn and remember_group, another thread's
// reap_strays would take the new child for a stray and kill it.
// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables)
std::mutex children_mutex;

void remember_group(pid_t pid) {
    for (std::atomic<pid_t>& slot : live_groups) {
        pid_t empty = 0;
        if (slot.compare_exchange_strong(empty, pid)) return;
    }
}
void forget_group(pid_t pid) {
    for (std::atomic<pid_t>& slot : live_groups) {
        pid_t here = pid;
        (void)slot.compare_exchange_strong(here, 0);
    }
}

bool is_live_group(pid_t pid) {
    for (const std::atomic<pid_t>& slot : live_groups) {
        if (slot.load() == pid) return true;
    }
    return false;
}

// ---- Processes that escaped their process group.
//
// A command may start a process in a session of its own (setsid, a daemon's
// double fork): killing the command's process group does not reach it. dcel
// is a child subreaper (PR_SET_CHILD_SUBREAPER), so such a process, once its
// parent dies, becomes dcel's child instead of init's; then it can be found
// in /proc/self/task/*/children, killed and reaped. Everything here uses
// only async-signal-safe calls (open, read, close, kill, waitpid), since
// the signal handler runs it too.

constexpr std::size_t kMaxStrays = 512;  // per round; more are taken next round

// Appends the pids listed in a /proc/.../children file to `out`.
void read_children(const char* path, pid_t* out, std::size_t& n) {
    const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;
    char buffer[4096];
    pid_t value = 0;
    bool in_number = false;
    for (;;) {
        const ssize_t k = ::read(fd, buffer, sizeof buffer);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) break;
        for (ssize_t i = 0; i < k; ++i) {
            const char c = buffer[i];
            if (c >= '0' && c <= '9') {
                value = value * 10 + (c - '0');
                in_number = true;
            } else if (in_number) {
                if (n < kMaxStrays) out[n++] = value;
                value = 0;
                in_number = false;
            }
        }
    }
    if (in_number && n < kMaxStrays) out[n++] = value;
    ::close(fd);
}

// "/proc/self/task/<tid>/children" into path (at least 64 bytes).
void children_path(char* path, long tid) {
    const char head[] = "/proc/self/task/";
    const char tail[] = "/children";
    std::size_t n = 0;
    for (const char c : std::string_view(head)) path[n++] = c;
    char digits[24];
    std::size_t k = 0;
    do {
        digits[k++] = static_cast<char>('0' + tid % 10);
        tid /= 10;
    } while (tid > 0);
    while (k > 0) path[n++] = digits[--k];
    for (const char c : std::string_view(tail)) path[n++] = c;
    path[n] = '\0';
}

// Our children other than the commands still running. Orphans are handed to
// a live thread of the subreaper, normally the main thread; the other
// threads' lists are read too when `all_threads` (not in a signal handler,
// where opendir is not allowed).
std::size_t stray_children(pid_t* out, bool all_threads) {
    std::size_t n = 0;
    char path[64];
    children_path(path, ::getpid());
    read_children(path, out, n);
    if (all_threads) {
        if (DIR* dir = ::opendir("/proc/self/task")) {
            while (const dirent* entry = ::readdir(dir)) {
                const long tid = std::strtol(entry->d_name, nullptr, 10);
                if (tid > 0 && tid != ::getpid()) {
                    children_path(path, tid);
                    read_children(path, out, n);
                }
            }
            ::closedir(dir);
        }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_live_group(out[i])) out[kept++] = out[i];
    }
    return kept;
}

// Kills and reaps every stray child, round after round: reaping one hands
// its own children to us, and they are taken in the next round. Bounded,
// so that a process forking as fast as we kill cannot keep us here.
void reap_strays(bool all_threads) {
    pid_t strays[kMaxStrays];
    for (int round = 0; round < 256; ++round) {
        const std::size_t n = stray_children(strays, all_threads);
        if (n == 0) return;
        for (std::size_t i = 0; i < n; ++i) {
            ::kill(-strays[i], SIGKILL);  // its group, when it leads one (setsid)
            ::kill(strays[i], SIGKILL);
        }
        for (std::size_t i = 0; i < n; ++i) {
            while (::waitpid(strays[i], nullptr, 0) < 0 && errno == EINTR) {
            }
        }
    }
}

extern "C" void kill_groups_and_die(int sig) {
    const int saved = errno;
    for (std::atomic<pid_t>& slot : live_groups) {
        const pid_t pid = slot.exchange(
            0);  // now a stray like any other: reaped below, so that its escaped children come to us
        if (pid != 0) ::kill(-pid, SIGKILL);
    }
    reap_strays(false);
    errno = saved;
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

// Once: dcel becomes a child subreaper (above); SIGPIPE ignored (writing to
// a child that stopped reading must fail with EPIPE, not kill us); SIGINT,
// SIGTERM and SIGHUP take the children down with us, unless they were
// ignored (nohup).
void install_signal_handling() {
    static const bool once = [] {
        ::prctl(PR_SET_CHILD_SUBREAPER, 1UL, 0UL, 0UL, 0UL);
        std::signal(SIGPIPE, SIG_IGN);
        for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
            if (std::signal(sig, kill_groups_and_die) == SIG_IGN) std::signal(sig, SIG_IGN);
        }
        return true;
    }();
    (void)once;
}

// A close-on-exec pipe whose ends are above 2, so that dup2 onto 0, 1, 2 in
// the child never maps an end onto itself (which would keep close-on-exec).
struct Pipe {
    int read = -1, write = -1;
};
int above_stdio(int fd) {
    if (fd > 2) return fd;
    const int high = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
    ::close(fd);
    return high;
}
// pipe2 sets close-on-exec atomically: with --jobs, another thread's
// posix_spawn between pipe() and fcntl() would hand this pipe's write end to
// its child, and our reader would never see end of file while that lives.
void close_pipe(Pipe& p) {
    for (int* fd : {&p.read, &p.write}) {
        if (*fd >= 0) ::close(*fd);
        *fd = -1;
    }
}
Pipe make_pipe() {
    Pipe p;
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw ProcessError(std::string("cannot create a pipe: ") + std::strerror(errno));
    p.read = above_stdio(fds[0]);
    const int read_errno = errno;
    p.write = above_stdio(fds[1]);
    if (p.read < 0 || p.write < 0) {
        const int e = p.read < 0 ? read_errno : errno;
        close_pipe(p);
        throw ProcessError(std::string("cannot create a pipe: ") + std::strerror(e));
    }
    return p;
}
// The three pipes of a child, or none: a pipe made before the one that
// failed is closed (each failure would leak its descriptors, and a long
// campaign that meets a passing shortage would run out for good).
std::array<Pipe, 3> make_pipes() {
    std::array<Pipe, 3> pipes;
    try {
        for (Pipe& p : pipes) p = make_pipe();
    } catch (const ProcessError&) {
        for (Pipe& p : pipes) close_pipe(p);
        throw;
    }
    return pipes;
}
void set_nonblocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

struct Child {
    pid_t pid = -1;
    int in = -1, out = -1, err = -1;
};

// /bin/sh -c COMMAND in a new process group, with SIGPIPE back at its default
// (an ignored signal stays ignored across exec) and no blocked signals.
// SIGINT, SIGTERM and SIGHUP need no reset: a caught signal is reset by exec.
Child spawn(const std::string& command) {
    install_signal_handling();
    auto [in, out, err] = make_pipes();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in.read, 0);
    posix_spawn_file_actions_adddup2(&actions, out.write, 1);
    posix_spawn_file_actions_adddup2(&actions, err.write, 2);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    posix_spawnattr_setpgroup(&attr, 0);
    sigset_t set;
    sigemptyset(&set);
    posix_spawnattr_setsigmask(&attr, &set);
    sigaddset(&set, SIGPIPE);
    posix_spawnattr_setsigdefault(&attr, &set);

    std::string sh = "/bin/sh", dash_c = "-c", cmd = command;
    char* argv[] = {sh.data(), dash_c.data(), cmd.data(), nullptr};
    pid_t pid = -1;
    std::unique_lock<std::mutex> lock(children_mutex);
    const int rc = ::posix_spawn(&pid, "/bin/sh", &actions, &attr, argv, environ);
    if (rc == 0) remember_group(pid);
    lock.unlock();
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    ::close(in.read);
    ::close(out.write);
    ::close(err.write);
    if (rc != 0) {
        ::close(in.write);
        ::close(out.read);
        ::close(err.read);
        throw ProcessError(std::string("cannot start /bin/sh: ") + std::strerror(rc));
    }
    for (int fd : {in.write, out.read, err.read}) set_nonblocking(fd);
    return {pid, in.write, out.read, err.read};
}

// Has the child exited? Does not reap it: while it is a zombie its pid, and
// so its process group id, cannot be reused, which makes kill(-pid) safe.
bool has_exited(pid_t pid) {
    siginfo_t info;
    std::memset(&info, 0, sizeof info);
    return ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

bool wait_exit(pid_t pid, Clock::time_point deadline) {
    std::chrono::microseconds nap{100};
    while (!has_exited(pid)) {
        if (Clock::now() >= deadline) return false;
        std::this_thread::sleep_for(nap);
        nap = std::min<std::chrono::microseconds>(nap * 2, std::chrono::milliseconds(5));
    }
    return true;
}

// Kills what is left of the child's group, reaps the child, closes our ends.
// Fills end/exit_status/signal unless the caller already decided the end.
void finish(Child& c, ProcessResult& r, bool decided) {
    ::kill(-c.pid, SIGKILL);
    int status = 0;
    while (::waitpid(c.pid, &status, 0) < 0 && errno == EINTR) {
    }
    forget_group(c.pid);
    {
        const std::lock_guard<std::mutex> lock(children_mutex);
        reap_strays(true);  // what escaped the group and came back to us
    }
    if (!decided) {
        if (WIFSIGNALED(status)) {
            r.end = ProcessEnd::Signalled;
            r.signal = WTERMSIG(status);
        } else {
            r.end = ProcessEnd::Exited;
            r.exit_status = WEXITSTATUS(status);
        }
    }
    close_fd(c.in);
    close_fd(c.out);
    close_fd(c.err);
    c.pid = -1;
    if (r.err_tail.size() > kErrKeep) r.err_tail.erase(0, r.err_tail.size() - kErrKeep);
}

enum class Pump : std::uint8_t { Done, OutputClosed, Deadline, TooMuchOutput };

// Moves bytes: `input` into the child's stdin (closed once written when
// close_in), its stdout into `out`, its stderr into `err` (trimmed), until
// done() holds, both outputs are closed, the deadline passes, or `out` grows
// past max_out.
Pump pump(Child& c, std::string_view& input, bool close_in, std::string& out, std::string& err, Clock::time_point deadline,
          std::size_t max_out, const std::function<bool()>& done) {
    char buffer[1 << 16];
    for (;;) {
        if (done && done()) return Pump::Done;
        if (close_in && input.empty()) close_fd(c.in);
        pollfd fds[3];
        nfds_t n = 0;
        int* owner[3];
        if (c.in >= 0 && !input.empty()) fds[n] = {c.in, POLLOUT, 0}, owner[n++] = &c.in;
        if (c.out >= 0) fds[n] = {c.out, POLLIN, 0}, owner[n++] = &c.out;
        if (c.err >= 0) fds[n] = {c.err, POLLIN, 0}, owner[n++] = &c.err;
        if (n == 0 || (c.out < 0 && c.err < 0)) return Pump::OutputClosed;
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
        if (left.count() <= 0) return Pump::Deadline;
        const int rc = ::poll(fds, n, static_cast<int>(std::min(left, kPollSlice).count()));
        if (rc < 0 && errno != EINTR) throw ProcessError(std::string("poll failed: ") + std::strerror(errno));
        for (nfds_t i = 0; rc > 0 && i < n; ++i) {
            if (fds[i].revents == 0) continue;
            int& fd = *owner[i];
            if (&fd == &c.in) {
                const ssize_t k = ::write(fd, input.data(), std::min<std::size_t>(input.size(), sizeof buffer));
                if (k > 0) {
                    input.remove_prefix(static_cast<std::size_t>(k));
                } else if (k < 0 && errno != EAGAIN && errno != EINTR) {
                    close_fd(fd);  // it stopped reading (EPIPE): its answer decides
                    input = {};
                }
                continue;
            }
            const ssize_t k = ::read(fd, buffer, sizeof buffer);
            if (k == 0 || (k < 0 && errno != EAGAIN && errno != EINTR)) {
                close_fd(fd);
            } else if (k > 0 && &fd == &c.out) {
                out.append(buffer, static_cast<std::size_t>(k));
                if (out.size() > max_out) return Pump::TooMuchOutput;
            } else if (k > 0) {
                err.append(buffer, static_cast<std::size_t>(k));
                if (err.size() > 16 * kErrKeep) err.erase(0, err.size() - kErrKeep);
            }
        }
    }
}

}  // namespace

std::string describe_end(const ProcessResult& r, const ProcessLimits& limits) {
    switch (r.end) {
        case ProcessEnd::Exited: return "exit status " + std::to_string(r.exit_status);
        case ProcessEnd::Signalled: {
            const char* name = ::strsignal(r.signal);
            return "killed by signal " + std::to_string(r.signal) + (name != nullptr ? std::string(" (") + name + ")" : "");
        }
        case ProcessEnd::TimedOut:
            return "no answer within " + std::to_string(limits.timeout.count()) + " ms (killed with its process group)";
        case ProcessEnd::OutputTooLarge:
            return "more than " + std::to_string(limits.max_output) + " bytes on stdout (killed)";
    }
    return "?";
}

ProcessResult run_command(const std::string& command, std::string_view input, const ProcessLimits& limits) {
    const Clock::time_point deadline = Clock::now() + limits.timeout;
    Child c = spawn(command);
    ProcessResult r;
    Pump p = pump(c, input, true, r.out, r.err_tail, deadline, limits.max_output, [&] { return has_exited(c.pid); });
    if (p == Pump::Done) {
        // Exited: take what is still in the pipes. A grandchild may hold them
        // open, so only for a moment.
        p = pump(c, input, true, r.out, r.err_tail, std::min(deadline, Clock::now() + kGrace), limits.max_output, {});
        if (p == Pump::Deadline) p = Pump::OutputClosed;
    } else if (p == Pump::OutputClosed && !wait_exit(c.pid, deadline)) {
        p = Pump::Deadline;  // closed its output but kept running
    }
    if (p == Pump::Deadline) r.end = ProcessEnd::TimedOut;
    if (p == Pump::TooMuchOutput) r.end = ProcessEnd::OutputTooLarge;
    finish(c, r, p == Pump::Deadline || p == Pump::TooMuchOutput);
    return r;
}

void StreamProcess::start() {
    const Child c = spawn(command_);
    pid_ = c.pid;
    in_ = c.in;
    out_ = c.out;
    err_ = c.err;
    pending_.clear();
    ++starts_;
}

StreamProcess::Reply StreamProcess::exchange(std::string_view line) { return exchange(line, limits_.timeout); }

StreamProcess::Reply StreamProcess::exchange(std::string_view line, std::chrono::milliseconds timeout) {
    if (pid_ < 0) start();
    const Clock::time_point deadline = Clock::now() + timeout;
    std::string payload(line);
    payload += '\n';
    std::string_view input = payload;
    Reply reply;
    std::string err;
    // The next non-blank line in pending_, taken out of it.
    auto take_line = [&] {
        for (std::size_t nl = pending_.find('\n'); nl != std::string::npos; nl = pending_.find('\n')) {
            std::string candidate = pending_.substr(0, nl);
            pending_.erase(0, nl + 1);
            if (candidate.find_first_not_of(" \t\r") != std::string::npos) {
                reply.line = std::move(candidate);
                return true;
            }
        }
        return false;
    };
    Child c{pid_, in_, out_, err_};
    Pump p = pump(c, input, false, pending_, err, deadline, limits_.max_output, take_line);
    in_ = c.in, out_ = c.out, err_ = c.err;
    if (p == Pump::Done) {
        reply.answered = true;
        return reply;
    }
    if (p == Pump::OutputClosed && !wait_exit(pid_, deadline)) p = Pump::Deadline;
    if (p == Pump::Deadline) reply.failure.end = ProcessEnd::TimedOut;
    if (p == Pump::TooMuchOutput) reply.failure.end = ProcessEnd::OutputTooLarge;
    reply.failure.out = std::move(pending_);
    reply.failure.err_tail = std::move(err);
    finish(c, reply.failure, p == Pump::Deadline || p == Pump::TooMuchOutput);
    pid_ = in_ = out_ = err_ = -1;
    pending_.clear();
    return reply;
}

// Draining the pipes in stop() allocates; if that fails, the process group
// is still killed and reaped, without the drain.
StreamProcess::~StreamProcess() {
    try {
        stop();
    } catch (...) {
        Child c{pid_, in_, out_, err_};
        ProcessResult ignored;
        if (c.pid >= 0) finish(c, ignored, true);
    }
}

void StreamProcess::stop() {
    if (pid_ < 0) return;
    Child c{pid_, in_, out_, err_};
    close_fd(c.in);  // end of input: a well-behaved stream exits now
    std::string_view none;
    std::string sink_out, sink_err;
    (void)pump(c, none, true, sink_out, sink_err, Clock::now() + kGrace, limits_.max_output, {});
    ProcessResult ignored;
    finish(c, ignored, false);
    pid_ = in_ = out_ = err_ = -1;
    pending_.clear();
}

}  // namespace dcel::diff
