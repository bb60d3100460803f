// SPDX-License-Identifier: GPL-3.0-or-later
// Gmsh's C API (gmshc.h), loaded the first time an RVE mesh asks for it (internal).
// Linked in, libgmsh brings OpenCASCADE, FLTK, X11 and some ninety other libraries into
// every process that links disktune, 0.12-0.15 s at each start (an empty program linked
// to it: 0.00 -> 0.14 s, measured 2026-12-06), for a command that only samples or
// remeshes; only mesh_rve needs it.
#pragma once

#include <gmshc.h>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace disktune::detail {

/// The functions of Gmsh's C API that disktune calls, resolved in the loaded library.
struct GmshApi {
  decltype(&gmshInitialize) initialize;
  decltype(&gmshFinalize) finalize;
  decltype(&gmshFree) free;
  decltype(&gmshLoggerGetLastError) last_error;
  decltype(&gmshOptionSetNumber) set_number;
  decltype(&gmshModelAdd) add_model;
  decltype(&gmshModelGetBoundingBox) bounding_box;
  decltype(&gmshModelGetEntities) entities;
  decltype(&gmshModelGetEntitiesInBoundingBox) entities_in_box;
  decltype(&gmshModelOccAddRectangle) add_rectangle;
  decltype(&gmshModelOccAddDisk) add_disk;
  decltype(&gmshModelOccRotate) rotate;
  decltype(&gmshModelOccFragment) fragment;
  decltype(&gmshModelOccRemove) remove;
  decltype(&gmshModelOccSynchronize) synchronize;
  decltype(&gmshModelMeshSetPeriodic) set_periodic;
  decltype(&gmshModelMeshGenerate) generate;
  decltype(&gmshModelMeshGetNodes) nodes;
  decltype(&gmshModelMeshGetElements) elements;
};

/// Gmsh's library, loaded and resolved once per process. Throws IoError naming
/// the library and the package to install when it cannot be loaded.
const GmshApi& gmsh_api();

/// Throws std::runtime_error("Gmsh: " + Gmsh's last error message).
[[noreturn]] void throw_gmsh_error();

/// Calls a function of the C API with its error flag appended; throws (above) when Gmsh
/// sets it.
template <class R, class... Params, class... Args>
R gmsh_call(R (*function)(Params...), Args&&... args) {
  int error = 0;
  if constexpr (std::is_void_v<R>) {
    function(std::forward<Args>(args)..., &error);
    if (error != 0) throw_gmsh_error();
  } else {
    R result = function(std::forward<Args>(args)..., &error);
    if (error != 0) throw_gmsh_error();
    return result;
  }
}

/// An array Gmsh allocated, copied and handed back to it.
template <class T>
std::vector<T> gmsh_take(T* data, std::size_t n) {
  std::vector<T> out(data, data + n);
  gmsh_api().free(data);
  return out;
}

/// Arrays of arrays (element tags by type, fragments by input): each copied and freed.
template <class T>
std::vector<std::vector<T>> gmsh_take(T** data, std::size_t* sizes, std::size_t n) {
  std::vector<std::vector<T>> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(gmsh_take(data[i], sizes[i]));
  gmsh_api().free(data);
  gmsh_api().free(sizes);
  return out;
}

}  // namespace disktune::detail
