#include "dcel/format.hpp"

#include "dcel/core/utf8.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace dcel {

std::string format_double(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    return {buf, res.ptr};
}

// Built with append: GCC 12 at -O3 warns falsely on "(" + std::string (bug 105329).
std::string format_point(Point p) {
    std::string s = "(";
    s.append(format_double(p.x)).append(", ").append(format_double(p.y)).append(")");
    return s;
}

std::string describe_vertex(const PlanarGraph& g, VertexId v) {
    std::string s = "vertex ";
    s.append(std::to_string(v.index())).append(" ").append(format_point(g.vertices[v.index()]));
    return s;
}

std::string describe_edge(const PlanarGraph& g, EdgeId e) {
    const GraphEdge& ge = g.edges[e.index()];
    std::string s = "edge ";
    s.append(std::to_string(e.index())).append(" [").append(std::to_string(ge.u.index())).append(", ");
    s.append(std::to_string(ge.v.index())).append("] from ").append(format_point(g.vertices[ge.u.index()]));
    s.append(" to ").append(format_point(g.vertices[ge.v.index()]));
    return s;
}

}  // namespace dcel

namespace dcel {
namespace {

constexpr char kHex[] = "0123456789ABCDEF";

// Code points that must not reach a terminal as they are.
bool is_unsafe(char32_t cp) {
    return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0x200E || cp == 0x200F || (cp >= 0x2028 && cp <= 0x202E) ||
           (cp >= 0x2066 && cp <= 0x2069);
}

void append_escaped(std::string& out, std::string_view text, std::size_t max_bytes, bool quoted) {
    std::size_t i = 0;
    while (i < text.size()) {
        char32_t cp = 0;
        const std::size_t len = detail::utf8_sequence(text, i, &cp);
        if (i + std::max<std::size_t>(len, 1) > max_bytes) {
            out += "...";
            return;
        }
        if (len == 0) {  // not UTF-8: the byte itself
            const auto b = static_cast<unsigned char>(text[i]);
            out += "\\x";
            out += kHex[b >> 4];
            out += kHex[b & 15];
            ++i;
            continue;
        }
        if (cp == '\\' || (quoted && cp == '"')) {
            out += '\\';
            out += static_cast<char>(cp);
        } else if (cp == '\n') {
            out += "\\n";
        } else if (cp == '\r') {
            out += "\\r";
        } else if (cp == '\t') {
            out += "\\t";
        } else if (is_unsafe(cp)) {
            out += "\\u";
            for (int shift = 12; shift >= 0; shift -= 4) out += kHex[(cp >> shift) & 15];
        } else {
            out.append(text.substr(i, len));
        }
        i += len;
    }
}

}  // namespace

std::string escape_for_message(std::string_view text, std::size_t max_bytes) {
    std::string out;
    out.reserve(std::min(text.size(), max_bytes) + 8);
    append_escaped(out, text, max_bytes, false);
    return out;
}

std::string quote_for_message(std::string_view text, std::size_t max_bytes) {
    std::string out(1, '"');
    append_escaped(out, text, max_bytes, true);
    out += '"';
    return out;
}

bool needs_escaping(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        char32_t cp = 0;
        const std::size_t len = detail::utf8_sequence(text, i, &cp);
        if (len == 0 || is_unsafe(cp)) return true;
        i += len;
    }
    return false;
}

}  // namespace dcel
