// A one-line status on stderr while a command works on a large input:
// "dcel: faces: reading big.json (812 MiB)", then "building the DCEL", ...
// Shown only when stderr is a terminal and only once the command has run
// for a second (short runs print nothing), redrawn in place by a
// background thread, and erased before any message and at the end.
#pragma once

#include <cstdint>
#include <string>

namespace dcel::cli {

class StatusLine {
public:
    // From main, once the command is known; does nothing unless stderr is a terminal.
    static void start(const std::string& command);
    // The stage the command is in now.
    static void set(const std::string& stage);
    // Bytes done in the current stage (shown after it).
    static void progress(std::uint64_t bytes);
    // Stops the thread and erases the line (safe to call more than once).
    static void stop();
};

}  // namespace dcel::cli
