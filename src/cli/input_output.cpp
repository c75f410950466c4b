// Reading inputs under the size limit, with every failure reported
// (cli_support.hpp; writing is output.cpp's).
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <vector>

#include "cli_support.hpp"
#include "dcel/build.hpp"
#include "dcel/io/graph_json.hpp"
#include "status_line.hpp"

namespace dcel::cli {
namespace {

std::uint64_t max_input = kDefaultMaxInputBytes;  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)

std::string os_reason(int err) { return std::strerror(err); }

// "512 MiB" for a whole number of KiB/MiB/GiB, for the message.
std::string in_units(std::uint64_t bytes) {
    const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
    std::string best;
    for (int k = 0; k < 4 && bytes != 0 && bytes % 1024 == 0; ++k) {
        bytes /= 1024;
        best = std::to_string(bytes) + " " + units[k];
    }
    return best.empty() ? "" : " (" + best + ")";
}

[[noreturn]] void throw_too_large(const std::string& name, std::uint64_t size, bool exact) {
    const std::string limit = std::to_string(max_input) + " bytes" + in_units(max_input);
    const std::string raise = "; raise it with dcel --max-input-bytes N";
    if (exact) {
        throw UsageError(name + " is " + std::to_string(size) + " bytes, over the input limit of " + limit + raise);
    }
    throw UsageError(name + " holds more than " + limit + ", the input limit" + raise);
}

class FileDescriptor {
public:
    explicit FileDescriptor(int fd, bool owned) : fd_(fd), owned_(owned) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (owned_ && fd_ >= 0) ::close(fd_);
    }
    [[nodiscard]] int get() const { return fd_; }

private:
    int fd_;
    bool owned_;
};

// One read(), waiting when the descriptor is non-blocking (a stdin left
// O_NONBLOCK by the shell's previous command); -1 with errno on failure.
ssize_t read_some(int fd, char* buffer, std::size_t size) {
    for (;;) {
        const ssize_t n = ::read(fd, buffer, size);
        if (n >= 0) return n;
        if (errno == EINTR) continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK) return -1;
        pollfd p{fd, POLLIN, 0};
        (void)::poll(&p, 1, -1);
    }
}

// Watches the first bytes of a stream: whitespace and a leading UTF-8 BOM,
// then one byte that either can start a JSON value or cannot.
class JsonStart {
public:
    enum class Verdict : std::uint8_t { Undecided, MayBeJson, NotJson };
    Verdict feed(std::string_view bytes) {
        for (std::size_t i = 0; i < bytes.size() && verdict_ == Verdict::Undecided; ++i, ++offset_) {
            const auto c = static_cast<unsigned char>(bytes[i]);
            if (offset_ == 0 && c == kBom[0]) {
                bom_ = 1;
            } else if (bom_ == 1 || bom_ == 2) {  // inside a BOM, or not a BOM after all
                if (c != kBom[bom_]) verdict_ = Verdict::NotJson;
                ++bom_;
            } else if (c != ' ' && c != '\n' && c != '\r' && c != '\t') {
                const bool starts_value = c == '{' || c == '[' || c == '"' || c == '-' || (c >= '0' && c <= '9') ||
                                          c == 't' || c == 'f' || c == 'n';
                verdict_ = starts_value ? Verdict::MayBeJson : Verdict::NotJson;
            }
        }
        return verdict_;
    }

private:
    static constexpr unsigned char kBom[3] = {0xEF, 0xBB, 0xBF};
    Verdict verdict_ = Verdict::Undecided;
    std::size_t offset_ = 0;
    std::size_t bom_ = 0;  // BOM bytes seen at the start
};

[[noreturn]] void throw_cannot_read(const std::string& name, int err) {
    throw UsageError("cannot read " + name + ": " + os_reason(err));
}

// The descriptor to read `path` from: stdin for "-", else the file opened.
FileDescriptor open_input(const std::string& path, const std::string& name) {
    if (path == "-") return FileDescriptor(0, false);
    StatusLine::set("opening " + name);  // a FIFO waits here for its writer
    int raw = 0;
    do {
        raw = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
    } while (raw < 0 && errno == EINTR);
    if (raw < 0) throw UsageError("cannot open " + name + ": " + os_reason(errno));
    return FileDescriptor(raw, true);
}

// A regular file, straight into `text` at its size. Returns false when it
// turned out shorter (it shrank while read): then `text` is all of it.
bool read_whole_file(int fd, const std::string& name, std::size_t size, std::string& text, std::uint64_t& total) {
    text.resize(size);
    while (total < text.size()) {
        const ssize_t n = read_some(fd, text.data() + total, text.size() - total);
        if (n < 0) throw_cannot_read(name, errno);
        if (n == 0) break;
        total += static_cast<std::uint64_t>(n);
    }
    text.resize(static_cast<std::size_t>(total));
    return total == size;
}

// Anything else (or a file that grew): chunks of growing size, joined at
// the end onto `text`, so that the peak is twice the input, not the three
// times of a doubling string's reallocation.
//
// Whether the first byte after whitespace (and a BOM) can start a JSON
// value is known as soon as it arrives: a stream that cannot be JSON
// (/dev/zero, a binary) is cut there, and the parser reports that byte, as
// it would at the end of the whole stream, without holding it all.
void read_in_chunks(int fd, const std::string& name, std::string& text, std::uint64_t& total) {
    std::vector<std::unique_ptr<char[]>> chunks;
    std::vector<std::size_t> sizes;
    std::size_t chunk = std::size_t{64} << 10;
    JsonStart start;
    for (bool cut = false; !cut;) {
        auto buffer = std::make_unique<char[]>(chunk);  // NOLINT(cppcoreguidelines-avoid-c-arrays)
        std::size_t filled = 0;
        while (filled < chunk) {
            const ssize_t n = read_some(fd, buffer.get() + filled, chunk - filled);
            if (n < 0) throw_cannot_read(name, errno);
            if (n == 0) break;
            const std::string_view got(buffer.get() + filled, static_cast<std::size_t>(n));
            filled += static_cast<std::size_t>(n);
            total += static_cast<std::uint64_t>(n);
            if (start.feed(got) == JsonStart::Verdict::NotJson) {
                cut = true;
                break;
            }
            if (total > max_input) throw_too_large(name, total, false);
            StatusLine::progress(total);
        }
        if (filled == 0) break;
        chunks.push_back(std::move(buffer));
        sizes.push_back(filled);
        if (filled < chunk) break;
        chunk = std::min(chunk * 2, std::size_t{64} << 20);
    }
    text.reserve(static_cast<std::size_t>(total));
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        text.append(chunks[i].get(), sizes[i]);
        chunks[i].reset();
    }
}

}  // namespace

void set_max_input_bytes(std::uint64_t bytes) { max_input = bytes; }
std::uint64_t max_input_bytes() { return max_input; }

std::string read_input(const std::string& path) {
    const std::string name = display_name(path);
    const FileDescriptor fd = open_input(path, name);
    struct stat st {};
    if (::fstat(fd.get(), &st) != 0) throw_cannot_read(name, errno);
    if (S_ISDIR(st.st_mode)) throw_cannot_read(name, EISDIR);
    const bool regular = S_ISREG(st.st_mode);
    if (regular && static_cast<std::uint64_t>(st.st_size) > max_input) {
        throw_too_large(name, static_cast<std::uint64_t>(st.st_size), true);
    }
    StatusLine::set("reading " + name);
    std::string text;
    std::uint64_t total = 0;
    if (regular && st.st_size > 0 && !read_whole_file(fd.get(), name, static_cast<std::size_t>(st.st_size), text, total)) {
        return text;
    }
    read_in_chunks(fd.get(), name, text, total);
    return text;
}

void require_one_stdin(std::initializer_list<std::pair<std::string_view, const std::string*>> inputs) {
    std::string_view first;
    for (const auto& [what, path] : inputs) {
        if (path == nullptr || *path != "-") continue;
        if (first.empty()) {
            first = what;
        } else {
            throw UsageError(std::string(first) + " and " + std::string(what) +
                             " cannot both be - (stdin): give one of them as a file");
        }
    }
}

PlanarGraph load_graph(const std::string& path) {
    const std::string text = read_input(path);
    StatusLine::set("parsing " + display_name(path));
    return with_source(path, [&] { return io::read_graph(text); });
}

Dcel build_dcel(const std::string& path, const PlanarGraph& g) {
    StatusLine::set("building the DCEL (" + std::to_string(g.vertices.size()) + " vertices, " +
                    std::to_string(g.edges.size()) + " edges)");
    return with_source(path, [&] { return build(g); });
}

}  // namespace dcel::cli
