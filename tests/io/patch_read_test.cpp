// Patch readers: the three formats read what they say, and every kind of
// malformed file is an error with its line; the mesh writers round-trip.
#include "casteljau/io/mesh_write.h"
#include "casteljau/io/patch_read.h"
#include "casteljau/tessellate/uniform.h"
#include "patch_models.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace casteljau {
namespace {

PatchFile bpt(const std::string& text) { return parse_patches(text, PatchFormat::Bpt, "t.bpt"); }
PatchFile map(const std::string& text) {
    return parse_patches(text, PatchFormat::QuakeMap, "t.map");
}
PatchFile json(const std::string& text) { return parse_patches(text, PatchFormat::Json, "t.json"); }

const char* kBilinear = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n";

TEST(BptReader, ReadsPatchesOfEveryDegree) {
    const PatchFile f = bpt(kBilinear);
    ASSERT_TRUE(f.model) << f.error;
    ASSERT_EQ(f.model->patches.size(), 1u);
    const auto& p = std::get<BilinearPatch>(f.model->patches[0]);
    EXPECT_EQ(p.eval(1, 1).p, (Point3{1, 1, 1}));
    EXPECT_EQ(p.eval(1, 0).p, (Point3{1, 0, 0})); // rows along v: the second point is u = 1
    EXPECT_EQ(p.eval(0.5, 0.5).st, (Point{0.5, 0.5}));
    // A 1 x 2 patch is elevated to the biquadratic kind, keeping its surface.
    const PatchFile mixed = bpt("1\n1 2\n0 0 0\n1 0 0\n0 1 1\n1 1 1\n0 2 0\n1 2 0\n");
    ASSERT_TRUE(mixed.model) << mixed.error;
    const auto& q = std::get<QuadPatch>(mixed.model->patches[0]);
    EXPECT_NEAR(q.eval(0.5, 0.5).p.z, 0.5, 1e-15);
}

TEST(BptReader, MalformedFilesNameTheLine) {
    const struct {
        const char* text;
        const char* expect;
    } cases[] = {
        {"", "t.bpt:1: unexpected end of file, expected patch count"},
        {"2\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n",
         "t.bpt:7: unexpected end of file, expected degree m"},
        {"1\n4 1\n", "t.bpt:2: degree m: 4 is not in 1..3"},
        {"1\n1 1\n0 0 0\n1 zero 0\n", "t.bpt:4: y: 'zero' is not a finite number"},
        {"1\n1 1\n0 0 0\n1 nan 0\n", "t.bpt:4: y: 'nan' is not a finite number"},
        {"1\n1 1\n0 0 0\n1 1e999 0\n", "t.bpt:4: y: '1e999' is not a finite number"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1\n", "t.bpt:7: unexpected end of file, expected z"},
        {"1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n5\n",
         "t.bpt:7: text after the last of the 1 patches"},
        {"x\n", "t.bpt:1: patch count: 'x' is not an integer"},
        // A few bytes claiming a million patches: an error at the end of the
        // text, not a million patches' worth of memory reserved up front.
        {"1000000\n1 1\n0 0 0\n", "t.bpt:4: unexpected end of file, expected x"},
    };
    for (const auto& c : cases) {
        const PatchFile f = bpt(c.text);
        EXPECT_FALSE(f.model) << c.text;
        EXPECT_EQ(f.error.rfind(c.expect, 0), 0u) << "got: " << f.error;
    }
}

std::string grid_map(int rows, int cols, const char* bad = nullptr) {
    std::ostringstream s;
    s << "{\n\"classname\" \"worldspawn\"\n{\npatchDef2\n{\ntex/a\n( " << rows << " " << cols
      << " 0 0 0 )\n(\n";
    for (int r = 0; r < rows; ++r) {
        s << "( ";
        for (int k = 0; k < cols; ++k) {
            if (bad && r == 1 && k == 1)
                s << "( " << bad << " 0 0 0 0 ) ";
            else
                s << "( " << k << " " << r << " " << (r * k) % 3 << " " << k << " " << r << " ) ";
        }
        s << ")\n";
    }
    s << ")\n}\n}\n}\n";
    return s.str();
}

TEST(QuakeMapReader, ReadsEveryPatchDef2AsBiquadraticPatches) {
    const PatchFile f = map(grid_map(5, 7));
    ASSERT_TRUE(f.model) << f.error;
    ASSERT_EQ(f.model->patches.size(), 2u * 3u);
    const auto& p = std::get<QuadPatch>(f.model->patches[4]); // second row, second column
    EXPECT_EQ(p.eval(0, 0).p, (Point3{2, 2, 1}));
    EXPECT_EQ(p.eval(0, 0).st, (Point{2, 2}));
    // Neighbours share their boundary column exactly.
    EXPECT_EQ(std::get<QuadPatch>(f.model->patches[3]).column(2), p.column(0));
}

TEST(QuakeMapReader, MalformedFilesNameTheLine) {
    EXPECT_EQ(map(grid_map(4, 5)).error, "t.map:7: patch grid 4 x 5: both sizes must be odd");
    EXPECT_EQ(map(grid_map(3, 1)).error, "t.map:7: patch height: 1 is not in 3..1025");
    EXPECT_EQ(map(grid_map(3, 3, "inf")).error, "t.map:10: x: 'inf' is not a finite number");
    std::string cut = grid_map(3, 3);
    cut.resize(cut.size() / 2);
    EXPECT_EQ(map(cut).error.rfind("t.map:", 0), 0u);
    EXPECT_NE(map(cut).error.find("unexpected end of file"), std::string::npos) << map(cut).error;
    EXPECT_EQ(map("{ \"classname\" \"worldspawn\" }").error, "t.map:1: no patchDef2 block");
}

TEST(JsonReader, ReadsBezierAndBSplinePatchesAndTheCamera) {
    const PatchFile f = json(R"({"patches": [
      {"type": "bezier", "degree": [1, 1], "points": [[0,0,0],[1,0,0],[0,1,0],[1,1,1]],
       "st": [[0,0],[2,0],[0,2],[2,2]]},
      {"type": "bspline", "size": [4, 5],
       "points": [[0,0,0],[1,0,0],[2,0,0],[3,0,0],[4,0,0],
                  [0,1,0],[1,1,0],[2,1,0],[3,1,0],[4,1,0],
                  [0,2,0],[1,2,0],[2,2,0],[3,2,0],[4,2,0],
                  [0,3,0],[1,3,0],[2,3,0],[3,3,0],[4,3,0]]}],
      "camera": {"eye": [5, -5, 5], "target": [0, 0, 0], "fov": 30}})");
    ASSERT_TRUE(f.model) << f.error;
    ASSERT_EQ(f.model->patches.size(), 3u); // 1 + (4-3) x (5-3)
    EXPECT_EQ(std::get<BilinearPatch>(f.model->patches[0]).eval(1, 1).st, (Point{2, 2}));
    // A B-spline of a regular grid is the grid's bilinear map: piece 0 spans x 1..2.
    EXPECT_NEAR(std::get<CubicPatch>(f.model->patches[1]).eval(0.5, 0.5).p.x, 1.5, 1e-12);
    ASSERT_TRUE(f.camera);
    EXPECT_EQ(f.camera->eye, (Point3{5, -5, 5}));
    EXPECT_EQ(f.camera->fov_deg, 30);
}

TEST(JsonReader, MalformedFilesNameTheLine) {
    const struct {
        const char* text;
        const char* expect;
    } cases[] = {
        {"{\"patches\": [\n{\"type\": \"bezier\", \"degree\": [1, 1],\n\"points\": [[0,0,0]]}]}",
         "t.json:3: \"points\" has 1 points, expected 2 x 2 = 4"},
        {"{\"patches\": [{\"type\": \"bezier\", \"degree\": [1, 1], \"points\":\n"
         "[[0,0,0],[1,0,0],[0,1,0],[1,\"x\",1]]}]}",
         "t.json:2: a point: not a number"},
        {"{\"patches\": [{\"type\": \"bezier\", \"degree\": [1, 1], \"points\":\n"
         "[[0,0,0],[1,0,0],[0,1,0],[1,NaN,1]]}]}",
         "t.json:2: 'N' is not a finite JSON number"},
        {"{\"patches\": [{\"type\": \"bezier\", \"degree\": [0, 1]}]}",
         "t.json:1: degree m must be an integer in 1..3"},
        {"{\"patches\": [{\"type\": \"nurbs\"}]}", "t.json:1: patch type 'nurbs' is neither"},
        {"{\"patches\": [{\"type\": \"bspline\", \"size\": [3, 4], \"points\": []}]}",
         "t.json:1: rows must be an integer in 4..1025"},
        {"{\"patches\": [\n", "t.json:2: unexpected end of file"},
        {"{\"patches\": []}", "t.json:1: \"patches\" is empty"},
        {"[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[",
         "t.json:1: nested deeper than 64 levels"},
    };
    for (const auto& c : cases) {
        const PatchFile f = json(c.text);
        EXPECT_FALSE(f.model) << c.text;
        EXPECT_EQ(f.error.rfind(c.expect, 0), 0u) << "got: " << f.error;
    }
}

TEST(PatchFile, UnknownExtensionAndMissingFile) {
    EXPECT_NE(read_patch_file("model.stl").error.find("unknown patch format"), std::string::npos);
    const PatchFile missing = read_patch_file("/nonexistent/model.bpt");
    EXPECT_TRUE(missing.io_error);
}

TEST(PatchFile, BundledExamplesRead) {
    for (const char* name : {"arch.map", "pipe.map", "wave.bpt", "terrain.json"}) {
        // One literal, then one append: GCC 12 at -O1 took string + literal +
        // name for a write past the buffer (-Warray-bounds, a false positive).
        const PatchFile f = read_patch_file(CASTELJAU_EXAMPLES "/patch/" + std::string(name));
        EXPECT_TRUE(f.model) << f.error;
    }
}

TEST(MeshWrite, ObjAndPlyHoldTheMesh) {
    Mesh mesh;
    tessellate_uniform(test::sphere_model(), 3, 3, mesh);
    const auto dir = std::filesystem::temp_directory_path();
    const std::string obj = (dir / "casteljau_mesh_test.obj").string();
    const std::string ply = (dir / "casteljau_mesh_test.ply").string();
    ASSERT_EQ(write_mesh_atomic(obj, mesh), "");
    ASSERT_EQ(write_mesh_atomic(ply, mesh), "");
    std::ifstream in(obj);
    std::size_t v = 0, vt = 0, vn = 0, f = 0;
    for (std::string line; std::getline(in, line);) {
        const std::string tag = line.substr(0, line.find(' '));
        v += tag == "v", vt += tag == "vt", vn += tag == "vn", f += tag == "f";
    }
    EXPECT_EQ(v, mesh.positions.size());
    EXPECT_EQ(vt, v);
    EXPECT_EQ(vn, v);
    EXPECT_EQ(f, mesh.triangles.size());
    // Binary PLY: header, then 8 floats a vertex and 13 bytes a face.
    std::ifstream bin(ply, std::ios::binary);
    std::string header, line;
    while (std::getline(bin, line) && line != "end_header") header += line + "\n";
    const auto body = std::filesystem::file_size(ply) - header.size() - 11;
    EXPECT_EQ(body, mesh.positions.size() * 32 + mesh.triangles.size() * 13);
    EXPECT_NE(write_mesh_atomic((dir / "x.stl").string(), mesh).find("unknown mesh format"),
              std::string::npos);
    std::filesystem::remove(obj);
    std::filesystem::remove(ply);
}

} // namespace
} // namespace casteljau
