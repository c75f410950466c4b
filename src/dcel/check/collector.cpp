#include "dcel/check/collector.hpp"

namespace dcel::check {

std::string_view kind_name(DifferenceKind k) {
    switch (k) {
        case DifferenceKind::VertexCount: return "vertex-count";
        case DifferenceKind::NotAnEdge: return "not-an-edge";
        case DifferenceKind::BrokenInvariant: return "broken-invariant";
        case DifferenceKind::MissingCycle: return "missing-cycle";
        case DifferenceKind::ExtraCycle: return "extra-cycle";
        case DifferenceKind::ReversedCycle: return "reversed-cycle";
        case DifferenceKind::WrongNext: return "wrong-next";
        case DifferenceKind::WrongHole: return "wrong-hole";
        case DifferenceKind::WrongOuterBoundary: return "wrong-outer-boundary";
        case DifferenceKind::WrongIsolatedVertex: return "wrong-isolated-vertex";
        case DifferenceKind::WrongPoint: return "wrong-point";
        case DifferenceKind::UnreadableAnswer: return "unreadable-answer";
        case DifferenceKind::NotAVertex: return "not-a-vertex";
        case DifferenceKind::WrongOrientation: return "wrong-orientation";
        case DifferenceKind::MissingFace: return "missing-face";
        case DifferenceKind::ExtraPolygon: return "extra-polygon";
        case DifferenceKind::WrongRefusal: return "wrong-refusal";
        case DifferenceKind::WrongQueryAnswer: return "wrong-query-answer";
    }
    return "unknown";
}

namespace detail {

namespace {
// The report order, most telling first: an answer that cannot be read, or one
// for the wrong vertices or with the wrong points, explains everything after
// it; a broken dump explains its cycles; a wrong next names the exact place
// where a walk goes astray; in a session, the first step answered wrongly
// explains the state after it.
constexpr std::array<DifferenceKind, kKindCount> kOrder{
    DifferenceKind::UnreadableAnswer,   DifferenceKind::VertexCount,      DifferenceKind::NotAVertex,
    DifferenceKind::WrongPoint,         DifferenceKind::BrokenInvariant,  DifferenceKind::WrongRefusal,
    DifferenceKind::WrongQueryAnswer,   DifferenceKind::NotAnEdge,        DifferenceKind::WrongNext,
    DifferenceKind::ReversedCycle,      DifferenceKind::WrongOrientation, DifferenceKind::MissingCycle,
    DifferenceKind::ExtraCycle,         DifferenceKind::MissingFace,      DifferenceKind::ExtraPolygon,
    DifferenceKind::WrongOuterBoundary, DifferenceKind::WrongHole,        DifferenceKind::WrongIsolatedVertex,
};
}  // namespace

bool Collector::wants(DifferenceKind k) {
    if (by_kind_[static_cast<std::size_t>(k)].size() < kMaxListedPerKind) return true;
    ++unlisted_;
    return false;
}

void Collector::add(DifferenceKind k, std::string message, std::vector<Index> vertices) {
    auto& list = by_kind_[static_cast<std::size_t>(k)];
    if (list.size() >= kMaxListedPerKind) {
        ++unlisted_;
        return;
    }
    list.push_back({k, std::move(message), std::move(vertices)});
}

std::size_t Collector::count() const {
    std::size_t n = unlisted_;
    for (const auto& list : by_kind_) n += list.size();
    return n;
}

Report Collector::finish() && {
    Report r;
    for (const DifferenceKind k : kOrder) {
        auto& list = by_kind_[static_cast<std::size_t>(k)];
        for (Difference& d : list) r.differences.push_back(std::move(d));
    }
    r.unlisted = unlisted_;
    return r;
}

}  // namespace detail

Report unreadable_answer(std::string message) {
    Report r;
    r.differences.push_back({DifferenceKind::UnreadableAnswer, std::move(message), {}});
    return r;
}

}  // namespace dcel::check
