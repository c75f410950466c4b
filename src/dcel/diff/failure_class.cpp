#include "dcel/diff/failure_class.hpp"

#include <cctype>
#include <vector>

namespace dcel::diff {
namespace {

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())) != 0) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())) != 0) s.remove_suffix(1);
    return s;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// A line that is part of a trace, an excerpt or a banner rather than the error.
bool is_noise(std::string_view raw) {
    const std::string_view line = trimmed(raw);
    if (line.empty()) return true;
    const bool indented = raw.front() == ' ' || raw.front() == '\t';
    if (starts_with(line, "at ") && indented) return true;                                    // JavaScript, Java frames
    if (starts_with(line, "File \"")) return true;                                            // Python frames
    if (starts_with(line, "Traceback (most recent call last)")) return true;                  // Python
    if (line.find_first_not_of("^~ ") == std::string_view::npos) return true;                 // carets under an excerpt
    if (starts_with(line, "Node.js v") && line.size() > 9 && is_digit(line[9])) return true;  // node's banner
    if (line.front() == '#' && line.size() > 1 && is_digit(line[1])) return true;             // gdb / sanitizer frames
    if (starts_with(line, "...") || starts_with(line, "at <")) return true;
    return indented && !starts_with(line, "Error") && line.find("rror:") == std::string_view::npos &&
           line.find("xception") == std::string_view::npos;  // an indented excerpt of source
}

}  // namespace

std::string meaningful_line(std::string_view text) {
    std::vector<std::string_view> lines;
    for (std::size_t begin = 0; begin <= text.size();) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(begin, end - begin);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        begin = end + 1;
    }
    // Last line first. (Not std::ranges::reverse_view: clang 14 cannot
    // compile libstdc++ 12's ranges.)
    for (std::size_t i = lines.size(); i-- > 0;) {
        if (!is_noise(lines[i])) return std::string(trimmed(lines[i]));
    }
    return {};
}

std::string message_class(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        const bool number_start = is_digit(c) || ((c == '-' || c == '.') && i + 1 < text.size() && is_digit(text[i + 1]));
        const bool inside_word = i > 0 && (std::isalpha(static_cast<unsigned char>(text[i - 1])) != 0 || text[i - 1] == '_');
        if (number_start && !inside_word) {
            // A number: digits, a fraction, an exponent; or 0x and hex digits.
            std::size_t j = i + 1;
            if (c == '0' && j < text.size() && (text[j] == 'x' || text[j] == 'X')) {
                ++j;
                while (j < text.size() && std::isxdigit(static_cast<unsigned char>(text[j])) != 0) ++j;
            } else {
                // Digits, a fraction, an exponent, and a rational's "/q"
                // (exact programs print coordinates as fractions).
                while (j < text.size() &&
                       (is_digit(text[j]) || text[j] == '.' || text[j] == 'e' || text[j] == 'E' ||
                        ((text[j] == '-' || text[j] == '+') && (text[j - 1] == 'e' || text[j - 1] == 'E')) ||
                        (text[j] == '/' && j + 1 < text.size() && is_digit(text[j + 1])))) {
                    ++j;
                }
            }
            out += '#';
            i = j;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c)) != 0) {
            if (!out.empty() && out.back() != ' ') out += ' ';
            ++i;
            continue;
        }
        out += c;
        ++i;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

}  // namespace dcel::diff
