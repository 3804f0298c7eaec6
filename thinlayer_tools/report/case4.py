"""Case 4 of the report: passive earth pressure on smooth and rough walls
(Table 2, Figures 11 and 12), with the rough wall by other methods and by
zero-thickness elements."""
import matplotlib.pyplot as plt

from thinlayer_tools import closed_form
from thinlayer_tools import results
from thinlayer_tools.report import figures, page
from thinlayer_tools.report.page import Section

# Table 2 (CP2): K_pc by C_w / c_u.
CP2 = {0.0: 2.0, 0.5: 2.4, 1.0: 2.6}
# "around 30% higher": the rough wall over the smooth, read as 30 +- 5 points.
PAPER_RISE, RISE_BAND = 0.30, 0.05
# Conservative as the paper expects of aspect ratio 10, but not far below:
# within this fraction under CP2, and no more than 2% above it.
BELOW, ABOVE = 0.07, 0.02


def final_load(directory):
    """K_pc of a wall run: the load of its last converged state."""
    states = results.states(results.history(directory))
    return results.number(states[-1]["load"]) if states else None


def walls(runs, method):
    """(C_w / c_u, results directory) of the walls by @p method (paper or
    default): the smooth wall and the figure-12 sweep over the adhesion."""
    found = [(0.0, runs.path("case4-smooth-" + method))]
    for r in runs.sweep("case4-figure12-" + method):
        found.append((float(r["Material 2/Cohesion"]),
                      runs.path("case4-figure12-" + method, r["run"])))
    return sorted(found)


def figure11(runs, quick):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.2))
    cells = figures.draw_mesh(axes[0], runs.path("case4-figure12-paper", 1), "x / H", "y / H")
    axes[0].set_title("thin column beside the wall (red), aspect ratio 10", fontsize=9)
    figures.draw_mesh(axes[1], runs.path("case4-zero"), "x / H", "y / H")
    axes[1].set_title("with a stiff wall and zero-thickness elements (beyond the paper)",
                      fontsize=9)
    fig.tight_layout()
    return page.mesh_section(
        "figure11", "Figure 11: mesh for the earth-pressure analysis",
        "a thin column of elements adjacent to the wall; no wall in the analysis, the wall's "
        "movement prescribed on the soil.",
        "%d cells (meshes/earth-pressure.geo), the thin column beside a wall of height H = 1 "
        "whose movement is prescribed, vertically restrained for a rough wall and free for a "
        "smooth one." % cells, (figures.data_uri(fig), "The meshes as meshed."), cells,
        figures.layer_cells(runs.path("case4-figure12-paper", 1), "wall column"))


def figure12(runs, quick):
    fig, ax = plt.subplots(figsize=(8, 5))
    rows = [["C_w / c_u", "CP2 K_pc (Table 2)", "slip-line K_pc", "the paper's method",
             "against CP2", "default method (or the row's)", "against CP2"]]
    computed = {}
    default = dict(walls(runs, "default"))
    for (ratio, directory), colour in zip(walls(runs, "paper"), ("C0", "C1", "C2")):
        figures.curve(ax, directory, "C_w / c_u = %g, the paper's method" % ratio,
                      color=colour, marker=".", ms=3)
        figures.curve(ax, default[ratio], "C_w / c_u = %g, default method" % ratio,
                      color=colour, ls="--", lw=2.5, alpha=0.5)
        ax.axhline(CP2[ratio], color=colour, ls=":", lw=1.2)
        computed[ratio] = final_load(directory)
        by_default = final_load(default[ratio])
        rows.append(["%g" % ratio, "%.1f" % CP2[ratio],
                     "%.3f" % closed_form.passive_rough_wall(ratio), "%.3f" % computed[ratio],
                     "%+.1f%%" % (100 * (computed[ratio] / CP2[ratio] - 1)),
                     "%.3f" % by_default, "%+.1f%%" % (100 * (by_default / CP2[ratio] - 1))])
    for name, label, style in (
            ("case4-rough-accelerated", "C_w / c_u = 1, accelerated initial stress, TOL 1e-5",
             dict(color="C4", ls="-.", lw=1, marker="s", ms=3, markevery=4)),
            ("case4-zero", "C_w / c_u = 1, zero-thickness elements (default method)",
             dict(color="C5", ls=":", lw=1.5))):
        figures.curve(ax, runs.path(name), label, **style)
        rows.append(["1 (%s)" % label.split(", ", 1)[1], "2.6",
                     "%.3f" % closed_form.passive_rough_wall(1.0), "", "",
                     "%.3f" % final_load(runs.path(name)),
                     "%+.1f%%" % (100 * (final_load(runs.path(name)) / 2.6 - 1))])
    ax.set_xlabel("wall movement, E delta / (c_u H)")
    ax.set_ylabel("K_pc = P_p / (c_u H)")
    ax.set_title("dotted: CP2's K_pc (Table 2)", fontsize=9)
    ax.grid(alpha=0.3)
    figures.failure_legend(ax, fontsize=7, loc="lower right")
    fig.tight_layout()
    rise = computed[1.0] / computed[0.0] - 1
    conservative = all(CP2[r] * (1 - BELOW) <= k <= CP2[r] * (1 + ABOVE) for r, k in computed.items())
    verdict = "reproduced" if conservative and abs(rise - PAPER_RISE) <= RISE_BAND else "differs"
    zero = final_load(runs.path("case4-zero"))
    return Section(
        "figure12", "Table 2 and Figure 12: build-up of passive resistance",
        "weightless soil; the passive resistance ranged from the Rankine (smooth) value to the "
        "rough value around 30% higher, with interfaces of aspect ratio 10 'expected to be "
        "somewhat conservative'. Table 2 (CP2): K_pc = 2.0, 2.4, 2.6 for C_w / c_u = 0, 0.5, 1.",
        verdict,
        "By the paper's method the rough wall carries %+.0f%% over the smooth (the paper: "
        "around +30%%, read as +- 5 points), and every K_pc lies %s CP2's, from %+.1f%% to "
        "%+.1f%%: conservative, as the paper expects. The default method's values stand beside "
        "them in the table. Zero-thickness elements with a stiff wall give %.3f on this mesh: there the "
        "concentrated force at "
        "the wall's toe counts in the load." % (
            100 * rise, "within 7% below" if conservative else "outside 7% below",
            min(100 * (k / CP2[r] - 1) for r, k in computed.items()),
            max(100 * (k / CP2[r] - 1) for r, k in computed.items()), zero),
        rows=rows, figures=[(figures.data_uri(fig), "Converged states joined; x: the attempt "
                             "that ended a run (none under prescribed displacement when every "
                             "step converges). Solid: the paper's method; wide dashed: the "
                             "default method, in the same colour.")],
        cost="%.1f s for %d runs" % (runs.seconds(
            "case4-smooth-paper", "case4-figure12-paper", "case4-smooth-default",
            "case4-figure12-default", "case4-rough-accelerated", "case4-zero"), 8),
        paper_value="2.0 / 2.4 / 2.6; rough +30%",
        our_value="%s; rough %+.0f%%" % (" / ".join("%.2f" % computed[r] for r in sorted(computed)),
                                        100 * rise))


def sections(runs, quick):
    return [figure11(runs, quick), figure12(runs, quick)]
