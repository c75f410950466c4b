#include "dcel/contracts.hpp"

#include <cstdio>
#include <cstdlib>

namespace dcel::detail {

// The only output of the library outside io/: a broken contract is a bug in
// the calling code, and the process stops here (see contracts.hpp).
void contract_failed(const char* kind, const char* condition, const char* file, int line) noexcept {
    std::fprintf(stderr, "dcel: %s failed at %s:%d: %s\n", kind, file, line, condition);
    std::fflush(stderr);
    std::abort();
}

}  // namespace dcel::detail
