// A string as a JSON string literal: quoted, with '"', '\\' and the control
// characters escaped (RFC 8259, section 7); well-formed UTF-8 passes through
// unchanged, and each byte that is not part of it is written as U+FFFD, so
// the literal is always valid JSON text whatever bytes it was given.
#pragma once

#include <string>
#include <string_view>

namespace dcel::io {

[[nodiscard]] std::string json_string(std::string_view s);

}  // namespace dcel::io
