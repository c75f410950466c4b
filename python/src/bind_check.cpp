// Checking answers in-process: the text entry points behind dcel.check() and
// dcel.validate() (python/dcel/_check.py turns Python answers into the JSON
// documents of docs/formats.md and hands them here). The reading is the
// library's own (check::read_answer, io::read_dump), so a Python answer is
// read exactly as `dcel check` reads the same answer from a file.
#include <memory>
#include <optional>
#include <utility>

#include "binding.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/json_reader.hpp"
#include "dcel/validate.hpp"
#include "dcel_object.hpp"

namespace dcel::python {
namespace {

// The report, and the kind the answer was read as: the library's own reading
// (check::read_answer, the kind given or detected from the answer's shape)
// and comparison under the conventions, as `dcel check` does.
using Result = std::pair<check::Report, std::string>;

Result unreadable(const InvalidInput& e, const std::optional<check::AnswerKind>& kind) {
    return {check::unreadable_answer(std::string("answer: ") + e.what()),
            std::string(check::answer_kind_name(kind.value_or(check::AnswerKind::Faces)))};
}

Result compare_text(const Dcel& reference, const std::string& text, const std::optional<check::AnswerKind>& kind,
                    const check::Conventions& conventions) {
    try {
        const check::Answer answer = check::read_answer(text, kind);
        return {check::compare(reference, answer, conventions), std::string(check::answer_kind_name(answer.kind))};
    } catch (const InvalidInput& e) {
        return unreadable(e, kind);
    }
}

// The answer's text and its comparison with the GIL released; the reference
// is held, so that an edit made meanwhile by another thread copies it. A str
// that UTF-8 cannot encode (a lone surrogate) is unreadable, as invalid
// UTF-8 in a file is.
Result compare_released(const DcelObject& reference, const TextArg& text, const std::optional<check::AnswerKind>& kind,
                        const check::Conventions& conventions) {
    std::string utf8;
    try {
        utf8 = text_from(text, "");
    } catch (const InvalidInput& e) {
        return unreadable(e, kind);
    }
    const std::shared_ptr<const Dcel> held = reference.get();
    const py::gil_scoped_release unlocked;
    return compare_text(*held, utf8, kind, conventions);
}

}  // namespace

py::list violations_to_python(const std::vector<Violation>& all) {
    const py::handle type = value_type("Violation");
    py::list out;
    for (const Violation& v : all) {
        out.append(type(to_string(v.invariant), message_str(v.message), ids_to_python(v.vertices),
                        ids_to_python(v.half_edges), ids_to_python(v.faces)));
    }
    return out;
}

void bind_check(py::module_& m) {
    // The JSON reader's nesting limit: dcel.check() writes an answer nested
    // deeper only as far as the reader reads it (python/dcel/_check.py).
    m.attr("_JSON_MAX_DEPTH") = io::JsonReader::kMaxDepth;
    m.def(
        "_check_text",
        [](const DcelObject& reference, const TextArg& text, const std::string& kind, const FlagArg& face_on_right,
           const FlagArg& one_based, const FlagArg& unoriented) {
            std::optional<check::AnswerKind> chosen;
            if (kind != "auto") {
                chosen = check::answer_kind_from_name(kind);
                if (!chosen) throw InvalidInput(InputErrorKind::Shape, "check: unknown kind \"" + kind + "\"");
            }
            const check::Conventions conventions{flag_from(face_on_right, "check: face_on_right"),
                                                 flag_from(one_based, "check: one_based"),
                                                 flag_from(unoriented, "check: unoriented")};
            const Result result = compare_released(reference, text, chosen, conventions);
            const check::Report& report = result.first;
            const py::handle type = value_type("Difference");
            py::list differences;
            for (const check::Difference& d : report.differences) {
                py::list vertices;
                for (const Index v : d.vertices) vertices.append(v);
                differences.append(type(std::string(check::kind_name(d.kind)), message_str(d.message), vertices));
            }
            py::list notes;
            for (const std::string& note : report.notes) notes.append(message_str(note));
            return py::make_tuple(differences, report.unlisted, message_str(check::report_text(report)), result.second,
                                  notes);
        },
        py::arg("reference"), py::arg("text"), py::arg("kind"), py::arg("face_on_right") = false,
        py::arg("one_based") = false, py::arg("unoriented") = false,
        "(differences, unlisted, report text, kind read, notes) of an answer given as JSON text of a kind "
        "(\"faces\", \"dump\", \"polygons\", \"rings\", or \"auto\": detected from its shape), as `dcel "
        "check` reads and compares it.");
    m.def(
        "_validate_text",
        [](const TextArg& text) {
            std::vector<Violation> found;
            {
                DcelDump dump = io::read_dump(text_from(text, ""));  // InvalidInput when it is not a dump
                const py::gil_scoped_release unlocked;
                found = validate_all(dump);
            }
            return violations_to_python(found);
        },
        py::arg("text"), "Every broken invariant of a dump given as JSON text (the `dcel build` format).");
}

}  // namespace dcel::python
