#include "inputs.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace dcel::bench {
namespace {

// splitmix64: small, fast, the same on every platform.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31U);
    }
    std::uint64_t below(std::uint64_t n) { return next() % n; }

private:
    std::uint64_t state_;
};

template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
}

using I64 = std::int64_t;
__extension__ typedef __int128 I128;  // NOLINT(modernize-use-using): __extension__ needs typedef

struct IPoint {
    I64 x;
    I64 y;
};

// Exact for |coordinates| < 2^30: positive when a, b, c turn counterclockwise.
I64 cross(IPoint a, IPoint b, IPoint c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Exact: positive when d is strictly inside the circle through a, b, c
// (a, b, c counterclockwise).
bool in_circle(IPoint a, IPoint b, IPoint c, IPoint d) {
    const I128 adx = a.x - d.x, ady = a.y - d.y;
    const I128 bdx = b.x - d.x, bdy = b.y - d.y;
    const I128 cdx = c.x - d.x, cdy = c.y - d.y;
    const I128 ad = adx * adx + ady * ady;
    const I128 bd = bdx * bdx + bdy * bdy;
    const I128 cd = cdx * cdx + cdy * cdy;
    const I128 det = adx * (bdy * cd - bd * cdy) - ady * (bdx * cd - bd * cdx) + ad * (bdx * cdy - bdy * cdx);
    return det > 0;
}

// Sweep-hull Delaunay triangulation (the method of Sinclair's s-hull and of
// the Delaunator library): points sorted by distance from a seed circle's
// centre are added outside the current convex hull, each fanned to the hull
// edges it sees, with Lawson flips after each triangle. Triangles are
// counterclockwise. Predicates are exact (integers), so flips terminate.
class SweepHull {
public:
    explicit SweepHull(const std::vector<IPoint>& p) : p_(p) {}

    // Returns triangles as vertex triples; points it cannot place (exactly on
    // the hull) are absent from every triangle.
    std::vector<std::uint32_t> run() {
        const auto n = static_cast<std::uint32_t>(p_.size());
        if (n < 3) return {};
        I64 minx = p_[0].x, maxx = minx, miny = p_[0].y, maxy = miny;
        for (const IPoint& q : p_) {
            minx = std::min(minx, q.x), maxx = std::max(maxx, q.x);
            miny = std::min(miny, q.y), maxy = std::max(maxy, q.y);
        }
        const double cx = 0.5 * static_cast<double>(minx + maxx), cy = 0.5 * static_cast<double>(miny + maxy);
        auto d2 = [](double ax, double ay, double bx, double by) { return (ax - bx) * (ax - bx) + (ay - by) * (ay - by); };
        std::uint32_t i0 = 0, i1 = 0, i2 = 0;
        double best = INFINITY;
        for (std::uint32_t i = 0; i < n; ++i) {
            const double d = d2(cx, cy, dx(i), dy(i));
            if (d < best) best = d, i0 = i;
        }
        best = INFINITY;
        for (std::uint32_t i = 0; i < n; ++i) {
            const double d = d2(dx(i0), dy(i0), dx(i), dy(i));
            if (i != i0 && d < best) best = d, i1 = i;
        }
        best = INFINITY;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (i == i0 || i == i1 || cross(p_[i0], p_[i1], p_[i]) == 0) continue;
            const double r = circumradius2(i0, i1, i);
            if (r < best) best = r, i2 = i;
        }
        if (best == INFINITY) return {};  // all collinear
        if (cross(p_[i0], p_[i1], p_[i2]) < 0) std::swap(i1, i2);
        center(i0, i1, i2);

        std::vector<std::uint32_t> ids(n);
        std::iota(ids.begin(), ids.end(), 0U);
        std::vector<double> dist(n);
        for (std::uint32_t i = 0; i < n; ++i) dist[i] = d2(dx(i), dy(i), cx_, cy_);
        std::sort(ids.begin(), ids.end(), [&](std::uint32_t a, std::uint32_t b) { return dist[a] < dist[b]; });

        hash_size_ = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(n))));
        hull_prev_.assign(n, 0);
        hull_next_.assign(n, 0);
        hull_tri_.assign(n, 0);
        hash_.assign(hash_size_, kNone);
        tri_.reserve(6 * static_cast<std::size_t>(n));
        half_.reserve(6 * static_cast<std::size_t>(n));

        // The hull runs counterclockwise: next is the ccw successor.
        hull_start_ = i0;
        hull_next_[i0] = hull_prev_[i2] = i1;
        hull_next_[i1] = hull_prev_[i0] = i2;
        hull_next_[i2] = hull_prev_[i1] = i0;
        hull_tri_[i0] = 0;
        hull_tri_[i1] = 1;
        hull_tri_[i2] = 2;
        hash_edge(i0);
        hash_edge(i1);
        hash_edge(i2);
        add_triangle(i0, i1, i2, kNone, kNone, kNone);

        for (const std::uint32_t i : ids) {
            if (i == i0 || i == i1 || i == i2) continue;
            const IPoint q = p_[i];
            // A hull vertex near q's angle, then back along the hull to an
            // edge that q sees (q strictly right of the ccw edge e -> next).
            std::uint32_t start = kNone;
            const std::uint32_t key = hash_key(dx(i), dy(i));
            for (std::uint32_t j = 0; j < hash_size_; ++j) {
                start = hash_[(key + j) % hash_size_];
                if (start != kNone && start != hull_next_[start]) break;
            }
            start = hull_prev_[start];
            std::uint32_t e = start;
            while (cross(p_[e], p_[hull_next_[e]], q) >= 0) {
                e = hull_next_[e];
                if (e == start) {
                    e = kNone;
                    break;
                }
            }
            if (e == kNone) continue;  // on the hull: left out

            std::uint32_t t = add_triangle(e, i, hull_next_[e], kNone, kNone, hull_tri_[e]);
            hull_tri_[i] = legalize(t + 2);
            hull_tri_[e] = t;
            std::uint32_t nx = hull_next_[e];
            while (cross(p_[nx], p_[hull_next_[nx]], q) < 0) {
                const std::uint32_t qn = hull_next_[nx];
                t = add_triangle(nx, i, qn, hull_tri_[i], kNone, hull_tri_[nx]);
                hull_tri_[i] = legalize(t + 2);
                hull_next_[nx] = nx;  // removed from the hull
                nx = qn;
            }
            if (e == start) {
                while (cross(p_[hull_prev_[e]], p_[e], q) < 0) {
                    const std::uint32_t qp = hull_prev_[e];
                    t = add_triangle(qp, i, e, kNone, hull_tri_[e], hull_tri_[qp]);
                    legalize(t + 2);
                    hull_tri_[qp] = t;
                    hull_next_[e] = e;
                    e = qp;
                }
            }
            hull_start_ = hull_prev_[i] = e;
            hull_next_[e] = hull_prev_[nx] = i;
            hull_next_[i] = nx;
            hash_edge(i);
            hash_edge(e);
        }
        return tri_;
    }

private:
    static constexpr std::uint32_t kNone = 0xFFFFFFFFU;

    [[nodiscard]] double dx(std::uint32_t i) const { return static_cast<double>(p_[i].x); }
    [[nodiscard]] double dy(std::uint32_t i) const { return static_cast<double>(p_[i].y); }

    [[nodiscard]] double circumradius2(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
        const double bx = dx(b) - dx(a), by = dy(b) - dy(a), ex = dx(c) - dx(a), ey = dy(c) - dy(a);
        const double bl = bx * bx + by * by, cl = ex * ex + ey * ey, d = 0.5 / (bx * ey - by * ex);
        const double x = (ey * bl - by * cl) * d, y = (bx * cl - ex * bl) * d;
        return x * x + y * y;
    }
    void center(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const double bx = dx(b) - dx(a), by = dy(b) - dy(a), ex = dx(c) - dx(a), ey = dy(c) - dy(a);
        const double bl = bx * bx + by * by, cl = ex * ex + ey * ey, d = 0.5 / (bx * ey - by * ex);
        cx_ = dx(a) + (ey * bl - by * cl) * d;
        cy_ = dy(a) + (bx * cl - ex * bl) * d;
    }
    // Only a heuristic for where to start looking: floating point is fine.
    [[nodiscard]] std::uint32_t hash_key(double x, double y) const {
        const double ddx = x - cx_, ddy = y - cy_;
        const double pp = ddx / (std::fabs(ddx) + std::fabs(ddy));
        const double a = (ddy > 0 ? 3 - pp : 1 + pp) / 4;  // pseudo-angle in [0, 1]
        return static_cast<std::uint32_t>(std::floor(a * hash_size_)) % hash_size_;
    }
    void hash_edge(std::uint32_t i) { hash_[hash_key(dx(i), dy(i))] = i; }

    void link(std::uint32_t a, std::uint32_t b) {
        half_[a] = b;
        if (b != kNone) half_[b] = a;
    }
    std::uint32_t add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t ha, std::uint32_t hb,
                               std::uint32_t hc) {
        const auto t = static_cast<std::uint32_t>(tri_.size());
        tri_.insert(tri_.end(), {a, b, c});
        half_.insert(half_.end(), {kNone, kNone, kNone});
        link(t, ha);
        link(t + 1, hb);
        link(t + 2, hc);
        return t;
    }

    // Flips edge a (and the edges that flips expose) until locally Delaunay.
    // Triangles here are (e, i, next): clockwise in this orientation-neutral
    // labelling, so in_circle takes them reversed.
    std::uint32_t legalize(std::uint32_t a) {
        std::uint32_t ar = 0;
        for (;;) {
            const std::uint32_t b = half_[a];
            const std::uint32_t a0 = a - a % 3;
            ar = a0 + (a + 2) % 3;
            if (b == kNone) {
                if (stack_.empty()) break;
                a = stack_.back();
                stack_.pop_back();
                continue;
            }
            const std::uint32_t b0 = b - b % 3;
            const std::uint32_t al = a0 + (a + 1) % 3;
            const std::uint32_t bl = b0 + (b + 2) % 3;
            const std::uint32_t p0 = tri_[ar], pr = tri_[a], pl = tri_[al], p1 = tri_[bl];
            if (illegal(p0, pr, pl, p1)) {
                tri_[a] = p1;
                tri_[b] = p0;
                const std::uint32_t hbl = half_[bl];
                if (hbl == kNone) {  // the flipped edge was on the hull: fix its triangle link
                    std::uint32_t e = hull_start_;
                    do {
                        if (hull_tri_[e] == bl) {
                            hull_tri_[e] = a;
                            break;
                        }
                        e = hull_prev_[e];
                    } while (e != hull_start_);
                }
                link(a, hbl);
                link(b, half_[ar]);
                link(ar, bl);
                stack_.push_back(b0 + (b + 1) % 3);
            } else {
                if (stack_.empty()) break;
                a = stack_.back();
                stack_.pop_back();
            }
        }
        return ar;
    }
    // p1 inside the circumcircle of triangle (p0, pr, pl), whichever way it turns.
    [[nodiscard]] bool illegal(std::uint32_t p0, std::uint32_t pr, std::uint32_t pl, std::uint32_t p1) const {
        const I64 o = cross(p_[p0], p_[pr], p_[pl]);
        return o > 0 ? in_circle(p_[p0], p_[pr], p_[pl], p_[p1]) : in_circle(p_[p0], p_[pl], p_[pr], p_[p1]);
    }

    const std::vector<IPoint>& p_;
    double cx_ = 0, cy_ = 0;
    std::uint32_t hash_size_ = 1;
    std::uint32_t hull_start_ = 0;
    std::vector<std::uint32_t> hull_prev_, hull_next_, hull_tri_, hash_, tri_, half_, stack_;
};

// Position along a Hilbert curve over a 2^order grid.
std::uint64_t hilbert(std::uint64_t x, std::uint64_t y, int order) {
    std::uint64_t d = 0;
    for (std::uint64_t s = std::uint64_t{1} << (order - 1); s > 0; s >>= 1U) {
        const std::uint64_t rx = (x & s) != 0 ? 1 : 0;
        const std::uint64_t ry = (y & s) != 0 ? 1 : 0;
        d += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - x;
                y = s - 1 - y;
            }
            std::swap(x, y);
        }
    }
    return d;
}

// Renumbers vertices by `order` (order[new] = old), drops vertices no edge
// uses when drop_unused, and sorts edges by (smaller, larger) new endpoint.
PlanarGraph spatially_ordered(const std::vector<IPoint>& pts, std::vector<std::pair<std::uint32_t, std::uint32_t>> edges) {
    const auto n = static_cast<std::uint32_t>(pts.size());
    std::vector<char> used(n, 0);
    for (const auto& [a, b] : edges) used[a] = used[b] = 1;
    std::vector<std::uint32_t> order;
    for (std::uint32_t i = 0; i < n; ++i) {
        if (used[i] != 0) order.push_back(i);
    }
    std::vector<std::uint64_t> key(n);
    for (std::uint32_t i = 0; i < n; ++i)
        key[i] = hilbert(static_cast<std::uint64_t>(pts[i].x), static_cast<std::uint64_t>(pts[i].y), 31);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    std::vector<std::uint32_t> renumber(n, 0);
    PlanarGraph g;
    for (std::uint32_t r = 0; r < order.size(); ++r) {
        renumber[order[r]] = r;
        g.vertices.push_back({static_cast<double>(pts[order[r]].x), static_cast<double>(pts[order[r]].y)});
    }
    for (auto& [a, b] : edges) {
        a = renumber[a];
        b = renumber[b];
        if (a > b) std::swap(a, b);
    }
    std::sort(edges.begin(), edges.end());
    g.edges.reserve(edges.size());
    for (const auto& [a, b] : edges) g.edges.push_back({VertexId(a), VertexId(b)});
    return g;
}

}  // namespace

PlanarGraph delaunay(std::size_t n, std::uint64_t seed) {
    Rng rng(seed);
    const auto side = static_cast<std::uint64_t>(4 * std::sqrt(static_cast<double>(n)) * 256) + 16;
    std::vector<IPoint> pts;
    pts.reserve(n);
    std::vector<std::uint64_t> seen;
    while (pts.size() < n) {
        // Draw, then drop duplicates; repeat for the shortfall.
        while (pts.size() < n) pts.push_back({static_cast<I64>(rng.below(side)), static_cast<I64>(rng.below(side))});
        std::sort(pts.begin(), pts.end(), [](IPoint a, IPoint b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
        pts.erase(std::unique(pts.begin(), pts.end(), [](IPoint a, IPoint b) { return a.x == b.x && a.y == b.y; }),
                  pts.end());
    }
    shuffle(pts, rng);
    const std::vector<std::uint32_t> tri = SweepHull(pts).run();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(tri.size());
    for (std::size_t t = 0; t < tri.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = tri[t + k], b = tri[t + (k + 1) % 3];
            if (a > b) std::swap(a, b);
            edges.emplace_back(a, b);
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return spatially_ordered(pts, std::move(edges));
}

PlanarGraph shuffled(const PlanarGraph& g, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<std::uint32_t> perm(g.vertices.size());
    std::iota(perm.begin(), perm.end(), 0U);
    shuffle(perm, rng);  // perm[old] = new
    PlanarGraph out;
    out.vertices.resize(g.vertices.size());
    for (std::size_t v = 0; v < g.vertices.size(); ++v) out.vertices[perm[v]] = g.vertices[v];
    out.edges = g.edges;
    for (GraphEdge& e : out.edges) {
        e.u = VertexId(perm[e.u.index()]);
        e.v = VertexId(perm[e.v.index()]);
        if ((rng.next() & 1U) != 0) std::swap(e.u, e.v);
    }
    shuffle(out.edges, rng);
    return out;
}

PlanarGraph grid(std::size_t w, std::size_t h) {
    PlanarGraph g;
    g.vertices.reserve(w * h);
    for (std::size_t y = 0; y < h; ++y) {
        for (std::size_t x = 0; x < w; ++x) g.vertices.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
    g.edges.reserve(2 * w * h);
    for (std::size_t y = 0; y < h; ++y) {
        for (std::size_t x = 0; x < w; ++x) {
            const auto v = static_cast<Index>(y * w + x);
            if (x + 1 < w) g.edges.push_back({VertexId(v), VertexId(v + 1)});
            if (y + 1 < h) g.edges.push_back({VertexId(v), VertexId(static_cast<Index>(v + w))});
        }
    }
    return g;
}

PlanarGraph star(std::size_t degree) {
    // Leaves walk the boundary of the square [-R, R]^2 counterclockwise
    // from (R, 0), with 8R >= degree points; each ray from the centre meets
    // the boundary once, so all directions differ.
    const auto r = static_cast<I64>((degree + 7) / 8);
    PlanarGraph g;
    g.vertices.push_back({0, 0});
    std::vector<IPoint> boundary;
    for (I64 y = 0; y < r; ++y) boundary.push_back({r, y});
    for (I64 x = r; x > -r; --x) boundary.push_back({x, r});
    for (I64 y = r; y > -r; --y) boundary.push_back({-r, y});
    for (I64 x = -r; x < r; ++x) boundary.push_back({x, -r});
    for (I64 y = -r; y < 0; ++y) boundary.push_back({r, y});
    for (std::size_t i = 0; i < degree; ++i) {
        const IPoint q = boundary[i * boundary.size() / degree];
        g.vertices.push_back({static_cast<double>(q.x), static_cast<double>(q.y)});
        g.edges.push_back({VertexId(0), VertexId(static_cast<Index>(i + 1))});
    }
    return g;
}

PlanarGraph nested_squares(std::size_t n) {
    PlanarGraph g;
    for (std::size_t i = 0; i < n; ++i) {
        const auto r = static_cast<double>(n - i);
        const auto b = static_cast<Index>(4 * i);
        g.vertices.insert(g.vertices.end(), {{-r, -r}, {r, -r}, {r, r}, {-r, r}});
        for (Index k = 0; k < 4; ++k) g.edges.push_back({VertexId(b + k), VertexId(b + (k + 1) % 4)});
    }
    return g;
}

PlanarGraph collinear_chain(std::size_t n) {
    PlanarGraph g;
    for (std::size_t i = 0; i < n; ++i) g.vertices.push_back({static_cast<double>(2 * i), static_cast<double>(i)});
    for (std::size_t i = 0; i + 1 < n; ++i)
        g.edges.push_back({VertexId(static_cast<Index>(i)), VertexId(static_cast<Index>(i + 1))});
    return g;
}

PlanarGraph forest(std::size_t w, std::uint64_t seed) {
    // Points jittered by at most 3 in cells of 16: grid edges cannot cross
    // (every cell stays a convex quadrilateral).
    Rng rng(seed);
    PlanarGraph g;
    for (std::size_t y = 0; y < w; ++y) {
        for (std::size_t x = 0; x < w; ++x) {
            const auto jx = static_cast<double>(rng.below(7)) - 3;
            const auto jy = static_cast<double>(rng.below(7)) - 3;
            g.vertices.push_back({16.0 * static_cast<double>(x) + jx, 16.0 * static_cast<double>(y) + jy});
        }
    }
    std::vector<Index> parent(w * w);
    std::iota(parent.begin(), parent.end(), 0U);
    auto root = [&](Index x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    auto maybe_join = [&](Index a, Index b) {
        if ((rng.next() & 1U) != 0) return;
        const Index ra = root(a);
        const Index rb = root(b);
        if (ra == rb) return;
        parent[ra] = rb;
        g.edges.push_back({VertexId(a), VertexId(b)});
    };
    for (std::size_t y = 0; y < w; ++y) {
        for (std::size_t x = 0; x < w; ++x) {
            const auto v = static_cast<Index>(y * w + x);
            if (x + 1 < w) maybe_join(v, v + 1);
            if (y + 1 < w) maybe_join(v, static_cast<Index>(v + w));
        }
    }
    return g;
}

}  // namespace dcel::bench
