// What a failure *is*, in words a group can be keyed by: the class of an
// outcome (a wrong answer, a crash by signal N, an exit with status N and
// its error line, a timeout, an unreadable answer, a refusal and its
// message), with the numbers of messages masked, so that "node 17 is too
// close to edge 3" and "node 4 is too close to edge 12" are one class.
#pragma once

#include <string>
#include <string_view>

namespace dcel::diff {

// The line of a program's stderr that says what went wrong: from the end,
// past blank lines, stack-trace frames ("  at f (file.js:3:9)", "  File
// \"x.py\", line 3", "#3 0x... in f"), source excerpts and carets, and an
// interpreter's banner ("Node.js v20.11.0"); "" when nothing is left.
[[nodiscard]] std::string meaningful_line(std::string_view stderr_text);

// The text with every number (and hexadecimal address) written as "#", and
// runs of blanks as one space: the class of a message.
[[nodiscard]] std::string message_class(std::string_view text);

}  // namespace dcel::diff
