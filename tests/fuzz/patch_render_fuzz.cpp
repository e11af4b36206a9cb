// Fuzz target: whatever the patch readers accept (the first byte picks the
// format, as in patch_read_fuzz.cpp) is tessellated adaptively and drawn
// with wireframe on a 64 x 48 image, from the file's camera when it has one
// (degenerate cameras included) or from the CLI's default orbit view.
#include "casteljau/io/patch_read.h"
#include "casteljau/render3d/mesh_raster.h"
#include "casteljau/tessellate/adaptive.h"
#include "fuzz_target.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace casteljau;
    if (size == 0) return 0;
    const PatchFile f = parse_patches({reinterpret_cast<const char*>(data + 1), size - 1},
                                      PatchFormat(data[0] % 3), "fuzz");
    if (!f.model || f.model->patches.empty()) return 0;
    constexpr int kWidth = 64, kHeight = 48;
    const LookAt camera =
        f.camera ? *f.camera : orbit_view(f.model->control_bounds(), 35, 25, kWidth, kHeight);
    const ScreenProjection view = make_projection(camera, kWidth, kHeight);
    static Mesh mesh; // reused, as an application would
    const AdaptiveStats stats = tessellate_adaptive(*f.model, view, 0.25, mesh);
    if (stats.pieces > default_piece_budget(view) + 2 * f.model->patches.size()) std::abort();
    Canvas canvas(kWidth, kHeight);
    MeshRenderer().render(mesh, view, MeshStyle{nullptr, {0.75f, 0.75f, 0.75f}, true}, canvas);
    return 0;
}
