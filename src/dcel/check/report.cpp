#include "dcel/check/report.hpp"

#include "dcel/io/json_string.hpp"

namespace dcel::check {

namespace {

using io::json_string;

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
