#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Draws a fiber RVE mesh (Gmsh MSH, read by meshio) as SVG: the fibers' triangles blue,
# the matrix's light gray, every edge thin and dark. For docs/rve.md's pictures.
#   /usr/bin/python3 docs/pictures/mesh_svg.py CELL.msh OUT.svg
import sys
import meshio
import numpy as np

mesh = meshio.read(sys.argv[1])
points = mesh.points[:, :2]
triangles = np.concatenate([c.data for c in mesh.cells if c.type == "triangle"])
in_fibers = np.zeros(len(triangles), dtype=bool)
in_fibers[mesh.cell_sets_dict["fibers"]["triangle"]] = True
width, height = points[:, 0].max(), points[:, 1].max()
scale = 800 / width
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="800" height="{height * scale:.0f}">']
for fiber, fill in ((False, "#eeeeee"), (True, "#4a7fd4")):
    out.append(f'<g fill="{fill}" stroke="#333" stroke-width="0.3">')
    for tri in triangles[in_fibers == fiber]:
        xy = " ".join(f"{x * scale:.1f},{(height - y) * scale:.1f}" for x, y in points[tri])
        out.append(f'<polygon points="{xy}"/>')
    out.append("</g>")
out.append("</svg>")
open(sys.argv[2], "w").write("\n".join(out) + "\n")
