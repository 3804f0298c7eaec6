"""Cases 2 and 3 of the report: the laterally loaded strip and circular
footings (Figures 6 to 10), their zero-thickness variants, and the footing
validations against closed forms (Prandtl, Shield)."""
import math

import matplotlib.pyplot as plt

from thinlayer_tools import results
from thinlayer_tools.report import figures
from thinlayer_tools.report.page import Section

# The paper's failure loads over the sliding load, read from its text,
# with the band we read its words as: "around 10% higher" (Case 2) and
# "approximately 20% higher" (Case 3) as 10 and 20 +- 5 percentage points.
PAPER_RATIO = {"case2": 1.10, "case3": 1.20}
BAND = 0.05
REFERENCE = {"case2": "L C_w", "case3": "pi R^2 C_w"}
LENGTH = {"case2": "L", "case3": "R"}


def collapse_text(summary):
    load = results.collapse_load(summary) if results.collapse_detected(summary) else None
    if load is None:
        return "%s (last converged %.3f)" % (summary["outcome"], summary["last_converged_load"])
    return "%.3f" % load


def curves(ax, runs, case, names, labels):
    for name, label, colour in zip(names, labels, ("C0", "C1", "C2", "C3")):
        figures.curve(ax, runs.path(name), label, color=colour, marker=".", ms=4)
    ax.axhline(1.0, color="k", ls="--", lw=1, label="pure sliding, %s" % REFERENCE[case])
    ax.axhline(PAPER_RATIO[case], color="grey", ls=":", lw=1.5,
               label="the paper's failure load (text)")
    ax.set_xlabel("horizontal displacement of the footing, E u / (C_w %s)" % LENGTH[case])
    ax.set_ylabel("horizontal load / (%s)" % REFERENCE[case])
    ax.grid(alpha=0.3)
    figures.failure_legend(ax, fontsize=7, loc="lower right")


def lateral_footing(runs, case, key, title, mesh_title):
    """The mesh and the load-displacement curve of Case 2 (Figure 6) or
    Case 3 (Figures 8 and 9)."""
    paper, default = runs.summary(case + "-paper"), runs.summary(case + "-default")
    fig, (ax_mesh, ax) = plt.subplots(1, 2, figsize=(13, 4.6),
                                      gridspec_kw={"width_ratios": [1.1, 1]})
    cells = figures.draw_mesh(ax_mesh, runs.path(case + "-paper"),
                              "%s / %s" % ("x" if case == "case2" else "r", LENGTH[case]),
                              ("y" if case == "case2" else "z") + " / " + LENGTH[case])
    ax_mesh.set_title(mesh_title, fontsize=9)
    curves(ax, runs, case, [case + "-paper", case + "-default"],
           ["the paper's method (viscoplastic, TOL 1e-4)", "default method"])
    fig.tight_layout()
    ratio = results.collapse_load(paper) if results.collapse_detected(paper) else None
    verdict = ("reproduced" if ratio is not None and abs(ratio - PAPER_RATIO[case]) <= BAND + 1e-9
               else "differs")
    above = all(results.collapse_detected(s) and results.collapse_load(s) > 1.0
                for s in (paper, default))
    why = ("By the paper's method the footing fails at %s %s (%+.1f%%); the paper reads %+.0f%%, "
           "which we take as +- %.0f points. thinlayer's default method fails at %s. %s" % (
               collapse_text(paper), REFERENCE[case], 100 * (ratio - 1) if ratio else math.nan,
               100 * (PAPER_RATIO[case] - 1), 100 * BAND, collapse_text(default),
               "Both fail above the sliding load for the paper's reason: the layer runs on "
               "beyond the footing, and its first Gauss points sit a small distance below the "
               "footing, so the soil beyond the edge must tear (Figure 7; Figure 10 removes "
               "the cause)." if above else "Not both fail above the sliding load."))
    return Section(
        key, title,
        {"case2": "failure 'around 10% higher than the pure sliding value' L C_w, signalled by a "
                  "dramatic rise in iterations (no convergence in 250).",
         "case3": "two odd harmonics, stresses at 0, 45, 90, 135 and 180 degrees: 'a sudden "
                  "failure at a load approximately 20% higher than the pure sliding value' "
                  "pi R^2 C_w."}[case],
        verdict, why, cost="%.1f s (paper's method), %.1f s (default), %d cells" % (
            paper["wall_seconds"], default["wall_seconds"], cells),
        figures=[(figures.data_uri(fig), "Left: the mesh as meshed (interface layer red). "
                  "Right: converged states joined; x: the attempt that ended the run.")],
        paper_value="%.2f %s" % (PAPER_RATIO[case], REFERENCE[case]),
        our_value="%s (default %s)" % (collapse_text(paper), collapse_text(default)))


def figure7(runs, quick):
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.6), gridspec_kw={"width_ratios": [1, 1.3]})
    largest = figures.vectors(axes[0], runs.path("case2-paper"), increment=True)
    axes[0].set_title("increment of the step that ended the paper's-method run (the mechanism), "
                      "largest %.3g L" % largest, fontsize=9)
    axes[0].set_xlim(-0.2, 3.0)
    axes[0].set_ylim(-1.6, 0.8)
    largest = figures.vectors(axes[1], runs.path("case2-paper"), increment=False)
    axes[1].set_title("total displacement at the last step, largest %.3g L" % largest, fontsize=9)
    fig.tight_layout()
    # Shallow: below half a footing width the increment is a small part of
    # the largest (the footing's and the layer's).
    deep = figures.increment_below(runs.path("case2-paper"), -0.5)
    return Section(
        "figure7", "Figure 7: displacement vectors at failure (Case 2)",
        "the vectors at failure show the extent of the shallow tearing mechanism.",
        "reproduced" if deep < 0.1 else "differs",
        "The increment of the step that ended the run moves the footing and the layer under "
        "it, tearing at the footing's edge; deeper than 0.5 L below the surface it is at most "
        "%.1f%% of its largest value: a shallow tearing mechanism, as the paper describes. "
        "(The antisymmetric half-mesh: vertical movement is held on the left side.)"
        % (100 * deep),
        figures=[(figures.data_uri(fig), "Arrows at the vertices, scaled to 6% of the body's "
                  "size; grey: the body's outline; left panel zoomed on the footing.")],
        paper_value="shallow tearing",
        our_value="shallow: below 0.5 L at most %.1f%% of the largest increment" % (100 * deep))


def figure10(runs, quick):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4), gridspec_kw={"width_ratios": [1.1, 1, 1]})
    figures.draw_mesh(axes[0], runs.path("case2-better-paper"), "x / L", "y / L")
    axes[0].set_xlim(-0.1, 2.0)
    axes[0].set_ylim(-1.0, 0.8)
    axes[0].set_title("Case 2's better mesh, near the footing", fontsize=9)
    rows = [["case", "the paper's method", "default method", "zero-thickness elements (default)"]]
    for ax, case in zip(axes[1:], ("case2", "case3")):
        curves(ax, runs, case, [case + "-better-paper", case + "-better-default", case + "-zero"],
               ["paper's method", "default method", "zero-thickness elements"])
        ax.set_title({"case2": "Case 2", "case3": "Case 3"}[case] + ", interface under the "
                     "footing only", fontsize=9)
        rows.append([case] + [collapse_text(runs.summary(case + suffix))
                              for suffix in ("-better-paper", "-better-default", "-zero")])
    fig.tight_layout()
    zero = [results.collapse_error(runs.summary(c + "-zero")) for c in ("case2", "case3")]
    better = [results.collapse_load(runs.summary(c + "-better-" + m))
              for c in ("case2", "case3") for m in ("paper", "default")]
    good = all(z is not None and abs(z) <= 0.0051 for z in zero) and \
        all(b is not None and b <= 1.0 + 1e-9 for b in better)
    return Section(
        "figure10", "Figure 10: a better mesh for pure sliding",
        "a better sliding result would be obtained if the interface only extended to the "
        "edge of the footing and not beyond (no computed result given).",
        "reproduced" if good else "differs",
        ("With the layer under the footing only, no tearing: both methods fail at or below "
         "the sliding load (a layer of aspect ratio 10 is conservative, as the paper expects "
         "of it), and zero-thickness elements on the same line give the sliding load itself "
         if good else "Not every run fails at or below the sliding load, or the zero-thickness "
         "elements miss it ") +
        "(errors of the zero-thickness elements: %s)." % ", ".join(
            "%+.2f%%" % (100 * z) if z is not None else "none" for z in zero),
        rows=rows, figures=[(figures.data_uri(fig), "Converged states joined; x: the attempt "
                             "that ended the run.")],
        cost="%.1f s for 6 runs" % runs.seconds(*[c + s for c in ("case2", "case3")
                                                   for s in ("-better-paper", "-better-default", "-zero")]),
        paper_value="better sliding (no value)",
        our_value="%s, %s / %s, %s (paper's, default)" % tuple("%.3f" % b if b else "-"
                                                             for b in better))


def displacement_control(runs, quick):
    summary = runs.summary("case3-displacement")
    load = results.collapse_load(summary)
    fig, ax = plt.subplots(figsize=(6.5, 4))
    figures.curve(ax, runs.path("case3-displacement"), "reaction on the footing", marker=".")
    ax.axhline(1.0, color="k", ls="--", lw=1, label="pi R^2 C_w")
    ax.axhline(1.2, color="grey", ls=":", lw=1.5, label="the paper's failure load")
    ax.set_xlabel("prescribed horizontal displacement, E u / (C_w R)")
    ax.set_ylabel("horizontal reaction / (pi R^2 C_w)")
    ax.grid(alpha=0.3)
    figures.failure_legend(ax, fontsize=7, loc="lower right")
    fig.tight_layout()
    good = load is not None and abs(load - 1.2) <= BAND
    return Section(
        "case3-displacement", "Case 3 under prescribed displacement",
        "failure approximately 20% above pi R^2 C_w (Figure 9).",
        "reproduced" if good else "differs",
        "Pushing the footing instead of loading it, the reaction levels off at %s pi R^2 C_w "
        "(the plateau; default method): the tearing load without the load-controlled "
        "run's question of when a step counts as failed." % (
            "%.3f" % load if load is not None else summary["outcome"]),
        figures=[(figures.data_uri(fig), "Converged states joined.")],
        cost="%.1f s" % summary["wall_seconds"],
        paper_value="1.20", our_value="%.3f (plateau)" % load if load else summary["outcome"])


def validations(runs, quick):
    rows = [["scene", "closed form", "method", "computed", "error", "time (s)"]]
    good = True
    checks = [("prandtl-paper", "Prandtl (2 + pi) c", "viscoplastic"),
              ("prandtl-default", "Prandtl (2 + pi) c", "default"),
              ("circular-footing-rigid", "Shield 5.69 c (smooth rigid disc)", "default")]
    for name, truth, method in checks:
        if not runs.has(name):
            rows.append([name, truth, method, "not run in --quick", "", ""])
            continue
        s = runs.summary(name)
        error = results.collapse_error(s)
        good = good and error is not None and abs(error) <= 0.03
        rows.append([name, truth, method, collapse_text(s),
                     "-" if error is None else "%+.2f%%" % (100 * error), "%.1f" % s["wall_seconds"]])
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for name, label in (("prandtl-paper", "paper's method"), ("prandtl-default", "default method")):
        figures.curve(ax, runs.path(name), label, marker=".", ms=3)
    ax.axhline(2 + math.pi, color="k", ls="--", lw=1, label="(2 + pi) c")
    ax.set_xlabel("settlement under the centre, w / b (b: half-width; E = 1e5 c)")
    ax.set_ylabel("footing pressure / c")
    ax.grid(alpha=0.3)
    figures.failure_legend(ax, fontsize=7, loc="lower right")
    fig.tight_layout()
    return Section(
        "validation-footings", "Validation: footings against closed-form collapse loads",
        "(not in the paper) the plasticity the interfaces rely on, checked where the answer "
        "is known.",
        "agrees" if good else "disagrees",
        "Prandtl's strip footing (a collapse bracketed to 0.5%) and Shield's smooth rigid "
        "circular footing (Fourier harmonic 0, the plateau of the reaction) within 3%. "
        "The tests (ctest) check the rest against closed forms: the patch test, Lame's thick "
        "cylinder with its convergence rates, the return mappings and tangents against "
        "finite differences.",
        rows=rows, figures=[(figures.data_uri(fig), "Prandtl: converged states joined; x: the "
                             "attempt that ended the run.")],
        paper_value="(not in the paper)", our_value=" / ".join(r[4] for r in rows[1:]))


def sections(runs, quick):
    return [lateral_footing(runs, "case2", "figure6",
                            "Figure 6: mesh and load against displacement, strip footing",
                            "Case 2: half the footing, antisymmetric"),
            figure7(runs, quick),
            lateral_footing(runs, "case3", "figure9",
                            "Figures 8 and 9: circular footing, radial-plane mesh and load "
                            "against displacement",
                            "Case 3: the r-z plane, harmonics 1 and 3"),
            displacement_control(runs, quick), figure10(runs, quick), validations(runs, quick)]
