// The words a failure is grouped by: the error line of a program's stderr,
// past the frames, excerpts and banners of real interpreters' traces, and a
// message's class with its numbers masked.
#include <gtest/gtest.h>

#include "dcel/diff/failure_class.hpp"

namespace dcel::diff {
namespace {

TEST(FailureClass, TheErrorLineOfAPythonTraceback) {
    EXPECT_EQ(meaningful_line("Traceback (most recent call last):\n  File \"impl.py\", line 9, in <module>\n"
                              "    main()\n  File \"impl.py\", line 5, in main\n    raise ValueError(\"vertex 3\")\n"
                              "ValueError: vertex 3 is isolated\n"),
              "ValueError: vertex 3 is isolated");
}

TEST(FailureClass, TheErrorLineOfANodeTraceNotItsBanner) {
    EXPECT_EQ(meaningful_line("/work/impl.mjs:10\n    throw new Error(\"no faces\");\n    ^\n\n"
                              "Error: no faces for 5 edges\n    at answer (/work/impl.mjs:10:11)\n"
                              "    at main (/work/impl.mjs:20:3)\n\nNode.js v20.20.2\n"),
              "Error: no faces for 5 edges");
}

TEST(FailureClass, SanitizerFramesAndBlankLinesAreSkipped) {
    EXPECT_EQ(meaningful_line("==12==ERROR: AddressSanitizer: heap-buffer-overflow\n    #0 0x55 in walk dcel.c:3\n"
                              "    #1 0x56 in main dcel.c:9\n\n"),
              "==12==ERROR: AddressSanitizer: heap-buffer-overflow");
    EXPECT_EQ(meaningful_line(""), "");
    EXPECT_EQ(meaningful_line("\n\n  \n"), "");
}

TEST(FailureClass, NumbersAreMaskedWordsAreNot) {
    EXPECT_EQ(message_class("vertex 17 at (-1.5e-300, 3) is too close to edge 4"),
              "vertex # at (#, #) is too close to edge #");
    EXPECT_EQ(message_class("node 3/7 at 0x7ffd12 in  ST_AddEdge2"), "node # at # in ST_AddEdge2");
    EXPECT_EQ(message_class("vertex 0 at (-2265571/1073741824, 7)"), "vertex # at (#, #)");
}

}  // namespace
}  // namespace dcel::diff
