// Peak heap use of a piece of code: the bench binary replaces the global
// operator new and delete (alloc_counter.cpp) to keep a running total of
// live bytes (malloc_usable_size of each block) and its high-water mark.
// GMP's allocations (CGAL's exact numbers) are routed through the same
// counter. What is measured is heap only, above what was live at reset.
#pragma once

#include <cstddef>

namespace dcel::bench {

// Starts a measurement: the peak becomes the current live total.
void reset_peak();
// Bytes above the live total at reset_peak(), at the highest point since.
[[nodiscard]] std::size_t peak_above_reset();
// Routes GMP's allocation functions through the counter (no-op without GMP).
void count_gmp_allocations();

}  // namespace dcel::bench
