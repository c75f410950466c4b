#include "dcel/diff/html_text.hpp"

#include "dcel/core/utf8.hpp"

namespace dcel::diff {
namespace {

// Shown as escapes: C0 controls but newline and tab, DEL and the C1
// controls, the Arabic letter mark, zero-width and directional marks, the
// line and paragraph separators, the bidirectional embeddings, overrides and
// isolates, the invisible operators and the byte order mark.
bool shown_as_escape(char32_t c) {
    if (c == U'\n' || c == U'\t') return false;
    return c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == 0x061c || (c >= 0x200b && c <= 0x200f) ||
           (c >= 0x2028 && c <= 0x202e) || (c >= 0x2060 && c <= 0x2069) || c == 0xfeff;
}

std::string escape_name(char32_t c) {
    static constexpr const char* kHex = "0123456789ABCDEF";
    if (c == U'\r') return "\\r";
    const int digits = c < 0x100 ? 2 : 4;
    std::string s = c < 0x100 ? "\\x" : "\\u";
    for (int d = digits - 1; d >= 0; --d) s += kHex[(c >> (4 * d)) & 0xfU];
    return s;
}

// One code point at text[i] (U+FFFD for a byte that starts no well-formed
// UTF-8), and how many bytes it took.
std::size_t next_code_point(std::string_view text, std::size_t i, char32_t& c) {
    const std::size_t n = detail::utf8_sequence(text, i, &c);
    if (n == 0) c = U'\uFFFD';
    return n == 0 ? 1 : n;
}

void append(std::string& out, std::string_view text, bool marked) {
    for (std::size_t i = 0; i < text.size();) {
        char32_t c = 0;
        i += next_code_point(text, i, c);
        switch (c) {
            case U'&': out += "&amp;"; break;
            case U'<': out += "&lt;"; break;
            case U'>': out += "&gt;"; break;
            case U'"': out += "&quot;"; break;
            case U'\'': out += "&#39;"; break;
            default:
                if (!shown_as_escape(c)) {
                    detail::append_utf8(out, c);
                } else if (marked) {
                    out += "<span class=\"esc\">" + escape_name(c) + "</span>";
                } else {
                    out += escape_name(c);
                }
        }
    }
}

std::string lines(std::size_t n) { return std::to_string(n) + (n == 1 ? " more line" : " more lines"); }

}  // namespace

std::string html_text(std::string_view text) {
    std::string out;
    append(out, text, true);
    return out;
}

std::string html_attribute(std::string_view text) {
    std::string out;
    append(out, text, false);
    return out;
}

std::string html_block(std::string_view text, std::string_view cls, BlockLimits limits) {
    std::string out = "<pre class=\"" + html_attribute(cls) + "\">";
    std::size_t shown = 0;
    for (std::size_t begin = 0; begin < text.size(); ++shown) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string_view::npos) end = text.size();
        if (shown == limits.lines) {
            std::size_t rest = 1;
            for (std::size_t i = begin; i + 1 < text.size(); ++i) rest += text[i] == '\n' ? 1 : 0;
            out += "<span class=\"cut\">[cut: " + lines(rest) + " not shown]</span>";
            break;
        }
        const std::string_view line = text.substr(begin, end - begin);
        std::size_t chars = 0;
        std::size_t cut_at = line.size();
        for (std::size_t i = 0; i < line.size(); ++chars) {
            if (chars == limits.line_chars) cut_at = i;
            char32_t c = 0;
            i += next_code_point(line, i, c);
        }
        append(out, line.substr(0, cut_at), true);
        if (cut_at < line.size()) {
            out += "<span class=\"cut\">[cut: the line has " + std::to_string(chars) + " characters; the first " +
                   std::to_string(limits.line_chars) + " are shown]</span>";
        }
        if (end < text.size()) out += '\n';
        begin = end + 1;
    }
    return out + "</pre>\n";
}

}  // namespace dcel::diff
