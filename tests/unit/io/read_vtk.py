#!/usr/bin/python3
"""Reads back the VTK series written by unit_io (VtkSeriesWriterTest.cpp) with VTK's own
readers and checks them value by value. Node order is checked independently of contactlab's
tables: every VTK node must sit at x = b + A p, with p VTK's parametric coordinates of that
node and A, b the per-cell affine map the test wrote as cell data (see TestMeshes.hpp).

usage: read_vtk.py OUTPUT_DIR NP [NP ...]
"""
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

# Mirrors TestMeshes.cpp.
PLANE = ["point1", "line2", "line3", "tri3", "tri6", "quad4", "quad8", "quad9"]
SOLID = ["tet4", "tet10", "hex8", "hex20", "hex27"]
SERIES = {  # name: (cell types, number of cells, dimension, step times)
    "plane": (PLANE, 16, 2, [0.0, 0.1, 1.0 / 3.0]),
    "solid": (SOLID, 10, 3, [0.0, 0.1]),
    "single": (SOLID, 1, 3, [0.5, 0.1]),
}
# Expected VTK ids from VTK's own constants, not from contactlab's table.
VTK_TYPE = {
    "point1": vtk.VTK_VERTEX, "line2": vtk.VTK_LINE, "line3": vtk.VTK_QUADRATIC_EDGE,
    "tri3": vtk.VTK_TRIANGLE, "tri6": vtk.VTK_QUADRATIC_TRIANGLE, "quad4": vtk.VTK_QUAD,
    "quad8": vtk.VTK_QUADRATIC_QUAD, "quad9": vtk.VTK_BIQUADRATIC_QUAD, "tet4": vtk.VTK_TETRA,
    "tet10": vtk.VTK_QUADRATIC_TETRA, "hex8": vtk.VTK_HEXAHEDRON,
    "hex20": vtk.VTK_QUADRATIC_HEXAHEDRON, "hex27": vtk.VTK_TRIQUADRATIC_HEXAHEDRON,
}
NODES = {"point1": 1, "line2": 2, "line3": 3, "tri3": 3, "tri6": 6, "quad4": 4, "quad8": 8,
         "quad9": 9, "tet4": 4, "tet10": 10, "hex8": 8, "hex20": 20, "hex27": 27}
POINT_ARRAYS = [("displacement", 3), ("gap", 1)]
CELL_ARRAYS = [("von_mises", 1), ("stress", 6), ("map_A", 9), ("map_b", 3), ("cell_id", 1),
               ("rank", 1)]

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        if len(failures) > 50:
            report_and_exit()


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


def report_and_exit():
    for f in failures[:50]:
        print("FAIL:", f)
    print("%d failure(s)" % len(failures))
    sys.exit(1)


def map_a(g, dim):
    a = [1.0 + 0.1 * g, 0.2, 0.1, -0.15, 0.8 + 0.05 * g, -0.2, 0.05, 0.1, 1.2]
    if dim == 2:
        for i in (2, 5, 6, 7, 8):
            a[i] = 0.0
    return a


def map_b(g, dim):
    return [3.0 * g, 0.5 * g, -0.25 * g if dim == 3 else 0.0]


def apply(a, b, p):
    return [b[i] + a[3 * i] * p[0] + a[3 * i + 1] * p[1] + a[3 * i + 2] * p[2] for i in range(3)]


def expected_size(name, a):
    col = [[a[0], a[3], a[6]], [a[1], a[4], a[7]], [a[2], a[5], a[8]]]
    cross = [col[0][1] * col[1][2] - col[0][2] * col[1][1],
             col[0][2] * col[1][0] - col[0][0] * col[1][2],
             col[0][0] * col[1][1] - col[0][1] * col[1][0]]
    area = math.sqrt(sum(c * c for c in cross))
    det = abs(sum(cross[i] * col[2][i] for i in range(3)))
    return {"line2": math.sqrt(sum(c * c for c in col[0])), "tri3": area / 2, "quad4": area,
            "tet4": det / 6, "hex8": det}[{"line3": "line2", "tri6": "tri3", "quad8": "quad4",
                                            "quad9": "quad4", "tet10": "tet4", "hex20": "hex8",
                                            "hex27": "hex8"}.get(name, name)]


def read(path):
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def array_values(data, name):
    arr = data.GetArray(name)
    n = arr.GetNumberOfComponents()
    return [[arr.GetComponent(t, c) for c in range(n)] for t in range(arr.GetNumberOfTuples())]


def check_arrays(where, data, expected):
    names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())]
    check(names == [n for n, _ in expected], "%s: arrays %s" % (where, names))
    for name, comps in expected:
        arr = data.GetArray(name)
        if arr is None:
            continue
        check(arr.GetNumberOfComponents() == comps,
              "%s: '%s' has %d components, expected %d"
              % (where, name, arr.GetNumberOfComponents(), comps))
        check(arr.GetDataType() == vtk.VTK_DOUBLE, "%s: '%s' is not Float64" % (where, name))


def check_grid(where, grid, types, num_cells, dim, time):
    cell_ids = [int(v[0]) for v in array_values(grid.GetCellData(), "cell_id")]
    check(sorted(cell_ids) == list(range(num_cells)), "%s: cell ids %s" % (where, cell_ids))
    check(grid.GetNumberOfPoints() == sum(NODES[types[g % len(types)]] for g in range(num_cells)),
          "%s: %d points" % (where, grid.GetNumberOfPoints()))
    check_arrays(where + " point data", grid.GetPointData(), POINT_ARRAYS)
    check_arrays(where + " cell data", grid.GetCellData(), CELL_ARRAYS)

    sizes_filter = vtkCellSizeFilter()
    sizes_filter.SetInputData(grid)
    vtk.vtkObject.GlobalWarningDisplayOff()  # it warns about (and skips) hex27
    sizes_filter.Update()
    vtk.vtkObject.GlobalWarningDisplayOn()
    sizes = sizes_filter.GetOutput().GetCellData()

    von_mises = array_values(grid.GetCellData(), "von_mises")
    stress = array_values(grid.GetCellData(), "stress")
    a_values = array_values(grid.GetCellData(), "map_A")
    b_values = array_values(grid.GetCellData(), "map_b")
    displacement = array_values(grid.GetPointData(), "displacement")
    gap = array_values(grid.GetPointData(), "gap")
    for c in range(grid.GetNumberOfCells()):
        g = cell_ids[c]
        name = types[g % len(types)]
        here = "%s cell %d (%s)" % (where, g, name)
        check(grid.GetCellType(c) == VTK_TYPE[name],
              "%s: VTK type %d, expected %d" % (here, grid.GetCellType(c), VTK_TYPE[name]))
        a, b = map_a(g, dim), map_b(g, dim)
        check(a_values[c] == a and b_values[c] == b, "%s: map_A/map_b differ" % here)
        check(von_mises[c][0] == 1.5 * g + time, "%s: von_mises %r" % (here, von_mises[c]))
        check(stress[c] == [10.0 * g + k for k in range(6)], "%s: stress %r" % (here, stress[c]))

        cell = grid.GetCell(c)
        pcoords = cell.GetParametricCoords()
        for i in range(cell.GetNumberOfPoints()):
            p = [pcoords[3 * i + k] for k in range(3)]
            x = grid.GetPoint(cell.GetPointId(i))
            want = apply(a, b, p)
            check(all(close(x[k], want[k]) for k in range(3)),
                  "%s: VTK node %d at %s, expected %s (parametric %s)" % (here, i, x, want, p))
            pid = cell.GetPointId(i)
            s = 1.0 + time
            u = [s * (x[0] + 2 * x[1]), s * (3 * x[0] - x[1]), s * (x[2] - x[0]) if dim == 3 else 0.0]
            check(all(close(displacement[pid][k], u[k]) for k in range(3)),
                  "%s: displacement %s, expected %s" % (here, displacement[pid], u))
            check(close(gap[pid][0], x[0] - time), "%s: gap %s" % (here, gap[pid]))
        if name == "point1":
            continue
        # Interpolating through VTK's shape functions must reproduce the affine map inside.
        p = [0.2, 0.3, 0.1] if dim == 3 else [0.2, 0.3, 0.0]
        if cell.GetCellDimension() == 1:
            p = [0.3, 0.0, 0.0]
        x = [0.0] * 3
        weights = [0.0] * cell.GetNumberOfPoints()
        cell.EvaluateLocation(vtk.reference(0), p, x, weights)
        want = apply(a, b, p)
        check(all(close(x[k], want[k]) for k in range(3)),
              "%s: EvaluateLocation(%s) = %s, expected %s" % (here, p, x, want))
        # So must the Jacobian of VTK's shape functions: dx/dp = A (first dim columns).
        n = cell.GetNumberOfPoints()
        derivs = [0.0] * (cell.GetCellDimension() * n)
        cell.InterpolateDerivs(p, derivs)
        for d in range(cell.GetCellDimension()):
            column = [sum(grid.GetPoint(cell.GetPointId(j))[i] * derivs[d * n + j]
                          for j in range(n)) for i in range(3)]
            check(all(close(column[i], a[3 * i + d], 1e-10) for i in range(3)),
                  "%s: dx/dp%d = %s, expected %s" % (here, d, column, a[d::3]))
        if name == "hex27":
            continue  # vtkCellSizeFilter cannot triangulate it (VTK 9.1): size reads 0
        measure = {1: "Length", 2: "Area", 3: "Volume"}[cell.GetCellDimension()]
        got = sizes.GetArray(measure).GetValue(c)
        check(close(got, expected_size(name, a), 1e-9),
              "%s: %s %r, expected %r" % (here, measure, got, expected_size(name, a)))


def check_series(directory, name, np):
    types, num_cells, dim, times = SERIES[name]
    where = "%s (np %d)" % (name, np)
    hidden = [f for f in os.listdir(directory) if f.startswith(".")]
    check(not hidden, "%s: temporary files left: %s" % (where, hidden))
    datasets = ET.parse(os.path.join(directory, name + ".pvd")).getroot().find("Collection")
    datasets = list(datasets)
    check([float(d.get("timestep")) for d in datasets] == times,
          "%s: pvd times %s, expected %s" % (where, [d.get("timestep") for d in datasets], times))
    ext = "vtu" if np == 1 else "pvtu"
    for step, (dataset, time) in enumerate(zip(datasets, times)):
        file = dataset.get("file")
        check(file == "%s_%06d.%s" % (name, step, ext), "%s: pvd names %s" % (where, file))
        path = os.path.join(directory, file)
        grid = read(path)
        check(grid.GetNumberOfCells() == num_cells,
              "%s: %s has %d cells" % (where, file, grid.GetNumberOfCells()))
        check_grid("%s %s" % (where, file), grid, types, num_cells, dim, time)
        if np > 1:
            # Each piece holds the cells of one rank, as written by that rank.
            for rank in range(np):
                piece = "%s_%06d_p%d.vtu" % (name, step, rank)
                pgrid = read(os.path.join(directory, piece))
                ranks = {v[0] for v in array_values(pgrid.GetCellData(), "rank")}
                check(ranks <= {float(rank)}, "%s: %s holds ranks %s" % (where, piece, ranks))
                check(pgrid.GetNumberOfCells() == len(range(rank, num_cells, np)),
                      "%s: %s has %d cells" % (where, piece, pgrid.GetNumberOfCells()))


def main():
    output = sys.argv[1]
    for np in map(int, sys.argv[2:]):
        for name in SERIES:
            check_series(os.path.join(output, "np%d" % np, name), name, np)
    if failures:
        report_and_exit()
    print("read_vtk.py: all series read back correctly")


if __name__ == "__main__":
    main()
