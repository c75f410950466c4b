// JSON text with every spelling choice a reader must treat alike: the
// whitespace between tokens (none, spaces, newlines, tabs, CR LF), numbers
// (an id 3 as 3, 3.0, 3e0, 3E+00, 0.3e1 or 30e-1; a coordinate in its
// shortest form, with 17 digits, in scientific form, a zero with either
// sign), keys with \u escapes, and members a reader ignores. For the
// answer trials (answer_spellings.hpp); the choices come from Choices.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "dcel/ids.hpp"
#include "support/answer_spellings.hpp"

namespace dcel::test_support {

class AnswerText {
public:
    // Picks the whitespace, number and key styles for the whole text.
    explicit AnswerText(Choices& choices);

    void begin_object();
    void end_object();
    void key(std::string_view k);  // the next member's key (escaped when the style says so)
    void begin_array();
    void end_array();
    void id(Index v);                     // a non-negative integer, in one of its spellings
    void number(double x);                // any finite double, in a spelling that reads back to it (or -x for a zero)
    void literal(std::string_view json);  // a value written as given

    // Maybe (one time in four) a member the reader ignores, whose key is
    // none of `taken` (the keys with a meaning in this object) nor one the
    // object has already.
    void maybe_ignored_member(const std::vector<std::string_view>& taken);

    [[nodiscard]] std::string take() { return std::move(out_); }

private:
    void before_value();
    void space();

    Choices& choices_;
    std::string out_;
    struct Level {
        bool object = false;
        std::size_t count = 0;
        std::vector<std::string> keys;  // an object's keys so far (each may be given once)
    };
    std::vector<Level> levels_;
    bool after_key_ = false;
    std::size_t spacing_ = 0, ids_ = 0, doubles_ = 0, keys_ = 0;
    bool flip_zeros_ = false;
};

}  // namespace dcel::test_support
