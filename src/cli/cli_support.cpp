#include "cli_support.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "dcel/io/decimal.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::cli {

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

std::string read_input(const std::string& path) {
    std::FILE* f = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
    if (f == nullptr) throw UsageError("cannot open " + path + ": " + std::strerror(errno));
    std::string text;
    // Reserve a regular file's size up front: no regrowth copies of a large input.
    if (f != stdin && std::fseek(f, 0, SEEK_END) == 0) {
        const long size = std::ftell(f);
        if (size > 0) text.reserve(static_cast<std::size_t>(size));
        std::rewind(f);
    }
    char buffer[1 << 16];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    const bool failed = std::ferror(f) != 0;
    if (f != stdin) std::fclose(f);
    if (failed) throw UsageError("cannot read " + display_name(path));
    return text;
}

PlanarGraph load_graph(const std::string& path) {
    const std::string text = read_input(path);
    return with_source(path, [&] { return io::read_graph(text); });
}

double parse_coordinate(const std::string& text, const std::string& what) {
    double v = 0;
    const char* const end = text.data() + text.size();
    const auto [ptr, ec] = io::parse_double(text.data(), end, v);  // std::from_chars where the library has it
    if (ec != std::errc() || ptr != end || !std::isfinite(v)) {
        throw UsageError(what + ": expected a finite number, found \"" + text + "\"");
    }
    return v;
}

void write_stdout(std::string_view text) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
}

}  // namespace dcel::cli
