// Text from a report as HTML: what an implementation printed (stdout,
// stderr), its command line and anything else a report holds is untrusted,
// so every character that means something to HTML becomes an entity, bytes
// that are not UTF-8 become U+FFFD, and controls and the invisible
// formatting characters (bidirectional overrides, zero-width spaces) are
// shown as \x1B-style escapes, so that what the page shows is what was
// printed, and nothing printed can add markup or look like other text.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace dcel::diff {

// The text escaped for element content or a quoted attribute value. In
// content, the escapes are marked up (<span class="esc">) so they stand out.
[[nodiscard]] std::string html_text(std::string_view text);
[[nodiscard]] std::string html_attribute(std::string_view text);

// Lines shown of one block, and characters of one line.
struct BlockLimits {
    std::size_t lines = 200;
    std::size_t line_chars = 1000;
};

// A <pre class="CLS"> of the text, each line cut after limits.line_chars
// characters and the block after limits.lines lines, each cut said in place.
[[nodiscard]] std::string html_block(std::string_view text, std::string_view cls = "out", BlockLimits limits = {});

}  // namespace dcel::diff
