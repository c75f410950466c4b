#include "dcel/diff/implementation.hpp"

#include <string_view>
#include <utility>

namespace dcel::diff {
namespace {

class CommandImplementation : public Implementation {
public:
    CommandImplementation(std::string command, bool stream, const ProcessLimits& limits)
        : command_(std::move(command)), stream_(stream), limits_(limits) {}

    ProcessResult run(const std::string& text) override { return run(text, limits_.timeout); }
    ProcessResult run(const std::string& text, std::chrono::milliseconds timeout) override {
        if (!stream_) {
            ProcessLimits limits = limits_;
            limits.timeout = timeout;
            return run_command(command_, text, limits);
        }
        if (!process_) process_ = std::make_unique<StreamProcess>(command_ + " --stream", limits_);
        StreamProcess::Reply reply = process_->exchange(std::string_view(text).substr(0, text.size() - 1), timeout);
        if (!reply.answered) return std::move(reply.failure);
        ProcessResult r;
        r.out = std::move(reply.line);
        return r;
    }
    void restart() override {
        if (process_) process_->stop();
    }
    [[nodiscard]] std::size_t starts() const override { return process_ ? process_->starts() : 0; }

private:
    std::string command_;
    bool stream_;
    ProcessLimits limits_;
    std::unique_ptr<StreamProcess> process_;
};

}  // namespace

ImplementationFactory command_implementation(std::string command, bool stream) {
    return [command = std::move(command), stream](const ProcessLimits& limits) -> std::unique_ptr<Implementation> {
        return std::make_unique<CommandImplementation>(command, stream, limits);
    };
}

}  // namespace dcel::diff
