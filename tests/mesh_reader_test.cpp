// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh file readers (OFF, OBJ, PLY, STL; issue #17): malformed files give
// InvalidInput naming the file and the line or element, counts a file cannot hold fail
// fast, binary garbage is never echoed, no flipped byte crashes a reader, and valid files
// give exactly the soup CGAL 5.5's reader gives (same doubles, same order).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "../src/io/polygon_soup.h"
#include "disktune/errors.h"
#include "test_util.h"

namespace disktune {
namespace {

using detail::PolygonSoup;
using detail::read_polygon_soup;
using test::message_of;
using test::TempDir;

const std::string kData = std::string(DISKTUNE_DATA_DIR) + "/";
const std::string kMeshes = kData + "../tests/data/meshes/";

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

PolygonSoup cgal_soup(const std::string& path) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  PolygonSoup soup;
  EXPECT_TRUE(CGAL::IO::read_polygon_soup(path, points, soup.polygons)) << path;
  for (const Point& p : points) soup.points.push_back({p.x(), p.y(), p.z()});
  return soup;
}

/// Our reader gives CGAL's soup bit for bit (so -0 and 0 differ here).
void expect_as_cgal(const std::string& path) {
  SCOPED_TRACE(path);
  const PolygonSoup ours = read_polygon_soup(path);
  const PolygonSoup cgal = cgal_soup(path);
  ASSERT_EQ(ours.points.size(), cgal.points.size());
  ASSERT_EQ(ours.polygons.size(), cgal.polygons.size());
  EXPECT_EQ(std::memcmp(ours.points.data(), cgal.points.data(),
                        ours.points.size() * sizeof(ours.points[0])),
            0);
  EXPECT_EQ(ours.polygons, cgal.polygons);
  EXPECT_FALSE(ours.polygons.empty());
}

/// Messages carry printable ASCII only, and not much of it.
void expect_printable(const std::string& msg) {
  for (const char c : msg) {
    EXPECT_TRUE(c >= 0x20 && c < 0x7f)
        << "byte " << int(static_cast<unsigned char>(c)) << " in " << msg;
  }
  EXPECT_LT(msg.size(), 400u) << msg;
}

/// The message of the InvalidInput that reading `bytes` as dir/name throws, after
/// checking that it names the file and is printable.
std::string refusal(const TempDir& dir, const std::string& name, const std::string& bytes) {
  const std::string path = dir.file(name);
  write_bytes(path, bytes);
  const std::string msg = message_of<InvalidInput>([&] { read_polygon_soup(path); });
  EXPECT_TRUE(mentions(msg, name)) << msg;
  expect_printable(msg);
  return msg;
}

/// The same, and it must be quick: the count is refused before anything is allocated.
std::string fast_refusal(const TempDir& dir, const std::string& name, const std::string& bytes) {
  const auto start = std::chrono::steady_clock::now();
  const std::string msg = refusal(dir, name, bytes);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0) << msg;
  return msg;
}

template <class T>
void put(std::string& out, T value, bool big_endian = false) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof value);
  if (big_endian) std::reverse(b, b + sizeof b);  // the tests run on little-endian hosts
  out.append(b, sizeof b);
}

// A tetrahedron with coordinates that are not exact in float, so widening is seen.
const std::vector<std::array<float, 3>> kTetra = {
    {0.1f, 0.2f, 0.3f}, {1.7f, 0.1f, -0.3f}, {0.3f, 1.9f, 0.1f}, {-0.2f, 0.3f, 1.3f}};
const std::vector<std::array<int, 3>> kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

std::string binary_ply(bool big_endian) {
  std::string out = std::string("ply\nformat binary_") + (big_endian ? "big" : "little") +
                    "_endian 1.0\ncomment test\nelement vertex 4\nproperty float x\n"
                    "property float y\nproperty float z\nproperty uchar flag\nelement face 4\n"
                    "property list uchar int vertex_indices\nelement edge 1\n"
                    "property list uchar float weights\nend_header\n";
  for (const auto& p : kTetra) {
    for (const float c : p) put(out, c, big_endian);
    put(out, std::uint8_t{7}, big_endian);
  }
  for (const auto& f : kTetraFaces) {
    put(out, std::uint8_t{3}, big_endian);
    for (const int i : f) put(out, std::int32_t{i}, big_endian);
  }
  put(out, std::uint8_t{2}, big_endian);
  put(out, 0.5f, big_endian);
  put(out, 0.25f, big_endian);
  return out;
}

const char* kAsciiPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0.1 0.2 0.3\n1.7 0.1 -0.3\n0.3 1.9 0.1\n-0.2 0.3 1.3\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

const char* kOff =
    "OFF\n4 4 0\n0.1 0.2 0.3\n1.7 0.1 -0.3\n0.3 1.9 0.1\n-0.2 0.3 1.3\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

const char* kObj =
    "v 0.1 0.2 0.3\nv 1.7 0.1 -0.3\nv 0.3 1.9 0.1\nv -0.2 0.3 1.3\n"
    "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

std::string ascii_stl() {
  std::string out = "solid tetra\n";
  for (const auto& f : kTetraFaces) {
    out += "  facet normal 0 0 1\n    outer loop\n";
    for (const int i : f) {
      out += "      vertex " + std::to_string(kTetra[i][0]) + " " + std::to_string(kTetra[i][1]) +
             " " + std::to_string(kTetra[i][2]) + "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid tetra\n";
}

std::string binary_stl(const std::string& header_start) {
  std::string out = header_start;
  out.resize(80, ' ');
  put(out, std::uint32_t(kTetraFaces.size()));
  for (const auto& f : kTetraFaces) {
    for (int k = 0; k < 3; ++k) put(out, 0.0f);  // the normal
    for (const int i : f) {
      for (const float c : kTetra[i]) put(out, c);
    }
    put(out, std::uint16_t{0});
  }
  return out;
}

std::string crlf(std::string text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

// --- valid files: the very soup CGAL gives --------------------------------------------

TEST(MeshReader, DataFilesReadAsCgalReadsThem) {
  std::vector<std::string> files = {kData + "domains/square_with_hole.off"};
  for (const auto& entry : std::filesystem::directory_iterator(kData + "surfaces")) {
    if (entry.path().extension() == ".off") files.push_back(entry.path().string());
  }
  EXPECT_GE(files.size(), 6u);
  for (const std::string& f : files) expect_as_cgal(f);
}

// Small files from CGAL's data set (tests/data/meshes/README.md): an ascii PLY, a binary
// STL (CGAL merges equal corners: 162 points, not 3 x 320), a PLY with colours and an
// edge element to read past, a COFF with comments after values and a face of 5 corners,
// and an OFF of quads.
TEST(MeshReader, CgalSamplesReadAsCgalReadsThem) {
  for (const char* name :
       {"sphere.ply", "sphere.stl", "colored_tetra.ply", "mesh_with_colors.off", "cube_poly.off"}) {
    expect_as_cgal(kMeshes + name);
  }
  const PolygonSoup stl = read_polygon_soup(kMeshes + "sphere.stl");
  EXPECT_EQ(stl.points.size(), 162u);
  EXPECT_EQ(stl.polygons.size(), 320u);
  const PolygonSoup quads = read_polygon_soup(kMeshes + "cube_poly.off");
  EXPECT_EQ(quads.polygons[2].size(), 4u);  // kept: the callers refuse them with their message
}

TEST(MeshReader, GeneratedFilesReadAsCgalReadsThem) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"t.off", kOff},
      {"comments.off",
       "# a comment\n\n#another\nOFF # keyword\n# between\n4 4 0 # counts\n"
       "0.1 0.2 0.3 # v0\n1.7 0.1 -0.3\n# in between\n0.3 1.9 0.1\n-0.2 0.3 1.3\n"
       "3 0 2 1 # f0\n3 0 1 3\n3 1 2 3\n3 0 3 2 1 0 0\n"},
      {"same_line.off",
       "OFF 4 4 0\n0.1 0.2 0.3\n1.7 0.1 -0.3\n0.3 1.9 0.1\n-0.2 0.3 1.3\n"
       "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2"},
      {"noff.off",
       "NOFF\n4 4 0\n0.1 0.2 0.3 0 0 1\n1.7 0.1 -0.3 0 0 1\n0.3 1.9 0.1 0 0 1\n"
       "-0.2 0.3 1.3 0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {"homogeneous.off",
       "4OFF\n4 4 0\n0.2 0.4 0.6 2\n1.7 0.1 -0.3 1\n0.9 5.7 0.3 3\n"
       "-0.2 0.3 1.3 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {"crlf.off", crlf(kOff)},
      {"t.obj", kObj},
      {"slashes.obj",
       "# exported\nmtllib m.mtl\no tetra\nv 0.1 0.2 0.3\nv 1.7 0.1 -0.3\nv 0.3 1.9 0.1\n"
       "v -0.2 0.3 1.3 1.0\nvt 0 0\nvn 0 0 1\ng g1\nusemtl m\ns off\n"
       "f 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf -3/1 -2/1 -1/1\nf 1 4 3 # last\n"},
      {"crlf.obj", crlf(kObj)},
      {"ascii.ply", kAsciiPly},
      {"crlf.ply", crlf(kAsciiPly)},
      {"little.ply", binary_ply(false)},
      {"big.ply", binary_ply(true)},
      {"ascii.stl", ascii_stl()},
      {"crlf.stl", crlf(ascii_stl())},
      {"binary.stl", binary_stl("binary STL written by a test")},
      {"solid_header.stl", binary_stl("solid but binary")},
  };
  for (const auto& [name, bytes] : files) {
    write_bytes(dir.file(name), bytes);
    expect_as_cgal(dir.file(name));
  }
}

TEST(MeshReader, ByteOrderMarkIsSkipped) {
  TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"t.off", kOff}, {"t.obj", kObj}, {"t.ply", kAsciiPly}, {"t.stl", ascii_stl()}}) {
    write_bytes(dir.file(name), bytes);
    write_bytes(dir.file("bom_" + name), bom + bytes);
    const PolygonSoup plain = read_polygon_soup(dir.file(name));
    const PolygonSoup marked = read_polygon_soup(dir.file("bom_" + name));
    EXPECT_EQ(marked.points, plain.points) << name;
    EXPECT_EQ(marked.polygons, plain.polygons) << name;
  }
}

// --- finding 1: PLY headers that crashed CGAL ------------------------------------------

TEST(MeshReader, PlyPropertyBeforeAnyElementIsRefused) {
  TempDir dir;
  const std::string msg =
      refusal(dir, "early.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n");
  EXPECT_TRUE(mentions(msg, "line 3")) << msg;
  EXPECT_TRUE(mentions(msg, "before any element")) << msg;
}

// Every single-bit flip of every byte of small valid files (headers and some data):
// the reader returns a sound soup or throws InvalidInput, nothing else.
TEST(MeshReader, NoFlippedBitCrashesAReader) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> files = {{"f.ply", binary_ply(false)},
                                                                  {"f.ply", binary_ply(true)},
                                                                  {"f.ply", kAsciiPly},
                                                                  {"f.off", kOff},
                                                                  {"f.obj", kObj},
                                                                  {"f.stl", ascii_stl()},
                                                                  {"f.stl", binary_stl("x")},
                                                                  {"f.stl", binary_stl("solid x")}};
  int refused = 0, accepted = 0;
  for (const auto& [name, good] : files) {
    const std::size_t end = std::min<std::size_t>(good.size(), 360);
    for (std::size_t i = 0; i < end; ++i) {
      for (int bit = 0; bit < 8; ++bit) {
        std::string bytes = good;
        bytes[i] = static_cast<char>(bytes[i] ^ (1 << bit));
        write_bytes(dir.file(name), bytes);
        try {
          const PolygonSoup soup = read_polygon_soup(dir.file(name));
          for (const auto& p : soup.points) {
            for (const double c : p) ASSERT_TRUE(std::isfinite(c)) << name << " byte " << i;
          }
          for (const auto& poly : soup.polygons) {
            ASSERT_GE(poly.size(), 3u) << name << " byte " << i;
            for (const std::size_t v : poly)
              ASSERT_LT(v, soup.points.size()) << name << " byte " << i;
          }
          ++accepted;
        } catch (const InvalidInput& e) {
          expect_printable(e.what());
          ++refused;
        } catch (const std::exception& e) {
          ADD_FAILURE() << name << " byte " << i << " bit " << bit << ": " << e.what();
        }
      }
    }
  }
  EXPECT_GT(refused, 1000);
  EXPECT_GT(accepted, 100);
}

TEST(MeshReader, PlyHeaderProblemsAreNamed) {
  TempDir dir;
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 1\n";
  const std::string tail = "end_header\n0 0 0\n";
  struct Case {
    std::string bytes, line, words;
  };
  const std::vector<Case> cases = {
      {"plx\n" + head.substr(4) + tail, "line 1", "starts with the line 'ply'"},
      {"ply\nformat ascii_text 1.0\n", "line 2", "unknown format 'ascii_text'"},
      {head + "property flaot x\n" + tail, "line 4", "unknown type 'flaot'"},
      {head + "property float x\nproperty float y\n" + tail, "line 3", "no property 'z'"},
      {head + "property list vertex_indices\n" + tail, "line 4", "property list COUNT_TYPE"},
      {head + "property list float int vertex_indices\n" + tail, "line 4", "integer type"},
      {head + "property float x\nproperty float y\nproperty float z\nelemfnt face 0\n" + tail,
       "line 7", "unknown header line 'elemfnt'"},
      {head + "property float x\nproperty float y\nproperty float z\n", "line 7", "no end_header"},
      {"ply\nformat ascii 1.0\nelement vertex -1\n" + tail, "line 3", "not '-1'"},
      {head + "property float x\nproperty float y\nproperty float z\nelement face 1\n"
              "property list uchar int corners\nend_header\n0 0 0\n3 0 0 0\n",
       "line 7", "no list of integers 'vertex_indices'"},
  };
  for (const Case& c : cases) {
    const std::string msg = refusal(dir, "h.ply", c.bytes);
    EXPECT_TRUE(mentions(msg, "h.ply, " + c.line + ":")) << msg;
    EXPECT_TRUE(mentions(msg, c.words)) << msg;
  }
}

// --- finding 2: counts a file cannot hold fail before anything is allocated ------------

TEST(MeshReader, OffCountsBeyondTheFileFailFast) {
  TempDir dir;
  // A face line claiming 2e8 corners (CGAL allocated 1.5 GB for it).
  std::string msg =
      fast_refusal(dir, "corners.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n200000000 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 6: face 0 declares 200000000 corners but lists 3")) << msg;
  msg = fast_refusal(dir, "faces.off", "OFF\n3 200000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 2: the header promises 3 vertices and 200000000 faces")) << msg;
  msg = fast_refusal(dir, "vertices.off", "OFF\n2000000000000 1 0\n0 0 0\n");
  EXPECT_TRUE(mentions(msg, "2000000000000 vertices")) << msg;
  msg = fast_refusal(dir, "overflow.off", "OFF\n99999999999999999999 1 0\n0 0 0\n");
  EXPECT_TRUE(mentions(msg, "line 2: expected the number of vertices")) << msg;
  EXPECT_TRUE(mentions(msg, "too large")) << msg;
  msg = fast_refusal(dir, "negative.off", "OFF\n3 -1 0\n0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_TRUE(mentions(msg, "line 2: expected the number of faces")) << msg;
  msg = fast_refusal(dir, "negative_corners.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 6: face 0 has -3 corners")) << msg;
}

TEST(MeshReader, PlyCountsBeyondTheFileFailFast) {
  TempDir dir;
  const std::string header =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list int int vertex_indices\nend_header\n";
  // A list length of 2e8 (CGAL allocated 768 MB for it), ascii and binary.
  std::string msg =
      fast_refusal(dir, "list.ply",
                   "ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n0 1 0\n200000000 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 13: face 0: the list 'vertex_indices' claims 200000000")) << msg;
  std::string bin = "ply\nformat binary_little_endian 1.0\n" + header;
  for (int k = 0; k < 9; ++k) put(bin, k == 3 || k == 7 ? 1.0f : 0.0f);
  put(bin, std::int32_t{200000000});
  for (int k = 0; k < 3; ++k) put(bin, std::int32_t{k});
  msg = fast_refusal(dir, "list_binary.ply", bin);
  EXPECT_TRUE(mentions(msg, "face 0: the list 'vertex_indices' claims 200000000")) << msg;
  // A negative length.
  std::string neg = bin.substr(0, bin.size() - 16);
  put(neg, std::int32_t{-5});
  neg += std::string(12, '\0');
  msg = fast_refusal(dir, "negative_list.ply", neg);
  EXPECT_TRUE(mentions(msg, "face 0: the list 'vertex_indices' has a negative length")) << msg;
  // Element counts: more vertices than the bytes hold, binary and ascii; a count too large.
  msg = fast_refusal(dir, "vertices.ply",
                     "ply\nformat binary_big_endian 1.0\nelement vertex 1000000000\n"
                     "property double x\nproperty double y\nproperty double z\nend_header\n" +
                         std::string(48, '\0'));
  EXPECT_TRUE(mentions(msg, "line 3: the element 'vertex' has 1000000000 items")) << msg;
  EXPECT_TRUE(mentions(msg, "only 48 bytes follow the header")) << msg;
  msg = fast_refusal(dir, "faces.ply",
                     "ply\nformat ascii 1.0\n" +
                         std::string(header).replace(header.find("face 1"), 6, "face 4000000000") +
                         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 7: the element 'face' has 4000000000 items")) << msg;
  msg = fast_refusal(dir, "huge.ply", "ply\nformat ascii 1.0\nelement vertex 1e30\nend_header\n");
  EXPECT_TRUE(mentions(msg, "line 3: an element line reads")) << msg;
}

TEST(MeshReader, StlCountBeyondTheFileFailsFast) {
  TempDir dir;
  std::string bytes = binary_stl("x");
  bytes[82] = '\x01';  // 65540 triangles claimed: the file holds 4
  std::string msg = fast_refusal(dir, "count.stl", bytes);
  EXPECT_TRUE(mentions(msg, "counts 65540 triangles, which take 3277084 bytes")) << msg;
  EXPECT_TRUE(mentions(msg, "the file has 284")) << msg;
  // Truncated by one byte, even with a header that starts like an ascii file.
  bytes = binary_stl("solid x");
  msg = fast_refusal(dir, "cut.stl", bytes.substr(0, bytes.size() - 1));
  EXPECT_TRUE(mentions(msg, "counts 4 triangles")) << msg;
  msg = refusal(dir, "short.stl", "not an stl");
  EXPECT_TRUE(mentions(msg, "too short for a binary STL")) << msg;
}

// --- finding 3: every kind of wrong content is named ----------------------------------

TEST(MeshReader, NonFiniteCoordinatesAreNamed) {
  TempDir dir;
  std::string msg = refusal(dir, "nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 4: vertex 1: 'nan' is not a finite number")) << msg;
  msg = refusal(dir, "big.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 1e400\n3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 5: vertex 2: '1e400' is not a finite number")) << msg;
  msg = refusal(dir, "w.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 4: vertex 1 has the homogeneous coordinate w = '0'")) << msg;
  msg = refusal(dir, "inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
  EXPECT_TRUE(mentions(msg, "line 3: vertex 2 (OBJ index 3): 'inf' is not a finite number")) << msg;
  msg = refusal(dir, "nan.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n0 1 -nan\n3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 12: vertex 2 has a coordinate that is not a finite")) << msg;
  std::string ply = binary_ply(false);
  const std::size_t body = ply.find("end_header\n") + 11;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&ply[body + 13 + 4], &nan, 4);  // vertex 1's y
  msg = refusal(dir, "nan_binary.ply", ply);
  EXPECT_TRUE(mentions(msg, "vertex 1 has a coordinate that is not a finite number")) << msg;
  std::string stl = ascii_stl();
  stl.replace(stl.find("vertex ") + 7, 8, "inf");
  msg = refusal(dir, "inf.stl", stl);
  EXPECT_TRUE(mentions(msg, "line 4: facet 0: 'inf' is not a finite number")) << msg;
  stl = binary_stl("x");
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(&stl[84 + 50 + 12 + 12 + 8], &inf, 4);  // triangle 1, corner 1, z
  msg = refusal(dir, "inf_binary.stl", stl);
  EXPECT_TRUE(mentions(msg, "triangle 1, corner 1 has a coordinate that is not a finite")) << msg;
}

TEST(MeshReader, FaceIndicesOutOfRangeAreNamed) {
  TempDir dir;
  const std::string v3 = "0 0 0\n1 0 0\n0 1 0\n";
  std::string msg = refusal(dir, "i.off", "OFF\n3 2 0\n" + v3 + "3 0 1 2\n3 0 2 3\n");
  EXPECT_TRUE(mentions(msg, "line 7: face 1 names vertex 3, but the file has 3 vertices (0 to 2)"))
      << msg;
  msg = refusal(dir, "neg.off", "OFF\n3 1 0\n" + v3 + "3 0 -1 2\n");
  EXPECT_TRUE(mentions(msg, "line 6: face 0 names vertex -1")) << msg;
  msg = refusal(dir, "i.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\nf 1 2 4\n");
  EXPECT_TRUE(mentions(msg, "line 6: face 1 names vertex 4, but the file has 3 vertices")) << msg;
  msg = refusal(dir, "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 4: face 0 names vertex 0; OBJ numbers vertices from 1")) << msg;
  msg = refusal(dir, "rel.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n");
  EXPECT_TRUE(mentions(msg, "line 3: face 0 names vertex -3, counting back from the 2")) << msg;
  msg = refusal(dir, "i.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n" +
                    v3 + "3 0 1 9\n");
  EXPECT_TRUE(mentions(msg, "line 13: face 0 names vertex 9, but the file has 3 vertices")) << msg;
  std::string ply = binary_ply(true);
  const std::size_t faces = ply.find("end_header\n") + 11 + 4 * 13;
  ply[faces + 1 + 4 + 3] = '\x09';  // face 0, corner 1: 2 -> 9
  msg = refusal(dir, "i_binary.ply", ply);
  EXPECT_TRUE(mentions(msg, "face 0 names vertex 9, but the file has 4 vertices")) << msg;
}

TEST(MeshReader, FacesOfFewerThanThreeCornersAreNamed) {
  TempDir dir;
  std::string msg = refusal(dir, "two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n");
  EXPECT_TRUE(mentions(msg, "line 6: face 0 has 2 corners; a face needs at least 3")) << msg;
  msg = refusal(dir, "two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 3: face 0 has 2 corners")) << msg;
  msg = refusal(dir, "two.ply",
                "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n2 0 1\n\n\n");
  EXPECT_TRUE(mentions(msg, "line 12: face 0 has 2 corners")) << msg;
  std::string stl = ascii_stl();
  const std::size_t loop = stl.find("      vertex");
  msg = refusal(dir, "two.stl", stl.erase(loop, stl.find('\n', loop) + 1 - loop));
  EXPECT_TRUE(mentions(msg, "facet 0 has 2 vertices; STL facets are triangles")) << msg;
  stl = ascii_stl();
  stl.insert(stl.find("    endloop"), "      vertex 5 5 5\n");
  msg = refusal(dir, "four.stl", stl);
  EXPECT_TRUE(mentions(msg, "line 7: facet 0 has more than 3 vertices")) << msg;
}

TEST(MeshReader, TruncatedFilesAreNamed) {
  TempDir dir;
  std::string msg = refusal(dir, "cut.off", "OFF\n4 1 0\n0.1 0.2 0.3\n1.7 0.1 -0.3\n0.3 1.9 0.1\n");
  EXPECT_TRUE(mentions(msg, "line 6: the file ends after 3 of the 4 vertices")) << msg;
  msg = refusal(dir, "cut_faces.off", std::string(kOff).substr(0, std::string(kOff).size() - 9));
  EXPECT_TRUE(mentions(msg, "the file ends after 3 of the 4 faces")) << msg;
  msg = refusal(dir, "short_line.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(mentions(msg, "line 4: vertex 1 has 2 numbers")) << msg;
  const std::string ply = binary_ply(false);
  msg = refusal(dir, "cut.ply", ply.substr(0, ply.size() - 20));
  EXPECT_TRUE(mentions(msg, "the element 'face' has 4 items")) << msg;
  std::string ascii = kAsciiPly;
  ascii.replace(ascii.find("3 0 3 2\n"), 8, "3 0 3\n");
  msg = refusal(dir, "cut_ascii.ply", ascii);
  EXPECT_TRUE(mentions(msg, "line 17: the file ends in face 3")) << msg;
  std::string stl = ascii_stl();
  msg = refusal(dir, "no_end.stl", stl.substr(0, stl.find("endsolid")));
  EXPECT_TRUE(mentions(msg, "line 1") && mentions(msg, "has no 'endsolid'")) << msg;
  msg = refusal(dir, "in_facet.stl", stl.substr(0, stl.find("endfacet")));
  EXPECT_TRUE(mentions(msg, "the file ends inside facet 0, which starts on line 2")) << msg;
}

TEST(MeshReader, GarbageIsRefusedAndNeverEchoed) {
  TempDir dir;
  std::mt19937_64 rng(17);
  for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::string bytes(200 + 37 * trial, '\0');
      for (char& c : bytes) c = static_cast<char>(rng());
      if (trial % 2) bytes.replace(0, 6, std::string(ext) == ".stl" ? "solid " : "OFF\n\x01\x02");
      refusal(dir, std::string("garbage") + ext, bytes);
    }
  }
  std::string msg = refusal(dir, "words.obj", "v 0 0 0\n\x01\xfe\x7f garbage\n");
  EXPECT_TRUE(mentions(msg, "line 2: '\\x01\\xfe\\x7f' starts no OBJ record")) << msg;
  msg = refusal(dir, "keyword.off", "\x89PNG\r\n\x1a\n");
  EXPECT_TRUE(mentions(msg, "line 1: expected the keyword OFF")) << msg;
  EXPECT_TRUE(mentions(msg, "\\x89PNG")) << msg;
  msg = refusal(dir, "empty.off", "");
  EXPECT_TRUE(mentions(msg, "the file is empty")) << msg;
  msg = refusal(dir, "empty.stl", " \n");
  EXPECT_TRUE(mentions(msg, "the file is empty")) << msg;
  msg = refusal(dir, "skel.off", "SKEL\n2 1\n0 0 0\n1 0 0\n2 0 1\n");
  EXPECT_TRUE(mentions(msg, "skeleton")) << msg;
  msg = refusal(dir, "binary.off", "OFF BINARY\n\0\0\0\3");
  EXPECT_TRUE(mentions(msg, "binary OFF is not supported")) << msg;
  msg = refusal(dir, "nothing.obj", "# only a comment\nv 0 0 0\n");
  EXPECT_TRUE(mentions(msg, "no faces ('f' lines)")) << msg;
}

TEST(MeshReader, OnlyAMissingFileIsAnIoError) {
  TempDir dir;
  EXPECT_THROW(read_polygon_soup(dir.file("missing.off")), IoError);
  EXPECT_THROW(read_polygon_soup(dir.path.string()), InvalidInput);  // no extension
  std::filesystem::create_directories(dir.file("folder.off"));
  EXPECT_THROW(read_polygon_soup(dir.file("folder.off")), IoError);
  write_bytes(dir.file("mesh.ts"), kOff);
  const std::string msg = message_of([&] { read_polygon_soup(dir.file("mesh.ts")); });
  EXPECT_TRUE(mentions(msg, "'.ts'") && mentions(msg, ".off, .obj, .ply or .stl")) << msg;
  write_bytes(dir.file("upper.OFF"), kOff);
  EXPECT_EQ(read_polygon_soup(dir.file("upper.OFF")).polygons.size(), 4u);
}

}  // namespace
}  // namespace disktune
