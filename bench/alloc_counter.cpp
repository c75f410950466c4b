#include "alloc_counter.hpp"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::size_t g_live = 0;
std::size_t g_peak = 0;
std::size_t g_base = 0;

void* counted_alloc(std::size_t n) {
    void* p = std::malloc(n == 0 ? 1 : n);
    if (p == nullptr) throw std::bad_alloc();
    g_live += malloc_usable_size(p);
    if (g_live > g_peak) g_peak = g_live;
    return p;
}

void counted_free(void* p) {
    if (p == nullptr) return;
    g_live -= malloc_usable_size(p);
    std::free(p);
}

}  // namespace

// The bench is single-threaded, so plain counters suffice.
void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return counted_alloc(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return counted_alloc(n);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }

#ifdef DCEL_BENCH_HAVE_GMP
#include <gmp.h>
namespace {
void* gmp_alloc(std::size_t n) { return counted_alloc(n); }
void* gmp_realloc(void* p, std::size_t, std::size_t n) {
    if (p != nullptr) g_live -= malloc_usable_size(p);
    void* q = std::realloc(p, n);
    if (q == nullptr) throw std::bad_alloc();
    g_live += malloc_usable_size(q);
    if (g_live > g_peak) g_peak = g_live;
    return q;
}
void gmp_free(void* p, std::size_t) { counted_free(p); }
}  // namespace
#endif

namespace dcel::bench {

void reset_peak() {
    g_base = g_live;
    g_peak = g_live;
}

std::size_t peak_above_reset() { return g_peak - g_base; }

void count_gmp_allocations() {
#ifdef DCEL_BENCH_HAVE_GMP
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
#endif
}

}  // namespace dcel::bench
