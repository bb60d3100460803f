// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module `disktune` (pybind11): numpy arrays in and out, the library's calls
// with keyword arguments, its errors as Python exceptions, the GIL released while the
// library works. Only conversions live here; every algorithm is the library's.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "disktune/disktune.h"
#include "python_packing.h"

namespace py = pybind11;
using namespace disktune;
using disktune::python::PyPacking;

namespace {

// ---------------------------------------------------------------- arrays

template <class T>
py::array_t<T> array_of(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::array_t<bool> array_of(const std::vector<bool>& values) {
  py::array_t<bool> out(static_cast<py::ssize_t>(values.size()));
  auto a = out.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) a(i) = values[i];
  return out;
}

py::array_t<double> rows_of(const std::vector<Vec2>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) a(i, 0) = points[i].x, a(i, 1) = points[i].y;
  return out;
}

py::array_t<double> rows_of(const std::vector<Vec3>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    a(i, 0) = points[i].x, a(i, 1) = points[i].y, a(i, 2) = points[i].z;
  return out;
}

py::array_t<std::int64_t> rows_of(const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(triangles.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    for (int k = 0; k < 3; ++k) a(i, k) = triangles[i][k];
  return out;
}

// An n x `columns` array of doubles (any numeric dtype, C order made here), or a clear error.
py::array_t<double, py::array::c_style | py::array::forcecast> table(const py::handle& given,
                                                                     py::ssize_t columns,
                                                                     const char* what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
  if (!a || a.ndim() != 2 || a.shape(1) != columns) {
    throw InvalidInput(std::string(what) + ": give an n x " + std::to_string(columns) +
                       " array of numbers");
  }
  return a;
}

std::vector<Vec2> points2(const py::handle& given, const char* what) {
  const auto a = table(given, 2, what);
  const auto v = a.unchecked<2>();
  std::vector<Vec2> out;
  for (py::ssize_t i = 0; i < v.shape(0); ++i) out.push_back({v(i, 0), v(i, 1)});
  return out;
}

// ---------------------------------------------------------------- domains

std::shared_ptr<const PlanarDomain> planar_from(const py::handle& outer,
                                                const std::vector<py::handle>& holes) {
  std::vector<std::vector<Vec2>> inner;
  for (std::size_t k = 0; k < holes.size(); ++k)
    inner.push_back(points2(holes[k], ("hole " + std::to_string(k)).c_str()));
  return std::make_shared<const PlanarDomain>(points2(outer, "outer"), std::move(inner));
}

// A surface with the sharp features at `features` degrees (0 or None: none), less the
// stray folds shorter than `stray` times the bounding-box diagonal.
std::shared_ptr<const SurfaceDomain> with_features(SurfaceDomain surface,
                                                   std::optional<double> features, double stray) {
  const double angle = features.value_or(0);
  if (!(angle >= 0 && angle < 180)) {
    throw InvalidInput(
        "features: give a dihedral angle in degrees in (0, 180), or 0 / None for no features");
  }
  if (angle > 0) surface.set_features(detect_features(surface, {angle, 60, stray}));
  return std::make_shared<const SurfaceDomain>(std::move(surface));
}

std::shared_ptr<const SurfaceDomain> surface_from(const py::handle& vertices,
                                                  const py::handle& faces,
                                                  std::optional<double> features, double stray) {
  const auto v = table(vertices, 3, "vertices").unchecked<2>();
  auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(faces);
  if (!f || f.ndim() != 2 || f.shape(1) != 3)
    throw InvalidInput("faces: give an m x 3 array of vertex indices");
  const auto t = f.unchecked<2>();
  std::vector<Vec3> points;
  for (py::ssize_t i = 0; i < v.shape(0); ++i) points.push_back({v(i, 0), v(i, 1), v(i, 2)});
  std::vector<SurfaceDomain::Triangle> triangles;
  for (py::ssize_t i = 0; i < t.shape(0); ++i) {
    SurfaceDomain::Triangle tri;
    for (int k = 0; k < 3; ++k) {
      if (t(i, k) < 0 || t(i, k) >= v.shape(0)) {
        throw InvalidInput("faces: face " + std::to_string(i) + " names vertex " +
                           std::to_string(t(i, k)) + ", but there are " +
                           std::to_string(v.shape(0)) + " vertices (indices from 0)");
      }
      tri[k] = static_cast<std::size_t>(t(i, k));
    }
    triangles.push_back(tri);
  }
  return with_features(SurfaceDomain(std::move(points), std::move(triangles)), features, stray);
}

// ---------------------------------------------------------------- errors and progress

// Python exception types, created once with two bases each (disktune.Error and the
// builtin that fits), kept for the module's life.
struct ErrorTypes {
  PyObject *error, *invalid, *io, *cancelled, *internal;
};
ErrorTypes errors{};

PyObject* new_error(py::module_& m, const char* name, PyObject* bases, const char* doc) {
  PyObject* type =
      PyErr_NewExceptionWithDoc((std::string("disktune.") + name).c_str(), doc, bases, nullptr);
  if (!type) throw py::error_already_set();
  m.attr(name) = py::handle(type);
  return type;
}

void add_errors(py::module_& m) {
  errors.error = new_error(m, "Error", PyExc_RuntimeError, "Any error disktune reports.");
  const auto pair = [](PyObject* a, PyObject* b) {
    return PyTuple_Pack(2, a, b);
  };  // new references, kept
  errors.invalid =
      new_error(m, "InvalidInput", pair(errors.error, PyExc_ValueError),
                "An argument or input file disktune cannot use; the message says what to change.");
  errors.io = new_error(m, "IoError", pair(errors.error, PyExc_OSError),
                        "A file could not be read or written.");
  errors.cancelled =
      new_error(m, "Cancelled", errors.error, "The progress callable asked to stop.");
  errors.internal =
      new_error(m, "InternalError", errors.error, "A bug in disktune; please report it.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(errors.invalid, e.what());
    } catch (const IoError& e) {
      PyErr_SetString(errors.io, e.what());
    } catch (const Cancelled& e) {
      PyErr_SetString(errors.cancelled, e.what());
    } catch (const InternalError& e) {
      PyErr_SetString(errors.internal, e.what());
    } catch (const Error& e) {
      PyErr_SetString(errors.error, e.what());
    }
  });
}

// Runs `work` without the GIL. Now and then the library reports progress: the GIL is
// taken back to check for Ctrl-C (KeyboardInterrupt) and to call `progress` (if any)
// with a dict; a progress callable that returns False stops the work
// (disktune.Cancelled), one that raises stops it and its exception is raised here.
template <class Work>
auto without_gil(const py::object& progress, TuneOptions& options, Work&& work)
    -> decltype(work()) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw InvalidInput("progress: give a callable (or None)");
  std::optional<py::error_already_set> raised;
  options.on_progress = [&](const Progress& p) {
    py::gil_scoped_acquire gil;
    if (raised) return false;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (progress.is_none()) return true;
      const py::object answer = progress(
          py::dict(py::arg("count") = p.count, py::arg("area_fraction") = p.area_fraction,
                   py::arg("phase") = to_string(p.phase), py::arg("phase_goal") = p.phase_goal));
      return answer.is_none() || answer.cast<bool>();
    } catch (py::error_already_set& e) {
      raised.emplace(std::move(e));
      return false;
    }
  };
  try {
    py::gil_scoped_release released;
    return work();
  } catch (const Cancelled&) {
    if (raised) throw std::move(*raised);
    throw;
  }
}

Target target_of(std::optional<std::size_t> count, std::optional<double> area_fraction,
                 std::optional<double> relative_radius) {
  const int given = count.has_value() + area_fraction.has_value() + relative_radius.has_value();
  if (given != 1)
    throw InvalidInput("tune: give exactly one of count, area_fraction and relative_radius");
  if (count) return Target::count(*count);
  return area_fraction ? Target::area_fraction(*area_fraction)
                       : Target::relative_radius(*relative_radius);
}

py::object json_value(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

// ---------------------------------------------------------------- results

// A triangle mesh: points (n x 2 or n x 3), triangles (m x 3 indices into points),
// disks (for each point the row of its disk in the packing's arrays) and, from remesh,
// a report.
struct PyMesh {
  py::array_t<double> points;
  py::array_t<std::int64_t> triangles;
  py::array_t<std::int64_t> disks;
  py::object report = py::none();
  /// Writes the library's mesh (kept beside the arrays) to a path, in the format named
  /// or else the one of its extension.
  std::function<void(const std::string&, const std::optional<std::string>&)> write;
};

// A writer for one of the library's meshes, kept by value: write(path, mesh, format),
// the format named or else the path's.
template <class Mesh, class Write>
std::function<void(const std::string&, const std::optional<std::string>&)> writer_of(Mesh mesh,
                                                                                     Write write) {
  auto kept = std::make_shared<const Mesh>(std::move(mesh));
  return [kept, write](const std::string& path, const std::optional<std::string>& format) {
    write(path, *kept, format ? mesh_format_named(*format) : mesh_format_for_path(path));
  };
}

py::dict mesh_check_dict(const SurfaceMeshCheck& c) {
  return py::dict(
      py::arg("manifold") = c.manifold, py::arg("oriented") = c.oriented,
      py::arg("components") = c.components, py::arg("genus") = c.genus,
      py::arg("boundary_loops") = c.boundary_loops, py::arg("boundary_edges") = c.boundary_edges,
      py::arg("non_manifold_edges") = c.non_manifold_edges,
      py::arg("non_manifold_vertices") = c.non_manifold_vertices,
      py::arg("isolated_vertices") = c.isolated_vertices, py::arg("problems") = c.problems);
}

// A surface mesh: vertex i is the i-th disk.
PyMesh surface_mesh_of(const SurfaceMesh& m) {
  PyMesh out;
  out.points = rows_of(m.vertices), out.triangles = rows_of(m.triangles);
  std::vector<std::int64_t> disks(m.vertices.size());
  std::iota(disks.begin(), disks.end(), 0);
  out.disks = array_of(disks);
  out.write = writer_of(m, [](const std::string& path, const SurfaceMesh& k, MeshFormat f) {
    write_surface_mesh(path, k, f);
  });
  return out;
}

PyMesh mesh_of(const PyPacking& packing) {
  PyMesh out;
  std::vector<std::int64_t> disks;
  if (packing.surface) {
    SurfaceMesh m;
    {
      py::gil_scoped_release released;
      m = restricted_delaunay(*packing.surface);
    }
    return surface_mesh_of(m);
  }
  if (packing.planar) {
    Packing copy = *packing.plane;  // boundary_loops marks the boundary disks
    const auto rows = packing.rows();
    PlanarMesh m;
    {
      py::gil_scoped_release released;
      m = constrained_delaunay(copy, boundary_loops(copy, *packing.planar));
    }
    for (const DiskId id : m.vertex_disk) disks.push_back(rows.at(id));
    out.points = rows_of(m.vertices), out.triangles = rows_of(m.triangles);
    out.write = writer_of(std::move(m), [](const std::string& path, const PlanarMesh& k,
                                           MeshFormat f) { write_mesh(path, k, f); });
  } else {
    const auto rows = packing.rows();
    TriangleMesh m;
    {
      py::gil_scoped_release released;
      m = periodic_delaunay(*packing.plane);
    }
    for (const DiskId id : m.vertex_disk) disks.push_back(rows.at(id));
    out.points = rows_of(m.vertices), out.triangles = rows_of(m.triangles);
    out.write = writer_of(std::move(m), [](const std::string& path, const TriangleMesh& k,
                                           MeshFormat f) { write_mesh(path, k, f); });
  }
  out.disks = array_of(disks);
  return out;
}

py::object report_of(const PyPacking& packing, bool spectrum, unsigned threads) {
  if (packing.surface) {
    const SurfacePacking& p = *packing.surface;
    py::dict out;
    bool maximal = false, conflict_free = false;
    SurfaceMesh m;
    SurfaceMeshQuality q;
    const bool meshed = p.size() >= 4;  // a restricted Delaunay mesh needs a tetrahedron
    {
      py::gil_scoped_release released;
      maximal = is_maximal(p), conflict_free = is_conflict_free(p);
      if (meshed) {
        std::vector<double> radii;
        for (const DiskId id : p.ids()) radii.push_back(p.radius(id));
        m = restricted_delaunay(p);
        q = measure_surface_mesh(m, radii);
        q.hausdorff = hausdorff_distance(m, p.domain(), 10000, 1, 0);
      }
    }
    out["count"] = p.size();
    out["area_fraction"] = packing.area_fraction();
    out["relative_radius"] = relative_radius_for(packing.area_fraction());
    out["maximal"] = maximal, out["conflict_free"] = conflict_free;
    if (meshed) {
      out["mesh_check"] = mesh_check_dict(check_surface_mesh(m));
      out["mesh"] = json_value(quality_json(q));
    }
    return std::move(out);
  }
  const Packing& p = *packing.plane;
  std::string text;
  if (packing.planar) {
    Packing copy = p;
    py::gil_scoped_release released;
    const PlanarMesh m = constrained_delaunay(copy, boundary_loops(copy, *packing.planar));
    text = quality_json(measure_planar_quality(copy, m, packing.planar->area()));
  } else {
    if (p.sizing())
      throw InvalidInput(
          "report: the periodic box's report needs one radius; this packing has a sizing");
    py::gil_scoped_release released;
    const QualityReport q = measure_quality(p, periodic_delaunay(p), p.max_radius());
    std::optional<Spectrum> s;
    SpectrumOptions options;
    options.threads = threads;
    if (spectrum) s = measure_spectrum(p, options);
    text = quality_json(q, s ? &*s : nullptr);
  }
  return json_value(text);
}

// ---------------------------------------------------------------- calls

PyPacking sample(std::optional<double> radius, const py::object& domain,
                 std::optional<std::string> sizing, std::uint64_t seed) {
  if (radius.has_value() == sizing.has_value()) {
    throw InvalidInput(
        "sample: give the disk radius (radius=R) or radii that vary (sizing='SPEC'), one of the "
        "two");
  }
  python::Domain where;
  if (domain.is_none()) {
    where.box = PeriodicBox();
  } else if (py::isinstance<PeriodicBox>(domain)) {
    where.box = domain.cast<PeriodicBox>();
  } else if (py::isinstance<python::PlanarHandle>(domain)) {
    where.planar = domain.cast<python::PlanarHandle>().domain;
  } else if (py::isinstance<python::SurfaceHandle>(domain)) {
    where.surface = domain.cast<python::SurfaceHandle>().domain;
  } else {
    throw InvalidInput(
        "sample: domain must be a PeriodicBox, a PlanarDomain or a Surface (or None: the unit "
        "box)");
  }
  PyPacking out;
  {
    py::gil_scoped_release released;
    Rng rng(seed);
    out = python::sample(where, radius, sizing, rng);
  }
  if (!out.note.empty() && PyErr_WarnEx(PyExc_UserWarning, out.note.c_str(), 1) != 0)
    throw py::error_already_set();
  return out;
}

PyPacking tune_copy(const PyPacking& packing, std::optional<std::size_t> count,
                    std::optional<double> area_fraction, std::optional<double> relative_radius,
                    const std::string& method, std::uint64_t seed, const py::object& progress) {
  const Target target = target_of(count, area_fraction, relative_radius);
  TuneOptions options;
  options.method = method_named(method);
  PyPacking out = packing;
  out.tuning = without_gil(progress, options, [&] {
    Rng rng(seed);
    return python::tune(out, target, rng, options);
  });
  return out;
}

PyMesh remesh_surface(const python::SurfaceHandle& surface, std::size_t vertices,
                      std::uint64_t seed, int relax_sweeps, unsigned threads,
                      const py::object& progress) {
  RemeshOptions options;
  options.seed = seed;
  options.relax_sweeps = relax_sweeps;
  options.threads = threads;
  options.feature_angle = 0;  // the Surface carries its features
  RemeshResult r = without_gil(progress, options.tune,
                               [&] { return remesh(surface.domain, vertices, options); });
  SurfaceMeshQuality q;
  {
    py::gil_scoped_release released;
    q = measure_surface_mesh(r.mesh, r.radii);
    q.hausdorff = hausdorff_distance(r.mesh, *surface.domain, 10000, 1, threads);
  }
  PyMesh out = surface_mesh_of(r.mesh);
  py::dict report;
  report["vertices"] = r.mesh.vertices.size();
  report["reached"] = r.tuning.reached;
  report["radius"] = r.radius;
  report["note"] = r.grading_note;
  report["mesh_check"] = mesh_check_dict(r.check);
  report["mesh"] = json_value(quality_json(q));
  out.report = std::move(report);
  return out;
}

struct PyRve {
  Rve rve;
  std::uint64_t seed = 1;
};

PyRve make_rve_py(double diameter, double gap, std::optional<double> vf,
                  std::optional<std::size_t> fibers, double width, double height,
                  double diameter_cv, std::uint64_t seed, const py::object& progress) {
  RveSpec spec;
  spec.diameter = diameter, spec.gap = gap, spec.width = width, spec.height = height;
  spec.diameter_cv = diameter_cv, spec.seed = seed;
  if (vf.has_value() == fibers.has_value())
    throw InvalidInput("rve: give exactly one of vf and fibers");
  if (vf) spec.fiber_fraction = *vf;
  if (fibers) spec.fibers = *fibers;
  return {without_gil(progress, spec.tune, [&] { return make_rve(spec); }), seed};
}

}  // namespace

PYBIND11_MODULE(disktune, m) {
  m.doc() =
      "Maximal random disk packings tuned to an exact count, area fraction or relative radius by "
      "disk "
      "injection and ejection (periodic box, planar domains with holes, triangulated surfaces), "
      "their "
      "meshes and quality reports, surface remeshing and fiber-composite RVEs.";
  m.attr("__version__") = DISKTUNE_VERSION;
  add_errors(m);

  py::class_<PeriodicBox>(m, "PeriodicBox", "A periodic W x H box (a torus).")
      .def(py::init<double, double>(), py::arg("width") = 1.0, py::arg("height") = 1.0)
      .def_property_readonly("width", &PeriodicBox::width)
      .def_property_readonly("height", &PeriodicBox::height)
      .def_property_readonly("area", &PeriodicBox::area)
      .def("__repr__", [](const PeriodicBox& b) {
        return "PeriodicBox(width=" + std::to_string(b.width()) +
               ", height=" + std::to_string(b.height()) + ")";
      });

  py::class_<python::PlanarHandle>(m, "PlanarDomain", "A polygon with polygonal holes.")
      .def(py::init([](const py::handle& outer, const std::vector<py::handle>& holes) {
             return python::PlanarHandle{planar_from(outer, holes)};
           }),
           py::arg("outer"), py::arg("holes") = std::vector<py::handle>{},
           "outer: k x 2 array of the outer loop's corners; holes: a list of such arrays")
      .def_static(
          "read",
          [](const std::string& path) {
            return python::PlanarHandle{
                std::make_shared<const PlanarDomain>(read_planar_domain(path))};
          },
          py::arg("path"), "Reads a .poly file, or a flat .off or .obj mesh")
      .def_property_readonly("area", [](const python::PlanarHandle& d) { return d.domain->area(); })
      .def_property_readonly("loops", [](const python::PlanarHandle& d) {
        py::list out;
        for (const auto& loop : d.domain->loops()) out.append(rows_of(loop));
        return out;
      });

  py::class_<python::SurfaceHandle>(
      m, "Surface", "A triangulated surface, with the sharp features found at an angle.")
      .def(
          py::init([](const py::handle& vertices, const py::handle& faces,
                      std::optional<double> features, double stray) {
            return python::SurfaceHandle{surface_from(vertices, faces, features, stray)};
          }),
          py::arg("vertices"), py::arg("faces"), py::arg("features") = 60.0, py::arg("stray") = 0.2,
          "vertices: n x 3 array; faces: m x 3 vertex indices; features: dihedral angle in degrees "
          "that makes an edge sharp (0 or None: no features); stray: groups of sharp edges with a "
          "loose end shorter than this share of the bounding-box diagonal are dropped (0 keeps "
          "all)")
      .def_static(
          "read",
          [](const std::string& path, std::optional<double> features, double stray) {
            return python::SurfaceHandle{with_features(read_surface(path), features, stray)};
          },
          py::arg("path"), py::arg("features") = 60.0, py::arg("stray") = 0.2,
          "Reads an OFF, OBJ, PLY or STL file")
      .def_property_readonly(
          "vertices", [](const python::SurfaceHandle& s) { return rows_of(s.domain->vertices()); })
      .def_property_readonly(
          "faces",
          [](const python::SurfaceHandle& s) {
            std::vector<std::array<std::uint32_t, 3>> t;
            for (const auto& f : s.domain->triangles())
              t.push_back({static_cast<std::uint32_t>(f[0]), static_cast<std::uint32_t>(f[1]),
                           static_cast<std::uint32_t>(f[2])});
            return rows_of(t);
          })
      .def_property_readonly("area",
                             [](const python::SurfaceHandle& s) { return s.domain->area(); })
      .def_property_readonly("genus",
                             [](const python::SurfaceHandle& s) { return s.domain->genus(); })
      .def_property_readonly("is_closed",
                             [](const python::SurfaceHandle& s) { return s.domain->is_closed(); })
      .def_property_readonly("feature_curves", [](const python::SurfaceHandle& s) {
        return s.domain->features().curves.size();
      });

  py::class_<PyPacking>(m, "Packing",
                        "A conflict-free maximal disk packing and the domain it fills.")
      .def_property_readonly("points", &PyPacking::points, "n x 2 centers (n x 3 on a surface)")
      .def_property_readonly(
          "radii", [](const PyPacking& p) { return array_of(p.radii()); }, "each disk's radius")
      .def_property_readonly(
          "fixed", [](const PyPacking& p) { return array_of(p.fixed()); },
          "True for disks held on a boundary or feature curve")
      .def_property_readonly("area_fraction", &PyPacking::area_fraction,
                             "eta (relative to the sizing where radii vary)")
      .def_property_readonly(
          "relative_radius",
          [](const PyPacking& p) { return relative_radius_for(p.area_fraction()); })
      .def_property_readonly(
          "tuning",
          [](const PyPacking& p) -> py::object {
            if (!p.tuning) return py::none();
            return py::dict(py::arg("target") = p.tuning->target,
                            py::arg("count") = p.tuning->count,
                            py::arg("reached") = p.tuning->reached,
                            py::arg("last_phase") = to_string(p.tuning->last_phase),
                            py::arg("seconds") = p.tuning->seconds);
          },
          "what tune() did (None for a sample)")
      .def("__len__", &PyPacking::size)
      .def(
          "is_maximal",
          [](const PyPacking& p) {
            py::gil_scoped_release r;
            return p.is_maximal();
          },
          "checks exactly that no point of the domain is left uncovered")
      .def("is_conflict_free",
           [](const PyPacking& p) {
             py::gil_scoped_release r;
             return p.is_conflict_free();
           })
      .def("write_csv", &PyPacking::write_csv, py::arg("path"),
           "x,y,r (x,y,z,r on a surface), as `disktune` writes")
      .def("__repr__", [](const PyPacking& p) {
        return "<disktune.Packing of " + std::to_string(p.size()) + " disks, eta " +
               std::to_string(p.area_fraction()) + ">";
      });

  py::class_<PyMesh>(m, "Mesh", "A triangle mesh of a packing's centers.")
      .def_readonly("points", &PyMesh::points, "n x 2 or n x 3 vertex positions")
      .def_readonly("triangles", &PyMesh::triangles, "m x 3 indices into points")
      .def_readonly("disks", &PyMesh::disks,
                    "for each vertex the row of its disk in the packing (periodic copies across "
                    "the seam repeat it)")
      .def_readonly("report", &PyMesh::report, "remesh's quality figures (None for mesh())")
      .def(
          "write",
          [](const PyMesh& mesh, const std::string& path, std::optional<std::string> format) {
            py::gil_scoped_release released;
            mesh.write(path, format);
          },
          py::arg("path"), py::arg("format") = py::none(),
          "Writes the mesh atomically: OFF, OBJ, PLY, VTK, VTU, MSH, STL or Triangle's .node/.ele "
          "pair (planar meshes) by the path's extension, or the format named (off, obj, ply, "
          "ply-binary, vtk, vtu, msh, stl, triangle); a "
          "surface mesh's feature edges go as lines into OBJ, VTK, VTU and MSH");

  py::class_<PyRve>(m, "Rve", "A periodic cell of non-overlapping fibers.")
      .def_property_readonly("centers", [](const PyRve& r) { return rows_of(r.rve.centers); })
      .def_property_readonly("diameters", [](const PyRve& r) { return array_of(r.rve.diameters); })
      .def_property_readonly("fiber_fraction", [](const PyRve& r) { return r.rve.fiber_fraction; })
      .def_property_readonly("cell", [](const PyRve& r) { return r.rve.cell; })
      .def(
          "statistics",
          [](const PyRve& r) {
            std::string text;
            {
              py::gil_scoped_release released;
              const Rve& rve = r.rve;
              const FiberStatistics s = fiber_statistics(rve.cell, rve.centers, rve.diameters);
              std::optional<FiberStatistics>
                  rsa;  // the sample it was tuned from (7 fibers at least)
              if (rve.sample_centers.size() >= 7)
                rsa = fiber_statistics(rve.cell, rve.sample_centers, rve.sample_diameter);
              text = fiber_statistics_json(s, rsa ? &*rsa : nullptr, rve.gap, r.seed);
            }
            return json_value(text);
          },
          "the arrangement's statistics (as `disktune rve --stats` writes them)")
      .def(
          "write_csv",
          [](const PyRve& r, const std::string& path) {
            write_fibers_csv(path, r.rve.centers, r.rve.diameters);
          },
          py::arg("path"));

  m.def("sample", &sample, py::arg("radius") = py::none(), py::kw_only(),
        py::arg("domain") = py::none(), py::arg("sizing") = py::none(), py::arg("seed") = 1,
        "A maximal Poisson-disk sample of the domain (default: the unit periodic box) at radius r, "
        "or with "
        "radii from a sizing spec as `disktune sample --sizing` takes it.");
  m.def("tune", &tune_copy, py::arg("packing"), py::kw_only(), py::arg("count") = py::none(),
        py::arg("area_fraction") = py::none(), py::arg("relative_radius") = py::none(),
        py::arg("method") = "auto", py::arg("seed") = 1, py::arg("progress") = py::none(),
        "A copy of the packing tuned to an exact count, area fraction or relative radius, "
        "conflict-free and "
        "maximal. progress(dict) is called now and then; returning False cancels "
        "(disktune.Cancelled).");
  m.def("mesh", &mesh_of, py::arg("packing"),
        "The packing's Delaunay mesh: periodic in the box, constrained in a planar domain, "
        "restricted on a surface.");
  m.def("set_default_threads", &set_default_threads, py::arg("threads"),
        "At most this many threads per call where a call is given no count (the final checks, the "
        "restricted Delaunay meshes; 0: one per core, the default); results do not depend on it.");
  m.def("default_threads", &default_threads,
        "The default set by set_default_threads (0: one per core).");
  m.def("report", &report_of, py::arg("packing"), py::kw_only(), py::arg("spectrum") = true, py::arg("threads") = 0,
        "The quality figures `disktune report --json` writes, as a dict; the spectrum on `threads` threads "
        "(0: one per core).");
  m.def("remesh", &remesh_surface, py::arg("surface"), py::kw_only(), py::arg("vertices"),
        py::arg("seed") = 1, py::arg("relax_sweeps") = 30, py::arg("threads") = 0,
        py::arg("progress") = py::none(),
        "A mesh of the surface with exactly `vertices` vertices on it, from a tuned and relaxed "
        "packing; relaxation and the meshes on `threads` threads (0: one per core), the mesh the "
        "same for any number.");
  m.def(
      "rve", &make_rve_py, py::kw_only(), py::arg("diameter"), py::arg("gap") = 0.0,
      py::arg("vf") = py::none(), py::arg("fibers") = py::none(), py::arg("width") = 1.0,
      py::arg("height") = 1.0, py::arg("diameter_cv") = 0.0, py::arg("seed") = 1,
      py::arg("progress") = py::none(),
      "A random periodic fiber arrangement at an exact fiber count or fraction (`disktune rve`).");
}
