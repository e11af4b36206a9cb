// Filling a run of 8-bit pixels with one color: the clear of every band and
// the inside of every opaque fill, so the store the frame is bound by on
// large areas (the full-canvas scene is one such run a row).
//
// Two forms, chosen once per process (cpu.h): 16-byte SSE2 stores (the
// x86-64 baseline) and 32-byte AVX2 stores where the CPU has them. Both store the
// run's first and last vector unaligned, overlapping the aligned stores
// between them, so no pixel is written one at a time. They write the same
// bytes (tests/paint/fill_run_test.cpp). Measured on bench/README.md's
// machine, 2026-11-29:
// - GCC's loop for std::fill over 4-byte structs of chars reloaded the
//   color from the stack for every 16 bytes it stored (chars may alias the
//   row) and ran at half the SSE2 loop's speed;
// - the string store (rep stosd) lost to the SSE2 loop at every row width
//   from 100 to 2048 pixels (1024 rows of 1024 pixels: 57 against 48 us);
// - AVX2 against SSE2: the full canvas 0.576 -> 0.525x Cairo, the ellipse
//   0.80 -> 0.73x; AVX-512 (64-byte stores) measured 5% slower than AVX2.
#pragma once

#include "casteljau/paint/pixel8.h"

namespace casteljau {

/// d[0, n) = c. `d` is 4-byte aligned (every canvas pixel is: a canvas's
/// storage starts on a 16-byte boundary), so the aligned vector stores
/// write whole pixels.
void fill_run(Premul8* d, int n, Premul8 c) noexcept;

namespace detail {
/// fill_run with SSE2 stores (scalar where SSE2 is not the baseline).
void fill_run_sse2(Premul8* d, int n, Premul8 c) noexcept;
/// fill_run with AVX2 stores; only where cpu_has_avx2() (cpu.h).
void fill_run_avx2(Premul8* d, int n, Premul8 c) noexcept;
} // namespace detail

} // namespace casteljau
