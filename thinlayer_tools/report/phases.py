"""The report's section on loading phases: a block pressed down by V (the
Loading section) and then pushed sideways with V held (Phase 2) slides at
H = V tan(delta), by zero-thickness interface elements
(prm/sliding-block.prm) and by thin layers of decreasing thickness
(prm/sliding-block-thin-layer.prm)."""
from thinlayer_tools import results
from thinlayer_tools.report.page import Section
from thinlayer_tools.report.runs import PAPER

INTERFACE = "sliding-block"
LAYER = "sliding-block-thin-layer"
# Asked of the interface elements: H / (V tan(delta)) = 1 to rounding.
EXACT = 1e-9
# The thin layer's thickness over the block's width: the file's (1/20)
# and thinner ones in the full report.
THICKNESSES = (20, 100, 500)


def geometry(ratio):
    return ("Mesh/Geometry parameters=block_width=1, block_height=0.5, layer=%g, "
            "soil_width=4, soil_depth=2, n_block=10, n_block_height=4, n_side=6, "
            "n_depth=8" % (1 / ratio))


def thicknesses(quick):
    return THICKNESSES[:1] if quick else THICKNESSES


def run_list(quick):
    runs = [("phases-interface", INTERFACE, ("Output/Write VTU=false",)),
            ("phases-interface-paper", INTERFACE, PAPER + ("Output/Write VTU=false",))]
    runs += [("phases-layer-%d" % ratio, LAYER, (geometry(ratio), "Output/Write VTU=false"))
             for ratio in thicknesses(quick)]
    return runs


def phases(runs, quick):
    table = [["interface", "method", "outcome", "H / (V tan delta)", "error", "iterations",
              "wall s"]]
    rows = [("phases-interface", "interface elements", "default"),
            ("phases-interface-paper", "interface elements", "paper's")]
    rows += [("phases-layer-%d" % ratio, "thin layer, t = B/%d" % ratio, "default")
             for ratio in thicknesses(quick)]
    exact, layer, paper = None, [], "-"
    for name, what, method in rows:
        if not runs.has(name):
            continue
        s = runs.summary(name)
        found = results.collapse_load(s)
        last = results.number(s.get("last_converged_load"))
        shown = found if found is not None else last
        table.append([what, method, s["outcome"],
                      ("%.6f" % shown if found is not None else "%.4f (last converged)" % last),
                      "%+.2e" % (found - 1) if found is not None else "-",
                      "%d" % s["total_iterations"], "%.2f" % s["wall_seconds"]])
        if name == "phases-interface":
            exact = found
        elif name == "phases-interface-paper":
            paper = "%s at %s" % (s["outcome"], table[-1][3])
        elif method == "default" and name != "phases-interface":
            layer.append(shown)
    good = exact is not None and abs(exact - 1) < EXACT
    approaching = len(layer) < 2 or all(b > a for a, b in zip(layer, layer[1:]))
    names = [n for n, _, _ in run_list(quick)]
    why = ("Two loading phases: the Loading section presses a block of width B with "
           "V = 10 B (its top held sideways), then Phase 2 pushes its top sideways with V "
           "held. Whatever the distribution of the normal tractions under a rigid block, "
           "they add up to V, so when every point slides at tau = sigma_n tan(delta) the "
           "horizontal force is V tan(delta) (Coulomb's law of sliding friction). On "
           "zero-thickness interface elements (delta = 30) the plateau is asked to equal it "
           "to %.0e: %s. A thin layer of elements (phi = psi = 30, so that a long layer "
           "slides at tan(phi)) levels off below it, its free ends carrying less than a "
           "long layer's ratio, and approaches it as the layer thins%s; near the limit the "
           "default method's steps on the thinner layers do not converge (their last "
           "converged states are shown). The paper's method on the interface elements "
           "(this file's solver settings): %s." % (
               EXACT, "it does" if good else "it does NOT",
               "" if quick else (": " + ", ".join("%.3f" % v for v in layer)
                                 + (" (rising)" if approaching else " (NOT rising)")),
               paper))
    return Section(
        "loading-phases", "Loading phases: a block pressed, then pushed until it slides",
        "(not in the paper) H = V tan(delta) for a rigid block sliding on a Coulomb "
        "interface.",
        "agrees" if good and approaching else "disagrees", why, rows=table,
        cost="%.1f s for the %d runs" % (runs.seconds(*names), len(names)),
        paper_value="H / (V tan delta) = 1",
        our_value="%.6f (interface elements)" % exact if exact is not None else "-")


def sections(runs, quick):
    return [phases(runs, quick)]
