"""The report's section on the limit, not the knee: rough rigid footings
driven by a load and by a prescribed settlement, whose collapse loads must
agree within the collapse resolution, with the knee of the load-controlled
curve beside them."""
import matplotlib.pyplot as plt

from thinlayer_tools import cases, results
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section

# Loading/Collapse resolution of the scenes: the agreement asked of the two
# ways of driving a footing.
RESOLUTION = 0.005

# footing: (parameter files' stem, title, the classical limit's source); the
# limit itself is the files' Reference/Analytic load, read from the runs.
FOOTINGS = {
    "strip": ("strip-footing-rigid", "rough rigid strip footing", "Prandtl"),
    "circular": ("circular-footing-rigid", "rough rigid circular footing (harmonic 0)",
                 "Eason and Shield 1960"),
}
CONTROLS = ("load", "settlement")


def levels(quick):
    return (1,) if quick else (1, 2)


def run_name(footing, control, level):
    return "limit-%s-%s-%d" % (footing, control, level)


def run_list(quick):
    """The runs: each footing by load and by settlement at each mesh level
    (the footing meshes' levels of thinlayer_tools.cases, a row of aspect
    ratio 10 under the footing)."""
    return [(run_name(footing, control, level), "%s-%s" % (stem, control),
             ("Mesh/Geometry parameters=" + cases.geometry("case3", level, 10),
              "Output/Write VTU=false"))
            for footing, (stem, *_) in FOOTINGS.items() for level in levels(quick)
            for control in CONTROLS]


def classical(runs, footing):
    """The classical limit / c of @p footing, as its files state it, and
    its source."""
    value = runs.summary(run_name(footing, "load", 1))["reference_load"]
    return value, "%.4g c, %s" % (value, FOOTINGS[footing][2])


def pairs(runs, quick):
    """(title, level, run under load, run under displacement, classical
    value or None, its source) of every comparison: the rigid footings at
    each level, and Case 3's stiff footing pushed sideways (the report's
    runs case3-default and case3-displacement, the same mesh)."""
    rows = [(title, level, run_name(footing, "load", level),
             run_name(footing, "settlement", level)) + classical(runs, footing)
            for footing, (stem, title, _) in FOOTINGS.items()
            for level in levels(quick)]
    rows.append(("Case 3's footing, lateral (harmonics 1, 3)", 1, "case3-default",
                 "case3-displacement", None, "no closed form; the paper: about 1.2"))
    return rows


def limit_not_knee(runs, quick):
    table = [["footing", "mesh level", "knee under load", "collapse under load",
              "plateau under displacement", "load against displacement",
              "knee below collapse", "collapse against classical",
              "wall s (load, displacement)"]]
    disagreements, gaps = [], []
    for title, level, by_load_run, by_displacement_run, limit, source in pairs(runs, quick):
        load = runs.summary(by_load_run)
        settled = runs.summary(by_displacement_run)
        by_load, by_settlement = results.collapse_load(load), results.collapse_load(settled)
        knee = results.number(load.get("knee_load"))
        if by_load is None or by_settlement is None or \
                abs(by_load - by_settlement) > RESOLUTION * max(by_load, by_settlement):
            disagreements.append("%s, level %d" % (title, level))
        if by_load is not None and knee == knee:
            gaps.append(1 - knee / by_load)
        table.append([title, "%d" % level, "%.4f" % knee if knee == knee else "none",
                      "%.4f" % by_load if by_load else load["outcome"],
                      "%.4f" % by_settlement if by_settlement else settled["outcome"],
                      "%+.2f%%" % (100 * (by_load / by_settlement - 1))
                      if by_load and by_settlement else "-",
                      "%.2f%%" % (100 * (1 - knee / by_load)) if by_load and knee == knee
                      else "-",
                      "%+.2f%% (%s)" % (100 * (by_load / limit - 1), source)
                      if by_load and limit else source,
                      "%.1f, %.1f" % (load["wall_seconds"], settled["wall_seconds"])])
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, (footing, (stem, title, _)) in zip(axes, FOOTINGS.items()):
        limit, source = classical(runs, footing)
        for control, style in (("load", "o-"), ("settlement", ".-")):
            figures.curve(ax, runs.path(run_name(footing, control, 1)),
                          "by " + control, marker=style[0], ms=3)
        knee = results.number(runs.summary(run_name(footing, "load", 1)).get("knee_load"))
        if knee == knee:
            ax.axhline(knee, color="grey", ls=":", lw=1.2, label="knee under load")
        ax.axhline(limit, color="k", ls="--", lw=1, label=source)
        # Near the limit, where the knee and the plateau part.
        ax.set_ylim(0.85 * limit, 1.1 * limit)
        ax.set_title(title + ", level 1", fontsize=9)
        ax.set_xlabel("settlement E u / (c B)" if footing == "strip" else
                      "settlement E u / (c R)")
        ax.set_ylabel("pressure / c")
        ax.grid(alpha=0.3)
        figures.failure_legend(ax, fontsize=7, loc="lower right")
    fig.tight_layout()
    names = [name for pair in pairs(runs, quick) for name in pair[2:4]]
    why = ("A rough rigid footing (a block 1000 times stiffer than the soil) on weightless "
           "Tresca soil (loads and pressures per c), default method, driven two ways: a "
           "pressure on its top (load control, automatic stepping) and a prescribed "
           "settlement of its top; and Case 3's footing on its thin Tresca row, pushed "
           "sideways by a traction and by a prescribed displacement (loads per pi R^2 C_w). "
           "The collapse load is where the curve reaches its plateau: the first state whose "
           "load rose by at most the resolution (%.1f%%) while the displacement doubled (on "
           "a curve that levels off like a hyperbola that rise is the fraction of the limit "
           "still to come; under load, steps that more than double the displacement are cut "
           "back to the resolution, so that the curve is sampled as finely as under "
           "displacement control), or, under load, a step of the resolution that no longer "
           "converges, with a mechanism as evidence. The knee (a step's secant stiffness below 0.01 of the elastic one), "
           "which automatic stepping used to bracket as the collapse, is reported beside it: "
           "it lay %s below the collapse. Asked: the two ways agree within the "
           "resolution. %s" % (
               100 * RESOLUTION,
               "%.1f-%.1f%%" % (100 * min(gaps), 100 * max(gaps)) if gaps else "nowhere",
               "They do on every mesh." if not disagreements else
               "They differ on: " + "; ".join(disagreements) + "."))
    return Section(
        "limit-not-knee", "The limit, not the knee: load control against prescribed displacement",
        "(not in the paper) the paper's collapse is its first failed load step.",
        "beyond" if not disagreements else "differs", why, rows=table,
        figures=[(figures.data_uri(fig), "The curves near the limit (from 85% of the classical "
                  "value): converged states joined; x: the attempt that ended the run; dotted: "
                  "the knee of the load-controlled curve.")],
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="(not in the paper)",
        our_value="load against settlement within %.1f%%" % (100 * RESOLUTION)
        if not disagreements else "differs")


def sections(runs, quick):
    return [limit_not_knee(runs, quick)]
