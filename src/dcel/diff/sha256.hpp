// SHA-256 (FIPS 180-4), for the HTML report's Content Security Policy: the
// page allows exactly its own script, named by the script's hash, so that
// nothing else (markup that escaping let through, were it ever to) can run.
#pragma once

#include <string>
#include <string_view>

namespace dcel::diff {

// The digest of the bytes in base64 (44 characters), as a CSP source wants it.
[[nodiscard]] std::string sha256_base64(std::string_view bytes);

}  // namespace dcel::diff
