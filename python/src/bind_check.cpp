// Checking answers in-process: the text entry points behind dcel.check() and
// dcel.validate() (python/dcel/_check.py turns Python answers into the JSON
// documents of docs/formats.md and hands them here). The reading is the
// library's own (io::read_faces_answer, io::read_dump), so a Python answer is
// read exactly as `dcel check` reads the same answer from a file.
#include <utility>

#include "binding.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/validate.hpp"
#include "dcel_object.hpp"

namespace dcel::python {
namespace {

// The report, and the kind the answer was read as (kind, or for "auto" what
// io::read_answer found: a dump when the text has "half_edges").
std::pair<check::Report, std::string> compare_text(const Dcel& reference, const std::string& text, std::string kind) {
    try {
        if (kind == "faces") return {check::compare_faces(reference, io::read_faces_answer(text)), kind};
        if (kind == "dump") return {check::compare_dump(reference, io::read_dump(text)), kind};
        auto parsed = io::read_answer(text);
        if (auto* faces = std::get_if<check::FacesAnswer>(&parsed))
            return {check::compare_faces(reference, *faces), "faces"};
        return {check::compare_dump(reference, std::get<DcelDump>(parsed)), "dump"};
    } catch (const InvalidInput& e) {
        return {check::unreadable_answer(std::string("answer: ") + e.what()), kind == "auto" ? "faces" : kind};
    }
}

}  // namespace

py::list violations_to_python(const std::vector<Violation>& all) {
    const py::object type = value_type("Violation");
    py::list out;
    for (const Violation& v : all) {
        out.append(type(to_string(v.invariant), v.message, ids_to_python(v.vertices), ids_to_python(v.half_edges),
                        ids_to_python(v.faces)));
    }
    return out;
}

void bind_check(py::module_& m) {
    m.def(
        "_check_text",
        [](const DcelObject& reference, const std::string& text, const std::string& kind) {
            if (kind != "faces" && kind != "dump" && kind != "auto") {
                throw InvalidInput(InputErrorKind::Shape, "check: unknown kind \"" + kind + "\"");
            }
            std::pair<check::Report, std::string> result;
            {
                const py::gil_scoped_release unlocked;
                result = compare_text(reference.get(), text, kind);
            }
            const check::Report& report = result.first;
            const py::object type = value_type("Difference");
            py::list differences;
            for (const check::Difference& d : report.differences) {
                py::list vertices;
                for (const Index v : d.vertices) vertices.append(v);
                differences.append(type(std::string(check::kind_name(d.kind)), d.message, vertices));
            }
            return py::make_tuple(differences, report.unlisted, check::report_text(report), result.second);
        },
        py::arg("reference"), py::arg("text"), py::arg("kind"),
        "(differences, unlisted, report text, kind read) of an answer given as JSON text of the given kind "
        "(\"faces\", \"dump\", or \"auto\": a dump when it has \"half_edges\").");
    m.def(
        "_validate_text",
        [](const std::string& text) {
            std::vector<Violation> found;
            {
                DcelDump dump = io::read_dump(text);  // InvalidInput when it is not a dump
                const py::gil_scoped_release unlocked;
                found = validate_all(dump);
            }
            return violations_to_python(found);
        },
        py::arg("text"), "Every broken invariant of a dump given as JSON text (the `dcel build` format).");
}

}  // namespace dcel::python
