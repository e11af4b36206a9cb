// Frame-sized buffers in transparent huge pages.
//
// A 1024 x 1024 8-bit frame is 4 MiB: 1,024 pages of 4 KiB, each mapped by
// the kernel on its first write (a page fault), and so is the PNG encoder's
// copy of its rows. On the 2-core machines of 2026-11-29 (a paravirtualized
// kernel) a fault cost about 6 us: the command line's first frame and its
// PNG paid 12 ms of faults, a sixth of its time from start to file on the
// tiger. Linux maps a region marked with madvise(MADV_HUGEPAGE) in 2 MiB
// pages, one fault each, when its transparent huge pages are `always` or
// `madvise` (Debian's default); elsewhere, or where the kernel has no huge
// page to give, the mark does nothing and the buffer is an ordinary one.
//
// So a buffer of at least kHugePageBytes is allocated on a huge page's
// boundary, rounded up to whole huge pages, and marked; a smaller one is
// plain malloc. Both are released with std::free (free_large).
#pragma once

#include <cstddef>
#include <memory>

namespace casteljau {

/// The size of a transparent huge page on x86-64 and of the buffers worth one.
inline constexpr std::size_t kHugePageBytes = std::size_t(1) << 21;

/// `bytes` of uninitialized memory (top of the file); throws std::bad_alloc.
void* allocate_large(std::size_t bytes);
/// Releases memory from allocate_large (nullptr does nothing).
void free_large(void* p) noexcept;

/// The std::allocator of frame-sized vectors (top of the file).
template <class T>
struct LargeAllocator {
    using value_type = T; ///< what it allocates
    LargeAllocator() = default;
    /// Rebinding: stateless, so any other is this one.
    template <class U>
    LargeAllocator(const LargeAllocator<U>&) noexcept {}
    /// Room for n values, uninitialized.
    T* allocate(std::size_t n) { return static_cast<T*>(allocate_large(n * sizeof(T))); }
    /// Releases what allocate returned.
    void deallocate(T* p, std::size_t) noexcept { free_large(p); }
    /// Stateless: every one frees what any other allocated.
    friend bool operator==(const LargeAllocator&, const LargeAllocator&) { return true; }
};

/// unique_ptr's deleter for allocate_large.
struct FreeLarge {
    /// free_large(p).
    void operator()(void* p) const noexcept { free_large(p); }
};

/// An array of bytes from allocate_large, uninitialized.
using LargeBytes = std::unique_ptr<unsigned char[], FreeLarge>;

/// `bytes` bytes from allocate_large, owned; throws std::bad_alloc.
inline LargeBytes large_bytes(std::size_t bytes) {
    return LargeBytes(static_cast<unsigned char*>(allocate_large(bytes)));
}

} // namespace casteljau
