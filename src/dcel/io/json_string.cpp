#include "dcel/io/json_string.hpp"

#include <cstdio>

#include "dcel/core/utf8.hpp"

namespace dcel::io {

std::string json_string(std::string_view s) {
    std::string out = "\"";
    out.reserve(s.size() + 2);
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t len = detail::utf8_sequence(s, i);
        if (len == 0) {
            // JSON text is UTF-8 (RFC 8259, section 8.1): a byte that is not
            // part of a well-formed sequence (a program's output may hold
            // any) becomes U+FFFD, so that the document always parses.
            out += "\ufffd";
            ++i;
            continue;
        }
        const char c = s[i];
        const auto byte = static_cast<unsigned char>(c);
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
                if (byte < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(byte));
                    out += buf;
                } else {
                    out.append(s.substr(i, len));
                }
        }
        i += len;
    }
    return out + "\"";
}

}  // namespace dcel::io
