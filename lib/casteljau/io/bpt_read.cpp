// The .bpt reader (patch_read.h): count, then "m n" and the points per patch.
#include "casteljau/io/detail/patch_formats.h"

#include <vector>

namespace casteljau::detail {

PatchModel parse_bpt(std::string_view text, const PatchLimits& limits) {
    Tokens tokens(text);
    PatchModel model;
    const int count = tokens.integer("patch count", 1, int(limits.max_patches));
    std::vector<PatchPoint> grid;
    for (int i = 0; i < count; ++i) {
        const int du = tokens.integer("degree m", 1, 3);
        const int dv = tokens.integer("degree n", 1, 3);
        grid.clear();
        for (int r = 0; r <= dv; ++r)
            for (int k = 0; k <= du; ++k) {
                PatchPoint q;
                q.p.x = tokens.number("x");
                q.p.y = tokens.number("y");
                q.p.z = tokens.number("z");
                q.st = {double(k) / du, double(r) / dv};
                grid.push_back(q);
            }
        model.patches.push_back(bezier_from_grid(du, dv, grid));
    }
    Token extra;
    if (tokens.next(extra))
        throw ReadError{extra.line, "text after the last of the " + std::to_string(count) +
                                        " patches (is the patch count right?)"};
    return model;
}

} // namespace casteljau::detail
