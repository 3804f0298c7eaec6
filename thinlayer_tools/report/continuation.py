"""The report's section on how the stepping reaches a collapse: the load
factor prescribed step by step on the scene's programme, adaptive step
lengths (Loading/Step length = adaptive), and work control (Loading/Control
= work: the load factor found with the displacements, the collapse reached
as the plateau of the load), each by the default method, on two scenes with
closed forms."""
import matplotlib.pyplot as plt

from thinlayer_tools import results
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section
from thinlayer_tools.report.runs import DEFAULT

# (run label, what it is, its overrides).
WAYS = [("load", "load factor, the file's programme", ()),
        ("adaptive", "load factor, adaptive step lengths", ("Loading/Step length=adaptive",)),
        ("work", "work control", ("Loading/Control=work",))]
# (scene, parameter file, what is asked of every way: the collapse over the
# closed form within this fraction).
SCENES = [("case1", "case1-inclined-adhesive", 0.005),
          ("prandtl", "prandtl-strip-footing", 0.01)]
# How far the ways may differ from the file's programme: the collapse
# resolution of every scene file.
RESOLUTION = 0.005


def run_name(scene, way):
    return "continuation-%s-%s" % (scene, way)


def run_list(quick):
    return [(run_name(scene, way), prm, DEFAULT + overrides + ("Output/Write VTU=false",))
            for scene, prm, _ in SCENES for way, _, overrides in WAYS]


def ratio(summary):
    """The collapse load over the closed form, None without a collapse."""
    load = results.collapse_load(summary)
    return load / summary["reference_load"] if load else None


def continuation(runs, quick):
    table = [["scene", "way", "outcome", "collapse load / closed form",
              "evidence", "attempts (steps)", "iterations", "wall s"]]
    missed = []
    for scene, prm, within in SCENES:
        by_load = ratio(runs.summary(run_name(scene, "load")))
        for way, label, _ in WAYS:
            s = runs.summary(run_name(scene, way))
            value = ratio(s)
            bracket = s.get("collapse_load_factor_bracket") or {}
            evidence = ("bracket %.4f - %.4f" % (bracket["low"], bracket["high"])
                        if "low" in bracket else "plateau" if value else "-")
            table.append([prm, label, s["outcome"], "%.4f" % value if value else "-",
                          evidence, "%d (%d)" % (s["attempts"], s["load_steps"]),
                          "%d" % s["total_iterations"], "%.2f" % s["wall_seconds"]])
            if not value or abs(value - 1) > within:
                missed.append("%s by %s: %s" % (prm, label, "%.4f" % value if value
                                                else s["outcome"]))
            elif by_load and abs(value / by_load - 1) > RESOLUTION:
                missed.append("%s by %s: %.4f against %.4f on the programme" % (
                    prm, label, value, by_load))
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for way, label, _ in WAYS:
        directory = runs.path(run_name("prandtl", way))
        reference = runs.summary(run_name("prandtl", way))["reference_load"]
        figures.curve(ax, directory, label, scale_load=1 / reference, marker=".")
    ax.axhline(1, color="k", lw=0.8, ls="--", label="Prandtl (2 + pi) c")
    # A failed attempt's load is no equilibrium (an out-of-balance state
    # can read twice the limit): the axis shows the curve.
    ax.set_ylim(0, 1.15)
    ax.set_xlabel("settlement of the footing's centre / half its width (E = 1e5 c)")
    ax.set_ylabel("pressure / (2 + pi) c")
    ax.grid(alpha=0.3)
    figures.failure_legend(ax, fontsize=7, loc="lower right")
    fig.tight_layout()
    why = ("The default method on Case 1 at 45 degrees (a thin Tresca layer; the block slides "
           "at P / (C_w B) = 1 / (sin a cos a) = 2) and on Prandtl's smooth strip footing "
           "((2 + pi) c on the file's mesh), three ways: the load factor of every step from "
           "the file's programme, cut back where a step fails, the collapse bracketed "
           "between the last converged state and a failed attempt; adaptive step lengths "
           "(the programme's first step and end only, each step grown from the iterations "
           "of the last, a load factor that failed twice bisected); and work control "
           "(after the first step each step prescribes the work of the load, f^T du, "
           "Newton finds the load factor with the displacements, and the collapse is the "
           "plateau of the load: no attempt beyond the limit). Asked: every way collapses "
           "within 0.5%% of Case 1's closed form and 1%% of Prandtl's, and within the "
           "collapse resolution (0.5%%) of the programme's collapse. %s" % (
               "Met." if not missed else "Missed: " + "; ".join(missed) + "."))
    names = [run_name(scene, way) for scene, _, _ in SCENES for way, _, _ in WAYS]
    return Section(
        "continuation", "Reaching the collapse: the programme, adaptive steps, work control",
        "(not in the paper) the paper loads by fixed increments and reads the collapse off "
        "the first step that fails.",
        "agrees" if not missed else "disagrees", why, rows=table,
        figures=[(figures.data_uri(fig), "Prandtl's footing by the three ways: converged "
                  "states joined; x: the attempt that ended the run; dashed: the closed form.")],
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="2 (Case 1), 1 (Prandtl, normalised)",
        our_value=", ".join(
            "%s %s %s" % (scene, way, "%.4f" % ratio(runs.summary(run_name(scene, way)))
                          if ratio(runs.summary(run_name(scene, way))) else "-")
            for scene, _, _ in SCENES for way, _, _ in WAYS))


def sections(runs, quick):
    return [continuation(runs, quick)]
