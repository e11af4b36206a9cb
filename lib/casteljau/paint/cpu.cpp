#include "casteljau/paint/cpu.h"

namespace casteljau {

bool cpu_has_avx2() noexcept {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    __builtin_cpu_init(); // needed where this runs before the constructors that would
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

} // namespace casteljau
