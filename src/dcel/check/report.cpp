#include "dcel/check/report.hpp"

#include <cstdio>

namespace dcel::check {

namespace {

std::string json_string(std::string_view s) {
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

std::size_t total(const Report& r) { return r.differences.size() + r.unlisted; }

}  // namespace

std::string report_text(const Report& report) {
    if (report.agrees()) return "agrees\n";
    const std::size_t n = total(report);
    std::string out = std::to_string(n) + (n == 1 ? " difference\n" : " differences\n");
    for (const Difference& d : report.differences) {
        out.append(kind_name(d.kind)).append(": ").append(d.message).append("\n");
    }
    if (report.unlisted != 0) out += "... and " + std::to_string(report.unlisted) + " more not listed\n";
    return out;
}

std::string report_json(const Report& report) {
    std::string out = "{\"agrees\": ";
    out += report.agrees() ? "true" : "false";
    out += ", \"count\": " + std::to_string(total(report)) + ", \"unlisted\": " + std::to_string(report.unlisted) +
           ", \"differences\": [";
    for (std::size_t i = 0; i < report.differences.size(); ++i) {
        const Difference& d = report.differences[i];
        out += i == 0 ? "\n  " : ",\n  ";
        out += "{\"kind\": " + json_string(kind_name(d.kind)) + ", \"message\": " + json_string(d.message) +
               ", \"vertices\": [";
        for (std::size_t j = 0; j < d.vertices.size(); ++j) {
            if (j != 0) out += ", ";
            out += std::to_string(d.vertices[j]);
        }
        out += "]}";
    }
    out += report.differences.empty() ? "]}\n" : "\n]}\n";
    return out;
}

}  // namespace dcel::check
