// What this CPU runs beyond the x86-64 baseline (SSE2), detected once.
//
// The hot loops that have a wider form (fill_run.h, pixel8.h's blend runs,
// image_shader.cpp's bilinear rows, gradient.cpp's radial parameters and
// pad entries) choose it by `use_avx2`, and each wider form computes the
// same bits as the baseline one (tested side by side), so a picture does
// not depend on the machine that drew it. Where the target is not x86-64,
// nothing is wider and `use_avx2` is false.
#pragma once

namespace casteljau {

/// Whether this CPU runs AVX2 (asked of the CPU at each call).
bool cpu_has_avx2() noexcept;

/// Whether the environment variable CASTELJAU_NO_AVX2 is set and not empty:
/// then the baseline forms run everywhere (as pixman's PIXMAN_DISABLE does),
/// which is how the tests check them on machines that have the wider ones
/// (scripts/test.sh).
bool avx2_disabled_by_environment() noexcept;

/// cpu_has_avx2() unless the environment says otherwise, read once at
/// start-up. Code that runs before this library's static initialization
/// reads false, the baseline forms: safe.
inline const bool use_avx2 = cpu_has_avx2() && !avx2_disabled_by_environment();

} // namespace casteljau
