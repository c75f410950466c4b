#include "dcel/diff/clock.hpp"

#include <ctime>

namespace dcel::diff {
namespace {

class SystemClock : public Clock {
public:
    [[nodiscard]] time_point now() const override { return std::chrono::steady_clock::now(); }
    [[nodiscard]] std::chrono::milliseconds cpu() const override {
        return std::chrono::milliseconds(
            static_cast<std::int64_t>(static_cast<double>(std::clock()) * 1000.0 / CLOCKS_PER_SEC));
    }
};

}  // namespace

const Clock& system_clock() {
    static const SystemClock clock;
    return clock;
}

}  // namespace dcel::diff
