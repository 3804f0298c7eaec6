#!/usr/bin/python3
"""Where the noise of the interface tractions comes from: the smooth pile
section (prm/circular-inclusion-zero-thickness.prm and prm/circular-
inclusion.prm, alpha = 0.01, 12 cells per quarter circle, curved), varied one
thing at a time: the interface's integration (Gauss, Lobatto), its normal
and shear penalty stiffness, the continuum's quadrature (Q8 2x2, Q8 3x3,
Q9 3x3), the soil's Poisson's ratio, straight or curved cells, and a thin
layer (t = R/50) in place of the interface elements.

    /usr/bin/python3 -m benchmarks.interface_tractions [--output DIR] [--page]

Per variant: the collapse load, and the normal traction along the contact
(the profile's samples, ordered by arc length) at the first step (elastic)
and at the last converged one: its range and the largest jump between
neighbouring samples. The resultant is 9-12 c per unit diameter, and a
smooth profile at collapse ranges over some +-6.5 c. The raw values are
the profile at the integration points (Output/Gauss-point profiles), the
recovered ones the profile the run writes: each element's nodal forces
sum_g N_i(xi_g) t_g w_g over the corner nodes, summed over the elements of
a node and divided by its tributary length (TractionRecovery). With
python3-vtk9, also
the soil's pressure -tr(sigma)/3 as the last VTU writes it at the points
within 1.0 < r < 1.03 of the pile: range and largest jump by angle. Writes
DIR/interface_tractions.md (DIR: output/benchmarks) and prints it; the runs
go into DIR/runs/tractions-*. Results are measurements, not tests.
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import subprocess

from thinlayer_tools import THINLAYER, TOP, overrides

from benchmarks import page

OUT = os.path.join(TOP, "output", "benchmarks")
GEOMETRY = "radius=1, thickness=0.02, outer=20, n_around=12, n_radial=20, growth=1.2"
INTERFACE = "circular-inclusion-zero-thickness"
LAYER = "circular-inclusion"


def penalty(normal=None, shear=None):
    return tuple(["Interface 4/Normal stiffness=%g" % normal] if normal else []) + \
        tuple(["Interface 4/Shear stiffness=%g" % shear] if shear else [])


LOBATTO = ("Interface 4/Integration=lobatto",)
THREE = ("Discretisation/Gauss points per direction=3",)
# name, scene, entries (beside the scene file's).
VARIANTS = [
    ("interface elements, Q8 2x2, Gauss, penalty 1e8 (the file)", INTERFACE, ()),
    ("Lobatto on the interface", INTERFACE, LOBATTO),
    ("soil Poisson's ratio 0.3 (not 0.49)", INTERFACE, ("Material 1/Poisson's ratio=0.3",)),
    ("continuum Q8 3x3", INTERFACE, THREE),
    ("continuum Q9 3x3", INTERFACE, THREE + ("Discretisation/Element=Q9",)),
    ("straight cells", INTERFACE, ("Mesh/Curved cells=false",)),
    ("shear penalty 1e6", INTERFACE, penalty(shear=1e6)),
    ("normal penalty 1e7", INTERFACE, penalty(normal=1e7)),
    ("normal penalty 1e6", INTERFACE, penalty(normal=1e6)),
    ("normal penalty 1e5", INTERFACE, penalty(normal=1e5)),
    ("normal penalty 1e6, Lobatto", INTERFACE, penalty(normal=1e6) + LOBATTO),
    ("thin layer t = R/50, Q8 2x2", LAYER, ()),
    ("thin layer, Q8 3x3", LAYER, THREE),
]


def profile(path):
    """The normal traction of a profile CSV, ordered by arc length."""
    with open(path) as f:
        rows = sorted(csv.DictReader(f), key=lambda r: float(r["arc_length"]))
    return [float(r["normal_traction"]) for r in rows]


def spread(values):
    """(largest magnitude, largest jump between neighbours)."""
    return (max(abs(v) for v in values),
            max(abs(a - b) for a, b in zip(values, values[1:])) if len(values) > 1 else 0.0)


def soil_pressure(directory):
    """The soil's pressure near the pile in the last VTU: (largest
    magnitude, largest jump by angle), or None without python3-vtk9."""
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        return None
    fields = sorted(glob.glob(os.path.join(directory, "fields-*.vtu")))
    if not fields:
        return None
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(fields[-1])
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    data = grid.GetPointData()
    stress = [vtk_to_numpy(data.GetArray(n)) for n in ("stress_xx", "stress_yy", "stress_zz")]
    material = vtk_to_numpy(data.GetArray("material_id"))
    near = [(math.atan2(y, x), -(stress[0][k] + stress[1][k] + stress[2][k]) / 3)
            for k, (x, y, _) in enumerate(points)
            if 1.0 < math.hypot(x, y) < 1.03 and material[k] == 1]
    return spread([p for _, p in sorted(near)]) if near else None


def measure(output):
    rows = []
    for name, scene, entries in VARIANTS:
        tag = "".join(c if c.isalnum() else "-" for c in name.lower()).strip("-")
        directory = os.path.join(output, "runs", "tractions-" + tag)
        geometry = GEOMETRY + (", zero_thickness=1" if scene == INTERFACE else "")
        strength = ("Interface 4/Adhesion=0.01" if scene == INTERFACE
                    else "Material 2/Cohesion=0.01")
        command = [THINLAYER, os.path.join(TOP, "prm", scene + ".prm")] + overrides(
            ["Mesh/Geometry parameters=" + geometry, strength,
             "Output/Directory=" + directory, "Output/Write VTU=true",
             "Output/Gauss-point profiles=true",
             "Output/Print timing=false"] + list(entries))
        if subprocess.run(command, cwd=TOP, stdout=subprocess.DEVNULL).returncode not in (0, 4):
            raise SystemExit("interface_tractions: %s failed (its error above)" % name)
        with open(os.path.join(directory, "summary.json")) as f:
            summary = json.load(f)
        def series(name):
            return sorted(p for p in glob.glob(os.path.join(directory, name + "-*.csv"))
                          if re.fullmatch(re.escape(name) + r"-\d{4}\.csv",
                                          os.path.basename(p)))

        contact = "interface-4" if scene == INTERFACE else "layer-2"
        raw, recovered = series(contact + "-gauss"), series(contact)
        rows.append({"name": name, "summary": summary, "first": spread(profile(raw[0])),
                     "last": spread(profile(raw[-1])), "samples": len(profile(raw[-1])),
                     "recovered": spread(profile(recovered[-1])),
                     "soil": soil_pressure(directory)})
    return rows


def table(rows):
    lines = ["| variant | collapse load / (c D) | outcome | samples | first step, raw: max "
             "abs, largest jump | last step, raw: max abs, largest jump | last step, "
             "recovered (written): max abs, largest jump | soil pressure near the pile: "
             "max abs, largest jump |", "|" + "---|" * 8]
    for r in rows:
        load = r["summary"].get("collapse_load")
        soil = r["soil"]
        lines.append("| %s | %s | %s | %d | %.1f, %.1f | %.1f, %.1f | %s | %s |" % (
            r["name"], "%.3f" % load if load is not None else "-", r["summary"]["outcome"],
            r["samples"], *r["first"], *r["last"], "%.1f, %.1f" % r["recovered"],
            "%.1f, %.1f" % soil if soil else "-"))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", default=OUT,
                        help="the results directory (default %(default)s)")
    page.add_argument(parser)
    arguments = parser.parse_args()
    page.configure(arguments)
    rows = measure(arguments.output)
    os.makedirs(arguments.output, exist_ok=True)
    page.write(arguments.output, "interface_tractions", "Where the interface tractions' noise "
               "comes from", table(rows) + [
                   "", "Tractions in units of c; the last step is the last converged one."])


if __name__ == "__main__":
    main()
