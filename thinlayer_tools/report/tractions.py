"""The report's section on interface tractions: the profiles every run
writes (tractions recovered at the interface's nodes from its nodal forces)
beside the raw values at the Gauss points (Output/Gauss-point profiles),
on the pile section of the curved-interfaces section, a smooth rigid strip
footing, Case 2 on interface elements, and Case 3's footing in 3D on
interface elements and on a thin layer (maps)."""
import math
import os
import re
import xml.etree.ElementTree as ElementTree

import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

from thinlayer_tools import results
from thinlayer_tools.report import curved, figures
from thinlayer_tools.report.page import Section

RAW = ("Output/Gauss-point profiles=true",)
NO_VTU = ("Output/Write VTU=false",)
# The pile section's contacts and strengths, on 12 cells per quarter circle.
PILES = [(kind, alpha) for kind in ("interface", "layer") for alpha in (0.01, 1.0)]
PROFILE = {"interface": "interface-4", "layer": "layer-2"}
# Asked of the pile's normal traction (units of c): bound, largest jump
# between neighbouring samples, and the profile's statics against the
# reaction.
PILE_BOUND, PILE_JUMP, PILE_STATICS = 25.0, 3.0, 0.01
# Asked of the smooth footing's contact pressure (against (2 + pi) c), of
# Case 2's shear (against C_w) and of the 3D footing's shear at sliding
# (against c), beyond the first cell from an edge.
FOOTING_WITHIN, CASE2_WITHIN, SLIDING_WITHIN = 0.05, 0.02, 0.02
PRANDTL = 2 + math.pi
FOOTING = "strip-footing-rigid-smooth-zero-thickness"
CASE2 = "case2-strip-footing-zero-thickness"
# Case 3 in 3D; in --quick with one element around the half circle's
# quarter and loaded from 0.9 (the interface elements) as the solid
# section's quick run.
CASE3_ZT, CASE3_LAYER = "case3-circular-footing-3d-zero-thickness", "case3-circular-footing-3d"
QUICK_3D = {
    CASE3_ZT: ("Mesh/Geometry parameters=sector=180, footing=1, zero_thickness=1, "
               "half_width=1, width=5, depth=3, footing_height=0.5, n_around=1, n_footing=4, "
               "n_side=12, n_depth=10, growth=1.2", "Loading/Load increments=0.9, 12*0.01"),
    CASE3_LAYER: ("Mesh/Geometry parameters=sector=180, footing=1, half_width=1, width=5, "
                  "depth=3, footing_height=0.5, aspect_ratio=10, n_around=1, n_footing=4, "
                  "n_side=12, n_depth=10, growth=1.2",),
}
MAPS = ("Output/Write VTU=true", "Output/Fields interval=0")


def pile_run(kind, alpha):
    return "tractions-pile-%s-%g" % (kind, alpha)


def run_list(quick):
    runs = [(pile_run(kind, alpha), curved.KINDS[kind],
             curved.overrides(kind, alpha, 12, True) + RAW + MAPS) for kind, alpha in PILES]
    runs += [("tractions-footing", FOOTING, NO_VTU + RAW),
             ("tractions-case2", CASE2, NO_VTU + RAW)]
    for name, scene in (("tractions-3d-interface", CASE3_ZT), ("tractions-3d-layer", CASE3_LAYER)):
        runs.append((name, scene, MAPS + RAW + (QUICK_3D[scene] if quick else ())))
    return runs


def converged_steps(directory):
    """The first and the last converged, accepted load step."""
    steps = [int(r["step"]) for r in results.states(results.history(directory))]
    return (steps[0], steps[-1]) if steps else (None, None)


def profile(directory, name, step, raw=False):
    """The rows of NAME[-gauss]-STEP.csv, in order along the run."""
    path = os.path.join(directory, "%s-%s%04d.csv" % (name, "gauss-" if raw else "", step))
    rows = results.read_csv(path)
    if "arc_length" in rows[0]:
        rows.sort(key=lambda r: float(r["arc_length"]))
    return rows


def spread(rows, field="normal_traction"):
    """(largest magnitude, largest jump between neighbours)."""
    values = [float(r[field]) for r in rows]
    return (max(abs(v) for v in values),
            max((abs(a - b) for a, b in zip(values, values[1:])), default=0.0))


def pile_load(rows, n):
    """The pile's load from a profile of n Gauss points per side (as
    tests/verification/circular_inclusion does): -sigma_n cos(theta) -
    tau sin(theta) per unit length, integrated with those points."""
    spread_1d = 1 / math.sqrt(3) if n == 2 else math.sqrt(3 / 5)
    weights = (0.5, 0.5) if n == 2 else (5 / 18, 8 / 18, 5 / 18)
    load = 0.0
    for k in range(0, len(rows) - n + 1, n):
        angle = [math.atan2(float(r["y"]), float(r["x"])) for r in rows[k:k + n]]
        span = abs(angle[-1] - angle[0]) / spread_1d
        for q, r in enumerate(rows[k:k + n]):
            load += weights[q] * span * math.hypot(float(r["x"]), float(r["y"])) * (
                -float(r["normal_traction"]) * math.cos(angle[q])
                - float(r["shear_traction"]) * math.sin(angle[q]))
    return load


def beyond_first_cells(rows, field, scale, reference, ends):
    """The largest |field / scale - reference| / reference over the samples
    beyond the first cell (three samples) from the run's ends @p ends
    ("last" or "both")."""
    first = 3 if ends == "both" else 0
    inner = rows[first:len(rows) - 3]
    return max((abs(float(r[field]) / scale - reference) / reference for r in inner),
               default=math.inf)


def surface_patches(path, field):
    """The quadrilateral patches (x, z corners) and the cell values
    @p field of a surface profile's VTU (the interface in 3D)."""
    piece = ElementTree.parse(path).getroot().find("UnstructuredGrid/Piece")
    numbers = [float(v) for v in piece.find("Points/DataArray").text.split()]
    points = [(numbers[k], numbers[k + 2]) for k in range(0, len(numbers), 3)]
    patches = [points[k:k + 4] for k in range(0, len(points), 4)]
    for array in piece.find("CellData"):
        if array.get("Name") == field:
            return patches, [float(v) for v in array.text.split()]
    raise SystemExit("tractions: no %s in %s" % (field, path))


def soil_mean_stress(directory, inner, outer):
    """(angles in degrees, tr(sigma) / 3) of the soil (material 1) at the
    points of the last fields VTU with inner < r < outer, by angle; None
    without python3-vtk9 (which the test command installs) or fields."""
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        return None
    fields = sorted(p for p in os.listdir(directory) if re.fullmatch(r"fields-\d{4}\.vtu", p))
    if not fields:
        return None
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(directory, fields[-1]))
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    stress = [vtk_to_numpy(data.GetArray(n)) for n in ("stress_xx", "stress_yy", "stress_zz")]
    material = vtk_to_numpy(data.GetArray("material_id"))
    near = sorted((math.degrees(math.atan2(y, x)), (stress[0][k] + stress[1][k] + stress[2][k]) / 3)
                  for k, (x, y, _) in enumerate(vtk_to_numpy(grid.GetPoints().GetData()))
                  if inner < math.hypot(x, y) < outer and material[k] == 1)
    return ([a for a, _ in near], [m for _, m in near]) if near else None


def pile_figure(runs):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), sharey=True)
    for ax, kind in zip(axes, ("interface", "layer")):
        directory = runs.path(pile_run(kind, 0.01))
        first, last = converged_steps(directory)
        for step, raw, style, label in (
                (last, True, dict(color="0.6", lw=0.8), "at the Gauss points, last converged"),
                (last, False, dict(color="C0", lw=2), "recovered at the nodes, last converged"),
                (first, False, dict(color="C1", ls="--"), "recovered, first step (elastic)")):
            rows = profile(directory, PROFILE[kind], step, raw)
            angle = [math.degrees(math.atan2(float(r["y"]), float(r["x"]))) for r in rows]
            ax.plot(angle, [float(r["normal_traction"]) for r in rows], label=label, **style)
        # The soil beside the contact (outside the skin or the layer, R + t).
        soil = soil_mean_stress(directory, 1.02, 1.05)
        if soil:
            ax.plot(*soil, color="C2", lw=1, label="soil beside it: mean stress tr(sigma) / 3, "
                    "last converged")
        ax.axhline(PILE_BOUND, color="k", ls=":", lw=1)
        ax.axhline(-PILE_BOUND, color="k", ls=":", lw=1, label="the truth's bound, 25 c")
        ax.set_ylim(-1.3 * PILE_BOUND, 1.3 * PILE_BOUND)
        ax.set_xlim(0, 180)
        ax.set_xlabel("angle on the pile from its front, theta (degrees)")
        ax.set_title({"interface": "interface elements", "layer": "thin layer t = R / 50"}[kind]
                     + ", alpha = 0.01", fontsize=10)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("normal traction sigma_n / c (tension positive)")
    axes[1].legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    return figures.data_uri(fig)


def line_figure(runs):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for ax, name, field, scale, within, title, ylabel in (
            (axes[0], "tractions-footing", "normal_traction", -PRANDTL, FOOTING_WITHIN,
             "smooth rigid strip footing at collapse", "contact pressure p / ((2 + pi) c)"),
            (axes[1], "tractions-case2", "shear_traction", 1.0, CASE2_WITHIN,
             "Case 2 on interface elements at sliding", "shear traction |tau| / C_w")):
        directory = runs.path(name)
        _, last = converged_steps(directory)
        for raw, style, label in ((True, dict(color="0.6", marker=".", lw=0.8),
                                   "at the Gauss points"),
                                  (False, dict(color="C0", lw=2), "recovered at the nodes")):
            rows = profile(directory, "interface-5", last, raw)
            ax.plot([float(r["x"]) for r in rows],
                    [abs(float(r[field]) / scale) for r in rows], label=label, **style)
        ax.axhline(1, color="k", lw=1, label="closed form")
        ax.axhspan(1 - within, 1 + within, color="0.9", label="%g%% band" % (100 * within))
        ax.set_ylim(0.5, 1.5)
        ax.set_xlabel("x / B (footing from its centreline x = 0 to its edge x = 1)")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    return figures.data_uri(fig)


def map_figure(runs):
    fig, axes = plt.subplots(2, 2, figsize=(11, 7))
    for row, (name, profile_name, title) in enumerate((
            ("tractions-3d-interface", "interface-7", "interface elements"),
            ("tractions-3d-layer", "layer-2", "thin layer, aspect ratio 10"))):
        directory = runs.path(name)
        _, last = converged_steps(directory)
        drawn = [surface_patches(os.path.join(directory, "%s-%s%04d.vtu" % (
            profile_name, "gauss-" if raw else "", last)), "normal_traction")
            for raw in (True, False)]
        # One colour scale per row, from the recovered map.
        low, high = min(drawn[1][1]), max(drawn[1][1])
        margin = 0.1 * (high - low) + 1e-9
        for ax, (patches, values), label in zip(axes[row], drawn,
                                                ("at the Gauss points", "recovered at the nodes")):
            keep = [k for k, p in enumerate(patches)
                    if max(math.hypot(x, z) for x, z in p) <= 1.0 + 1e-9]
            collection = PolyCollection([patches[k] for k in keep], cmap="viridis",
                                        edgecolors="face")
            collection.set_array([values[k] for k in keep])
            collection.set_clim(low - margin, high + margin)
            ax.add_collection(collection)
            ax.set_xlim(-1.05, 1.05)
            ax.set_ylim(-0.05, 1.05)
            ax.set_aspect("equal")
            ax.set_xlabel("x / B")
            ax.set_ylabel("z / B")
            ax.set_title("%s: %s" % (title, label), fontsize=10)
            fig.colorbar(collection, ax=ax, label="sigma_n / c (tension positive)")
    fig.tight_layout()
    return figures.data_uri(fig, dpi=80)


def truth_table(runs):
    """The table of the truths, raw beside recovered, and whether every
    one holds."""
    table = [["scene", "truth asked", "at the Gauss points", "recovered (written)", "holds"]]
    good = True

    def add(scene, truth, raw, recovered, holds):
        nonlocal good
        good = good and holds
        table.append([scene, truth, raw, recovered, "yes" if holds else "NO"])

    for kind, alpha in PILES:
        directory = runs.path(pile_run(kind, alpha))
        _, last = converged_steps(directory)
        raw, recovered = (profile(directory, PROFILE[kind], last, r) for r in (True, False))
        raw_max, raw_jump = spread(raw)
        top, jump = spread(recovered)
        summary = runs.summary(pile_run(kind, alpha))
        reaction = results.number(summary.get("last_converged_load")) * (
            1.02 if kind == "interface" else 1.0)
        statics = pile_load(recovered, 3 if kind == "interface" else 2) / reaction
        scene = "pile, %s, alpha = %g" % (
            "interface elements" if kind == "interface" else "thin layer", alpha)
        add(scene, "|sigma_n| <= %g c; jumps <= %g c" % (PILE_BOUND, PILE_JUMP),
            "%.1f c; %.1f c" % (raw_max, raw_jump), "%.1f c; %.1f c" % (top, jump),
            top <= PILE_BOUND and jump <= PILE_JUMP)
        add(scene, "the profile carries the reaction (%g%%)" % (100 * PILE_STATICS), "",
            "%.4f" % statics, abs(statics - 1) <= PILE_STATICS)

    directory = runs.path("tractions-footing")
    _, last = converged_steps(directory)
    off = [beyond_first_cells(profile(directory, "interface-5", last, r), "normal_traction",
                              -PRANDTL, 1.0, "last") for r in (True, False)]
    add("smooth rigid strip footing, interface elements",
        "p = (2 + pi) c within %g%% beyond the edge's cell" % (100 * FOOTING_WITHIN),
        "%.1f%%" % (100 * off[0]), "%.1f%%" % (100 * off[1]), off[1] <= FOOTING_WITHIN)

    directory = runs.path("tractions-case2")
    _, last = converged_steps(directory)
    off = [beyond_first_cells([dict(r, shear_traction=abs(float(r["shear_traction"])))
                               for r in profile(directory, "interface-5", last, raw)],
                              "shear_traction", 1.0, 1.0, "both") for raw in (True, False)]
    add("Case 2, interface elements, at sliding",
        "tau = C_w within %g%% beyond the ends' cells" % (100 * CASE2_WITHIN),
        "%.2f%%" % (100 * off[0]), "%.2f%%" % (100 * off[1]), off[1] <= CASE2_WITHIN)

    directory = runs.path("tractions-3d-interface")
    _, last = converged_steps(directory)
    off = []
    for raw in (True, False):
        rows = [r for r in profile(directory, "interface-7", last, raw)
                if math.hypot(float(r["x"]), float(r["z"])) < 1]
        off.append(max(abs(math.hypot(float(r["shear_traction_1"]),
                                      float(r["shear_traction_2"])) - 1) for r in rows))
    add("Case 3 in 3D, interface elements, at sliding (c = 1)",
        "|tau| = c within %g%% of c under the footing" % (100 * SLIDING_WITHIN),
        "%.2f%%" % (100 * off[0]), "%.2f%%" % (100 * off[1]), off[1] <= SLIDING_WITHIN)
    return table, good


def tractions(runs, quick):
    table, good = truth_table(runs)
    names = [name for name, _, _ in run_list(quick)]
    why = ("What every run writes along an interface (NAME-NNNN.csv, .vtu) are its tractions "
           "recovered at the nodes: the interface's nodal forces (the Gauss points' "
           "tractions times the corner nodes' linear shape functions, weights and length or "
           "area elements, summed over the elements at a node) divided by the nodes' "
           "tributary lengths or areas, evaluated where the raw values were "
           "(Output/Gauss-point profiles writes those beside, NAME-gauss-NNNN.csv). Once the "
           "soil flows, the raw tractions of stiff interface elements oscillate from one Gauss "
           "point to the next (Schellekens and de Borst 1993: the noise grows about fivefold "
           "per decade of normal stiffness, and the soil's own pressure beside the pile stays "
           "smooth, benchmarks/interface_tractions.py), and a thin layer of Q8 2x2 cells "
           "carries a mode linear within each cell. The recovery keeps the resultant, and it "
           "is a reading of the converged state: no load, iteration or collapse load changes. "
           "Asked, on the table's scenes: the pile section of the curved-interfaces section "
           "(12 cells per quarter) within %g c with no jump above %g c, carrying its reaction "
           "within %g%%; the smooth footing's pressure uniform at (2 + pi) c (Prandtl, Hill) "
           "within %g%%; Case 2's shear at C_w within %g%%; the 3D footing's shear on its "
           "interface elements at c within %g%% as it slides. %s The maps show Case 3 in 3D%s "
           "at its last converged step, on interface elements and on a thin layer." % (
               PILE_BOUND, PILE_JUMP, 100 * PILE_STATICS, 100 * FOOTING_WITHIN,
               100 * CASE2_WITHIN, 100 * SLIDING_WITHIN,
               "Every truth holds." if good else "Some truth FAILS (the table).",
               " (in --quick on its coarse mesh, one element around the quarter)" if quick
               else ""))
    return Section(
        "interface-tractions", "Interface tractions: recovered at the nodes",
        "(not in the paper) A smooth rigid footing's contact pressure is uniform, (2 + pi) c "
        "(Prandtl 1920, Hill 1950); a sliding interface carries its strength at every point.",
        "agrees" if good else "disagrees", why, rows=table,
        figures=[(pile_figure(runs), "The smooth pile's normal traction around the pile at the "
                  "last converged state: at the Gauss points (grey, beyond the axes on the "
                  "interface elements) and recovered at the nodes (blue), with the first "
                  "step's recovered profile (elastic, orange) and, where python3-vtk9 reads "
                  "the fields, the soil's mean stress beside the contact (green): smooth "
                  "where the raw tractions are not."),
                 (line_figure(runs), "Left: the smooth footing's contact pressure at collapse; "
                  "right: Case 2's shear traction at its last converged step, sliding."),
                 (map_figure(runs), "Case 3's footing in 3D, its interface seen from above "
                  "(the half footing, r <= B), at the last converged step: the normal traction "
                  "at the Gauss points and recovered, on one colour scale per row.")],
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="uniform (2 + pi) c; tau = strength",
        our_value="every truth holds" if good else "a truth fails")


def sections(runs, quick):
    return [tractions(runs, quick)]
