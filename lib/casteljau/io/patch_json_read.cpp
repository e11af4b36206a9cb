// The JSON scene reader (patch_read.h).
#include "casteljau/io/detail/json.h"
#include "casteljau/io/detail/patch_formats.h"
#include "casteljau/patch/grid.h"

#include <cmath>
#include <vector>

namespace casteljau::detail {

namespace {

using Kind = JsonValue::Kind;

[[noreturn]] void fail(const JsonValue& v, const std::string& what) {
    throw ReadError{v.line, what};
}

const JsonValue& member(const JsonValue& obj, const char* key, Kind kind, const char* kind_name) {
    const JsonValue* v = obj.find(key);
    if (!v) fail(obj, std::string("missing \"") + key + "\"");
    if (v->kind != kind) fail(*v, std::string("\"") + key + "\" must be " + kind_name);
    return *v;
}

// An array of exactly n numbers.
std::vector<double> numbers(const JsonValue& v, std::size_t n, const std::string& what) {
    if (v.kind != Kind::Array || v.items.size() != n)
        fail(v, what + " must be an array of " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (const JsonValue& x : v.items) {
        if (x.kind != Kind::Number) fail(x, what + ": not a number");
        out.push_back(x.number);
    }
    return out;
}

int integer_in(const JsonValue& v, int lo, int hi, const std::string& what) {
    if (v.kind != Kind::Number || v.number != std::floor(v.number) || v.number < lo ||
        v.number > hi)
        fail(v, what + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    return int(v.number);
}

std::vector<PatchPoint> grid_points(const JsonValue& patch, int rows, int cols) {
    const JsonValue& pts = member(patch, "points", Kind::Array, "an array");
    const std::size_t n = std::size_t(rows) * std::size_t(cols);
    if (pts.items.size() != n)
        fail(pts, "\"points\" has " + std::to_string(pts.items.size()) + " points, expected " +
                      std::to_string(rows) + " x " + std::to_string(cols) + " = " +
                      std::to_string(n));
    const JsonValue* st = patch.find("st");
    if (st && (st->kind != Kind::Array || st->items.size() != n))
        fail(*st, "\"st\" must hold one [s, t] per point (" + std::to_string(n) + ")");
    std::vector<PatchPoint> grid(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto p = numbers(pts.items[i], 3, "a point");
        grid[i].p = {p[0], p[1], p[2]};
        if (st) {
            const auto s = numbers(st->items[i], 2, "an st pair");
            grid[i].st = {s[0], s[1]};
        } else {
            grid[i].st = {double(i % cols) / (cols - 1), double(i / cols) / (rows - 1)};
        }
    }
    return grid;
}

void read_patch(const JsonValue& patch, const PatchLimits& limits, PatchModel& model) {
    if (patch.kind != Kind::Object) fail(patch, "a patch must be an object");
    const std::string& type = member(patch, "type", Kind::String, "a string").string;
    if (type == "bezier") {
        const JsonValue& degree = member(patch, "degree", Kind::Array, "an array [m, n]");
        if (degree.items.size() != 2) fail(degree, "\"degree\" must be [m, n]");
        const int du = integer_in(degree.items[0], 1, 3, "degree m");
        const int dv = integer_in(degree.items[1], 1, 3, "degree n");
        check_patch_count(model.patches.size(), 1, limits, patch.line);
        model.patches.push_back(bezier_from_grid(du, dv, grid_points(patch, dv + 1, du + 1)));
    } else if (type == "bspline") {
        int rows = 4, cols = 4;
        if (const JsonValue* size = patch.find("size")) {
            if (size->kind != Kind::Array || size->items.size() != 2)
                fail(*size, "\"size\" must be [rows, columns]");
            rows = integer_in(size->items[0], 4, limits.max_grid_side, "rows");
            cols = integer_in(size->items[1], 4, limits.max_grid_side, "columns");
        }
        check_patch_count(model.patches.size(), std::size_t(rows - 3) * (cols - 3), limits,
                          patch.line);
        for (const BSplinePatch& b :
             bspline_grid_patches(rows, cols, grid_points(patch, rows, cols)))
            model.patches.push_back(b.to_bezier());
    } else {
        fail(patch, "patch type '" + type + "' is neither \"bezier\" nor \"bspline\"");
    }
}

Point3 point(const JsonValue& v, const char* what) {
    const auto p = numbers(v, 3, what);
    return {p[0], p[1], p[2]};
}

LookAt read_camera(const JsonValue& cam) {
    if (cam.kind != Kind::Object) fail(cam, "\"camera\" must be an object");
    LookAt c;
    c.eye = point(member(cam, "eye", Kind::Array, "[x, y, z]"), "\"eye\"");
    c.target = point(member(cam, "target", Kind::Array, "[x, y, z]"), "\"target\"");
    if (const JsonValue* up = cam.find("up")) c.up = point(*up, "\"up\"") - Point3{};
    if (const JsonValue* fov = cam.find("fov")) {
        if (fov->kind != Kind::Number || !(fov->number > 1 && fov->number < 170))
            fail(*fov, "\"fov\" must be a number of degrees in (1, 170)");
        c.fov_deg = fov->number;
    }
    const Vec3 sight = c.target - c.eye;
    if (sight.length_sq() == 0) fail(cam, "camera \"eye\" and \"target\" are the same point");
    if (sight.cross(c.up).length() <= 1e-9 * sight.length() * c.up.length())
        fail(cam, "camera \"up\" is zero or along the line of sight");
    return c;
}

} // namespace

PatchModel parse_patch_json(std::string_view text, const PatchLimits& limits,
                            std::optional<LookAt>& camera) {
    const JsonValue doc = parse_json(text);
    if (doc.kind != Kind::Object) fail(doc, "the scene must be a JSON object");
    const JsonValue& patches = member(doc, "patches", Kind::Array, "an array");
    PatchModel model;
    for (const JsonValue& p : patches.items) read_patch(p, limits, model);
    if (model.patches.empty()) fail(patches, "\"patches\" is empty");
    if (const JsonValue* cam = doc.find("camera")) camera = read_camera(*cam);
    return model;
}

} // namespace casteljau::detail
