// A string as a JSON string literal: quoted, with '"', '\\' and the control
// characters escaped (RFC 8259, section 7); other bytes, UTF-8 included,
// pass through unchanged.
#pragma once

#include <string>
#include <string_view>

namespace dcel::io {

[[nodiscard]] std::string json_string(std::string_view s);

}  // namespace dcel::io
