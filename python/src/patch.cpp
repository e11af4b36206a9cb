// tessellate: surface patches to a triangle mesh, as `casteljau patch` does
// it (cli/patch_command.cpp): the same readers, camera, tessellators and
// limits, with the mesh returned as arrays instead of drawn.
#include "casteljau/io/patch_read.h"
#include "casteljau/render/output_size.h"
#include "casteljau/render3d/camera.h"
#include "casteljau/tessellate/adaptive.h"
#include "casteljau/tessellate/error.h"
#include "casteljau/tessellate/uniform.h"
#include "common.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace casteljau::python {

namespace {

using namespace pybind11::literals;

// The patch command's limits (cli/patch_command.cpp).
constexpr double kMinPatchTolerance = 0.01;
constexpr int kMaxSteps = 1024;
constexpr double kMaxUniformTriangles = double(1 << 25);

// Bezier control grids: (rows, cols, 3) x y z or (rows, cols, 5) x y z s t,
// rows and cols in 2..4 (degree cols - 1 in u, rows - 1 in v).
PatchModel model_from_grids(py::handle grids) {
    if (!PySequence_Check(grids.ptr()) && !py::hasattr(grids, "__iter__"))
        throw py::type_error("tessellate: expected a patch file path or a list of control grids");
    PatchModel model;
    const std::size_t max_patches = PatchLimits{}.max_patches;
    std::size_t index = 0;
    for (const py::handle g : py::iter(grids)) {
        const std::string where = "patches[" + std::to_string(index++) + "]";
        if (model.patches.size() >= max_patches)
            value_error(where + ": more than " + std::to_string(max_patches) + " patches");
        const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(g);
        if (!a || a.ndim() != 3 || a.shape(0) < 2 || a.shape(0) > 4 || a.shape(1) < 2 ||
            a.shape(1) > 4 || (a.shape(2) != 3 && a.shape(2) != 5))
            value_error(where + ": expected a (rows, cols, 3) or (rows, cols, 5) array of control "
                                "points, rows and cols in 2..4");
        const int rows = int(a.shape(0)), cols = int(a.shape(1));
        const bool has_st = a.shape(2) == 5;
        const auto v = a.unchecked<3>();
        std::vector<PatchPoint> points;
        for (int r = 0; r < rows; ++r)
            for (int k = 0; k < cols; ++k) {
                PatchPoint q;
                q.p = {v(r, k, 0), v(r, k, 1), v(r, k, 2)};
                q.st = has_st ? Point{v(r, k, 3), v(r, k, 4)}
                              : Point{double(k) / (cols - 1), double(r) / (rows - 1)};
                if (!q.is_finite()) value_error(where + ": control points must be finite");
                points.push_back(q);
            }
        model.patches.push_back(bezier_from_grid(cols - 1, rows - 1, points));
    }
    if (model.patches.empty()) value_error("tessellate: no patches");
    return model;
}

py::object tessellate(py::handle source, double tolerance, const std::string& method,
                      std::optional<int> steps, std::optional<std::pair<double, double>> view,
                      int width, int height, bool return_info) {
    if (!(tolerance >= kMinPatchTolerance && tolerance <= 1)) {
        char text[120];
        std::snprintf(text, sizeof text,
                      "tolerance %g: must be a number of device pixels in [0.01, 1]", tolerance);
        value_error(text);
    }
    if (method != "adaptive" && method != "uniform")
        value_error("method '" + method + "': expected 'adaptive' or 'uniform'");
    const bool adaptive = method == "adaptive";
    if (width < 1 || height < 1 || width > kMaxOutputSide || height > kMaxOutputSide)
        value_error("width and height must be in [1, " + std::to_string(kMaxOutputSide) + "]");
    if (double(width) * height > kMaxOutputPixels)
        value_error("the image is larger than 2^26 pixels");
    if (steps && adaptive) value_error("steps: only with method='uniform'");
    if (steps && (*steps < 1 || *steps > kMaxSteps))
        value_error("steps " + std::to_string(*steps) + ": must be in [1, " +
                    std::to_string(kMaxSteps) + "]");
    if (view && !(std::abs(view->first) <= 360 && std::abs(view->second) <= 360))
        value_error("view: azimuth and elevation are degrees in [-360, 360]");

    PatchFile file;
    const py::object os = py::module_::import("os");
    if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__")) {
        const std::string path = os.attr("fsdecode")(source).cast<std::string>();
        {
            py::gil_scoped_release release;
            file = read_patch_file(path);
        }
        if (!file.model) {
            if (file.io_error) os_error(file.error);
            value_error(file.error);
        }
    } else {
        file.model = model_from_grids(source);
    }
    const PatchModel& model = *file.model;

    Mesh mesh;
    AdaptiveStats stats;
    int n = steps.value_or(0);
    double max_error = -1;
    bool budget_warning = false;
    std::size_t budget = 0;
    {
        py::gil_scoped_release release;
        const LookAt camera = file.camera && !view
                                  ? *file.camera
                                  : orbit_view(model.control_bounds(), view ? view->first : 35,
                                               view ? view->second : 25, width, height);
        const ScreenProjection projection = make_projection(camera, width, height);
        const int step_cap = std::min(
            kMaxSteps, int(std::sqrt(kMaxUniformTriangles / (2.0 * double(model.patches.size())))));
        if (adaptive) {
            stats = tessellate_adaptive(model, projection, tolerance, mesh);
            budget_warning = stats.budget_reached;
            budget = default_piece_budget(projection);
        } else {
            if (n > step_cap)
                n = -n; // reported below, with the GIL
            else {
                if (n == 0)
                    n = fewest_uniform_steps(model, projection, tolerance, std::max(1, step_cap),
                                             mesh);
                tessellate_uniform(model, n, n, mesh);
            }
        }
        if (n >= 0 && return_info) max_error = measure_max_error_px(model, mesh, projection);
    }
    if (n < 0) value_error("steps " + std::to_string(-n) + " makes more than 2^25 triangles");
    if (budget_warning) {
        const std::string text =
            "adaptive tessellation stopped at its budget of " + std::to_string(budget) +
            " pieces; parts of the mesh may be off by more than the tolerance (is the camera "
            "inside the model?)";
        if (PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 1) != 0) throw py::error_already_set();
    }

    const py::ssize_t nv = py::ssize_t(mesh.positions.size());
    const py::ssize_t nt = py::ssize_t(mesh.triangles.size());
    py::array_t<double> vertices({nv, py::ssize_t(3)}), st({nv, py::ssize_t(2)}),
        normals({nv, py::ssize_t(3)});
    py::array_t<std::int64_t> triangles({nt, py::ssize_t(3)});
    double* pv = vertices.mutable_data();
    double* ps = st.mutable_data();
    double* pn = normals.mutable_data();
    for (py::ssize_t i = 0; i < nv; ++i) {
        const Point3& p = mesh.positions[std::size_t(i)];
        const Vec3& nm = mesh.normals[std::size_t(i)];
        const Point& t = mesh.st[std::size_t(i)];
        pv[3 * i] = p.x, pv[3 * i + 1] = p.y, pv[3 * i + 2] = p.z;
        pn[3 * i] = nm.x, pn[3 * i + 1] = nm.y, pn[3 * i + 2] = nm.z;
        ps[2 * i] = t.x, ps[2 * i + 1] = t.y;
    }
    std::int64_t* pt = triangles.mutable_data();
    for (py::ssize_t i = 0; i < nt; ++i)
        for (int c = 0; c < 3; ++c) pt[3 * i + c] = mesh.triangles[std::size_t(i)][std::size_t(c)];
    if (!return_info) return py::make_tuple(vertices, triangles, st);
    py::dict info;
    info["patches"] = model.patches.size();
    info["triangles"] = mesh.triangles.size();
    info["vertices"] = mesh.positions.size();
    info["max_error_px"] = max_error;
    info["method"] = method;
    info["steps"] = adaptive ? 0 : n;
    info["pieces"] = stats.pieces;
    info["budget_reached"] = stats.budget_reached;
    info["normals"] = normals;
    return py::make_tuple(vertices, triangles, st, info);
}

} // namespace

void bind_patch(py::module_& m) {
    m.def("tessellate", &tessellate, "file_or_patches"_a, py::kw_only(), "tolerance"_a = 0.25,
          "method"_a = "adaptive", "steps"_a = py::none(), "view"_a = py::none(), "width"_a = 800,
          "height"_a = 600, "return_info"_a = false,
          R"doc(
Tessellates surface patches into a triangle mesh, as `casteljau patch` does.

file_or_patches: a path (str or os.PathLike) to a .bpt, Quake 3 .map or
.json patch file, or a list of Bezier control grids, each an array of shape
(rows, cols, 3) (x y z; texture coordinates default to the grid's own
parameters) or (rows, cols, 5) (x y z s t), rows and cols in 2..4: degree
cols - 1 in u and rows - 1 in v, rows along v.

method 'adaptive' (default) splits each patch until every triangle is within
`tolerance` px (in [0.01, 1]) of the surface as seen by the camera; 'uniform'
uses `steps` per patch side, or without it the fewest steps whose measured
error meets the tolerance. The camera is the CLI's: a .json file's own
"camera" unless `view` is given, otherwise an orbit view (azimuth, elevation
in degrees, default (35, 25)) fitted to the model, on a `width` x `height`
image (default 800 x 600). The mesh is watertight across patches.

Returns (vertices, triangles, st): (V, 3) float64 positions, (T, 3) int64
vertex indices (counter-clockwise in each patch's (u, v)), (V, 2) float64
texture coordinates. With return_info=True a fourth item, a dict: patches,
triangles, vertices, max_error_px (measured projected distance between mesh
and surface), method, steps, pieces, budget_reached, normals ((V, 3) unit
normals). Bad files raise ValueError('file:line: what'), unreadable ones
OSError. The GIL is released while reading and tessellating.)doc");
}

} // namespace casteljau::python
