// The Quake 3 .map reader (patch_read.h): every patchDef2 block, as in
//   patchDef2 { textures/name ( W H 0 0 0 ) ( ( ( x y z s t ) ... ) ... ) }
// W rows of H points; the reader keeps rows along v (Quake 3's own
// tr_curve.c reads the grid the same way up to a transpose, which only flips
// which side faces du x dv; rendering is two-sided).
#include "casteljau/io/detail/patch_formats.h"
#include "casteljau/patch/grid.h"

#include <vector>

namespace casteljau::detail {

namespace {

void read_patch_def(Tokens& tokens, const PatchLimits& limits, PatchModel& model) {
    tokens.expect_text("{");
    tokens.expect("texture name");
    tokens.expect_text("(");
    const int rows = tokens.integer("patch width", 3, limits.max_grid_side);
    const int line = tokens.line();
    const int cols = tokens.integer("patch height", 3, limits.max_grid_side);
    if (rows % 2 == 0 || cols % 2 == 0)
        throw ReadError{line, "patch grid " + std::to_string(rows) + " x " + std::to_string(cols) +
                                  ": both sizes must be odd"};
    for (int i = 0; i < 3; ++i) tokens.number("patch parameter");
    tokens.expect_text(")");
    check_patch_count(model.patches.size(), std::size_t(rows / 2) * (cols / 2), limits, line);
    std::vector<PatchPoint> grid;
    grid.reserve(std::size_t(rows) * cols);
    tokens.expect_text("(");
    for (int r = 0; r < rows; ++r) {
        tokens.expect_text("(");
        for (int k = 0; k < cols; ++k) {
            tokens.expect_text("(");
            PatchPoint q;
            q.p.x = tokens.number("x");
            q.p.y = tokens.number("y");
            q.p.z = tokens.number("z");
            q.st.x = tokens.number("s");
            q.st.y = tokens.number("t");
            tokens.expect_text(")");
            grid.push_back(q);
        }
        tokens.expect_text(")");
    }
    tokens.expect_text(")");
    tokens.expect_text("}");
    for (const QuadPatch& p : quad_grid_patches(rows, cols, grid)) model.patches.push_back(p);
}

} // namespace

PatchModel parse_quake_map(std::string_view text, const PatchLimits& limits) {
    Tokens tokens(text);
    PatchModel model;
    Token t;
    while (tokens.next(t))
        if (t.text == "patchDef2") read_patch_def(tokens, limits, model);
    if (model.patches.empty()) throw ReadError{tokens.line(), "no patchDef2 block"};
    return model;
}

} // namespace casteljau::detail
