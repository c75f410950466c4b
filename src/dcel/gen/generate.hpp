// Random valid planar straight-line graphs, their exact transforms, planted
// defects and shrinking: the one generator library that the property tests
// (properties/), the fuzz harnesses (fuzz/) and the CLI (`dcel gen`,
// `dcel diff`) all draw from. Library target dcel::gen.
//
// Everything is deterministic in its arguments: the same (family, seed,
// vertices) gives the same graph on every platform (own PRNG, no
// std::uniform_*_distribution, whose output is implementation-defined).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "dcel/graph.hpp"

namespace dcel::gen {

enum class Family : std::uint8_t {
    RandomSegments,  // random integer points joined by random non-crossing segments
    Triangulation,   // a random subset of the edges of a triangulation of random integer points
    GridWithHoles,   // a grid with some cells' edges removed, leaving holes and islands
    NestedPolygons,  // polygons inside polygons, holes inside holes, to any depth
    Tree,            // random trees (dangling edges everywhere)
    Comb,            // a spine with teeth
    Star,            // one vertex of high degree
    CollinearChain,  // many collinear consecutive edges, with branches
    Components,      // many small components mixed with isolated vertices
    NearDegenerate,  // large offsets with tiny differences, tiny magnitudes,
                     // subnormals, -0.0, nearly parallel directions
};

[[nodiscard]] std::span<const Family> all_families();
[[nodiscard]] std::string_view family_name(Family f);  // "random-segments", ...
[[nodiscard]] std::optional<Family> family_from_name(std::string_view name);

struct Params {
    Family family = Family::RandomSegments;
    std::uint64_t seed = 0;
    std::size_t vertices = 16;  // every family gives exactly this many vertices
};

// A valid planar straight-line graph: build() accepts it. Deterministic.
[[nodiscard]] PlanarGraph generate(const Params& params);

// Exact transforms. Each maps every coordinate without rounding, or returns
// nullopt when that is impossible for this graph (e.g. a translation that
// would round, a scaling that would overflow or underflow).
enum class Transform : std::uint8_t {
    Translate,  // by (amount, -amount)
    Rotate90,   // (x, y) -> (-y, x): same cycles
    Mirror,     // (x, y) -> (-x, y): every cycle reversed
    ScalePow2,  // multiply by 2^amount
};
[[nodiscard]] std::optional<PlanarGraph> apply(const PlanarGraph& g, Transform t, std::int64_t amount = 0);

// Plants one defect into a valid graph, giving a graph that build() must
// reject: a crossing, a vertex touching an edge's interior, or a collinear
// overlap. nullopt when the graph offers no place for it.
enum class Defect : std::uint8_t { Crossing, Touch, Overlap };
[[nodiscard]] std::optional<PlanarGraph> plant(const PlanarGraph& g, Defect d, std::uint64_t seed);

// Smaller valid graphs derived from g, most aggressive first, one at a time:
// the empty graph, the isolated vertices dropped, each component alone and
// each dropped, blocks of vertices dropped, runs of edges dropped, vertices
// dropped, degree-2 vertices merged away (a-v-b becomes a-b), edges
// contracted, coordinates snapped towards small integers (shrink.cpp has the
// details). Every candidate is valid. Holds one candidate at a time, so it
// serves graphs of any size; each next() costs O(V + E) (O(V E) for a
// contraction's checks).
class ShrinkCandidates {
public:
    enum class Stage : std::uint8_t {
        Empty,
        Isolated,
        Components,
        VertexRuns,
        Edges,
        Vertices,
        MergeDegree2,
        Contract,
        GlobalSnaps,
        Moves,
        Done
    };
    // Where in the order a candidate came from: a shrinker that moved to a
    // candidate starts the next graph's candidates there (the steps before
    // it failed on a larger graph and rarely succeed on a smaller one), and
    // goes back to the start only when nothing from there on works.
    struct Position {
        Stage stage = Stage::Empty;
        std::size_t chunk = 0;  // VertexRuns and Edges: the run length (0: the stage's first)
    };

    explicit ShrinkCandidates(PlanarGraph g);
    ShrinkCandidates(PlanarGraph g, Position start);
    // The next candidate, or nothing when there are no more.
    [[nodiscard]] std::optional<PlanarGraph> next();
    // The position of the candidate next() returned last.
    [[nodiscard]] Position position() const { return last_; }

private:
    [[nodiscard]] std::optional<PlanarGraph> step();
    // One step of each stage (step() dispatches on stage_).
    [[nodiscard]] std::optional<PlanarGraph> empty_step();
    [[nodiscard]] std::optional<PlanarGraph> components_step();
    [[nodiscard]] std::optional<PlanarGraph> vertex_runs_step();
    [[nodiscard]] std::optional<PlanarGraph> edges_step();
    [[nodiscard]] std::optional<PlanarGraph> vertices_step();
    [[nodiscard]] std::optional<PlanarGraph> merge_degree2_step();
    [[nodiscard]] std::optional<PlanarGraph> contract_step();
    [[nodiscard]] std::optional<PlanarGraph> global_snaps_step();
    [[nodiscard]] std::optional<PlanarGraph> moves_step();
    void next_stage(Stage s);
    void start_vertex_runs(std::size_t chunk);
    void start_edges(std::size_t chunk);

    PlanarGraph g_;
    std::size_t fractions_ = 0;  // non-integer coordinates of g_
    Stage stage_ = Stage::Empty;
    bool isolated_first_ = false;
    Position last_;
    std::size_t index_ = 0;
    std::size_t chunk_ = 0;
    std::vector<Index> component_of_;
    std::size_t components_ = 0;
    std::vector<std::vector<std::size_t>> incident_;
};

// All of ShrinkCandidates' candidates at once (for small graphs).
[[nodiscard]] std::vector<PlanarGraph> shrink_candidates(const PlanarGraph& g);

// Greedy shrinking: repeatedly moves to the first candidate for which
// still_fails holds, until none does or max_steps predicate calls are spent.
[[nodiscard]] PlanarGraph shrink(PlanarGraph g, const std::function<bool(const PlanarGraph&)>& still_fails,
                                 std::size_t max_steps = 20000);

// The one greedy loop, behind shrink() and `dcel diff`'s shrinking: from the
// position of the last candidate taken, try candidates in order; take the
// first for which still_fails holds and start again from its position; when
// nothing from there on fails, go once more from the first stage; end when
// a whole pass from the start takes nothing (no single candidate of the
// current graph fails) or stop() says so (asked before each candidate).
struct GreedyShrink {
    PlanarGraph graph;      // the smallest failing graph taken (the input when none)
    std::size_t tried = 0;  // candidates handed to still_fails
    std::size_t taken = 0;  // of which still failed
    bool stopped = false;   // stop() ended it before a pass took nothing
};
[[nodiscard]] GreedyShrink shrink_greedily(PlanarGraph g, const std::function<bool(const PlanarGraph&)>& still_fails,
                                           const std::function<bool()>& stop);

}  // namespace dcel::gen
