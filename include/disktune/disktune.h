// SPDX-License-Identifier: GPL-3.0-or-later
// Everything disktune offers, in one include. The same verbs serve every domain (the
// periodic box, planar domains with holes, triangulated surfaces): sample_mps, tune,
// is_maximal, validate_packing and packing_defect, the meshes, and remesh, the
// mesh-improvement stage in one call. The adapters to CGAL and OpenMesh meshes are
// not included here (they need those libraries): disktune/cgal/*.h, disktune/openmesh/*.h.
#pragma once

#include "disktune/boundary.h"
#include "disktune/cvt_reference.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/frame.h"
#include "disktune/geometry.h"
#include "disktune/io.h"
#include "disktune/mesh.h"
#include "disktune/mesh_io.h"
#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"
#include "disktune/quality.h"
#include "disktune/quality_json.h"
#include "disktune/random.h"
#include "disktune/remesh.h"
#include "disktune/report_pictures.h"
#include "disktune/resources.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/spatial_grid.h"
#include "disktune/spectrum.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_geometry.h"
#include "disktune/surface_io.h"
#include "disktune/surface_mesh.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"
#include "disktune/tolerance.h"
#include "disktune/tuning.h"
#include "disktune/vec3.h"
#include "disktune/voids.h"
