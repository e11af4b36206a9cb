#include "casteljau/paint/cpu.h"

#include <cstdlib>

namespace casteljau {

bool cpu_has_avx2() noexcept {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    // The CPU model is filled in by a constructor of libgcc, which may not
    // have run yet when this runs during static initialization.
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

bool avx2_disabled_by_environment() noexcept {
    const char* v = std::getenv("CASTELJAU_NO_AVX2");
    return v && *v;
}

} // namespace casteljau
