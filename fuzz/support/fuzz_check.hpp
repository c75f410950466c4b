// FUZZ_CHECK(cond, message...): the harnesses' one way to report a failed
// property. It prints the condition and a message built lazily with <<, then
// aborts, which libFuzzer records as a crash and a replay run as a failure.
// (An uncaught exception would be reported too, but with no explanation.)
#pragma once

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace dcel::fuzz {

[[noreturn]] inline void check_failed(const char* file, int line, const char* condition, const std::string& message) {
    std::fprintf(stderr, "%s:%d: FUZZ_CHECK(%s) failed\n%s\n", file, line, condition, message.c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace dcel::fuzz

#define FUZZ_CHECK(cond, ...)                                                                 \
    do {                                                                                      \
        if (!(cond)) {                                                                        \
            std::ostringstream fuzz_check_message_;                                           \
            fuzz_check_message_ << __VA_ARGS__;                                               \
            ::dcel::fuzz::check_failed(__FILE__, __LINE__, #cond, fuzz_check_message_.str()); \
        }                                                                                     \
    } while (false)
