// JUnit XML for CI systems (dcel diff --junit): one test case for the run,
// one failing test case per distinct failure, its text the failure's body
// in the text report.
#include <sstream>

#include "dcel/core/utf8.hpp"
#include "dcel/diff/report.hpp"

namespace dcel::diff {

// Text as XML 1.0 character data and attribute values: the five special
// characters as entities; control characters XML does not allow (all but
// tab, newline and return) as '?'; bytes that are not well-formed UTF-8 as
// U+FFFD, so the document is always well-formed whatever the implementation
// printed.
std::string xml_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t len = detail::utf8_sequence(text, i);
        if (len == 0) {
            out += "\xEF\xBF\xBD";
            ++i;
            continue;
        }
        const char ch = text[i];
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default:
                if (len == 1 && static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') {
                    out += '?';
                } else {
                    out.append(text.substr(i, len));
                }
        }
        i += len;
    }
    return out;
}

std::string report_junit(const DiffOptions& options, const DiffResult& result) {
    std::ostringstream s;
    const std::size_t tests = result.failures.size() + 1;
    s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    s << "<testsuites name=\"dcel diff\" tests=\"" << tests << "\" failures=\"" << result.failures.size() << "\">\n";
    s << "  <testsuite name=\"" << xml_text("dcel diff --impl " + options.impl) << "\" tests=\"" << tests << "\" failures=\""
      << result.failures.size() << "\" time=\"" << static_cast<double>(result.elapsed.count()) / 1000.0 << "\">\n";
    s << "    <testcase classname=\"dcel.diff\" name=\"" << (result.cases_run - result.skipped) << " cases, seed "
      << options.schedule.seed << "\"/>\n";
    for (const Failure& f : result.failures) {
        std::ostringstream body;
        failure_body(body, options, f);
        s << "    <testcase classname=\"dcel.diff\" name=\""
          << xml_text("failure " + std::to_string(f.id) + ": " + f.signature) << "\">\n";
        s << "      <failure message=\""
          << xml_text(failure_label(f.example.first) + " on case " + std::to_string(f.example.original.spec.number) +
                      ", shrunk to " + size_of(f.example.graph))
          << "\" type=\"" << xml_text(failure_name(f.example.first.kind).data()) << "\">" << xml_text(body.str())
          << "</failure>\n";
        s << "    </testcase>\n";
    }
    s << "  </testsuite>\n</testsuites>\n";
    return s.str();
}

}  // namespace dcel::diff
