#include "dcel/check/cycles.hpp"

#include <algorithm>
#include <numeric>

namespace dcel::check::detail {

namespace {

constexpr std::size_t kShownVertices = 12;

std::uint64_t key(Index u, Index v) { return (std::uint64_t{u} << 32U) | v; }

std::string vertex(Index v) { return "v" + std::to_string(v); }
std::vector<Index> as_vector(std::span<const Index> s) { return {s.begin(), s.end()}; }
std::string step(Index u, Index v) { return vertex(u) + "->" + vertex(v); }

}  // namespace

std::string cycle_text(std::span<const Index> vertices) {
    std::string s = "[";
    const std::size_t shown = std::min(vertices.size(), kShownVertices);
    for (std::size_t i = 0; i < shown; ++i) {
        if (i != 0) s += ", ";
        s += std::to_string(vertices[i]);
    }
    if (shown < vertices.size()) s += ", ... (" + std::to_string(vertices.size()) + " vertices)";
    return s + "]";
}

// ---- Reference

Reference::Reference(const Dcel& d) : d_(d) {
    const auto halves = static_cast<Index>(d.num_half_edges());
    std::vector<Index> order(halves);
    std::iota(order.begin(), order.end(), Index{0});
    auto key_of = [&](Index h) { return key(d.origin(HalfEdgeId(h)).index(), d.target(HalfEdgeId(h)).index()); };
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return key_of(a) < key_of(b); });
    keys_.reserve(halves);
    by_key_.reserve(halves);
    for (const Index h : order) {
        keys_.push_back(key_of(h));
        by_key_.emplace_back(h);
    }
    cycle_of_.assign(halves, kNoIndex);
    for (Index h = 0; h < halves; ++h) {
        if (cycle_of_[h] != kNoIndex) continue;
        const auto c = static_cast<Index>(smallest_.size());
        smallest_.emplace_back(h);
        Index n = 0;
        for (const HalfEdgeId x : d.cycle(HalfEdgeId(h))) {
            cycle_of_[x.index()] = c;
            ++n;
        }
        length_.push_back(n);
    }
}

HalfEdgeId Reference::find(Index u, Index v) const {
    const std::uint64_t k = key(u, v);
    const auto it = std::lower_bound(keys_.begin(), keys_.end(), k);
    if (it == keys_.end() || *it != k) return {};
    return by_key_[static_cast<std::size_t>(it - keys_.begin())];
}

std::vector<Index> Reference::cycle_vertices(Index c) const {
    std::vector<Index> vs;
    vs.reserve(length_[c]);
    for (const HalfEdgeId h : d_.cycle(smallest_[c])) vs.push_back(d_.origin(h).index());
    return vs;
}

std::string AnswerCycles::label(std::size_t i) const {
    const std::string text = cycle_text((*cycles)[i]);
    if (through.empty()) return "answer cycle " + std::to_string(numbering ? (*numbering)[i] : i) + " " + text;
    return "the answer's cycle through " + through[i].str() + " " + text;
}

// ---- Matching

namespace {

// The half-edges of each answer cycle, flat: cycle i owns [begin[i], begin[i+1]).
struct AnswerHalfEdges {
    std::vector<HalfEdgeId> all;
    std::vector<std::size_t> begin{0};
};

// Maps cycle i to reference half-edges, or reports why it cannot.
bool map_cycle(const Reference& ref, const AnswerCycles& answer, std::size_t i, AnswerHalfEdges& hs, Collector& out) {
    const std::span<const Index> c = (*answer.cycles)[i];
    const auto vertices = static_cast<Index>(ref.dcel().num_vertices());
    if (c.empty()) {
        if (out.wants(DifferenceKind::ExtraCycle)) {
            out.add(DifferenceKind::ExtraCycle, answer.label(i) + " is empty: a boundary cycle has at least two vertices");
        }
        return false;
    }
    if (const auto bad = std::find_if(c.begin(), c.end(), [&](Index v) { return v >= vertices; }); bad != c.end()) {
        if (out.wants(DifferenceKind::VertexCount)) {
            std::vector<Index> known;
            std::copy_if(c.begin(), c.end(), std::back_inserter(known), [&](Index v) { return v < vertices; });
            out.add(DifferenceKind::VertexCount,
                    answer.label(i) + " names vertex " + std::to_string(*bad) + ", but the graph has " +
                        std::to_string(vertices) + " vertices" +
                        (vertices == 0 ? std::string() : " (0 to " + std::to_string(vertices - 1) + ")"),
                    std::move(known));
        }
        return false;
    }
    const std::size_t start = hs.all.size();
    for (std::size_t j = 0; j < c.size(); ++j) {
        const Index u = c[j];
        const Index v = c[(j + 1) % c.size()];
        const HalfEdgeId h = ref.find(u, v);
        if (h.is_null()) {
            hs.all.resize(start);
            if (out.wants(DifferenceKind::NotAnEdge)) {
                std::string why = c.size() == 1 ? " has a single vertex: " + step(u, v) +
                                                      " is not an edge (a boundary cycle has at least two vertices)"
                                                : " steps from " + vertex(u) + " to " + vertex(v) +
                                                      ", which is not an edge of the graph";
                out.add(DifferenceKind::NotAnEdge, answer.label(i) + why, {u, v});
            }
            return false;
        }
        hs.all.push_back(h);
    }
    return true;
}

// True when the reference's next takes each half-edge of hs to the one after
// it (cyclically): hs then walks a reference cycle, once or several times.
bool follows_reference(const Dcel& d, const HalfEdgeId* hs, std::size_t n) {
    for (std::size_t j = 0; j < n; ++j) {
        if (d.next(hs[j]) != hs[(j + 1) % n]) return false;
    }
    return true;
}

// The same for the cycle walked backwards: the half-edges twin(hs[n-1]), ..., twin(hs[0]).
bool follows_reference_reversed(const Dcel& d, const HalfEdgeId* hs, std::size_t n) {
    for (std::size_t j = 0; j < n; ++j) {
        if (d.next(twin(hs[(j + 1) % n])) != twin(hs[j])) return false;
    }
    return true;
}

}  // namespace

CycleMatch match_cycles(const Reference& ref, const AnswerCycles& answer, Collector& out) {
    const Dcel& d = ref.dcel();
    const std::size_t count = answer.cycles->size();
    CycleMatch m;
    m.status.assign(count, CycleStatus::Invalid);
    m.reference_cycle.assign(count, kNoIndex);
    m.first_match.assign(ref.cycle_count(), kNoIndex);
    AnswerHalfEdges hs;
    hs.begin.reserve(count + 1);

    // Cycles as they are: the first listing of a reference cycle matches it.
    for (std::size_t i = 0; i < count; ++i) {
        if (map_cycle(ref, answer, i, hs, out)) {
            const HalfEdgeId* h = hs.all.data() + hs.begin.back();
            const std::size_t n = hs.all.size() - hs.begin.back();
            const Index r = ref.cycle_of(h[0]);
            if (n == ref.cycle_length(r) && follows_reference(d, h, n)) {
                m.reference_cycle[i] = r;
                if (m.first_match[r] == kNoIndex) {
                    m.first_match[r] = static_cast<Index>(i);
                    m.status[i] = CycleStatus::Matched;
                } else {
                    m.status[i] = CycleStatus::Duplicate;
                }
            } else {
                m.status[i] = CycleStatus::Unexplained;
            }
        }
        hs.begin.push_back(hs.all.size());
    }

    // Backwards: a cycle that is not matched as it is may be a missing
    // reference cycle reversed. Only after every direct match is known, so a
    // reversed cycle never takes the place of one listed later.
    std::vector<char> claimed(ref.cycle_count(), 0);
    std::vector<Index> reversal_of(count, kNoIndex);
    for (std::size_t i = 0; i < count; ++i) {
        if (m.status[i] != CycleStatus::Unexplained && m.status[i] != CycleStatus::Duplicate) continue;
        const HalfEdgeId* h = hs.all.data() + hs.begin[i];
        const std::size_t n = hs.begin[i + 1] - hs.begin[i];
        const Index r = ref.cycle_of(twin(h[0]));
        if (n != ref.cycle_length(r) || !follows_reference_reversed(d, h, n)) continue;
        if (m.first_match[r] == kNoIndex && claimed[r] == 0) {
            claimed[r] = 1;
            m.status[i] = CycleStatus::Reversed;
            m.reference_cycle[i] = r;
            if (out.wants(DifferenceKind::ReversedCycle)) {
                out.add(DifferenceKind::ReversedCycle,
                        answer.label(i) + " is the reference cycle " + cycle_text(ref.cycle_vertices(r)) +
                            " walked backwards (wrong orientation)",
                        as_vector((*answer.cycles)[i]));
            }
        } else {
            reversal_of[i] = r;
        }
    }

    // Wrong next: where an unexplained cycle leaves the reference's walk.
    // Each reference half-edge is reported once, at its first such cycle.
    std::vector<char> reported(d.num_half_edges(), 0);
    for (std::size_t i = 0; i < count; ++i) {
        if (m.status[i] != CycleStatus::Unexplained) continue;
        const HalfEdgeId* h = hs.all.data() + hs.begin[i];
        const std::size_t n = hs.begin[i + 1] - hs.begin[i];
        for (std::size_t j = 0; j < n; ++j) {
            const HalfEdgeId given = h[(j + 1) % n];
            const HalfEdgeId expected = d.next(h[j]);
            if (given == expected || reported[h[j].index()] != 0) continue;
            reported[h[j].index()] = 1;
            if (!out.wants(DifferenceKind::WrongNext)) continue;
            const Index u = d.origin(h[j]).index();
            const Index v = d.target(h[j]).index();
            const Index x = d.target(given).index();
            const Index w = d.target(expected).index();
            out.add(DifferenceKind::WrongNext,
                    "at " + step(u, v) + " the answer continues to " + step(v, x) + " (in " + answer.label(i) +
                        "), the reference to " + step(v, w),
                    {u, v, x, w});
        }
    }

    for (Index r = 0; r < ref.cycle_count(); ++r) {
        if (m.first_match[r] != kNoIndex || claimed[r] != 0 || !out.wants(DifferenceKind::MissingCycle)) continue;
        std::vector<Index> vs = ref.cycle_vertices(r);
        std::string message = "the reference cycle " + cycle_text(vs) + " is missing from the answer";
        out.add(DifferenceKind::MissingCycle, std::move(message), std::move(vs));
    }

    for (std::size_t i = 0; i < count; ++i) {
        const CycleStatus s = m.status[i];
        if (s != CycleStatus::Duplicate && s != CycleStatus::Unexplained) continue;
        if (!out.wants(DifferenceKind::ExtraCycle)) continue;
        std::string why;
        if (s == CycleStatus::Duplicate) {
            why = " repeats " + answer.label(m.first_match[m.reference_cycle[i]]) + ": the reference has this cycle once";
        } else if (reversal_of[i] != kNoIndex) {
            why = " is not a cycle of the reference; walked backwards it is " +
                  cycle_text(ref.cycle_vertices(reversal_of[i])) + ", which the answer already has";
        } else {
            const HalfEdgeId* h = hs.all.data() + hs.begin[i];
            const std::size_t n = hs.begin[i + 1] - hs.begin[i];
            if (follows_reference(d, h, n)) {
                const Index r = ref.cycle_of(h[0]);
                why = " goes round the reference cycle " + cycle_text(ref.cycle_vertices(r)) + " " +
                      std::to_string(n / ref.cycle_length(r)) + " times";
            } else {
                why = " is not a boundary cycle of the reference";
            }
        }
        out.add(DifferenceKind::ExtraCycle, answer.label(i) + why, as_vector((*answer.cycles)[i]));
    }
    return m;
}

}  // namespace dcel::check::detail
