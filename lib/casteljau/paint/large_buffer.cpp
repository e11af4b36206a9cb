#include "casteljau/paint/large_buffer.h"

#include <cstdlib>
#include <new>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace casteljau {

void* allocate_large(std::size_t bytes) {
    if (bytes < kHugePageBytes) {
        // malloc(0) may return nullptr: ask for one byte.
        void* p = std::malloc(bytes > 0 ? bytes : 1);
        if (!p) throw std::bad_alloc();
        return p;
    }
    // Whole huge pages: the kernel maps a huge page only where the marked
    // range covers all of it. (Rounding cannot overflow a request that
    // malloc could meet: it adds under 2 MiB.)
    if (bytes > ~std::size_t(0) - kHugePageBytes) throw std::bad_alloc();
    const std::size_t size = (bytes + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
    void* p = std::aligned_alloc(kHugePageBytes, size);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE); // a hint: failing, the pages are ordinary ones
#endif
    return p;
}

void free_large(void* p) noexcept { std::free(p); }

} // namespace casteljau
