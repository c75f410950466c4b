// apply(): exact transforms of a whole graph. Rotation and mirroring only
// negate and swap coordinates, so they are always exact; translation and
// scaling are checked coordinate by coordinate and refused when one rounds.
#include <cmath>
#include <cstdlib>

#include "dcel/gen/generate.hpp"

namespace dcel::gen {
namespace {

// x + a without rounding? (Knuth's TwoSum: the tail is zero exactly then.)
bool exact_sum(double x, double a, double& out) {
    const double s = x + a;
    const double av = s - x;
    const double xv = s - av;
    const double tail = (x - xv) + (a - av);
    out = s;
    return std::isfinite(s) && tail == 0;
}

}  // namespace

std::optional<PlanarGraph> apply(const PlanarGraph& g, Transform t, std::int64_t amount) {
    PlanarGraph out = g;
    switch (t) {
        case Transform::Translate: {
            if (std::llabs(amount) > (std::int64_t{1} << 53)) return std::nullopt;  // amount itself must be exact
            const auto a = static_cast<double>(amount);
            for (Point& p : out.vertices) {
                if (!exact_sum(p.x, a, p.x) || !exact_sum(p.y, -a, p.y)) return std::nullopt;
            }
            return out;
        }
        case Transform::Rotate90:
            for (Point& p : out.vertices) p = {-p.y, p.x};
            return out;
        case Transform::Mirror:
            for (Point& p : out.vertices) p.x = -p.x;
            return out;
        case Transform::ScalePow2: {
            if (std::llabs(amount) > 4096) return std::nullopt;
            const auto k = static_cast<int>(amount);
            for (Point& p : out.vertices) {
                const Point q{std::ldexp(p.x, k), std::ldexp(p.y, k)};
                // Exact exactly when scaling back recovers the point (an
                // underflow loses low bits, an overflow gives infinity).
                if (!std::isfinite(q.x) || !std::isfinite(q.y) || std::ldexp(q.x, -k) != p.x || std::ldexp(q.y, -k) != p.y) {
                    return std::nullopt;
                }
                p = q;
            }
            return out;
        }
    }
    return std::nullopt;
}

}  // namespace dcel::gen
