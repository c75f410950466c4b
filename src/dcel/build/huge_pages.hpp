// Reserving the build's large arrays on transparent huge pages.
//
// A build touches about 200 bytes of fresh memory per edge; with 4 KiB
// pages, the page faults and the kernel's zeroing of them were 10% to 17%
// of the build's time (perf, nested squares and grids). Where the kernel
// gives huge pages only on request (transparent_hugepage = madvise, the
// Debian default), asking for them on arrays of several MiB cuts the number
// of faults by 512. A hint only: nothing depends on it being honoured.
#pragma once

#include <cstddef>
#include <vector>

namespace dcel::detail {

// Hints that [data, data + bytes) be backed by huge pages: the 2 MiB-aligned
// part of it, on Linux; nothing elsewhere.
void advise_huge_pages(void* data, std::size_t bytes) noexcept;

// v.reserve(n), with the hint given before any page of it is touched.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
    v.reserve(n);
    advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

// v.assign(n, value), on memory hinted as reserve_huge does.
template <class T>
void assign_huge(std::vector<T>& v, std::size_t n, const T& value = T{}) {
    reserve_huge(v, n);
    v.assign(n, value);
}

}  // namespace dcel::detail
