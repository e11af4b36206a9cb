#include "casteljau/paint/fill_run.h"

#include "casteljau/paint/cpu.h"

#include <bit>
#include <cstddef>
#include <cstdint>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CASTELJAU_X86_DISPATCH 1
#include <immintrin.h>
#endif

namespace casteljau {

namespace {

// Where the aligned stores start: the first `Align`-byte boundary after p
// (p's own when p is one: its bytes are the unaligned head store's anyway).
template <std::uintptr_t Align>
unsigned char* next_boundary(unsigned char* p) {
    return reinterpret_cast<unsigned char*>((reinterpret_cast<std::uintptr_t>(p) + Align) &
                                            ~(Align - 1));
}

std::uint32_t bits(Premul8 c) { return std::bit_cast<std::uint32_t>(c); }

} // namespace

namespace detail {

void fill_run_sse2(Premul8* d, int n, Premul8 c) noexcept {
#if defined(__SSE2__)
    if (n >= 4) {
        auto* b = reinterpret_cast<unsigned char*>(d);
        unsigned char* const end = b + std::size_t(n) * sizeof c;
        const __m128i v = _mm_set1_epi32(int(bits(c)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(b), v);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(end - 16), v);
        // Four stores to a 64-byte line a turn: the loop's own instructions
        // then cost less than the stores.
        for (b = next_boundary<16>(b); end - b >= 64; b += 64) {
            _mm_store_si128(reinterpret_cast<__m128i*>(b), v);
            _mm_store_si128(reinterpret_cast<__m128i*>(b + 16), v);
            _mm_store_si128(reinterpret_cast<__m128i*>(b + 32), v);
            _mm_store_si128(reinterpret_cast<__m128i*>(b + 48), v);
        }
        for (; end - b >= 16; b += 16) _mm_store_si128(reinterpret_cast<__m128i*>(b), v);
        return;
    }
#endif
    for (int i = 0; i < n; ++i) d[i] = c;
}

#if defined(CASTELJAU_X86_DISPATCH)
[[gnu::target("avx2")]] void fill_run_avx2(Premul8* d, int n, Premul8 c) noexcept {
    if (n < 8) { // no 32-byte vector fits: the head and tail stores would overrun
        fill_run_sse2(d, n, c);
        return;
    }
    auto* b = reinterpret_cast<unsigned char*>(d);
    unsigned char* const end = b + std::size_t(n) * sizeof c;
    const __m256i v = _mm256_set1_epi32(int(bits(c)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(b), v);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(end - 32), v);
    for (b = next_boundary<32>(b); end - b >= 64; b += 64) {
        _mm256_store_si256(reinterpret_cast<__m256i*>(b), v);
        _mm256_store_si256(reinterpret_cast<__m256i*>(b + 32), v);
    }
    if (end - b >= 32) _mm256_store_si256(reinterpret_cast<__m256i*>(b), v);
}
#else
void fill_run_avx2(Premul8* d, int n, Premul8 c) noexcept { fill_run_sse2(d, n, c); }
#endif

} // namespace detail

void fill_run(Premul8* d, int n, Premul8 c) noexcept {
    if (use_avx2)
        detail::fill_run_avx2(d, n, c);
    else
        detail::fill_run_sse2(d, n, c);
}

} // namespace casteljau
