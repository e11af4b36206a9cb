#include "casteljau/io/mesh_write.h"

#include "casteljau/io/atomic_file.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <utility>

namespace casteljau {

namespace fs = std::filesystem;

namespace {

void write_obj(std::ofstream& out, const Mesh& m) {
    out << "# casteljau tessellation: " << m.positions.size() << " vertices, " << m.triangles.size()
        << " triangles\n";
    char line[128];
    // %.9g: enough digits for a float's worth of precision and well within a line.
    for (const Point3& p : m.positions) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
        out << line;
    }
    for (const Point& st : m.st) {
        std::snprintf(line, sizeof line, "vt %.9g %.9g\n", st.x, st.y);
        out << line;
    }
    for (const Vec3& n : m.normals) {
        std::snprintf(line, sizeof line, "vn %.6f %.6f %.6f\n", n.x, n.y, n.z);
        out << line;
    }
    for (const auto& t : m.triangles) {
        const unsigned a = t[0] + 1, b = t[1] + 1, c = t[2] + 1;
        std::snprintf(line, sizeof line, "f %u/%u/%u %u/%u/%u %u/%u/%u\n", a, a, a, b, b, b, c, c,
                      c);
        out << line;
    }
}

template <class T>
void put(std::ofstream& out, T v) {
    static_assert(std::endian::native == std::endian::little, "PLY output assumes little-endian");
    out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

void write_ply(std::ofstream& out, const Mesh& m) {
    out << "ply\nformat binary_little_endian 1.0\ncomment casteljau tessellation\n"
        << "element vertex " << m.positions.size() << "\n"
        << "property float x\nproperty float y\nproperty float z\n"
        << "property float nx\nproperty float ny\nproperty float nz\n"
        << "property float s\nproperty float t\n"
        << "element face " << m.triangles.size() << "\n"
        << "property list uchar int vertex_indices\nend_header\n";
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Point3 p = m.positions[i];
        const Vec3 n = m.normals[i];
        for (double v : {p.x, p.y, p.z, n.x, n.y, n.z, m.st[i].x, m.st[i].y}) put(out, float(v));
    }
    for (const auto& t : m.triangles) {
        put(out, std::uint8_t(3));
        for (std::uint32_t v : t) put(out, std::int32_t(v));
    }
}

} // namespace

std::string write_mesh_atomic(const std::string& path, const Mesh& mesh) {
    const fs::path dest(path);
    const std::string ext = dest.extension().string();
    if (ext != ".obj" && ext != ".ply")
        return path + ": unknown mesh format '" + ext + "' (expected .obj or .ply)";
    std::error_code ec;
    if (fs::is_directory(dest, ec)) return path + ": is a folder, not a file";
    const fs::path tmp = temporary_sibling(dest);
    std::string error;
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return path + ": cannot write";
        if (ext == ".obj")
            write_obj(out, mesh);
        else
            write_ply(out, mesh);
        out.close();
        if (!out) error = path + ": write failed";
    }
    return finish_temporary(tmp, dest, std::move(error));
}

} // namespace casteljau
