# SPDX-License-Identifier: GPL-3.0-or-later
# The Python module end to end. Every result is checked here by brute force in numpy
# (pairwise distances, coverage of a fine grid, areas, edge counts), not by disktune.
import json
import math
import os
import signal
import threading

import numpy as np
import pytest

import disktune

DATA = os.environ.get("DISKTUNE_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))


def periodic_gaps(points, width=1.0, height=1.0):
    """All pairwise center distances on the torus (upper triangle)."""
    d = points[:, None, :] - points[None, :, :]
    d[..., 0] -= width * np.round(d[..., 0] / width)
    d[..., 1] -= height * np.round(d[..., 1] / height)
    dist = np.sqrt((d ** 2).sum(-1))
    return dist[np.triu_indices(len(points), 1)]


def uncovered_grid_points(points, r, samples=160, width=1.0, height=1.0):
    """Grid points of the box farther than r from every center (periodic)."""
    g = (np.arange(samples) + 0.5) / samples
    grid = np.stack(np.meshgrid(g * width, g * height), -1).reshape(-1, 2)
    nearest = np.full(len(grid), np.inf)
    for chunk in np.array_split(points, max(1, len(points) // 256)):
        d = grid[:, None, :] - chunk[None, :, :]
        d[..., 0] -= width * np.round(d[..., 0] / width)
        d[..., 1] -= height * np.round(d[..., 1] / height)
        nearest = np.minimum(nearest, np.sqrt((d ** 2).sum(-1)).min(1))
    return int((nearest > r).sum())


def edge_uses(triangles):
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return counts


def test_the_simplest_call_samples_the_unit_periodic_box():
    s = disktune.sample(radius=0.05, seed=3)
    assert s.points.shape == (len(s), 2) and s.radii.shape == (len(s),)
    assert s.points.dtype == np.float64
    assert np.all(s.radii == 0.05)
    assert np.all((s.points >= 0) & (s.points < 1))
    assert periodic_gaps(s.points).min() >= 0.05 * (1 - 1e-12)  # conflict-free
    assert uncovered_grid_points(s.points, 0.05) == 0  # maximal, as far as a grid can tell
    assert s.area_fraction == pytest.approx(len(s) * math.pi * 0.05 ** 2 / 4)
    assert s.tuning is None and s.is_maximal() and s.is_conflict_free()
    again = disktune.sample(0.05, seed=3)
    assert np.array_equal(again.points, s.points)  # a seed gives the same sample


def test_the_grid_check_above_can_fail():
    s = disktune.sample(radius=0.05, seed=3)
    assert uncovered_grid_points(s.points[1:], 0.05) > 0  # one disk less leaves a hole
    assert periodic_gaps(np.vstack([s.points, s.points[:1] + 0.01])).min() < 0.05


@pytest.mark.parametrize("more", [60, -40])
def test_tune_reaches_the_count_and_leaves_the_sample_as_it_was(more):
    s = disktune.sample(radius=0.05, seed=4)
    before = s.points.copy()
    t = disktune.tune(s, count=len(s) + more, seed=2)
    assert len(t) == len(s) + more and t.tuning["reached"] and t.tuning["count"] == len(t)
    assert np.array_equal(s.points, before)
    assert periodic_gaps(t.points).min() >= 0.05 * (1 - 1e-12)
    assert uncovered_grid_points(t.points, 0.05) == 0


def test_tune_to_an_area_fraction_in_a_wider_box():
    box = disktune.PeriodicBox(2.0, 1.0)
    s = disktune.sample(radius=0.04, domain=box, seed=5)
    t = disktune.tune(s, area_fraction=0.7, seed=1)
    assert t.area_fraction == pytest.approx(len(t) * math.pi * 0.04 ** 2 / 4 / 2.0)
    assert abs(t.area_fraction - 0.7) < 2 * math.pi * 0.04 ** 2 / 4 / 2.0
    assert periodic_gaps(t.points, 2.0, 1.0).min() >= 0.04 * (1 - 1e-12)
    assert uncovered_grid_points(t.points, 0.04, 200, 2.0, 1.0) == 0


def test_the_periodic_mesh_is_a_torus_of_the_disks():
    s = disktune.sample(radius=0.05, seed=6)
    m = disktune.mesh(s)
    assert m.triangles.min() >= 0 and m.triangles.max() < len(m.points)
    # Every vertex is its disk's center, up to the period.
    shift = m.points - s.points[m.disks]
    assert np.allclose(shift, np.round(shift), atol=1e-12)
    # A triangulated torus: twice as many triangles as vertices, each edge in two.
    assert len(m.triangles) == 2 * len(s)
    assert np.all(edge_uses(m.disks[m.triangles]) == 2)


def square(lo, hi):
    return np.array([[lo, lo], [hi, lo], [hi, hi], [lo, hi]], dtype=float)


def test_a_planar_domain_with_a_hole():
    domain = disktune.PlanarDomain(square(0, 1), [square(0.4, 0.6)])
    assert domain.area == pytest.approx(0.96)
    s = disktune.sample(radius=0.04, domain=domain, seed=7)
    p = s.points
    inside = (p >= 0).all(1) & (p <= 1).all(1) & ~((p > 0.4) & (p < 0.6)).all(1)
    assert inside.all()
    d = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(-1))[np.triu_indices(len(p), 1)]
    assert d.min() >= 0.04 * (1 - 1e-9)
    assert s.fixed.sum() > 0  # disks held on the boundary
    m = disktune.mesh(s)
    a, b, c = (m.points[m.triangles[:, k]] for k in range(3))
    areas = 0.5 * ((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
    assert np.all(areas > 0) and areas.sum() == pytest.approx(0.96, rel=1e-9)  # the hole is left out
    t = disktune.tune(s, count=len(s) + 30, seed=3)
    assert len(t) == len(s) + 30


def test_a_planar_domain_from_a_poly_file():
    domain = disktune.PlanarDomain.read(os.path.join(DATA, "domains", "square_with_hole.poly"))
    assert len(domain.loops) >= 2
    s = disktune.sample(radius=0.05, domain=domain, seed=1)
    assert len(s) > 0 and s.is_maximal()


def octahedron():
    v = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    f = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return v, f


def test_a_surface_from_arrays():
    v, f = octahedron()
    surface = disktune.Surface(v, f, features=None)
    assert surface.genus == 0 and surface.is_closed and surface.area == pytest.approx(4 * math.sqrt(3))
    s = disktune.sample(radius=0.1, domain=surface, seed=2)
    p = s.points
    assert p.shape == (len(s), 3)
    assert np.allclose(np.abs(p).sum(1), 1, atol=1e-12)  # the octahedron is |x| + |y| + |z| = 1
    d = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(-1))[np.triu_indices(len(p), 1)]
    assert d.min() >= 0.1 * (1 - 1e-9)
    m = disktune.mesh(s)
    assert np.all(edge_uses(m.triangles) == 2)  # closed and manifold
    edges = len(edge_uses(m.triangles))
    assert len(m.points) - edges + len(m.triangles) == 2  # a sphere


def test_stray_folds_are_dropped_unless_asked_for():
    path = os.path.join(DATA, "surfaces", "elephant.off")
    assert disktune.Surface.read(path).feature_curves == 0  # short scratches with loose ends
    assert disktune.Surface.read(path, stray=0).feature_curves == 84  # every 60-degree edge
    v, f = octahedron()  # its 12 edges fold by 109.5 degrees: one network, kept
    assert disktune.Surface(v, f).feature_curves == 12


def test_remesh_gives_the_count_on_a_surface_of_genus_two():
    surface = disktune.Surface.read(os.path.join(DATA, "surfaces", "eight.off"))
    m = disktune.remesh(surface, vertices=1500, seed=1, relax_sweeps=5)
    assert m.points.shape == (1500, 3)
    uses = edge_uses(m.triangles)
    assert np.all(uses == 2)
    assert len(m.points) - len(uses) + len(m.triangles) == 2 - 2 * 2
    assert m.report["mesh_check"]["manifold"] and m.report["mesh_check"]["genus"] == 2
    assert m.report["reached"] and m.report["mesh"]["angles"]["min"] > 0
    alone = disktune.remesh(surface, vertices=1500, seed=1, relax_sweeps=5, threads=1)
    assert np.array_equal(alone.points, m.points) and np.array_equal(alone.triangles, m.triangles)
    disktune.set_default_threads(1)
    assert disktune.default_threads() == 1
    default_one = disktune.remesh(surface, vertices=1500, seed=1, relax_sweeps=5)
    disktune.set_default_threads(0)
    assert np.array_equal(default_one.points, m.points)


def test_report_is_a_dict_of_the_json_report():
    s = disktune.sample(radius=0.05, seed=8)
    r = disktune.report(s, spectrum=False)
    assert isinstance(r, dict)
    json.dumps(r)
    assert r["maximal"] and r["conflict_free"]
    assert r["count"] == len(s)
    assert 0 <= r["order"]["psi6_global"] < 0.2 and r["order"]["grains"]["count"] >= 0
    with_spectrum = disktune.report(s)
    assert "spectrum" in with_spectrum
    assert disktune.report(s, threads=1)["spectrum"] == with_spectrum["spectrum"]


def test_csv_written_reads_back():
    s = disktune.sample(radius=0.05, seed=9)
    path = os.path.join(os.environ.get("TMPDIR", "/tmp"), "disktune_python_test_%d.csv" % os.getpid())
    try:
        s.write_csv(path)
        back = np.genfromtxt(path, delimiter=",", names=True)
        assert back.dtype.names == ("x", "y", "r")
        assert np.array_equal(np.stack([back["x"], back["y"]], 1), s.points)
    finally:
        if os.path.exists(path):
            os.remove(path)


def test_errors_are_python_exceptions_with_the_librarys_message():
    with pytest.raises(disktune.InvalidInput) as bad_radius:
        disktune.sample(radius=-1)
    assert isinstance(bad_radius.value, ValueError) and isinstance(bad_radius.value, disktune.Error)
    assert "radius" in str(bad_radius.value)
    with pytest.raises(disktune.InvalidInput):
        disktune.sample(radius=0.1, sizing="0.1")
    s = disktune.sample(radius=0.1)
    with pytest.raises(disktune.InvalidInput, match="exactly one"):
        disktune.tune(s, count=10, area_fraction=0.5)
    with pytest.raises(disktune.InvalidInput, match="method"):
        disktune.tune(s, count=10, method="magic")
    with pytest.raises(OSError):
        disktune.Surface.read("/nonexistent/surface.off")
    with pytest.raises(disktune.InvalidInput, match="faces"):
        disktune.Surface(np.zeros((3, 3)), np.array([[0, 1, 7]]))
    with pytest.raises(disktune.InvalidInput):
        disktune.PlanarDomain(np.zeros((4, 3)))


def test_progress_is_called_and_can_cancel():
    s = disktune.sample(radius=0.02, seed=10)
    seen = []

    def watch(p):
        seen.append(p)

    t = disktune.tune(s, area_fraction=0.7, progress=watch)
    assert seen and {"count", "area_fraction", "phase", "phase_goal"} <= set(seen[0])
    # Squeeze injection (the box) hands over at area fraction 0.82, past the target here:
    # its goal is the target's count, where tuning ends.
    assert [p["phase_goal"] for p in seen if p["phase"] == "squeeze injection"] == [len(t)] * len(seen)
    with pytest.raises(disktune.Cancelled):
        disktune.tune(s, area_fraction=0.7, progress=lambda p: False)

    def fail(p):
        raise KeyError("from the callable")

    with pytest.raises(KeyError, match="from the callable"):
        disktune.tune(s, area_fraction=0.7, progress=fail)


def test_ctrl_c_stops_a_long_tune():
    s = disktune.sample(radius=0.005, seed=12)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            # About two seconds untouched (void and repeller injection; targets of 0.84 and
            # more grow grains from the sample in well under a second).
            disktune.tune(s, area_fraction=0.80, seed=1)
    finally:
        timer.cancel()


def test_the_gil_is_released_while_tuning():
    s = disktune.sample(radius=0.01, seed=11)
    done = []
    worker = threading.Thread(target=lambda: done.append(disktune.tune(s, area_fraction=0.75, seed=1)))
    spins = 0
    worker.start()
    while worker.is_alive():
        spins += 1
    worker.join()
    assert len(done[0]) > len(s)
    # Held for the whole tune (about 0.2 s), the GIL would leave this loop a few turns.
    assert spins > 10000


def test_rve_fibers_keep_their_gap():
    r = disktune.rve(diameter=0.1, gap=0.005, vf=0.6, seed=1)
    c, d = r.centers, r.diameters
    assert c.shape == (len(d), 2)
    assert r.fiber_fraction == pytest.approx((math.pi * d ** 2 / 4).sum())
    assert abs(r.fiber_fraction - 0.6) < math.pi * 0.1 ** 2 / 4
    gaps = periodic_gaps(c)
    i, j = np.triu_indices(len(c), 1)
    assert np.all(gaps >= ((d[i] + d[j]) / 2 + 0.005) * (1 - 1e-12))
    stats = r.statistics()
    assert isinstance(stats, dict) and stats


def test_the_readme_example_hands_the_mesh_to_meshio():
    meshio = pytest.importorskip("meshio")
    surface = disktune.Surface.read(os.path.join(DATA, "surfaces", "sphere.off"), features=None)
    m = disktune.remesh(surface, vertices=500, relax_sweeps=3)
    path = os.path.join(os.environ.get("TMPDIR", "/tmp"), "disktune_python_test_%d.vtu" % os.getpid())
    try:
        meshio.write(path, meshio.Mesh(m.points, [("triangle", m.triangles)]))
        back = meshio.read(path)
        assert len(back.points) == 500 and len(back.cells_dict["triangle"]) == len(m.triangles)
    finally:
        if os.path.exists(path):
            os.remove(path)


def test_meshes_write_themselves_in_the_librarys_formats(tmp_path):
    meshio = pytest.importorskip("meshio")
    surface = disktune.Surface.read(os.path.join(DATA, "surfaces", "eight.off"))
    m = disktune.remesh(surface, vertices=400, relax_sweeps=2)
    m.write(str(tmp_path / "e.vtu"))
    back = meshio.read(str(tmp_path / "e.vtu"))
    assert np.allclose(back.points, m.points) and np.array_equal(back.cells_dict["triangle"], m.triangles)
    m.write(str(tmp_path / "e.mesh"), format="off")  # the format named, whatever the extension
    assert open(tmp_path / "e.mesh").readline().strip() == "OFF"
    planar = disktune.mesh(disktune.sample(radius=0.1, domain=disktune.PlanarDomain(square(0, 1)), seed=2))
    planar.write(str(tmp_path / "p.obj"))
    lines = open(tmp_path / "p.obj").read().split("\n")
    assert sum(line.startswith("v ") for line in lines) == len(planar.points)
    assert sum(line.startswith("f ") for line in lines) == len(planar.triangles)
    holed = disktune.PlanarDomain(square(0, 1), [square(0.3, 0.6)])
    holed_packing = disktune.sample(radius=0.1, domain=holed, seed=2)
    disktune.mesh(holed_packing).write(str(tmp_path / "h.msh"))  # loops as named physical groups
    back = meshio.read(str(tmp_path / "h.msh"))
    assert set(back.field_data) == {"domain", "outer boundary", "hole 1"}
    lines = sum(len(c.data) for c in back.cells if c.type == "line")
    assert lines == holed_packing.fixed.sum()  # an edge from each boundary disk to the next
    disktune.mesh(holed_packing).write(str(tmp_path / "h.node"))  # Triangle's pair, from 1
    node = np.loadtxt(tmp_path / "h.node", skiprows=2)
    ele = np.loadtxt(tmp_path / "h.ele", skiprows=2, dtype=int)
    hm = disktune.mesh(holed_packing)
    assert np.array_equal(node[:, 1:3], hm.points) and np.array_equal(ele[:, 1:] - 1, hm.triangles)
    assert sorted(set(node[:, 3])) == [0, 1, 2]  # inside, the outer loop, the hole
    with pytest.raises(disktune.InvalidInput):
        m.write(str(tmp_path / "e.node"))  # a surface mesh: not Triangle's
    with pytest.raises(disktune.IoError):
        m.write(str(tmp_path / "no" / "such" / "e.off"))
    with pytest.raises(disktune.InvalidInput):
        m.write(str(tmp_path / "e.off"), format="dxf")


def test_a_surface_report_and_a_planar_report():
    v, f = octahedron()
    s = disktune.sample(radius=0.15, domain=disktune.Surface(v, f), seed=3)
    r = disktune.report(s)
    assert r["count"] == len(s) and r["maximal"] and r["conflict_free"]
    assert r["mesh_check"]["manifold"] and r["mesh_check"]["genus"] == 0
    planar = disktune.sample(radius=0.05, domain=disktune.PlanarDomain(square(0, 1)), seed=2)
    assert disktune.report(planar)["maximal"]


def test_the_readme_example_runs_as_written(tmp_path, monkeypatch, capsys):
    pytest.importorskip("meshio")
    readme = open(os.path.join(DATA, "..", "README.md"), encoding="utf-8").read()
    start = readme.index("```python\n", readme.index("## Using it from Python")) + len("```python\n")
    code = readme[start:readme.index("```", start)]
    assert len(code.strip().splitlines()) <= 12
    monkeypatch.chdir(tmp_path)
    code = code.replace('"data/', '"' + DATA + "/")  # the data folder from anywhere
    exec(compile(code, "README.md", "exec"), {})
    assert os.path.exists(tmp_path / "eight.vtu")
    assert capsys.readouterr().out.splitlines()[-1].endswith(" 2")  # genus 2
