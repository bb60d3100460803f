// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh files: OFF, OBJ, legacy VTK, VTU, MSH (read by Gmsh itself, gmsh_reader_test.cpp) and binary
// STL read back to the same numbers; unknown extensions are refused before anything is written; the
// SVG picture.
#include "disktune/mesh_io.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../src/io/polygon_soup.h"
#include "disktune/boundary.h"
#include "disktune/errors.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/surface_mesh.h"
#include "lattices.h"
#include "test_util.h"

namespace disktune {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

TriangleMesh small_mesh() {
  // A shifted hex lattice: copies across the seam, coordinates with many digits.
  const Packing base = test::hex_lattice(6, 4, 0.3, 0.3);
  Packing p(base.frame(), 0.3);
  for (DiskId id : base.ids()) p.insert(base.center(id) + Vec2{0.0123456789, 0.1}, 0.3);
  return periodic_delaunay(p);
}

TEST(MeshIo, OffReadsBackEveryNumber) {
  TempDir dir;
  const TriangleMesh m = small_mesh();
  write_mesh(dir.file("m.off"), m);
  std::ifstream in(dir.file("m.off"));
  std::string magic;
  std::size_t nv, nf, ne;
  in >> magic >> nv >> nf >> ne;
  EXPECT_EQ(magic, "OFF");
  ASSERT_EQ(nv, m.vertices.size());
  ASSERT_EQ(nf, m.triangles.size());
  for (const Vec2 p : m.vertices) {
    double x, y, z;
    in >> x >> y >> z;
    EXPECT_EQ(x, p.x);
    EXPECT_EQ(y, p.y);
    EXPECT_EQ(z, 0);
  }
  for (const auto& t : m.triangles) {
    std::uint32_t k, a, b, c;
    in >> k >> a >> b >> c;
    EXPECT_EQ(k, 3u);
    EXPECT_EQ((std::array<std::uint32_t, 3>{a, b, c}), t);
  }
}

TEST(MeshIo, ObjCountsVerticesFromOne) {
  TempDir dir;
  const TriangleMesh m = small_mesh();
  write_mesh(dir.file("m.OBJ"), m);  // the extension in any case
  std::ifstream in(dir.file("m.OBJ"));
  std::string line;
  std::size_t v = 0, f = 0;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      double x, y;
      s >> x >> y;
      EXPECT_EQ(Vec2(x, y), m.vertices[v]);
      ++v;
    } else if (tag == "f") {
      std::uint32_t a, b, c;
      s >> a >> b >> c;
      EXPECT_EQ((std::array<std::uint32_t, 3>{a - 1, b - 1, c - 1}), m.triangles[f]);
      ++f;
    }
  }
  EXPECT_EQ(v, m.vertices.size());
  EXPECT_EQ(f, m.triangles.size());
}

TEST(MeshIo, VtkHasPointsPolygonsAndDiskIds) {
  TempDir dir;
  const TriangleMesh m = small_mesh();
  write_mesh(dir.file("m.vtk"), m);
  std::ifstream in(dir.file("m.vtk"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  EXPECT_EQ(s.rfind("# vtk DataFile Version 3.0\n", 0), 0u);
  // An unstructured grid (meshio reads no polygonal data): the triangles as cells of type 5.
  EXPECT_NE(s.find("\nASCII\nDATASET UNSTRUCTURED_GRID\n"), std::string::npos);
  EXPECT_NE(s.find("POINTS " + std::to_string(m.vertices.size()) + " double\n"), std::string::npos);
  EXPECT_NE(s.find("CELLS " + std::to_string(m.triangles.size()) + " " + std::to_string(4 * m.triangles.size()) + "\n"),
            std::string::npos);
  std::string types = "CELL_TYPES " + std::to_string(m.triangles.size()) + "\n";
  for (std::size_t t = 0; t < m.triangles.size(); ++t) types += "5\n";
  EXPECT_NE(s.find(types), std::string::npos);
  EXPECT_NE(s.find("POINT_DATA " + std::to_string(m.vertices.size()) +
                   "\nSCALARS disk_id unsigned_int 1\nLOOKUP_TABLE default\n"),
            std::string::npos);
}

// Every mesh kind goes through one writer: a planar mesh as PLY and a surface mesh as
// VTK read back, vertex for vertex, through the project's own reader and by hand.
TEST(MeshIo, EveryFormatServesEveryMeshKind) {
  TempDir dir;
  const TriangleMesh m = small_mesh();
  write_mesh(dir.file("m.ply"), m);
  const detail::PolygonSoup soup = detail::read_polygon_soup(dir.file("m.ply"));
  ASSERT_EQ(soup.points.size(), m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    EXPECT_EQ(soup.points[i][0], m.vertices[i].x);
    EXPECT_EQ(soup.points[i][1], m.vertices[i].y);
    EXPECT_EQ(soup.points[i][2], 0.0);
  }
  ASSERT_EQ(soup.polygons.size(), m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    EXPECT_EQ(soup.polygons[t], (std::vector<std::size_t>{m.triangles[t][0], m.triangles[t][1], m.triangles[t][2]}));
  }

  const SurfaceMesh tetra{{{0, 0, 0}, {1, 0, 1.0 / 3}, {0, 1, 0}, {0, 0, 1.0 / 7}}, {{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}}};
  write_surface_mesh(dir.file("t.vtk"), tetra);
  std::ifstream in(dir.file("t.vtk"));
  std::string line;
  while (std::getline(in, line) && line != "POINTS 4 double") {}
  for (const Vec3& p : tetra.vertices) {
    double x, y, z;
    in >> x >> y >> z;
    EXPECT_EQ((Vec3{x, y, z}), p);
  }
  in >> line;
  EXPECT_EQ(line, "CELLS");
  std::size_t n = 0, words = 0;
  in >> n >> words;
  EXPECT_EQ(n, 4u);
  EXPECT_EQ(words, 16u);
}

// A tetrahedron with two feature edges, coordinates with many digits.
SurfaceMesh tetrahedron() {
  SurfaceMesh m{{{0, 0, 0}, {1, 0, 1.0 / 3}, {0, 1, 0}, {0, 0, 1.0 / 7}},
                {{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}}};
  m.feature_edges = {{0, 1}, {1, 2}};
  return m;
}

// Base64 decoded, the test's own way: each digit's six bits, in order, '=' ending it.
std::string from_base64(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned bits = 0, held = 0;
  for (const char c : text) {
    if (c == '=') break;
    const std::size_t v = digits.find(c);
    if (v == std::string::npos) continue;  // line breaks, spaces
    bits = bits << 6 | static_cast<unsigned>(v), held += 6;
    if (held >= 8) out += static_cast<char>(bits >> (held - 8) & 0xff), held -= 8;
  }
  return out;
}

// The values of the binary DataArray whose opening tag holds `attribute` (Name="..."):
// base64 of a UInt64 byte count and the values of its type, as doubles.
std::vector<double> vtu_array(const std::string& text, const std::string& attribute) {
  const std::size_t tag = text.find(attribute);
  EXPECT_NE(tag, std::string::npos) << attribute;
  const std::size_t open = text.rfind("<DataArray", tag), from = text.find('>', tag) + 1;
  const std::string head = text.substr(open, from - open);
  EXPECT_NE(head.find("format=\"binary\""), std::string::npos) << head;
  const std::string bytes = from_base64(text.substr(from, text.find("</DataArray>", from) - from));
  std::uint64_t count = 0;
  EXPECT_GE(bytes.size(), sizeof count);
  std::memcpy(&count, bytes.data(), sizeof count);
  EXPECT_EQ(count, bytes.size() - sizeof count) << head;
  std::vector<double> out;
  const auto take = [&](auto zero) {
    for (std::size_t at = sizeof count; at + sizeof zero <= bytes.size(); at += sizeof zero) {
      std::memcpy(&zero, bytes.data() + at, sizeof zero);
      out.push_back(static_cast<double>(zero));
    }
  };
  if (head.find("\"Float64\"") != std::string::npos) take(double{});
  if (head.find("\"Int64\"") != std::string::npos) take(std::int64_t{});
  if (head.find("\"UInt32\"") != std::string::npos) take(std::uint32_t{});
  if (head.find("\"UInt8\"") != std::string::npos) take(std::uint8_t{});
  return out;
}

TEST(MeshIo, VtuHoldsPointsCellsLinesAndDiskIdsInBase64) {
  TempDir dir;
  const SurfaceMesh tetra = tetrahedron();
  write_surface_mesh(dir.file("t.vtu"), tetra);
  std::ifstream in(dir.file("t.vtu"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"4\" NumberOfCells=\"6\">"), std::string::npos);
  const std::vector<double> points = vtu_array(text, "NumberOfComponents=\"3\"");
  ASSERT_EQ(points.size(), 3 * tetra.vertices.size());
  for (std::size_t k = 0; k < tetra.vertices.size(); ++k)
    EXPECT_EQ((Vec3{points[3 * k], points[3 * k + 1], points[3 * k + 2]}), tetra.vertices[k]);
  EXPECT_EQ(vtu_array(text, "Name=\"connectivity\""),
            (std::vector<double>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 1, 1, 2}));
  EXPECT_EQ(vtu_array(text, "Name=\"offsets\""), (std::vector<double>{3, 6, 9, 12, 14, 16}));
  EXPECT_EQ(vtu_array(text, "Name=\"types\""), (std::vector<double>{5, 5, 5, 5, 3, 3}));
  const TriangleMesh m = small_mesh();
  write_mesh(dir.file("m.vtu"), m);
  std::ifstream in2(dir.file("m.vtu"));
  const std::string periodic((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>());
  const std::vector<double> ids = vtu_array(periodic, "Name=\"disk_id\"");
  ASSERT_EQ(ids.size(), m.vertex_disk.size());
  for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(ids[i], m.vertex_disk[i]);
}

// Triangle's .node/.ele pair, read back by hand: numbered from 1, every coordinate
// exact, the triangles as they are, and a vertex's boundary marker 1 + the number of the
// loop it lies on (found geometrically, on the domain's own segments), 0 inside; the
// periodic mesh has no boundary. Both files or neither: a failure writing the second
// leaves no first. A surface, or a path that is not .node/.ele, is refused.
TEST(MeshIo, TriangleNodeAndEleFilesHoldTheMeshAndItsBoundaryLoops) {
  TempDir dir;
  const std::vector<std::vector<Vec2>> loops = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                                {{0.2, 0.2}, {0.2, 0.4}, {0.4, 0.4}, {0.4, 0.2}},
                                                {{0.6, 0.6}, {0.6, 0.8}, {0.8, 0.8}, {0.8, 0.6}}};
  const auto domain = std::make_shared<const PlanarDomain>(
      loops[0], std::vector<std::vector<Vec2>>{loops[1], loops[2]});
  Rng rng(5);
  Packing packing = sample_mps(domain, 0.05, rng);
  const PlanarMesh planar = constrained_delaunay(packing, boundary_loops(packing, *domain));
  const auto loop_of = [&](Vec2 p) -> int {  // 1 + the loop p lies on, else 0
    for (std::size_t k = 0; k < loops.size(); ++k)
      for (std::size_t i = 0; i < loops[k].size(); ++i) {
        const Vec2 a = loops[k][i], b = loops[k][(i + 1) % loops[k].size()];
        const double t = dot(p - a, b - a) / dot(b - a, b - a);
        if (t >= -1e-12 && t <= 1 + 1e-12 && squared_norm(a + (b - a) * t - p) < 1e-24)
          return static_cast<int>(k) + 1;
      }
    return 0;
  };
  const auto check = [&](const std::vector<Vec2>& vertices,
                         const std::vector<std::array<std::uint32_t, 3>>& triangles,
                         const std::string& stem, bool bounded) {
    SCOPED_TRACE(stem);
    std::ifstream node(dir.file(stem + ".node")), ele(dir.file(stem + ".ele"));
    std::string comment;
    std::getline(node, comment);
    EXPECT_EQ(comment[0], '#');
    std::size_t n = 0, dimension = 0, attributes = 0, markers = 0;
    node >> n >> dimension >> attributes >> markers;
    ASSERT_EQ(n, vertices.size());
    EXPECT_EQ(dimension, 2u);
    EXPECT_EQ(attributes, 0u);
    EXPECT_EQ(markers, 1u);
    std::size_t on_loops = 0;
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t number = 0;
      double x = 0, y = 0;
      int marker = -1;
      node >> number >> x >> y >> marker;
      EXPECT_EQ(number, k + 1);
      EXPECT_EQ((Vec2{x, y}), vertices[k]);
      EXPECT_EQ(marker, bounded ? loop_of(vertices[k]) : 0) << "vertex " << k + 1;
      on_loops += marker > 0;
    }
    if (bounded) {
      EXPECT_GT(on_loops, 12u);
    }
    std::getline(ele, comment);
    std::getline(ele, comment);
    std::size_t nt = 0, corners = 0;
    std::istringstream(comment) >> nt >> corners >> attributes;
    ASSERT_EQ(nt, triangles.size());
    EXPECT_EQ(corners, 3u);
    for (std::size_t t = 0; t < nt; ++t) {
      std::size_t number = 0, a = 0, b = 0, c = 0;
      ele >> number >> a >> b >> c;
      EXPECT_EQ(number, t + 1);
      EXPECT_EQ((std::array<std::uint32_t, 3>{std::uint32_t(a - 1), std::uint32_t(b - 1),
                                              std::uint32_t(c - 1)}),
                triangles[t]);
    }
  };
  write_mesh(dir.file("planar.node"), planar);
  check(planar.vertices, planar.triangles, "planar", true);
  const TriangleMesh periodic = small_mesh();
  write_mesh(dir.file("torus.ele"), periodic);  // either name gives both files
  check(periodic.vertices, periodic.triangles, "torus", false);

  fs::create_directory(dir.file("blocked.ele"));  // the second file cannot be written
  EXPECT_THROW(write_mesh(dir.file("blocked.node"), planar), IoError);
  EXPECT_FALSE(fs::exists(dir.file("blocked.node")));
  EXPECT_THROW(write_surface_mesh(dir.file("t.node"), tetrahedron()), InvalidInput);
  EXPECT_THROW(write_mesh(dir.file("m.off"), planar, MeshFormat::Triangle), InvalidInput);
  EXPECT_EQ(mesh_format_named("triangle"), MeshFormat::Triangle);
  EXPECT_FALSE(fs::exists(dir.file("t.node")) || fs::exists(dir.file("t.ele")) ||
               fs::exists(dir.file("m.off")));
}

TEST(MeshIo, StlIsBinaryWithUnitNormals) {
  TempDir dir;
  const SurfaceMesh tetra = tetrahedron();
  write_surface_mesh(dir.file("t.stl"), tetra);
  EXPECT_EQ(fs::file_size(dir.file("t.stl")), 84u + 50u * 4);
  std::ifstream in(dir.file("t.stl"), std::ios::binary);
  char header[80];
  in.read(header, 80);
  EXPECT_NE(std::string(header, 80).rfind("solid", 0), 0u);  // readers take "solid" for ASCII
  std::uint32_t count = 0;
  in.read(reinterpret_cast<char*>(&count), 4);
  ASSERT_EQ(count, 4u);
  for (const auto& t : tetra.triangles) {
    float record[12];
    in.read(reinterpret_cast<char*>(record), sizeof record);
    const Vec3 n{record[0], record[1], record[2]};
    EXPECT_NEAR(norm(n), 1, 1e-6);
    for (int k = 0; k < 3; ++k) {
      const Vec3 v = tetra.vertices[t[k]];
      EXPECT_EQ(record[3 + 3 * k], static_cast<float>(v.x));
      EXPECT_EQ(record[4 + 3 * k], static_cast<float>(v.y));
      EXPECT_EQ(record[5 + 3 * k], static_cast<float>(v.z));
    }
    const Vec3 a = tetra.vertices[t[0]], b = tetra.vertices[t[1]], c = tetra.vertices[t[2]];
    EXPECT_GT(dot(n, cross(b - a, c - a)), 0);  // the triangle's own orientation
    EXPECT_NEAR(dot(n, b - a), 0, 1e-6);
    in.ignore(2);
  }
}

TEST(MeshIo, UnknownExtensionIsRefusedAndWritesNothing) {
  TempDir dir;
  const TriangleMesh m = small_mesh();
  for (const char* name : {"m.xyz", "m", "m.off.txt"}) {
    try {
      write_mesh(dir.file(name), m);
      ADD_FAILURE() << name << " was accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(".off, .obj, .ply, .vtk"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(MeshIo, SvgDrawsDisksAndEdges) {
  TempDir dir;
  const Packing p = test::hex_lattice(6, 4, 0.3, 0.3);
  write_mesh_svg(dir.file("m.svg"), periodic_delaunay(p), p);
  std::ifstream in(dir.file("m.svg"));
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("<svg"), std::string::npos);
  EXPECT_NE(text.str().find("<circle"), std::string::npos);
  EXPECT_NE(text.str().find("<path fill=\"none\""), std::string::npos);
  EXPECT_EQ(text.str().substr(text.str().size() - 7), "</svg>\n");
}

}  // namespace
}  // namespace disktune
