// SPDX-License-Identifier: GPL-3.0-or-later
// The fiber RVE mesh's files (rve_mesh.h): Gmsh's MSH 4.1 with its periodic node pairs,
// and an Abaqus input file with the element and node sets periodic boundary conditions
// are written on. Both from RveMesh alone, so they agree node for node.
#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "disktune/io.h"
#include "disktune/rve_mesh.h"
#include "../io/number_text.h"

namespace disktune {
namespace {

// MSH entity tags: points 1..4 are the corners, curves 1..4 the sides, surface 1 the
// matrix and surface k + 1 fiber k (material k).
enum Curve { kLeftCurve = 1, kRightCurve, kBottomCurve, kTopCurve };
// Physical group tags.
constexpr int kCornersGroup = 1, kFirstSideGroup = 2, kMatrixGroup = 6, kFibersGroup = 7;
const char* const kSideNames[4] = {"left", "right", "bottom", "top"};

// A side's nodes from corner to corner, in the order of RveMesh's lists.
std::array<std::vector<std::uint32_t>, 4> side_chains(const RveMesh& m) {
  const auto chain = [](std::uint32_t from, const std::vector<std::uint32_t>& inner, std::uint32_t to) {
    std::vector<std::uint32_t> c{from};
    c.insert(c.end(), inner.begin(), inner.end());
    c.push_back(to);
    return c;
  };
  const auto& k = m.corners;
  return {chain(k[0], m.left, k[3]), chain(k[1], m.right, k[2]), chain(k[0], m.bottom, k[1]),
          chain(k[3], m.top, k[2])};
}

std::uint32_t material_count(const RveMesh& m) {
  return m.material.empty() ? 0 : *std::max_element(m.material.begin(), m.material.end()) + 1;
}

void put_affine(std::ostream& out, double dx, double dy) {
  out << "16 1 0 0 ";
  detail::put_number(out, dx);
  out << " 0 1 0 ";
  detail::put_number(out, dy);
  out << " 0 0 1 0 0 0 0 1\n";
}

void write_msh(std::ostream& out, const RveMesh& m) {
  const std::uint32_t materials = material_count(m);
  const auto chains = side_chains(m);
  // Which entity each node belongs to: a corner, a side, else the first triangle's surface.
  std::vector<std::pair<int, int>> entity_of(m.nodes.size(), {-1, 0});
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    for (const std::uint32_t n : m.triangles[t]) entity_of[n] = {2, static_cast<int>(m.material[t]) + 1};
  }
  for (int s = 0; s < 4; ++s) {
    for (const std::uint32_t n : chains[s]) entity_of[n] = {1, s + 1};
  }
  for (int c = 0; c < 4; ++c) entity_of[m.corners[c]] = {0, c + 1};
  std::vector<std::vector<std::uint32_t>> triangles_of(materials);
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) triangles_of[m.material[t]].push_back(t);

  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n" << 7 + (materials > 0 ? materials - 1 : 0) << "\n";
  out << "0 " << kCornersGroup << " \"corners\"\n";
  for (int s = 0; s < 4; ++s) out << "1 " << kFirstSideGroup + s << " \"" << kSideNames[s] << "\"\n";
  out << "2 " << kMatrixGroup << " \"matrix\"\n2 " << kFibersGroup << " \"fibers\"\n";
  for (std::uint32_t k = 1; k < materials; ++k) out << "2 " << kFibersGroup + k << " \"fiber " << k << "\"\n";
  out << "$EndPhysicalNames\n";

  std::size_t surfaces = 0;
  for (const auto& tris : triangles_of) surfaces += !tris.empty();
  out << "$Entities\n4 4 " << surfaces << " 0\n";
  for (int c = 0; c < 4; ++c) {
    out << c + 1 << " ";
    detail::put_numbers(out, {m.nodes[m.corners[c]].x, m.nodes[m.corners[c]].y, 0.0}, " ");
    out << " 1 " << kCornersGroup << "\n";
  }
  const int ends[4][2] = {{1, 4}, {2, 3}, {1, 2}, {4, 3}};
  for (int s = 0; s < 4; ++s) {
    const Vec2 a = m.nodes[chains[s].front()], b = m.nodes[chains[s].back()];
    out << s + 1 << " ";
    detail::put_numbers(out, {a.x, a.y, 0.0, b.x, b.y, 0.0}, " ");
    out << " 1 " << kFirstSideGroup + s << " 2 " << ends[s][0] << " " << ends[s][1] << "\n";
  }
  for (std::uint32_t k = 0; k < materials; ++k) {
    if (triangles_of[k].empty()) continue;
    Vec2 lo = m.nodes[m.triangles[triangles_of[k][0]][0]], hi = lo;
    for (const std::uint32_t t : triangles_of[k]) {
      for (const std::uint32_t n : m.triangles[t]) {
        lo = {std::min(lo.x, m.nodes[n].x), std::min(lo.y, m.nodes[n].y)};
        hi = {std::max(hi.x, m.nodes[n].x), std::max(hi.y, m.nodes[n].y)};
      }
    }
    out << k + 1 << " ";
    detail::put_numbers(out, {lo.x, lo.y, 0.0, hi.x, hi.y, 0.0}, " ");
    if (k == 0) {
      out << " 1 " << kMatrixGroup << " 0\n";
    } else {
      out << " 2 " << kFibersGroup << " " << kFibersGroup + k << " 0\n";
    }
  }
  out << "$EndEntities\n";

  // Nodes, one block per entity; node tag = index + 1.
  std::vector<std::vector<std::uint32_t>> blocks[3] = {std::vector<std::vector<std::uint32_t>>(4),
                                                        std::vector<std::vector<std::uint32_t>>(4),
                                                        std::vector<std::vector<std::uint32_t>>(materials)};
  for (std::uint32_t n = 0; n < m.nodes.size(); ++n) {
    if (entity_of[n].first >= 0) blocks[entity_of[n].first][entity_of[n].second - 1].push_back(n);
  }
  std::size_t block_count = 0, node_count = 0;
  for (const auto& dim : blocks) {
    for (const auto& b : dim) block_count += !b.empty(), node_count += b.size();
  }
  out << "$Nodes\n" << block_count << " " << node_count << " 1 " << m.nodes.size() << "\n";
  for (int dim = 0; dim < 3; ++dim) {
    for (std::size_t e = 0; e < blocks[dim].size(); ++e) {
      const auto& b = blocks[dim][e];
      if (b.empty()) continue;
      out << dim << " " << e + 1 << " 0 " << b.size() << "\n";
      for (const std::uint32_t n : b) out << n + 1 << "\n";
      for (const std::uint32_t n : b) {
        detail::put_numbers(out, {m.nodes[n].x, m.nodes[n].y, 0.0}, " ");
        out << "\n";
      }
    }
  }
  out << "$EndNodes\n";

  std::size_t lines = 0;
  for (const auto& c : chains) lines += c.size() - 1;
  const std::size_t elements = 4 + lines + m.triangles.size();
  out << "$Elements\n" << 8 + surfaces << " " << elements << " 1 " << elements << "\n";
  std::size_t tag = 1;
  for (int c = 0; c < 4; ++c) out << "0 " << c + 1 << " 15 1\n" << tag++ << " " << m.corners[c] + 1 << "\n";
  for (int s = 0; s < 4; ++s) {
    out << "1 " << s + 1 << " 1 " << chains[s].size() - 1 << "\n";
    for (std::size_t i = 0; i + 1 < chains[s].size(); ++i) {
      out << tag++ << " " << chains[s][i] + 1 << " " << chains[s][i + 1] + 1 << "\n";
    }
  }
  for (std::uint32_t k = 0; k < materials; ++k) {
    if (triangles_of[k].empty()) continue;
    out << "2 " << k + 1 << " 2 " << triangles_of[k].size() << "\n";
    for (const std::uint32_t t : triangles_of[k]) {
      const auto& tri = m.triangles[t];
      out << tag++ << " " << tri[0] + 1 << " " << tri[1] + 1 << " " << tri[2] + 1 << "\n";
    }
  }
  out << "$EndElements\n";

  // The right side is the left moved by W, the top the bottom moved by H; the corners
  // follow (Gmsh writes point links too).
  const double w = m.width, h = m.height;
  const auto link = [&](int dim, int tag_copy, int tag_master, double dx, double dy,
                        const std::vector<std::uint32_t>& copies, const std::vector<std::uint32_t>& masters) {
    out << dim << " " << tag_copy << " " << tag_master << "\n";
    put_affine(out, dx, dy);
    out << copies.size() << "\n";
    for (std::size_t i = 0; i < copies.size(); ++i) out << copies[i] + 1 << " " << masters[i] + 1 << "\n";
  };
  const auto& k = m.corners;
  out << "$Periodic\n5\n";
  link(0, 2, 1, w, 0, {k[1]}, {k[0]});
  link(0, 3, 4, w, 0, {k[2]}, {k[3]});
  link(0, 4, 1, 0, h, {k[3]}, {k[0]});
  link(1, kRightCurve, kLeftCurve, w, 0, chains[1], chains[0]);
  link(1, kTopCurve, kBottomCurve, 0, h, chains[3], chains[2]);
  out << "$EndPeriodic\n";
}

// An Abaqus data line holds at most 16 entries.
void put_set(std::ostream& out, const std::string& header, const std::vector<std::size_t>& ids) {
  out << header << "\n";
  for (std::size_t i = 0; i < ids.size(); ++i) out << ids[i] << (i + 1 == ids.size() || i % 16 == 15 ? "\n" : ", ");
}

std::vector<std::size_t> node_ids(const std::vector<std::uint32_t>& nodes) {
  std::vector<std::size_t> ids;
  for (const std::uint32_t n : nodes) ids.push_back(n + std::size_t{1});
  return ids;
}

void write_inp(std::ostream& out, const RveMesh& m) {
  const std::uint32_t materials = material_count(m);
  out << "*Heading\n** disktune fiber RVE: a periodic ";
  detail::put_number(out, m.width);
  out << " x ";
  detail::put_number(out, m.height);
  out << " cell, " << (materials > 0 ? materials - 1 : 0) << " fibers, " << m.nodes.size() << " nodes, "
      << m.triangles.size() << " triangles\n"
      << "** Node sets LEFT/RIGHT and BOTTOM/TOP hold the periodic node pairs in matching order (corners excluded).\n";
  out << "*Node\n";
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    out << n + 1 << ", ";
    detail::put_numbers(out, {m.nodes[n].x, m.nodes[n].y}, ", ");
    out << "\n";
  }
  out << "*Element, type=CPE3\n";
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    out << t + 1 << ", " << tri[0] + 1 << ", " << tri[1] + 1 << ", " << tri[2] + 1 << "\n";
  }
  std::vector<std::vector<std::size_t>> elements_of(materials);
  std::vector<std::size_t> fibers;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    elements_of[m.material[t]].push_back(t + 1);
    if (m.material[t] > 0) fibers.push_back(t + 1);
  }
  if (materials > 0) put_set(out, "*Elset, elset=MATRIX", elements_of[0]);
  put_set(out, "*Elset, elset=FIBERS", fibers);
  for (std::uint32_t k = 1; k < materials; ++k) put_set(out, "*Elset, elset=FIBER-" + std::to_string(k), elements_of[k]);
  // unsorted: Abaqus keeps the order, which pairs LEFT with RIGHT and BOTTOM with TOP.
  put_set(out, "*Nset, nset=LEFT, unsorted", node_ids(m.left));
  put_set(out, "*Nset, nset=RIGHT, unsorted", node_ids(m.right));
  put_set(out, "*Nset, nset=BOTTOM, unsorted", node_ids(m.bottom));
  put_set(out, "*Nset, nset=TOP, unsorted", node_ids(m.top));
  for (int c = 0; c < 4; ++c) put_set(out, "*Nset, nset=CORNER-" + std::to_string(c + 1), {m.corners[c] + std::size_t{1}});
}

}  // namespace

void write_rve_msh(const std::string& path, const RveMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) { write_msh(out, mesh); });
}

void write_rve_inp(const std::string& path, const RveMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) { write_inp(out, mesh); });
}

}  // namespace disktune
