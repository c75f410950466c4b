// The GoogleTest and RapidCheck helpers moved to dcel/testing/check_testing.hpp
// (the testing layer sits above dcel::gen, which they draw graphs from). This
// path stays so that existing tests keep compiling.
#pragma once

#include "dcel/testing/check_testing.hpp"  // layers: allow (compatibility path)
