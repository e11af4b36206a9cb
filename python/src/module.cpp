// The extension module casteljau._casteljau. The package casteljau
// (python/casteljau/__init__.py) re-exports it with the pure-Python parts.
#include "common.h"

PYBIND11_MODULE(_casteljau, m) {
    using namespace casteljau::python;
    m.doc() = "Casteljau's C++ core: exact curve flattening, stroking, antialiased rendering "
              "and surface tessellation. Use it through the package `casteljau`.";
    bind_geometry(m);
    bind_hit(m);
    bind_paint(m);
    bind_drawing(m);
    bind_render(m);
    bind_flatten(m);
    bind_patch(m);
}
