#include "dcel/diff/speed.hpp"

#include <algorithm>

namespace dcel::diff {

void SpeedModel::record(std::size_t size, std::chrono::milliseconds took) {
    auto& slowest = slowest_[std::max(size, kMinScaleSize)];
    slowest = std::max(slowest, took);
    fastest_ = std::min(fastest_, took);
}

std::chrono::milliseconds SpeedModel::predicted(std::size_t size) const {
    if (slowest_.empty()) return std::chrono::milliseconds(0);
    const auto fixed = static_cast<double>(fastest_.count());
    double worst = 0;
    for (const auto& [n, t] : slowest_) {
        const double ratio = std::max(1.0, static_cast<double>(size) / static_cast<double>(n));
        worst = std::max(worst, (static_cast<double>(t.count()) - fixed) * ratio * ratio);
    }
    return std::chrono::milliseconds(static_cast<std::int64_t>(std::min(fixed + worst, 1e12)));
}

std::chrono::milliseconds SpeedModel::limit(std::size_t size, std::chrono::milliseconds base) const {
    const std::chrono::milliseconds scaled(std::min<std::int64_t>(predicted(size).count(), INT64_MAX / kSlack) * kSlack);
    return std::clamp(scaled, base, base * kMaxFactor);
}

}  // namespace dcel::diff
