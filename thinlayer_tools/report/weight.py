"""The report's section on the body's own weight: the critical height of a
vertical cut in Tresca clay by gravity loading, on three meshes, against
the limit-analysis bracket."""
import matplotlib.pyplot as plt

from thinlayer_tools import results
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section

# Asked of the finest mesh run, by its cells: the error halves with each
# halving of the elements (+5.8%, +2.5%, +1.2% measured).
WITHIN = {1024: 0.03, 4096: 0.02}
# (cells, geometry parameters): the file's mesh and two halvings.
MESHES = [
    (256, "n_height=8, n_behind=12, n_front=8, n_depth=8, growth=1.1"),
    (1024, "n_height=16, n_behind=24, n_front=16, n_depth=16, growth=1.05"),
    (4096, "n_height=32, n_behind=48, n_front=32, n_depth=32, growth=1.025"),
]


def run_name(cells):
    return "vertical-cut-%d" % cells


def meshes(quick):
    """The meshes run: the finest only in the full report."""
    return MESHES[:2] if quick else MESHES


def run_list(quick):
    return [(run_name(cells), "vertical-cut",
             ("Mesh/Geometry parameters=height=1, behind=3, front=2, depth=2, " + mesh,
              "Output/Write VTU=false")) for cells, mesh in meshes(quick)]


def vertical_cut(runs, quick):
    # Pastor, Thai and Francescato (2000): gamma H_c / c by lower- and
    # upper-bound limit analysis, as prm/vertical-cut.prm states it.
    stated = runs.summary(run_name(meshes(quick)[0][0]))["reference_bracket"]
    bracket = (stated["low"], stated["high"])
    middle = sum(bracket) / 2
    table = [["cells", "equations", "outcome", "gamma H_c / c", "against %.3f" % middle, "knee",
              "iterations", "wall s"]]
    loads = []
    finest = meshes(quick)[-1][0]
    for cells, _ in meshes(quick):
        s = runs.summary(run_name(cells))
        load = results.collapse_load(s)
        loads.append(load)
        knee = results.number(s.get("knee_load"))
        table.append(["%d" % s["cells"], "%d" % s["equations"], s["outcome"],
                      "%.3f" % load if load else "-",
                      "%+.2f%%" % (100 * (load / middle - 1)) if load else "-",
                      "%.3f" % knee if knee == knee else "-",
                      "%d" % s["total_iterations"], "%.1f" % s["wall_seconds"]])
    good = all(loads) and all(load > bracket[0] for load in loads) and \
        all(b < a for a, b in zip(loads, loads[1:])) and \
        abs(loads[-1] / middle - 1) <= WITHIN[finest]
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for cells, _ in meshes(quick):
        figures.curve(ax, runs.path(run_name(cells)), "%d cells" % cells, marker=".")
    ax.axhspan(*bracket, color="k", alpha=0.25, label="Pastor et al. 2000")
    ax.set_xlabel("mean horizontal displacement of the face, E u / (c H)")
    ax.set_ylabel("load factor = gamma H / c")
    ax.grid(alpha=0.3)
    figures.failure_legend(ax, fontsize=7, loc="lower right")
    fig.tight_layout()
    why = ("A vertical cut of height H in Tresca clay (c = 1, E = 1e4, gamma = 1 "
           "per unit load factor, prm/vertical-cut.prm), its weight raised by automatic "
           "stepping until the cut collapses, by the default method; the weight enters as "
           "consistent nodal loads (Material <id>/Unit weight). Asked: every mesh collapses "
           "above the exact bracket's lower end %.3f (a displacement mesh is too stiff), the "
           "load falls with refinement, and the finest mesh run (%d cells) lies within %.0f%% "
           "of %.2f (3%% on 1024 cells, 2%% on 4096, run in the full report only). %s" % (
               bracket[0], finest, 100 * WITHIN[finest], middle,
               "It does." if good else "It does not."))
    names = [run_name(cells) for cells, _ in meshes(quick)]
    return Section(
        "vertical-cut", "Self-weight: the critical height of a vertical cut",
        "(not in the paper) gamma H_c / c in [%.3f, %.3f] (Pastor, Thai and Francescato "
        "2000, limit analysis)." % bracket,
        "agrees" if good else "disagrees", why, rows=table,
        figures=[(figures.data_uri(fig), "Converged states joined; x: the attempt that ended "
                  "the run; grey band: the limit-analysis bracket.")],
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="%.3f - %.3f" % bracket, our_value=", ".join(
            "%.3f" % load if load else "-" for load in loads))


def sections(runs, quick):
    return [vertical_cut(runs, quick)]
