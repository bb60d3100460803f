// SPDX-License-Identifier: GPL-3.0-or-later
// Loads Gmsh's library by its soname (the one disktune was configured with, passed in as
// DISKTUNE_GMSH_SONAME) and resolves the C API's functions (gmsh_library.h).
#include "gmsh_library.h"

#include <dlfcn.h>

#include <stdexcept>

#include "disktune/errors.h"

namespace disktune::detail {
namespace {

std::string loader_message() {
  const char* why = dlerror();
  return why != nullptr ? why : "no reason given";
}

template <class F>
void resolve(void* library, const char* name, F& function) {
  function = reinterpret_cast<F>(dlsym(library, name));
  if (function == nullptr) {
    throw IoError(std::string("rve mesh: Gmsh's library ") + DISKTUNE_GMSH_SONAME +
                  " has no function " + name + " (" + loader_message() +
                  "); install the Gmsh that disktune was built with (Debian's libgmsh-dev)");
  }
}

GmshApi load() {
  // Never unloaded: OpenCASCADE keeps static state that its destructors at exit expect.
  void* library = dlopen(DISKTUNE_GMSH_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    throw IoError(std::string("rve mesh: Gmsh's library ") + DISKTUNE_GMSH_SONAME +
                  " could not be loaded (" + loader_message() +
                  "); the RVE mesh needs it: install Debian's libgmsh-dev");
  }
  GmshApi api{};
  resolve(library, "gmshInitialize", api.initialize);
  resolve(library, "gmshFinalize", api.finalize);
  resolve(library, "gmshFree", api.free);
  resolve(library, "gmshLoggerGetLastError", api.last_error);
  resolve(library, "gmshOptionSetNumber", api.set_number);
  resolve(library, "gmshModelAdd", api.add_model);
  resolve(library, "gmshModelGetBoundingBox", api.bounding_box);
  resolve(library, "gmshModelGetEntities", api.entities);
  resolve(library, "gmshModelGetEntitiesInBoundingBox", api.entities_in_box);
  resolve(library, "gmshModelOccAddRectangle", api.add_rectangle);
  resolve(library, "gmshModelOccAddDisk", api.add_disk);
  resolve(library, "gmshModelOccRotate", api.rotate);
  resolve(library, "gmshModelOccFragment", api.fragment);
  resolve(library, "gmshModelOccRemove", api.remove);
  resolve(library, "gmshModelOccSynchronize", api.synchronize);
  resolve(library, "gmshModelMeshSetPeriodic", api.set_periodic);
  resolve(library, "gmshModelMeshGenerate", api.generate);
  resolve(library, "gmshModelMeshGetNodes", api.nodes);
  resolve(library, "gmshModelMeshGetElements", api.elements);
  return api;
}

}  // namespace

const GmshApi& gmsh_api() {
  static const GmshApi api = load();  // a failed load throws and is tried again next time
  return api;
}

void throw_gmsh_error() {
  std::string message = "an error it did not describe";
  char* text = nullptr;
  int error = 0;
  gmsh_api().last_error(&text, &error);
  if (text != nullptr) {
    if (error == 0 && *text != '\0') message = text;
    gmsh_api().free(text);
  }
  throw std::runtime_error("Gmsh: " + message);
}

}  // namespace disktune::detail
