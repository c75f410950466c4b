// The streaming writers (dcel/io/text_sink.hpp): on a graph whose outputs
// run to megabytes, each hands its sink the same text as its string form,
// in pieces of at most 16 KiB, never the whole text at once. A writer that
// went back to building the string and handing it over would fail here:
// the bound on the largest piece is what keeps `dcel build` and `dcel
// faces` from holding their output (docs/formats.md, "Limits and errors").
// A sink that throws stops the writer where it threw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/dump.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/text_sink.hpp"

namespace dcel::io {
namespace {

// What text_sink.hpp promises of the writers' pieces.
constexpr std::size_t kMaxPiece = std::size_t{16} << 10;

// A sink that keeps the text, and counts the pieces and the largest one.
struct Recorder {
    std::string text;
    std::size_t pieces = 0;
    std::size_t largest = 0;
    std::size_t empty = 0;
    [[nodiscard]] TextSink sink() {
        return [this](std::string_view piece) {
            text.append(piece);
            ++pieces;
            largest = std::max(largest, piece.size());
            if (piece.empty()) ++empty;
        };
    }
};

// A w x h lattice (horizontal and vertical edges) with, in its first cell, a
// small square holding an isolated vertex (a hole with something inside),
// and an isolated vertex alone in its second cell: faces with inner cycles
// and isolated vertices, and coordinates that are not whole numbers.
PlanarGraph grid_with_extras(Index w, Index h) {
    PlanarGraph g;
    for (Index y = 0; y < h; ++y) {
        for (Index x = 0; x < w; ++x) g.vertices.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
    for (Index y = 0; y < h; ++y) {
        for (Index x = 0; x < w; ++x) {
            const Index v = y * w + x;
            if (x + 1 < w) g.edges.push_back({VertexId(v), VertexId(v + 1)});
            if (y + 1 < h) g.edges.push_back({VertexId(v), VertexId(v + w)});
        }
    }
    const auto n = static_cast<Index>(g.vertices.size());
    g.vertices.insert(g.vertices.end(), {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}, {0.5, 0.5}, {1.5, 0.5}});
    for (Index i = 0; i < 4; ++i) g.edges.push_back({VertexId(n + i), VertexId(n + (i + 1) % 4)});
    return g;
}

// Runs a streaming writer into a Recorder and checks it against the string
// form: the same text, in pieces none empty and none over kMaxPiece, so
// more than one piece for any text over kMaxPiece.
template <class Stream>
void expect_streamed(const std::string& whole, Stream&& stream) {
    Recorder r;
    stream(r.sink());
    EXPECT_EQ(r.text.size(), whole.size());
    EXPECT_TRUE(r.text == whole) << "the streamed text differs from the string form";
    EXPECT_EQ(r.empty, 0U);
    EXPECT_LE(r.largest, kMaxPiece) << "a piece of " << r.largest << " bytes (of " << whole.size() << ")";
    EXPECT_GE(r.pieces, whole.size() / kMaxPiece);
}

class Streaming : public ::testing::Test {
protected:
    // 200 x 200: a dump of about 17 MB, the faces about 1.4 MB.
    static void SetUpTestSuite() {
        graph_ = new PlanarGraph(grid_with_extras(200, 200));
        dcel_ = new Dcel(build(*graph_));
    }
    static void TearDownTestSuite() {
        delete dcel_;
        delete graph_;
    }
    static PlanarGraph* graph_;
    static Dcel* dcel_;
};
PlanarGraph* Streaming::graph_ = nullptr;
Dcel* Streaming::dcel_ = nullptr;

TEST_F(Streaming, DumpOfTheDcelIsToDumpsTextInBoundedPieces) {
    const Dcel& d = *dcel_;
    ASSERT_EQ(d.num_faces(), 199U * 199U + 2U);  // the cells, the small square and the unbounded face
    for (const DumpStyle style : {DumpStyle::Lines, DumpStyle::Compact}) {
        const std::string whole = write_dump(to_dump(d), style);
        ASSERT_GT(whole.size(), std::size_t{10} << 20);
        expect_streamed(whole, [&](const TextSink& sink) { write_dump_of(d, style, sink); });
        expect_streamed(whole, [&](const TextSink& sink) { write_dump(to_dump(d), style, sink); });
    }
}

TEST_F(Streaming, FacesAndGraphInBoundedPieces) {
    const std::string faces = write_faces_of(*dcel_);
    ASSERT_GT(faces.size(), std::size_t{1} << 20);
    expect_streamed(faces, [&](const TextSink& sink) { write_faces_of(*dcel_, sink); });
    const std::string graph = write_graph(*graph_);
    ASSERT_GT(graph.size(), std::size_t{1} << 20);
    expect_streamed(graph, [&](const TextSink& sink) { write_graph(*graph_, sink); });
}

TEST_F(Streaming, EveryReferenceAnswerInBoundedPieces) {
    for (const char* name : {"faces", "dump", "polygons", "rings", "even-odd"}) {
        SCOPED_TRACE(name);
        const check::AnswerKind kind = *check::answer_kind_from_name(name);
        const std::string whole = check::reference_answer(*dcel_, kind);
        ASSERT_GT(whole.size(), std::size_t{500} << 10);
        expect_streamed(whole, [&](const TextSink& sink) { check::write_reference_answer(*dcel_, kind, sink); });
    }
}

// The writers stop where the sink throws: the exception reaches the caller,
// the sink is not called again, and what it took is the text's beginning.
TEST_F(Streaming, AThrowingSinkStopsTheWriter) {
    struct Full : std::runtime_error {
        using std::runtime_error::runtime_error;
    };
    const std::string whole = write_dump(to_dump(*dcel_), DumpStyle::Lines);
    std::string taken;
    std::size_t calls = 0;
    const TextSink sink = [&](std::string_view piece) {
        if (++calls == 4) throw Full("disk full");
        taken.append(piece);
    };
    EXPECT_THROW(write_dump_of(*dcel_, DumpStyle::Lines, sink), Full);
    EXPECT_EQ(calls, 4U);
    EXPECT_GT(taken.size(), 0U);
    EXPECT_EQ(whole.compare(0, taken.size(), taken), 0) << "what the sink took is not the text's beginning";
}

}  // namespace
}  // namespace dcel::io
