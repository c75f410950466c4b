// One line of `dcel_bench --json`: a flat object of named fields, written
// with the library's JsonWriter (so a name with a quote in it is escaped and
// every number is valid JSON) and printed with its newline.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "dcel/io/json_writer.hpp"

namespace dcel::bench {

class JsonRow {
public:
    JsonRow() { writer_.raw('{'); }

    JsonRow& text(std::string_view key, std::string_view value) {
        field(key);
        writer_.string(value);
        return *this;
    }
    JsonRow& count(std::string_view key, std::uint64_t n) {
        field(key);
        writer_.count(n);
        return *this;
    }
    // v rounded to `decimals` places (10.0 / 10 is the double nearest the
    // decimal, so it prints as written); null when v is not finite.
    JsonRow& number(std::string_view key, double v, int decimals) {
        field(key);
        const double scale = std::pow(10.0, decimals);
        if (!writer_.number(std::round(v * scale) / scale)) writer_.raw("null");
        return *this;
    }
    JsonRow& null(std::string_view key) {
        field(key);
        writer_.raw("null");
        return *this;
    }
    void print() {
        writer_.raw("}\n");
        writer_.flush();
        std::fputs(text_.c_str(), stdout);
    }

private:
    void field(std::string_view key) {
        if (!first_) writer_.raw(", ");
        first_ = false;
        writer_.string(key);
        writer_.raw(": ");
    }

    std::string text_;
    io::JsonWriter writer_{text_};
    bool first_ = true;
};

}  // namespace dcel::bench
