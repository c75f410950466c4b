// Edits to a DcelDump read as text commands, for the check harness: the
// corruptions (set one field, rewire next, move a vertex, add or drop
// records) and the renumberings that must leave a valid dump valid. The
// command list is in fuzz/check.cpp.
#pragma once

#include <string>

#include "dcel/dump.hpp"
#include "support/token_reader.hpp"

namespace dcel::fuzz {

// Reads one command and applies it. Returns it as applied (" next 3 5"), or
// "" when the next token is not a known command (it is consumed, with its
// numbers, so the caller always makes progress).
std::string apply_edit(DcelDump& d, TokenReader& in);

}  // namespace dcel::fuzz
