"""Read thinlayer's results with VTK's own XML readers, the library ParaView
reads them with, and check what a client sees (run by vtk_reader.cc, with
Debian's /usr/bin/python3 and its python3-vtk9).

The scene (written by vtk_reader.cc): the inclined column of
meshes/inclined-column.geo, a layer of material 2 at ALPHA degrees, every
material elastic with E and nu, sides free, a traction (0, -p) on the top
and on the base u = (a x, 0) with a = nu (1 + nu) p / E: at load factor L
the exact solution is uniaxial plane-strain compression,

    sigma_yy = -L p,  sigma_xx = sigma_xy = 0,  sigma_zz = -L nu p,
    u = L (a x, -b y),  a = nu (1 + nu) p / E,  b = (1 - nu^2) p / E,

which every quadratic element reproduces to round-off. On the layer (its
tangent s = (cos, sin) from the lower left, normal n = (-sin, cos)):

    shear traction s.sigma.n = -L p cos sin,  normal n.sigma.n = -L p cos^2,

and slip and opening are u's jump from the layer's lower face to its upper
face between the points that face each other, which the mesh offsets
vertically by tv = h / cos (h the layer's thickness, l / aspect_ratio,
l = 1 / cos the layer's length): jump = (0, -L b tv), slip = jump.s =
-L b tv sin, opening = jump.n = -L b tv cos.

Tolerances: deal.II writes the fields' points and values as Float32
(zlib-compressed binary), which rounds each to 2^-24 = 6e-8 of itself, so
the fields are checked to 1e-6 of the field's largest exact value. The
layer's VTU is ASCII Float64 with 10 significant digits, so its values are
checked to 1e-8 of the exact value.

Usage: vtk_reader.py --young E --poisson NU --pressure P --alpha DEG
                     --aspect-ratio R --layer-id ID --steps N
                     LABEL:RANKS=DIRECTORY ...
checks the results in each DIRECTORY, written on RANKS ranks in N load
steps, then each run's numbers of points and cells against the first's.
Every check is printed as "name: value vs expected within tol: yes/NO";
the exit status is 1 if any says NO.
"""
import argparse
import math
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

import vtk

FAILURES = []


def report(name, ok, value=None, expected=None, tolerance=None):
    """Print one check, "name: value vs expected within tol: yes/NO";
    remember it if it failed."""
    text = name
    if value is not None:
        text += ": %s" % (value,)
        if expected is not None:
            text += " vs %s" % (expected,)
        if tolerance is not None:
            text += " within %s" % tolerance
    print("  %s: %s" % (text, "yes" if ok else "NO"))
    if not ok:
        FAILURES.append(name)


def number(x):
    """A value as printed: 6 significant digits, no negative zero."""
    text = "%.6g" % x
    return "0" if text in ("-0", "0") else text


class ErrorCatcher:
    """Every error or warning VTK reports while reading."""

    def __init__(self):
        # Messages that go to VTK's output window (from any object, the
        # piece readers inside a .pvtu reader too) are kept here.
        self.window = vtk.vtkStringOutputWindow()
        vtk.vtkOutputWindow.SetInstance(self.window)
        self.events = []

    def observe(self, reader):
        for event in ("ErrorEvent", "WarningEvent"):
            reader.AddObserver(event, self.on_event)

    @vtk.calldata_type(vtk.VTK_STRING)
    def on_event(self, caller, event, message):
        text = " ".join(str(message).split())
        self.events.append("%s: %s" % (event, text))

    def take(self):
        """The messages since the last call (empty: none)."""
        window = self.window.GetOutput().strip()
        messages = self.events + ([" ".join(window.split())] if window else [])
        self.events = []
        self.window = vtk.vtkStringOutputWindow()
        vtk.vtkOutputWindow.SetInstance(self.window)
        return messages


CATCHER = ErrorCatcher()


def read(path):
    """The unstructured grid in @p path (.vtu or .pvtu) and its reader;
    reports whether it was read without an error."""
    if path.endswith(".pvtu"):
        reader = vtk.vtkXMLPUnstructuredGridReader()
    else:
        reader = vtk.vtkXMLUnstructuredGridReader()
    CATCHER.observe(reader)
    reader.SetFileName(path)
    reader.Update()
    messages = CATCHER.take()
    ok = reader.GetErrorCode() == 0 and not messages and \
        reader.GetOutput() is not None
    if not ok:
        print("    reader error code %d, messages: %s"
              % (reader.GetErrorCode(), " | ".join(messages)))
    return reader.GetOutput(), reader, ok


def point_arrays(grid):
    """{name: (components, tuples)} of the grid's point data."""
    data = grid.GetPointData()
    arrays = {}
    for i in range(data.GetNumberOfArrays()):
        array = data.GetAbstractArray(i)
        arrays[array.GetName()] = (array.GetNumberOfComponents(),
                                   array.GetNumberOfTuples())
    return arrays


def check_arrays(what, grid, expected):
    """The arrays of @p expected ({name: components}) present, each with its
    components and one tuple per point."""
    arrays = point_arrays(grid)
    n = grid.GetNumberOfPoints()
    found = " ".join(
        "%s:%s" % (name, arrays[name][0] if name in arrays else "missing")
        + ("" if name not in arrays or arrays[name][1] == n
           else "(%d tuples)" % arrays[name][1])
        for name in expected)
    wanted = " ".join("%s:%d" % item for item in expected.items())
    report("%s point-data arrays, name:components, one tuple per point" % what,
           found == wanted, found, "the same")
    return found == wanted


class Worst:
    """The point furthest from the exact field, over every point checked;
    the check passes if it is within tolerance * scale."""

    def __init__(self, scale, tolerance):
        self.scale, self.tolerance = scale, tolerance
        self.error, self.value, self.exact, self.count = -1.0, 0.0, 0.0, 0

    def add(self, value, exact):
        self.count += 1
        error = math.inf if math.isnan(value) else abs(value - exact)
        if error > self.error:
            self.error, self.value, self.exact = error, value, exact

    def ok(self):
        return self.count > 0 and self.error <= self.tolerance * self.scale

    def report_value(self, name, exact_text):
        """For a uniform exact field: the furthest value against it (what
        is printed differs between machines by less than numdiff's 1e-6;
        a value within 1e-12 of the scale of 0 is printed as 0)."""
        value = 0.0 if abs(self.value) <= 1e-12 * self.scale else self.value
        report("%s at %d points, the furthest" % (name, self.count),
               self.ok(), number(value),
               "%s = %s" % (exact_text, number(self.exact)),
               "%g of %s" % (self.tolerance, number(self.scale)))

    def report_error(self, name, exact_text):
        """For a varying exact field: the largest difference, divided by the
        scale, against 0."""
        report("%s at %d points, max |%s - (%s)| / %s"
               % (name, self.count, name, exact_text, number(self.scale)),
               self.ok(), number(self.error / self.scale), 0,
               "%g" % self.tolerance)


def datasets(directory):
    """(timestep, file) of each DataSet in fields.pvd: a .pvd is a VTK
    collection, XML that lists the files (vtkPVDReader is ParaView's, not
    in python3-vtk9)."""
    root = ElementTree.parse(os.path.join(directory, "fields.pvd")).getroot()
    return [(float(d.get("timestep")), d.get("file"))
            for d in root.iter("DataSet")]


def open_file(directory, name, load, ranks, totals):
    """Read @p name with VTK's reader for its kind, report that it read
    without error, its pieces (a .pvtu: one per rank) and its sizes, and
    append (load, points, cells) to @p totals; the grid read."""
    print(" %s (load factor %s):" % (name, number(load)))
    grid, reader, ok = read(os.path.join(directory, name))
    report("read by %s without error" % reader.GetClassName(), ok)
    if name.endswith(".pvtu"):
        report("pieces", reader.GetNumberOfPieces() == ranks,
               reader.GetNumberOfPieces(), ranks)
    n_points, n_cells = grid.GetNumberOfPoints(), grid.GetNumberOfCells()
    report("points, cells", n_points > 0 and n_cells > 0,
           "%d, %d" % (n_points, n_cells), "above 0")
    totals.append((load, n_points, n_cells))
    return grid


def check_run(label, directory, exact):
    """Every check of one run; returns what the runs are compared on."""
    print("%s:" % label)
    # The fields, through fields.pvd.
    steps = datasets(directory)
    report("fields.pvd data sets", len(steps) == exact["steps"],
           len(steps), exact["steps"])
    totals = {"fields": [], "layer": []}
    fields = {"displacement": 3, "stress_xx": 1, "stress_yy": 1,
              "stress_zz": 1, "stress_xy": 1, "equivalent_stress": 1,
              "plastic_strain": 1, "yield_ratio": 1, "interface_slip": 1,
              "interface_opening": 1, "interface_shear_traction": 1,
              "interface_normal_traction": 1, "material_id": 1}
    p, a, b, nu = exact["p"], exact["a"], exact["b"], exact["nu"]
    c, s = exact["cos"], exact["sin"]
    tol = 1e-6  # Float32 in the fields' VTU
    for load, name in steps:
        grid = open_file(directory, name, load, exact["ranks"], totals["fields"])
        if not check_arrays("fields", grid, fields):
            continue
        data = grid.GetPointData()
        u = data.GetArray("displacement")
        stress = {k: data.GetArray("stress_" + k)
                  for k in ("xx", "yy", "zz", "xy")}
        material = data.GetArray("material_id")
        layer_normal = data.GetArray("interface_normal_traction")
        # The exact displacement's largest component over the mesh.
        bounds = grid.GetBounds()
        u_scale = load * max(a * max(abs(bounds[0]), abs(bounds[1])),
                             b * max(abs(bounds[2]), abs(bounds[3])))
        worst_ux, worst_uy = Worst(u_scale, tol), Worst(u_scale, tol)
        worst = {k: Worst(load * p, tol) for k in stress}
        worst_layer = Worst(load * p, tol)
        for i in range(grid.GetNumberOfPoints()):
            x, y, _ = grid.GetPoint(i)
            worst_ux.add(u.GetComponent(i, 0), load * a * x)
            worst_uy.add(u.GetComponent(i, 1), -load * b * y)
            for k, exact_stress in (("xx", 0.0), ("yy", -load * p),
                                    ("zz", -load * nu * p), ("xy", 0.0)):
                worst[k].add(stress[k].GetComponent(i, 0), exact_stress)
            if round(material.GetComponent(i, 0)) == exact["layer_id"]:
                worst_layer.add(layer_normal.GetComponent(i, 0),
                                -load * p * c * c)
        worst_ux.report_error("u_x", "L a x")
        worst_uy.report_error("u_y", "-L b y")
        worst["yy"].report_value("stress_yy", "-L p")
        worst["xx"].report_value("stress_xx", "0")
        worst["xy"].report_value("stress_xy", "0")
        worst["zz"].report_value("stress_zz", "-L nu p")
        worst_layer.report_value(
            "interface_normal_traction on the layer's cells", "-L p cos^2")

    # The layer's profile, one VTU per step: layer-<id>-NNNN.vtu.
    pattern = r"layer-%d-[0-9]{4}\.vtu" % exact["layer_id"]
    layer_files = sorted(f for f in os.listdir(directory)
                         if re.fullmatch(pattern, f))
    report("layer profile VTUs (layer-%d-NNNN.vtu)"
           % exact["layer_id"], len(layer_files) == exact["steps"],
           len(layer_files), exact["steps"])
    load_of_step = {int(re.search(r"-([0-9]{4})\.p?vtu$", f).group(1)): load
                    for load, f in steps}
    profile = {"slip": 1, "slip_out_of_plane": 1, "opening": 1,
               "slip_increment": 1, "opening_increment": 1,
               "shear_traction": 1, "shear_traction_out_of_plane": 1,
               "normal_traction": 1, "mobilised_strength": 1, "plastic": 1}
    tol = 1e-8  # ASCII with 10 significant digits in the layer's VTU
    for name in layer_files:
        load = load_of_step.get(int(name[-8:-4]), math.nan)
        grid = open_file(directory, name, load, exact["ranks"], totals["layer"])
        if not check_arrays("layer", grid, profile):
            continue
        data = grid.GetPointData()
        tv = exact["tv"]
        for array, exact_value, text in (
                ("shear_traction", -load * p * c * s, "-L p cos sin"),
                ("normal_traction", -load * p * c * c, "-L p cos^2"),
                ("slip", -load * b * tv * s, "-L b tv sin"),
                ("opening", -load * b * tv * c, "-L b tv cos")):
            worst = Worst(abs(exact_value), tol)
            values = data.GetArray(array)
            for i in range(grid.GetNumberOfPoints()):
                worst.add(values.GetComponent(i, 0), exact_value)
            worst.report_value(array, text)
    return totals


def main():
    parser = argparse.ArgumentParser()
    for option in ("young", "poisson", "pressure", "alpha", "aspect-ratio"):
        parser.add_argument("--" + option, type=float, required=True)
    parser.add_argument("--layer-id", type=int, required=True)
    parser.add_argument("--steps", type=int, required=True)
    parser.add_argument("runs", nargs="+", help="LABEL:RANKS=DIRECTORY")
    args = parser.parse_args()

    E, nu, p = args.young, args.poisson, args.pressure
    alpha = math.radians(args.alpha)
    thickness = 1 / math.cos(alpha) / args.aspect_ratio
    exact = {"p": p, "nu": nu, "a": nu * (1 + nu) * p / E,
             "b": (1 - nu * nu) * p / E, "cos": math.cos(alpha),
             "sin": math.sin(alpha), "tv": thickness / math.cos(alpha),
             "layer_id": args.layer_id, "steps": args.steps}
    print("exact: a = %s, b = %s, layer offset tv = %s"
          % (number(exact["a"]), number(exact["b"]), number(exact["tv"])))

    totals = []
    for run in args.runs:
        label, directory = run.split("=", 1)
        exact["ranks"] = int(label.split(":")[1])
        totals.append((label.split(":")[0],
                       check_run(label.split(":")[0], directory, exact)))

    # The same mesh however many ranks wrote it: the same cells and points
    # in total (the pieces of a .pvtu together) at every step.
    first_label, first = totals[0]
    for label, other in totals[1:]:
        print("%s against %s:" % (label, first_label))
        for what in ("fields", "layer"):
            report("%s points and cells at every step" % what,
                   other[what] == first[what] and len(first[what]) > 0,
                   "; ".join("%d, %d" % t[1:] for t in other[what]),
                   "; ".join("%d, %d" % t[1:] for t in first[what]))

    print("failed checks: %d" % len(FAILURES))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
