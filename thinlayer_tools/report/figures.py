"""Chart helpers every section of the report shares.

The rules they keep: a load-displacement curve joins converged,
accepted states only, and the attempts that ended a run are marked apart
(an 'x'), never joined to it; axes name their normalisation; meshes are
drawn from the mesh.msh a run wrote (the mesh as meshed, interface layers
coloured); vector plots carry the body's outline and axes.
"""
import base64
import csv
import io
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from thinlayer_tools import results  # noqa: E402

# Faces of the mesh drawings by the physical surface's name; others grey.
MATERIAL_COLOURS = {"interface": "#d62728", "footing": "#7f7f7f", "wall": "#7f7f7f",
                    "wall column": "#d62728", "block": "#c6dbef", "blocks": "#c6dbef",
                    "soil": "#fdf5e6"}


def data_uri(fig, dpi=100):
    """The figure as an embedded PNG (data URI); the figure is closed."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=dpi)
    plt.close(fig)
    return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")


def read_msh(path):
    """Nodes {id: (x, y)}, quadrilaterals [(physical id, node ids)] and
    physical names {(dimension, id): name} of a gmsh 2.2 ASCII mesh."""
    with open(path) as f:
        lines = [line.strip() for line in f]
    if lines[0] != "$MeshFormat" or not lines[1].startswith("2.2"):
        raise ValueError("%s: expected a gmsh 2.2 ASCII mesh" % path)
    names, nodes, quads = {}, {}, []
    i = 0
    while i < len(lines):
        if lines[i] == "$PhysicalNames":
            for k in range(int(lines[i + 1])):
                dim, tag, name = lines[i + 2 + k].split(" ", 2)
                names[(int(dim), int(tag))] = name.strip('"')
        elif lines[i] == "$Nodes":
            for k in range(int(lines[i + 1])):
                fields = lines[i + 2 + k].split()
                nodes[int(fields[0])] = (float(fields[1]), float(fields[2]))
        elif lines[i] == "$Elements":
            for k in range(int(lines[i + 1])):
                fields = [int(v) for v in lines[i + 2 + k].split()]
                if fields[1] == 3:  # 4-node quadrilateral
                    tags = fields[2]
                    quads.append((fields[3], fields[3 + tags:3 + tags + 4]))
        i += 1
    return nodes, quads, names


def outline(nodes, quads):
    """The edges that belong to one quadrilateral only: the body's outline
    (and both faces of a cut along zero-thickness interface elements)."""
    count = {}
    for _, cell in quads:
        for a, b in zip(cell, cell[1:] + cell[:1]):
            key = (min(a, b), max(a, b))
            count[key] = count.get(key, 0) + 1
    return [(nodes[a], nodes[b]) for (a, b), n in count.items() if n == 1]


def draw_mesh(ax, directory, xlabel="x", ylabel="y"):
    """The run's mesh, cells coloured by material, with a legend of the
    physical surfaces; the thin layers in red."""
    nodes, quads, names = read_msh(os.path.join(directory, "mesh.msh"))
    ids = sorted({material for material, _ in quads})
    colours = {}
    for k, material in enumerate(ids):
        name = names.get((2, material), "material %d" % material)
        colours[material] = MATERIAL_COLOURS.get(name, plt.cm.Pastel1(k % 9))
    ax.add_collection(PolyCollection([[nodes[n] for n in cell] for _, cell in quads],
                                     facecolors=[colours[m] for m, _ in quads],
                                     edgecolors="k", linewidths=0.3))
    ax.add_collection(LineCollection(outline(nodes, quads), colors="k", linewidths=1.0))
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(handles=[Patch(facecolor=colours[m], edgecolor="k",
                             label="%d %s" % (m, names.get((2, m), "")))
                       for m in ids], fontsize=7, loc="best")
    return len(quads)


def curve(ax, directory, label, scale_load=1.0, scale_displacement=1.0, **style):
    """The load-displacement curve of one run: the origin and its converged,
    accepted states joined; the attempts that ended the run marked 'x' in
    the same colour, not joined. An attempt far beyond the curve (a failed
    step's displacement can be 1e10 times the elastic one) is drawn as '>'
    at the right edge, so that it does not squash the curve. Returns the
    run's history rows. After an initial state (Initial state/Procedure)
    the curve is the loading's, from the state the loading starts from."""
    rows, start = results.loading_history(directory)
    states = results.states(rows)
    u = [scale_displacement * start[0]] + \
        [scale_displacement * results.number(s["displacement"]) for s in states]
    p = [scale_load * start[1]] + [scale_load * results.number(s["load"]) for s in states]
    line, = ax.plot(u, p, label=label, **style)
    reach = 1.6 * max(abs(v) for v in u) or 1.0
    ended = [(scale_displacement * results.number(s["displacement"]),
              scale_load * results.number(s["load"])) for s in results.failures(rows)]
    ended = [(x, y) for x, y in ended if math.isfinite(x) and math.isfinite(y)]
    near = [(x, y) for x, y in ended if abs(x) <= reach]
    far = [(math.copysign(reach, x), y) for x, y in ended if abs(x) > reach]
    ax.plot([x for x, _ in near], [y for _, y in near], "x", color=line.get_color(), ms=8, mew=1.5)
    ax.plot([x for x, _ in far], [y for _, y in far], ">" if not far or far[0][0] > 0 else "<",
            color=line.get_color(), ms=8)
    # The axis spans every curve drawn on it so far.
    shown = u + [x for x, _ in near + far]
    left, right = getattr(ax, "curve_extent", (math.inf, -math.inf))
    ax.curve_extent = (min(left, min(shown) - 0.03 * reach), max(right, max(shown) + 0.03 * reach))
    ax.set_xlim(*ax.curve_extent)
    return rows


def failure_legend(ax, figure=None, **kwargs):
    """The legend with the 'x' explained; with @p figure, below the panels."""
    handles, labels = ax.get_legend_handles_labels()
    cross, = ax.plot([], [], "x", color="k", ms=8, mew=1.5)
    beyond, = ax.plot([], [], ">", color="k", ms=8)
    handles += [cross, beyond]
    labels += ["x: attempt that ended the run (failed or on the mechanism; not on the curve)",
               "> : such an attempt far beyond the axis"]
    if figure is None:
        ax.legend(handles, labels, **kwargs)
    else:
        figure.legend(handles, labels, loc="lower center", ncol=3, **kwargs)


def layer_cells(directory, name):
    """The number of cells in the run's physical surface called @p name."""
    _, quads, names = read_msh(os.path.join(directory, "mesh.msh"))
    ids = {tag for (dim, tag), text in names.items() if dim == 2 and text == name}
    return sum(1 for material, _ in quads if material in ids)


def increment_below(directory, depth):
    """The largest displacement increment of the last step at vertices below
    y = @p depth, over the largest anywhere: how deep a mechanism reaches."""
    with open(os.path.join(directory, "displacements.csv"), newline="") as f:
        rows = [(float(r["y"]), math.hypot(float(r["du_x"]), float(r["du_y"])))
                for r in csv.DictReader(f)]
    largest = max(size for _, size in rows) or 1.0
    return max((size for y, size in rows if y < depth), default=0.0) / largest


def vectors(ax, directory, increment=True, length_unit="L"):
    """Arrows at the vertices: the last step's increment (at a failed step,
    the mechanism) or the total displacement, with the body's outline and
    axes in units of @p length_unit."""
    nodes, quads, _ = read_msh(os.path.join(directory, "mesh.msh"))
    with open(os.path.join(directory, "displacements.csv"), newline="") as f:
        rows = [[float(r[k]) for k in ("x", "y", "u_x", "u_y", "du_x", "du_y")]
                for r in csv.DictReader(f)]
    x, y, ux, uy, dux, duy = zip(*rows)
    vx, vy = (dux, duy) if increment else (ux, uy)
    size = max(max(x) - min(x), max(y) - min(y))
    largest = max(math.hypot(a, b) for a, b in zip(vx, vy)) or 1.0
    ax.add_collection(LineCollection(outline(nodes, quads), colors="0.4", linewidths=0.8))
    ax.quiver(x, y, vx, vy, angles="xy", scale_units="xy",
              scale=largest / (0.06 * size), width=0.0025, color="C0")
    ax.set_aspect("equal")
    ax.set_xlabel("x / %s" % length_unit)
    ax.set_ylabel("y / %s" % length_unit)
    return largest


def embed(path):
    """A PNG file as a data URI."""
    with open(path, "rb") as f:
        return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")
