#include "dcel/check/report.hpp"

#include "dcel/io/json_writer.hpp"

namespace dcel::check {

namespace {

std::size_t total(const Report& r) { return r.differences.size() + r.unlisted; }

}  // namespace

std::string report_text(const Report& report) {
    std::string out;
    if (report.agrees()) {
        out = "agrees\n";
    } else {
        const std::size_t n = total(report);
        out = std::to_string(n) + (n == 1 ? " difference\n" : " differences\n");
        for (const Difference& d : report.differences) {
            out.append(kind_name(d.kind)).append(": ").append(d.message).append("\n");
        }
        if (report.unlisted != 0) out += "... and " + std::to_string(report.unlisted) + " more not listed\n";
    }
    for (const std::string& note : report.notes) out.append("note: ").append(note).append("\n");
    return out;
}

std::string report_json(const Report& report) {
    std::string out;
    io::JsonWriter w(out);
    w.raw("{\"agrees\": ");
    w.raw(report.agrees() ? "true" : "false");
    w.raw(", \"count\": ");
    w.count(total(report));
    w.raw(", \"unlisted\": ");
    w.count(report.unlisted);
    w.raw(", \"differences\": [");
    for (std::size_t i = 0; i < report.differences.size(); ++i) {
        const Difference& d = report.differences[i];
        w.raw(i == 0 ? "\n  " : ",\n  ");
        w.raw("{\"kind\": ");
        w.string(kind_name(d.kind));
        w.raw(", \"message\": ");
        w.string(d.message);
        w.raw(", \"vertices\": [");
        for (std::size_t j = 0; j < d.vertices.size(); ++j) {
            if (j != 0) w.raw(", ");
            w.index(d.vertices[j]);
        }
        w.raw("]}");
    }
    w.raw(report.differences.empty() ? "]" : "\n]");
    w.raw(", \"notes\": [");
    for (std::size_t i = 0; i < report.notes.size(); ++i) {
        if (i != 0) w.raw(", ");
        w.string(report.notes[i]);
    }
    w.raw("]}\n");
    w.flush();
    return out;
}

}  // namespace dcel::check
