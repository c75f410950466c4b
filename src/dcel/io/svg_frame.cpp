#include "dcel/io/svg_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

namespace dcel::io::svg {
namespace {

struct Bounds {
    double pre = 1;  // a quarter when the full spans would overflow
    double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
    [[nodiscard]] double dx() const { return max_x - min_x; }
    [[nodiscard]] double dy() const { return max_y - min_y; }
};

Bounds bounds(const std::vector<Point>& points) {
    Bounds b;
    for (const double pre : {1.0, 0.25}) {
        b.pre = pre;
        b.min_x = b.max_x = points[0].x * pre;
        b.min_y = b.max_y = points[0].y * pre;
        for (const Point p : points) {
            b.min_x = std::min(b.min_x, p.x * pre);
            b.max_x = std::max(b.max_x, p.x * pre);
            b.min_y = std::min(b.min_y, p.y * pre);
            b.max_y = std::max(b.max_y, p.y * pre);
        }
        if (std::isfinite(b.dx()) && std::isfinite(b.dy())) break;
    }
    return b;
}

// The monotone stretch of one axis: each distinct value (-0 and 0 are one)
// to [0, 1]: each gap its share of the whole span, but at least the share
// of an even spacing; so at least half of that once the shares are scaled
// back to sum 1.
std::map<double, double> stretch(const std::vector<double>& values) {
    std::map<double, double> at;
    for (const double v : values) at.emplace(v, 0.0);
    if (at.size() < 2) return at;
    std::vector<double> gaps;
    double previous = at.begin()->first;
    double total = 0;
    for (auto it = std::next(at.begin()); it != at.end(); ++it) {
        gaps.push_back(it->first * 0.5 - previous * 0.5);  // halves: no overflow near DBL_MAX
        total += gaps.back();
        previous = it->first;
    }
    const double floor = 1.0 / static_cast<double>(gaps.size());
    double sum = 0;
    for (double& g : gaps) {
        g = std::max(total > 0 ? g / total : 0.0, floor);
        sum += g;
    }
    double position = 0;
    std::size_t i = 0;
    for (auto& [value, unit] : at) {
        unit = position / sum;
        if (i < gaps.size()) position += gaps[i++];
    }
    return at;
}

std::string range(const char* axis, double lo, double hi, double pre) {
    return std::string(axis) + " from " + exact_number(lo / pre) + " to " + exact_number(hi / pre);
}

}  // namespace

Frame::Frame(const std::vector<Point>& points, FrameKind kind) : kind_(kind) {
    if (points.empty()) return;
    const Bounds b = bounds(points);
    min_x_ = b.min_x / b.pre;
    max_x_ = b.max_x / b.pre;
    min_y_ = b.min_y / b.pre;
    max_y_ = b.max_y / b.pre;
    if (kind == FrameKind::Exact) {
        span_ = std::max(b.dx(), b.dy());
        if (!(span_ > 0)) span_ = 1;  // one point, or all at one point
        w_ = b.dx() / span_;          // the ratio first: 640 * 1e308 overflows
        h_ = b.dy() / span_;
        for (const Point p : points) unit_.push_back({(p.x * b.pre - b.min_x) / span_, (p.y * b.pre - b.min_y) / span_});
        span_ /= b.pre;
        return;
    }
    std::vector<double> xs, ys;
    for (const Point p : points) {
        xs.push_back(p.x);
        ys.push_back(p.y);
    }
    const auto sx = stretch(xs), sy = stretch(ys);
    // The aspect from the numbers of distinct values (the true one means
    // little once stretched), kept between 1:2 and 2:1; an axis with one
    // value is flat.
    const double ratio = sy.size() > 1
                             ? std::clamp(static_cast<double>(sx.size() - 1) / static_cast<double>(sy.size() - 1), 0.5, 2.0)
                             : 2.0;
    w_ = sx.size() < 2 ? 0 : ratio >= 1 ? 1 : ratio;
    h_ = sy.size() < 2 ? 0 : ratio >= 1 ? 1 / ratio : 1;
    if (w_ == 0 && h_ == 0) w_ = 1;
    for (const Point p : points) unit_.push_back({sx.at(p.x) * w_, sy.at(p.y) * h_});
}

Xy Frame::size(double longest) const { return {w_ * longest, h_ * longest}; }

Xy Frame::at(std::size_t i) const {
    const double s = w_ > 0 ? box_.w / w_ : h_ > 0 ? box_.h / h_ : 0;
    return {box_.x + unit_[i].x * s, box_.y + box_.h - unit_[i].y * s};
}

std::vector<std::string> Frame::note() const {
    const std::string ranges = range("x", min_x_, max_x_, 1) + ", " + range("y", min_y_, max_y_, 1);
    if (kind_ == FrameKind::Normalised) {
        return {"normalised frame: each axis stretched on its own, keeping the order of the x's and of the y's",
                "(lengths and angles are not to scale); " + ranges};
    }
    const double longest = std::max(box_.w, box_.h);
    if (!(longest > 0)) return {"exact frame; " + ranges};
    char scale[32];
    std::snprintf(scale, sizeof scale, "%.3g", span_ / longest * 100);
    return {"exact frame: one scale on both axes, 100 px = " + std::string(scale) + " units", ranges};
}

FrameKind choose_frame(const std::vector<Point>& points, double longest, double min_px) {
    if (points.size() < 2) return FrameKind::Exact;
    Frame exact(points, FrameKind::Exact);
    const Xy size = exact.size(longest);
    exact.place({0, 0, size.x, size.y});
    std::unordered_map<long long, std::vector<std::size_t>> grid;
    const auto key = [](long long cx, long long cy) { return (cx << 32) ^ (cy & 0xffffffffLL); };
    std::vector<Xy> at;
    for (std::size_t i = 0; i < points.size(); ++i) {
        at.push_back(exact.at(i));
        grid[key(static_cast<long long>(at[i].x / min_px), static_cast<long long>(at[i].y / min_px))].push_back(i);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto cx = static_cast<long long>(at[i].x / min_px), cy = static_cast<long long>(at[i].y / min_px);
        for (long long x = cx - 1; x <= cx + 1; ++x) {
            for (long long y = cy - 1; y <= cy + 1; ++y) {
                const auto it = grid.find(key(x, y));
                if (it == grid.end()) continue;
                for (const std::size_t j : it->second) {
                    if (j != i && std::hypot(at[i].x - at[j].x, at[i].y - at[j].y) < min_px) return FrameKind::Normalised;
                }
            }
        }
    }
    return FrameKind::Exact;
}

}  // namespace dcel::io::svg
