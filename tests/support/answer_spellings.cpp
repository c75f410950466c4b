#include "support/answer_spellings.hpp"

#include <optional>
#include <string>
#include <vector>

#include "dcel/check/report.hpp"
#include "dcel/error.hpp"
#include "support/answer_steps.hpp"
#include "support/check_helpers.hpp"

namespace dcel::test_support {

using check::AnswerKind;
using oracle::IdPolygon;
using oracle::IdRing;
using namespace spell;  // NOLINT(google-build-using-namespace): the steps of a trial, one file each

std::size_t Choices::below(std::size_t n) {
    if (n <= 1) return 0;
    std::size_t v = 0;
    const std::size_t bytes = n > 256 ? 2 : 1;
    for (std::size_t i = 0; i < bytes; ++i) {
        v |= static_cast<std::size_t>(at_ < bytes_.size() ? bytes_[at_] : 0) << (8 * i);
        ++at_;
    }
    return v % n;
}

namespace {

// The reference's boundary cycles, as `dcel faces` lists them.
std::vector<IdRing> plain_faces(const Dcel& d) {
    std::vector<IdRing> out;
    for (const std::vector<Index>& cycle : faces_answer(d)) out.push_back(cycle);
    return out;
}

}  // namespace

Trial make_trial(const Dcel& reference, const oracle::AnswerJudge& judge, const TrialSetup& setup, Choices& c) {
    Trial t;
    t.setup = setup;
    const Facts f(judge);
    const bool oriented = setup.kind == AnswerKind::Polygons && !setup.conventions.unoriented;
    std::string& story = t.story;
    switch (setup.kind) {
        case AnswerKind::Faces: {
            std::vector<IdRing> cycles = plain_faces(reference);
            for (IdRing& cycle : cycles) rotate(cycle, c);
            if (c.one_in(2)) shuffle(cycles, c);
            if (setup.corrupt) corrupt_faces(f, cycles, c, story);
            t.expected = judge.faces(cycles);
            t.text = faces_text(cycles, setup, c, story);
            break;
        }
        case AnswerKind::Dump: {
            DcelDump d = to_dump(reference);
            respell_dump(d, c, story);
            if (setup.corrupt) corrupt_dump(d, c, story);
            t.expected = judge.dump(d);
            t.text = dump_text(d, setup.conventions, c, story);
            break;
        }
        case AnswerKind::Polygons:
        case AnswerKind::Rings: {
            const bool rings_kind = setup.kind == AnswerKind::Rings;
            std::vector<IdPolygon> polygons;
            for (auto& p : check::reference_regions(reference, setup.kind)) {
                if (rings_kind && p.size() != 1) {
                    t.expected = {false, "reference_regions gives a face " + std::to_string(p.size()) + " rings"};
                }
                polygons.emplace_back(p.begin(), p.end());
            }
            respell_regions(f, polygons, rings_kind, !oriented, c, story);
            if (setup.corrupt) corrupt_regions(f, polygons, rings_kind, oriented, c, story);
            const oracle::AnswerVerdict v = judge.regions(
                polygons, rings_kind ? oracle::RegionKind::Rings : oracle::RegionKind::Polygons, oriented);
            if (t.expected.right) t.expected = v;
            t.text = regions_text(judge.graph(), polygons, setup, c, story);
            break;
        }
        case AnswerKind::EvenOdd:
            // Not spelled by the trials yet (the oracle has no even-odd
            // meaning): a trial asked for one fails rather than passes.
            t.expected = {false, "the answer trials do not spell even-odd answers"};
            break;
    }
    if (c.one_in(8)) {
        t.text.insert(0, "\xEF\xBB\xBF");  // a UTF-8 byte order mark, which JSON readers skip
        story += "with a byte order mark\n";
    }
    return t;
}

std::string judge_trial(const Dcel& reference, const Trial& t) {
    check::Report report;
    try {
        const check::Answer a = check::read_answer(t.text, t.setup.give_kind ? std::optional(t.setup.kind) : std::nullopt);
        if (a.kind != t.setup.kind) {
            return "read as " + std::string(check::answer_kind_name(a.kind)) + ", written as " +
                   std::string(check::answer_kind_name(t.setup.kind)) + "\ntext: " + t.text + "\n" + t.story;
        }
        report = check::compare(reference, a, t.setup.conventions);
    } catch (const InvalidInput& e) {
        report = check::unreadable_answer(e.what());
    }
    if (report.agrees() == t.expected.right) return {};
    const check::Conventions& cv = t.setup.conventions;
    return std::string(report.agrees() ? "the checker agrees" : "the checker differs") + "; the oracle says " +
           (t.expected.right ? "right" : "wrong: " + t.expected.why) + "\nkind " +
           std::string(check::answer_kind_name(t.setup.kind)) + (t.setup.give_kind ? " (given)" : " (detected)") +
           (cv.face_on_right ? ", --face-on right" : "") + (cv.one_based ? ", --one-based" : "") +
           (cv.unoriented ? ", --unoriented" : "") + "\ntext: " + t.text + "\nwhat was done:\n" + t.story + "report:\n" +
           check::report_text(report);
}

}  // namespace dcel::test_support
