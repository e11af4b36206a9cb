// The three patch-file parsers behind patch_read.h; each throws ReadError.
#pragma once

#include "casteljau/io/detail/tokens.h"
#include "casteljau/io/patch_read.h"

namespace casteljau::detail {

PatchModel parse_bpt(std::string_view text, const PatchLimits& limits);
PatchModel parse_quake_map(std::string_view text, const PatchLimits& limits);
PatchModel parse_patch_json(std::string_view text, const PatchLimits& limits,
                            std::optional<LookAt>& camera);

// Throws when adding `more` patches would pass the limit.
inline void check_patch_count(std::size_t have, std::size_t more, const PatchLimits& limits,
                              int line) {
    if (have + more > limits.max_patches)
        throw ReadError{line, "more than " + std::to_string(limits.max_patches) + " patches"};
}

} // namespace casteljau::detail
