// Contracts: DCEL_EXPECTS states a precondition of a public function (a valid
// id, a non-null half-edge), DCEL_ASSERT an internal invariant. Both are
// programmer errors, never user input: input is checked by build(), the
// readers and the edits, which throw InvalidInput or TopologyError instead.
//
// Levels (DCEL_CONTRACT_LEVEL, set for the whole build by CMake so that every
// translation unit sees the same inline accessors):
//   0  off: nothing is evaluated (release builds)
//   1  DCEL_EXPECTS only
//   2  both (debug, sanitizer and fuzz builds)
// A failed contract prints one line naming the condition and the place, then
// aborts, so a debugger or a sanitizer stops at the call that broke it.
#pragma once

#ifndef DCEL_CONTRACT_LEVEL
#ifdef NDEBUG
#define DCEL_CONTRACT_LEVEL 0
#else
#define DCEL_CONTRACT_LEVEL 2
#endif
#endif

namespace dcel::detail {
[[noreturn]] void contract_failed(const char* kind, const char* condition, const char* file, int line) noexcept;
}  // namespace dcel::detail

// Macros, not functions: the message names the caller's condition, file and
// line, and the condition is not evaluated at all when the level is off.
// NOLINTBEGIN(cppcoreguidelines-macro-usage)
#if DCEL_CONTRACT_LEVEL >= 1
#define DCEL_EXPECTS(condition) \
    ((condition) ? static_cast<void>(0) : ::dcel::detail::contract_failed("precondition", #condition, __FILE__, __LINE__))
#else
#define DCEL_EXPECTS(condition) static_cast<void>(0)
#endif

#if DCEL_CONTRACT_LEVEL >= 2
#define DCEL_ASSERT(condition) \
    ((condition) ? static_cast<void>(0) : ::dcel::detail::contract_failed("assertion", #condition, __FILE__, __LINE__))
#else
#define DCEL_ASSERT(condition) static_cast<void>(0)
#endif
// NOLINTEND(cppcoreguidelines-macro-usage)
