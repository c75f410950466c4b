// JsonWriter: the one JSON writer of the library and the CLI. Writes JSON
// text through a fixed buffer, so that the writers' loops do no per-token
// capacity checks, either onto a std::string or, a buffer at a time, into a
// TextSink (text_sink.hpp), so that an output of hundreds of megabytes can go
// to a file or a pipe without being held whole; numbers in their shortest
// round-trip form.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dcel/ids.hpp"
#include "dcel/io/json_string.hpp"
#include "dcel/io/text_sink.hpp"

namespace dcel::io {

// Call flush() at the end. The destination gets the buffer whenever it
// fills (16 KiB) and at flush(); a raw() text longer than the buffer goes to
// it whole, so no piece is larger than the buffer or the largest raw() text.
class JsonWriter {
public:
    // Appends to `out`.
    // buf_ is left uninitialized: bytes up to used_ are written before they are read.
    // cppcheck-suppress uninitMemberVar
    explicit JsonWriter(std::string& out) : sink_([&out](std::string_view text) { out.append(text); }) {}
    // Hands the text to `sink`, which may throw (a failed write): the
    // exception reaches the writer's caller.
    // cppcheck-suppress uninitMemberVar
    explicit JsonWriter(TextSink sink) : sink_(std::move(sink)) {}
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
                sink_(text);
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
        if (used_ == 0) return;  // a sink is never handed an empty piece
        const std::size_t n = used_;
        used_ = 0;  // first: when the sink throws, what it was handed is not handed again
        sink_(std::string_view(buf_, n));
    }

    // ---- Scopes, for documents written member by member (reports): the
    // writer puts the commas, and with Layout::Lines a newline and two
    // spaces per level before each member or element.
    //   w.begin_object(Layout::Lines); w.key("id"); w.count(1);
    //   w.key("cases"); w.begin_array(); w.item(); w.count(4); w.end_array();
    //   w.end_object();
    // Each value inside a scope comes after key() (objects) or item()
    // (arrays); begin_object and begin_array are values too.
    enum class Layout : std::uint8_t { Inline, Lines };
    void begin_object(Layout layout = Layout::Inline) { open('{', layout); }
    void end_object() { close('}'); }
    void begin_array(Layout layout = Layout::Inline) { open('[', layout); }
    void end_array() { close(']'); }
    void key(std::string_view k) {
        separate();
        string(k);
        raw(": ");
    }
    void item() { separate(); }
    void boolean(bool b) { raw(b ? std::string_view("true") : std::string_view("false")); }
    void null() { raw("null"); }

private:
    struct Scope {
        Layout layout;
        bool empty = true;
    };
    void open(char bracket, Layout layout) {
        raw(bracket);
        scopes_.push_back({layout});
    }
    void close(char bracket) {
        const Scope s = scopes_.back();
        scopes_.pop_back();
        if (s.layout == Layout::Lines && !s.empty) newline();
        raw(bracket);
    }
    void separate() {
        Scope& s = scopes_.back();
        if (!s.empty) raw(s.layout == Layout::Lines ? std::string_view(",") : std::string_view(", "));
        if (s.layout == Layout::Lines) newline();
        s.empty = false;
    }
    void newline() {
        raw('\n');
        for (std::size_t i = 0; i < scopes_.size(); ++i) raw("  ");
    }
    std::vector<Scope> scopes_;

    static constexpr std::size_t kSize = std::size_t{1} << 14;
    static constexpr std::size_t kNumberRoom = 32;  // "-2.2250738585072014e-308" is 24
    void room(std::size_t n) {
        if (kSize - used_ < n) flush();
    }

    TextSink sink_;
    std::size_t used_ = 0;
    char buf_[kSize];
};

// Throws InvalidInput(BadCoordinate, "<path>: <v> cannot be written as JSON ...").
[[noreturn]] void fail_not_finite(const std::string& path, double v);

}  // namespace dcel::io
