// dcel_bench: dcel's build against its peers, in one run, on generated
// inputs; prints a table of ns per edge, bytes per edge and ratios, and with
// --json one row per (input, implementation). See docs/performance.md.
//
//   dcel_bench [--small] [--json] [--verify] [--repeat N] [--only INPUT] [--impl IMPL] [--no-io] [--uncapped]
//   dcel_bench --write-input INPUT FILE     (the input as graph JSON, for timing the CLI)
// (--only and --impl keep the inputs and implementations whose names
// contain the given text; --no-io skips the JSON reader/writer rows;
// --uncapped runs the peers on the sizes their caps leave out: minutes to
// hours, for one-off runs with --impl.)
//
// Timing: from the in-memory PlanarGraph to the implementation's finished
// structure (dcel: the Dcel; peers: their cycles or arrangement), in thread
// CPU time (wall time is printed too); median of --repeat runs (3), or one
// run when the first takes over 5 s; each run in a child process forked
// after the input was generated. Ratios are per-input: "x dcel" is
// this row's time over dcel's (full, validated) in the same run.
// Memory: peak heap bytes above what was live before the call (a counting
// operator new in this binary; GMP routed through it), per undirected edge.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <malloc.h>
#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#include "alloc_counter.hpp"
#include "dcel/build.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/queries.hpp"
#include "inputs.hpp"
#include "json_row.hpp"
#include "peers/atan2_solver.hpp"
#include "peers/boost_traversal.hpp"
#include "peers/cycles.hpp"
#ifdef DCEL_BENCH_HAVE_CGAL
#include "peers/cgal_arrangement.hpp"
#endif

namespace dcel::bench {
namespace {

struct Case {
    std::string input;
    std::string family;
    std::function<PlanarGraph()> make;
    bool small = false;
};

struct Impl {
    std::string name;
    // Runs the implementation; returns its number of boundary cycles, and
    // fills `cycles` when asked (verify).
    std::function<std::size_t(const PlanarGraph&, Cycles* cycles)> run;
    // Whether it finishes in reasonable time on this input (size caps).
    std::function<bool(const Case&, const PlanarGraph&)> finishes;
};

struct Measurement {
    double seconds = 0;       // median thread CPU time
    double wall_seconds = 0;  // median wall-clock time
    std::size_t bytes = 0;
    std::size_t runs = 0;
    std::size_t cycles = 0;
};

Cycles dcel_cycles(const Dcel& d) {
    Cycles out;
    for (const auto& c : boundary_cycles(d)) {
        std::vector<std::uint32_t> vs;
        for (const VertexId v : c) vs.push_back(v.index());
        out.push_back(std::move(vs));
    }
    return out;
}

std::size_t count_cycles(const Dcel& d) {
    std::size_t n = d.num_faces() - 1;  // one outer cycle per bounded face
    for (Index f = 0; f < d.num_faces(); ++f) n += d.inner(FaceId(f)).size();
    return n;
}

std::vector<Impl> implementations() {
    auto always = [](const Case&, const PlanarGraph&) { return true; };
    std::vector<Impl> impls;
    impls.push_back({"dcel",
                     [](const PlanarGraph& g, Cycles* c) {
                         const Dcel d = build(g);
                         if (c != nullptr) *c = dcel_cycles(d);
                         return count_cycles(d);
                     },
                     always});
    impls.push_back({"dcel-unchecked",
                     [](const PlanarGraph& g, Cycles* c) {
                         const Dcel d = build(g, {.check_crossings = false});
                         if (c != nullptr) *c = dcel_cycles(d);
                         return count_cycles(d);
                     },
                     always});
    impls.push_back({"atan2",
                     [](const PlanarGraph& g, Cycles* c) {
                         Cycles cycles = atan2_cycles(g);
                         const std::size_t n = cycles.size();
                         if (c != nullptr) *c = std::move(cycles);
                         return n;
                     },
                     // O(sum of d^2): 1.4 s on a star of degree 1e5, so about 2.5 minutes
                     // at 1e6 and 20 at 3e6 (left out).
                     [](const Case& k, const PlanarGraph& g) { return k.family != "star" || g.edges.size() <= 1000000; }});
    impls.push_back({"boost",
                     [](const PlanarGraph& g, Cycles* c) {
                         PeerResult r = boost_geometric_cycles(g, c != nullptr);
                         if (c != nullptr) *c = std::move(r.cycles);
                         return r.count;
                     },
                     always});
    impls.push_back({"boost-bm",
                     [](const PlanarGraph& g, Cycles* c) {
                         PeerResult r = boost_bm_cycles(g, c != nullptr);
                         if (c != nullptr) *c = std::move(r.cycles);
                         return r.count;
                     },
                     // Superlinear, but it finishes on every input here: at most 44 us per
                     // edge, 132 s on shuffled Delaunay 1e6 (an --uncapped run).
                     always});
#ifdef DCEL_BENCH_HAVE_CGAL
    impls.push_back({"cgal",
                     [](const PlanarGraph& g, Cycles* c) {
                         PeerResult r = cgal_cycles(g, c != nullptr);
                         if (c != nullptr) *c = std::move(r.cycles);
                         return r.count;
                     },
                     // Slope comparisons at the centre: 32 s for a star of degree 1e5.
                     [](const Case& k, const PlanarGraph& g) { return k.family != "star" || g.edges.size() <= 100000; }});
#endif
    return impls;
}

std::vector<Case> cases() {
    // Generated once, shared by its shuffled variant.
    auto delaunay_pair = [](std::size_t n, std::uint64_t seed, bool small) {
        auto cached = std::make_shared<std::optional<PlanarGraph>>();
        auto get = [cached, n, seed] {
            if (!*cached) *cached = delaunay(n, seed);
            return **cached;
        };
        const std::string size = n == 10000 ? "1e4" : n == 100000 ? "1e5" : "1e6";
        return std::vector<Case>{{"delaunay-" + size, "delaunay", get, small},
                                 {"delaunay-" + size + "-shuffled", "delaunay-shuffled",
                                  [get, seed] { return shuffled(get(), seed + 1); }, small}};
    };
    std::vector<Case> all;
    for (auto& c : delaunay_pair(10000, 1, true)) all.push_back(c);
    for (auto& c : delaunay_pair(100000, 2, false)) all.push_back(c);
    for (auto& c : delaunay_pair(1000000, 3, false)) all.push_back(c);
    all.push_back({"grid-100x100", "grid", [] { return grid(100, 100); }, true});
    all.push_back({"grid-1000x1000", "grid", [] { return grid(1000, 1000); }, false});
    all.push_back({"star-1e4", "star", [] { return star(10000); }, true});  // CGAL: seconds at 3e4
    all.push_back({"star-3e4", "star", [] { return star(30000); }, false});
    all.push_back({"star-1e5", "star", [] { return star(100000); }, false});
    all.push_back({"star-1e6", "star", [] { return star(1000000); }, false});
    all.push_back({"star-3e6", "star", [] { return star(3000000); }, false});
    all.push_back({"nested-squares-1e3", "nested-squares", [] { return nested_squares(1000); }, true});
    all.push_back({"nested-squares-7500", "nested-squares", [] { return nested_squares(7500); }, false});
    all.push_back({"nested-squares-1e5", "nested-squares", [] { return nested_squares(100000); }, false});
    all.push_back({"nested-squares-750000", "nested-squares", [] { return nested_squares(750000); }, false});
    all.push_back({"forest-200", "forest", [] { return forest(200, 4); }, true});
    all.push_back({"forest-2000", "forest", [] { return forest(2000, 5); }, false});
    all.push_back({"chain-3e4", "chain", [] { return collinear_chain(30001); }, true});
    all.push_back({"chain-1e6", "chain", [] { return collinear_chain(1000001); }, false});
    all.push_back({"chain-3e6", "chain", [] { return collinear_chain(3000001); }, false});
    return all;
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// One timed run. Every implementation is single-threaded, so thread CPU
// time is its cost; unlike wall time it does not count the time a busy
// machine (this one is shared) keeps the process waiting. Both are reported.
struct Run {
    double cpu = 0;
    double wall = 0;
    std::size_t bytes = 0;
    std::size_t cycles = 0;
};

Run run_once(const Impl& impl, const PlanarGraph& g) {
    Run r;
    reset_peak();
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_seconds();
    r.cycles = impl.run(g, nullptr);
    const double c1 = thread_cpu_seconds();
    const auto w1 = std::chrono::steady_clock::now();
    r.bytes = peak_above_reset();
    r.cpu = c1 - c0;
    r.wall = std::chrono::duration<double>(w1 - w0).count();
    return r;
}

// The run in a child process forked for it, so that every implementation
// and every repetition starts from the heap the input left: in one process
// a run is faster or slower depending on the memory earlier runs freed
// (atan2 on grid 1000x1000 measured 99 to 135 ns/edge, dcel unchecked 115
// to 198, by what ran before them). Falls back to the calling process when
// fork fails.
Run run_in_child(const Impl& impl, const PlanarGraph& g) {
    int fds[2];
    if (pipe(fds) != 0) return run_once(impl, g);
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return run_once(impl, g);
    }
    if (pid == 0) {
        close(fds[0]);
        const Run r = run_once(impl, g);
        const bool written = write(fds[1], &r, sizeof r) == static_cast<ssize_t>(sizeof r);
        _exit(written ? 0 : 1);
    }
    close(fds[1]);
    Run r;
    std::size_t got = 0;
    while (got < sizeof r) {
        const ssize_t n = read(fds[0], reinterpret_cast<char*>(&r) + got, sizeof r - got);
        if (n <= 0) break;
        got += static_cast<std::size_t>(n);
    }
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (got != sizeof r || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "dcel_bench: the child measuring %s failed\n", impl.name.c_str());
        std::exit(2);
    }
    return r;
}

Measurement measure(const Impl& impl, const PlanarGraph& g, std::size_t repeat) {
    std::vector<double> cpu;
    std::vector<double> wall;
    Measurement m;
    for (std::size_t i = 0; i < repeat; ++i) {
        const Run r = run_in_child(impl, g);
        m.bytes = std::max(m.bytes, r.bytes);
        m.cycles = r.cycles;
        cpu.push_back(r.cpu);
        wall.push_back(r.wall);
        if (cpu.back() > 5.0) break;
    }
    m.seconds = median(cpu);
    m.wall_seconds = median(wall);
    m.runs = cpu.size();
    return m;
}

// Each implementation's cycles against dcel's. Boyer-Myrvold builds some
// embedding: on a 3-connected graph it is dcel's or its mirror image; on
// others only the number of cycles is fixed (Euler).
bool verify(const Case& k, const PlanarGraph& g, const std::vector<Impl>& impls) {
    Cycles ours;
    (void)impls[0].run(g, &ours);
    ours = canonical(std::move(ours));
    Cycles mirrored = ours;
    for (auto& c : mirrored) std::reverse(c.begin(), c.end());
    mirrored = canonical(std::move(mirrored));
    bool ok = true;
    for (const Impl& impl : impls) {
        if (!impl.finishes(k, g)) continue;
        Cycles theirs;
        const std::size_t count = impl.run(g, &theirs);
        theirs = canonical(std::move(theirs));
        std::string verdict;
        if (theirs == ours && count == ours.size()) {
            verdict = "same cycles";
        } else if (impl.name == "boost-bm" && theirs == mirrored) {
            verdict = "same cycles, mirrored (an embedding, not the geometric one)";
        } else if (impl.name == "boost-bm" && k.family.rfind("delaunay", 0) != 0 && theirs.size() == ours.size()) {
            verdict = "same number of cycles (an embedding, not the geometric one)";
        } else {
            verdict = "DIFFERENT: " + std::to_string(theirs.size()) + " cycles, dcel has " + std::to_string(ours.size());
            ok = false;
        }
        std::printf("verify %-24s %-15s %s\n", k.input.c_str(), impl.name.c_str(), verdict.c_str());
    }
    return ok;
}

struct Options {
    bool small = false;
    bool json = false;
    bool verify = false;
    std::size_t repeat = 3;
    std::string only;
    std::string impl;       // run only implementations whose name contains this
    bool io = true;         // also time the JSON reader and writer
    bool uncapped = false;  // ignore the peers' size caps (Impl::finishes)
};

// Reading and writing JSON on the text of the input graph: read_graph (text
// to PlanarGraph) and write_faces (dcel's boundary cycles to text), as MB/s
// of the text read or written; median of --repeat runs.
void measure_json(const Case& k, const PlanarGraph& g, const Options& o) {
    const std::string text = io::write_graph(g);
    const Dcel d = build(g);
    std::vector<double> read_s;
    std::vector<double> write_s;
    std::size_t out_size = 0;
    for (std::size_t i = 0; i < o.repeat; ++i) {
        double c0 = thread_cpu_seconds();
        const PlanarGraph back = io::read_graph(text);
        read_s.push_back(thread_cpu_seconds() - c0);
        if (back.edges.size() != g.edges.size()) std::abort();
        c0 = thread_cpu_seconds();
        const std::string out = io::write_faces_of(d);
        write_s.push_back(thread_cpu_seconds() - c0);
        out_size = out.size();
    }
    const double edges = static_cast<double>(std::max<std::size_t>(1, g.edges.size()));
    const struct {
        const char* name;
        double seconds;
        double bytes;
    } rows[] = {{"json-read", median(read_s), static_cast<double>(text.size())},
                {"json-write-faces", median(write_s), static_cast<double>(out_size)}};
    for (const auto& row : rows) {
        const double mb_s = row.bytes / 1e6 / row.seconds;
        const double ns = row.seconds * 1e9 / edges;
        if (o.json) {
            JsonRow()
                .text("input", k.input)
                .text("impl", row.name)
                .count("edges", g.edges.size())
                .number("ns_per_edge", ns, 1)
                .null("bytes_per_edge")
                .number("mb_per_s", mb_s, 0)
                .number("text_bytes", row.bytes, 0)
                .print();
        } else {
            std::printf("%-24s %9zu  %-15s %10.1f %8s   %.0f MB/s of %.1f MB\n", k.input.c_str(), g.edges.size(), row.name,
                        ns, "-", mb_s, row.bytes / 1e6);
        }
    }
}

// Writes the named input as graph JSON (for timing the CLI end to end).
int write_input(const std::string& name, const std::string& path) {
    for (const Case& k : cases()) {
        if (k.input != name) continue;
        const std::string text = io::write_graph(k.make());
        std::FILE* f = std::fopen(path.c_str(), "wb");
        if (f == nullptr || std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fclose(f) != 0) {
            std::fprintf(stderr, "dcel_bench: cannot write %s\n", path.c_str());
            return 2;
        }
        return 0;
    }
    std::fprintf(stderr, "dcel_bench: no input named %s\n", name.c_str());
    return 2;
}

int run(const Options& o) {
    count_gmp_allocations();
    const std::vector<Impl> impls = implementations();
    bool ok = true;
    if (!o.json && !o.verify) {
        std::printf("%-24s %9s  %-15s %10s %8s %9s %9s %10s\n", "input", "edges", "impl", "ns/edge", "B/edge", "x dcel",
                    "x uncheck", "wall ns/e");
    }
    for (const Case& k : cases()) {
        if (o.small && !k.small) continue;
        if (!o.only.empty() && k.input.find(o.only) == std::string::npos) continue;
        const PlanarGraph g = k.make();
        malloc_trim(0);  // the children's memory comes fresh from the kernel, not copied on write
        const double edges = static_cast<double>(std::max<std::size_t>(1, g.edges.size()));
        if (o.verify) {
            ok = verify(k, g, impls) && ok;
            continue;
        }
        double full = 0;
        double unchecked = 0;
        for (const Impl& impl : impls) {
            if ((!o.uncapped && !impl.finishes(k, g)) || impl.name.find(o.impl) == std::string::npos) continue;
            const Measurement m = measure(impl, g, o.repeat);
            const double ns = m.seconds * 1e9 / edges;
            const double wall_ns = m.wall_seconds * 1e9 / edges;
            const double bytes = static_cast<double>(m.bytes) / edges;
            if (impl.name == "dcel") full = ns;
            if (impl.name == "dcel-unchecked") unchecked = ns;
            if (o.json) {
                JsonRow()
                    .text("input", k.input)
                    .text("impl", impl.name)
                    .count("edges", g.edges.size())
                    .number("ns_per_edge", ns, 1)
                    .number("bytes_per_edge", bytes, 1)
                    .number("wall_ns_per_edge", wall_ns, 1)
                    .count("runs", m.runs)
                    .count("cycles", m.cycles)
                    .print();
            } else {
                std::printf("%-24s %9zu  %-15s %10.1f %8.1f %9.2f %9.2f %10.1f\n", k.input.c_str(), g.edges.size(),
                            impl.name.c_str(), ns, bytes, ns / full, ns / unchecked, wall_ns);
            }
            std::fflush(stdout);
        }
        const bool json_rows = o.impl.empty() || std::string("json").find(o.impl) != std::string::npos;
        if (o.io && json_rows && k.family.rfind("delaunay", 0) == 0) measure_json(k, g, o);
    }
    return ok ? 0 : 1;
}

}  // namespace
}  // namespace dcel::bench

namespace {

// Boost's Boyer-Myrvold recurses once per vertex along a DFS path: a star of
// degree 1e5 overflows the default 8 MiB stack. Every measurement runs on
// one thread with a 1 GiB stack (reserved, touched only as used).
struct Job {
    dcel::bench::Options options;
    int status = 0;
};

void* run_job(void* arg) {
    auto* job = static_cast<Job*>(arg);
    job->status = dcel::bench::run(job->options);
    return nullptr;
}

int run_with_large_stack(const dcel::bench::Options& o) {
    Job job{o, 0};
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, std::size_t{1} << 30);
    pthread_t thread;
    if (pthread_create(&thread, &attr, run_job, &job) != 0) {
        std::fprintf(stderr, "dcel_bench: cannot start the measuring thread\n");
        return 2;
    }
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attr);
    return job.status;
}

}  // namespace

int main(int argc, char** argv) {
    dcel::bench::Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--small") {
            o.small = true;
        } else if (a == "--json") {
            o.json = true;
        } else if (a == "--verify") {
            o.verify = true;
        } else if (a == "--repeat" && i + 1 < argc) {
            o.repeat = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--only" && i + 1 < argc) {
            o.only = argv[++i];
        } else if (a == "--impl" && i + 1 < argc) {
            o.impl = argv[++i];
        } else if (a == "--no-io") {
            o.io = false;
        } else if (a == "--uncapped") {
            o.uncapped = true;
        } else if (a == "--write-input" && i + 2 < argc) {
            return dcel::bench::write_input(argv[i + 1], argv[i + 2]);
        } else {
            std::fprintf(
                stderr,
                "usage: dcel_bench [--small] [--json] [--verify] [--repeat N] [--only INPUT] [--impl IMPL] [--no-io] "
                "[--uncapped]\n"
                "       dcel_bench --write-input INPUT FILE\n");
            return 2;
        }
    }
    return run_with_large_stack(o);
}
