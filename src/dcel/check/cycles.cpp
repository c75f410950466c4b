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
    if (through.empty()) return "answer cycle " + std::to_string(numbering != nullptr ? (*numbering)[i] : i) + " " + text;
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

// The passes of match_cycles, in order; each reads what the earlier ones
// decided (m.status, claimed, reversal_of).
class Matcher {
public:
    Matcher(const Reference& ref, const AnswerCycles& answer, Collector& out)
        : ref_(ref), d_(ref.dcel()), answer_(answer), out_(out), count_(answer.cycles->size()) {
        m_.status.assign(count_, CycleStatus::Invalid);
        m_.reference_cycle.assign(count_, kNoIndex);
        m_.first_match.assign(ref.cycle_count(), kNoIndex);
        claimed_.assign(ref.cycle_count(), 0);
        reversal_of_.assign(count_, kNoIndex);
        hs_.begin.reserve(count_ + 1);
    }

    CycleMatch run() && {
        match_as_given();
        match_reversed();
        report_wrong_next();
        report_missing();
        report_extra();
        return std::move(m_);
    }

private:
    [[nodiscard]] const HalfEdgeId* half_edges(std::size_t i) const { return hs_.all.data() + hs_.begin[i]; }
    [[nodiscard]] std::size_t length(std::size_t i) const { return hs_.begin[i + 1] - hs_.begin[i]; }

    // Cycles as they are: the first listing of a reference cycle matches it.
    void match_as_given() {
        for (std::size_t i = 0; i < count_; ++i) {
            if (map_cycle(ref_, answer_, i, hs_, out_)) {
                const HalfEdgeId* h = hs_.all.data() + hs_.begin.back();
                const std::size_t n = hs_.all.size() - hs_.begin.back();
                const Index r = ref_.cycle_of(h[0]);
                if (n == ref_.cycle_length(r) && follows_reference(d_, h, n)) {
                    m_.reference_cycle[i] = r;
                    const bool first = m_.first_match[r] == kNoIndex;
                    if (first) m_.first_match[r] = static_cast<Index>(i);
                    m_.status[i] = first ? CycleStatus::Matched : CycleStatus::Duplicate;
                } else {
                    m_.status[i] = CycleStatus::Unexplained;
                }
            }
            hs_.begin.push_back(hs_.all.size());
        }
    }

    // Backwards: a cycle that is not matched as it is may be a missing
    // reference cycle reversed. Only after every direct match is known, so a
    // reversed cycle never takes the place of one listed later.
    void match_reversed() {
        for (std::size_t i = 0; i < count_; ++i) {
            if (m_.status[i] != CycleStatus::Unexplained && m_.status[i] != CycleStatus::Duplicate) continue;
            const HalfEdgeId* h = half_edges(i);
            const std::size_t n = length(i);
            const Index r = ref_.cycle_of(twin(h[0]));
            if (n != ref_.cycle_length(r) || !follows_reference_reversed(d_, h, n)) continue;
            if (m_.first_match[r] != kNoIndex || claimed_[r] != 0) {
                reversal_of_[i] = r;
                continue;
            }
            claimed_[r] = 1;
            m_.status[i] = CycleStatus::Reversed;
            m_.reference_cycle[i] = r;
            if (out_.wants(DifferenceKind::ReversedCycle)) {
                out_.add(DifferenceKind::ReversedCycle,
                         answer_.label(i) + " is the reference cycle " + cycle_text(ref_.cycle_vertices(r)) +
                             " walked backwards (wrong orientation)",
                         as_vector((*answer_.cycles)[i]));
            }
        }
    }

    // Wrong next: where an unexplained cycle leaves the reference's walk.
    // Each reference half-edge is reported once, at its first such cycle.
    void report_wrong_next() {
        std::vector<char> reported(d_.num_half_edges(), 0);
        for (std::size_t i = 0; i < count_; ++i) {
            if (m_.status[i] != CycleStatus::Unexplained) continue;
            const HalfEdgeId* h = half_edges(i);
            const std::size_t n = length(i);
            for (std::size_t j = 0; j < n; ++j) {
                const HalfEdgeId given = h[(j + 1) % n];
                const HalfEdgeId expected = d_.next(h[j]);
                if (given == expected || reported[h[j].index()] != 0) continue;
                reported[h[j].index()] = 1;
                if (!out_.wants(DifferenceKind::WrongNext)) continue;
                const Index u = d_.origin(h[j]).index();
                const Index v = d_.target(h[j]).index();
                const Index x = d_.target(given).index();
                const Index w = d_.target(expected).index();
                out_.add(DifferenceKind::WrongNext,
                         "at " + step(u, v) + " the answer continues to " + step(v, x) + " (in " + answer_.label(i) +
                             "), the reference to " + step(v, w),
                         {u, v, x, w});
            }
        }
    }

    void report_missing() {
        for (Index r = 0; r < ref_.cycle_count(); ++r) {
            if (m_.first_match[r] != kNoIndex || claimed_[r] != 0 || !out_.wants(DifferenceKind::MissingCycle)) continue;
            std::vector<Index> vs = ref_.cycle_vertices(r);
            std::string message = "the reference cycle " + cycle_text(vs) + " is missing from the answer";
            out_.add(DifferenceKind::MissingCycle, std::move(message), std::move(vs));
        }
    }

    // Duplicates and unexplained cycles, each with the likeliest reason.
    void report_extra() {
        for (std::size_t i = 0; i < count_; ++i) {
            const CycleStatus s = m_.status[i];
            if (s != CycleStatus::Duplicate && s != CycleStatus::Unexplained) continue;
            if (!out_.wants(DifferenceKind::ExtraCycle)) continue;  // counts it as unlisted
            out_.add(DifferenceKind::ExtraCycle, answer_.label(i) + why_extra(i), as_vector((*answer_.cycles)[i]));
        }
    }

    [[nodiscard]] std::string why_extra(std::size_t i) const {
        if (m_.status[i] == CycleStatus::Duplicate) {
            return " repeats " + answer_.label(m_.first_match[m_.reference_cycle[i]]) +
                   ": the reference has this cycle once";
        }
        if (reversal_of_[i] != kNoIndex) {
            return " is not a cycle of the reference; walked backwards it is " +
                   cycle_text(ref_.cycle_vertices(reversal_of_[i])) + ", which the answer already has";
        }
        const HalfEdgeId* h = half_edges(i);
        const std::size_t n = length(i);
        if (!follows_reference(d_, h, n)) return " is not a boundary cycle of the reference";
        const Index r = ref_.cycle_of(h[0]);
        return " goes round the reference cycle " + cycle_text(ref_.cycle_vertices(r)) + " " +
               std::to_string(n / ref_.cycle_length(r)) + " times";
    }

    const Reference& ref_;
    const Dcel& d_;
    const AnswerCycles& answer_;
    Collector& out_;
    const std::size_t count_;
    CycleMatch m_;
    AnswerHalfEdges hs_;
    std::vector<char> claimed_;       // per reference cycle: taken by a reversed answer cycle
    std::vector<Index> reversal_of_;  // per answer cycle: the reference cycle it reverses, already listed
};

}  // namespace

CycleMatch match_cycles(const Reference& ref, const AnswerCycles& answer, Collector& out) {
    return Matcher(ref, answer, out).run();
}

}  // namespace dcel::check::detail
