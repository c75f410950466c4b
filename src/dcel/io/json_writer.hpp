// JsonWriter: the one JSON writer of the library and the CLI. Appends JSON
// text to a std::string through a fixed buffer, so that the writers' loops do
// no per-token capacity checks; numbers in their shortest round-trip form.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "dcel/ids.hpp"
#include "dcel/io/json_string.hpp"

namespace dcel::io {

// Call flush() at the end.
class JsonWriter {
public:
    // buf_ is left uninitialized: bytes up to used_ are written before they are read.
    // cppcheck-suppress uninitMemberVar
    explicit JsonWriter(std::string& out) : out_(out) {}
    JsonWriter(const JsonWriter&) = delete;
    JsonWriter& operator=(const JsonWriter&) = delete;
    ~JsonWriter() = default;

    // A string literal, written as is.
    template <std::size_t N>
    void raw(const char (&text)[N]) {
        raw(std::string_view(text, N - 1));
    }
    void raw(std::string_view text) {
        if (text.size() > kSize - used_) {
            flush();
            if (text.size() > kSize) {
                out_.append(text);
                return;
            }
        }
        std::memcpy(buf_ + used_, text.data(), text.size());
        used_ += text.size();
    }
    void raw(char c) {
        room(1);
        buf_[used_++] = c;
    }
    // v in its shortest round-trip form (std::to_chars; -0.0 is "-0").
    // Returns false, writing nothing, when v is NaN or infinite.
    [[nodiscard]] bool number(double v) {
        if (!std::isfinite(v)) return false;
        room(kNumberRoom);
        used_ = static_cast<std::size_t>(std::to_chars(buf_ + used_, buf_ + used_ + kNumberRoom, v).ptr - buf_);
        return true;
    }
    // A JSON string literal: quoted, escaped (json_string.hpp).
    void string(std::string_view text) { raw(json_string(text)); }
    // An unsigned count or offset.
    void count(std::uint64_t n) {
        room(kNumberRoom);
        used_ = static_cast<std::size_t>(std::to_chars(buf_ + used_, buf_ + used_ + kNumberRoom, n).ptr - buf_);
    }
    // An id; kNoIndex (the null id) is written as null.
    void index(Index i) {
        if (i == kNoIndex) {
            raw("null");
            return;
        }
        room(kNumberRoom);
        used_ = static_cast<std::size_t>(std::to_chars(buf_ + used_, buf_ + used_ + kNumberRoom, i).ptr - buf_);
    }
    void flush() {
        out_.append(buf_, used_);
        used_ = 0;
    }

private:
    static constexpr std::size_t kSize = std::size_t{1} << 14;
    static constexpr std::size_t kNumberRoom = 32;  // "-2.2250738585072014e-308" is 24
    void room(std::size_t n) {
        if (kSize - used_ < n) flush();
    }

    std::string& out_;
    std::size_t used_ = 0;
    char buf_[kSize];
};

// Throws InvalidInput(BadCoordinate, "<path>: <v> cannot be written as JSON ...").
[[noreturn]] void fail_not_finite(const std::string& path, double v);

}  // namespace dcel::io
