#include "status_line.hpp"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

#include "dcel/format.hpp"

namespace dcel::cli {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kQuiet{1000};  // nothing shown for runs shorter than this
constexpr std::chrono::milliseconds kRedraw{200};

// One status line per process. NOLINTBEGIN(cppcoreguidelines-avoid-non-const-global-variables)
struct State {
    std::mutex mutex;
    std::condition_variable wake;
    std::thread thread;
    bool running = false;
    bool stopping = false;
    bool drawn = false;
    std::string command;
    std::string stage;
    std::uint64_t bytes = 0;
    Clock::time_point started;
};
State state;
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables)

std::string human_bytes(std::uint64_t b) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
    int k = 0;
    auto v = static_cast<double>(b);
    while (v >= 1024 && k < 4) {
        v /= 1024;
        ++k;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, k == 0 ? "%.0f %s" : "%.1f %s", v, units[k]);
    return buf;
}

void draw_locked(const std::string& text) {
    std::fprintf(stderr, "\r\x1b[K%s", text.c_str());
    std::fflush(stderr);
    state.drawn = true;
}

void run() {
    std::unique_lock lock(state.mutex);
    std::string shown;
    while (!state.stopping) {
        state.wake.wait_for(lock, kRedraw);
        if (state.stopping || state.stage.empty() || Clock::now() - state.started < kQuiet) continue;
        std::string text = "dcel: " + state.command + ": " + state.stage;
        if (state.bytes != 0) text += " (" + human_bytes(state.bytes) + ")";
        if (text != shown) {
            draw_locked(text);
            shown = text;
        }
    }
}

}  // namespace

void StatusLine::start(const std::string& command) {
    if (::isatty(STDERR_FILENO) == 0) return;
    const std::lock_guard lock(state.mutex);
    if (state.running) return;
    state.command = escape_for_message(command);
    state.started = Clock::now();
    state.running = true;
    state.stopping = false;
    state.thread = std::thread(run);
}

void StatusLine::set(const std::string& stage) {
    const std::lock_guard lock(state.mutex);
    if (!state.running) return;
    state.stage = stage;
    state.bytes = 0;
}

void StatusLine::progress(std::uint64_t bytes) {
    const std::lock_guard lock(state.mutex);
    if (state.running) state.bytes = bytes;
}

void StatusLine::stop() {
    {
        const std::lock_guard lock(state.mutex);
        if (!state.running) return;
        state.stopping = true;
    }
    state.wake.notify_all();
    state.thread.join();
    const std::lock_guard lock(state.mutex);
    if (state.drawn) std::fprintf(stderr, "\r\x1b[K");
    std::fflush(stderr);
    state.running = false;
    state.drawn = false;
}

}  // namespace dcel::cli
