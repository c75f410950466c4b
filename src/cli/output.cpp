// Writing outputs, to stdout or a file, whole or streamed as they are
// produced, with every failure reported (cli_support.hpp).
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <utility>

#include "cli_support.hpp"
#include "status_line.hpp"

namespace dcel::cli {
namespace {

std::string os_reason(int err) { return std::strerror(err); }

void write_all(int fd, std::string_view text, const std::string& name) {
    while (!text.empty()) {
        const ssize_t n = ::write(fd, text.data(), std::min<std::size_t>(text.size(), std::size_t{1} << 30));
        if (n > 0) {
            text.remove_prefix(static_cast<std::size_t>(n));
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            pollfd p{fd, POLLOUT, 0};
            (void)::poll(&p, 1, -1);
            continue;
        }
        throw UsageError("cannot write " + name + ": " + os_reason(n < 0 ? errno : EIO));
    }
}

// The pieces a writer hands its sink (16 KiB or less), gathered into
// writes of kChunk bytes: a write() per piece would be a system call per
// 16 KiB, and the buffer is all of the output held at any time.
class ChunkedOutput {
public:
    ChunkedOutput(int fd, std::string name, bool progress) : fd_(fd), name_(std::move(name)), progress_(progress) {
        buffer_.reserve(kChunk);
    }
    void put(std::string_view text) {
        if (text.size() > kChunk - buffer_.size()) {
            drain();
            if (text.size() >= kChunk) {
                write_all(fd_, text, name_);
                count(text.size());
                return;
            }
        }
        buffer_.append(text);
    }
    void drain() {
        if (buffer_.empty()) return;
        write_all(fd_, buffer_, name_);
        count(buffer_.size());
        buffer_.clear();
    }

private:
    static constexpr std::size_t kChunk = std::size_t{256} << 10;
    void count(std::size_t n) {
        written_ += n;
        if (progress_) StatusLine::progress(written_);
    }
    int fd_;
    std::string name_;
    bool progress_;
    std::string buffer_;
    std::uint64_t written_ = 0;
};

// Runs the writer into fd, then writes what is left in the buffer (not
// when the writer threw: a failed output stops where it failed).
void produce_into(int fd, const std::string& name, bool progress, const Producer& produce) {
    ChunkedOutput out(fd, name, progress);
    produce([&out](std::string_view text) { out.put(text); });
    out.drain();
}

}  // namespace

void stream_stdout(const Producer& produce) {
    if (const std::string reason = flush_stdout(); !reason.empty()) {
        throw UsageError("cannot write to stdout: " + reason);
    }
    const bool terminal = ::isatty(STDOUT_FILENO) != 0;
    if (terminal) {
        StatusLine::stop();  // the output goes to the terminal the status line is on
    } else {
        StatusLine::set("writing the output");
    }
    produce_into(STDOUT_FILENO, "to stdout", !terminal, produce);
}

void write_stdout(std::string_view text) {
    stream_stdout([text](const io::TextSink& sink) { sink(text); });
}

void stream_file(const std::string& path, const Producer& produce) {
    const std::string name = display_name(path);
    int fd = -1;
    do {
        fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOCTTY, 0666);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) throw UsageError("cannot open " + name + " for writing: " + os_reason(errno));
    try {
        StatusLine::set("writing " + name);
        produce_into(fd, name, true, produce);
    } catch (...) {
        ::close(fd);
        throw;
    }
    // Written data may be reported lost only here, on some file systems.
    if (::close(fd) != 0) throw UsageError("cannot write " + name + ": " + os_reason(errno));
}

void write_file(const std::string& path, std::string_view text) {
    stream_file(path, [text](const io::TextSink& sink) { sink(text); });
}

std::string flush_stdout() {
    errno = 0;
    std::cout.flush();  // into stdout's buffer, or through it (synced with stdio)
    int err = errno;
    if (std::fflush(stdout) != 0 && err == 0) err = errno;
    if (std::ferror(stdout) != 0 || !std::cout) return os_reason(err != 0 ? err : EIO);
    return {};
}

}  // namespace dcel::cli
