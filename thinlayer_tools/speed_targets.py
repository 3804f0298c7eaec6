"""The project's speed targets (issue 53) and their verdicts, computed from
the rows benchmarks/performance.py measures: the benchmark prints them
beside its tables and the report's speed sections state them, so that the
two never judge the same run differently.

A row is a dict as the benchmark writes it (its CSV read back gives the
same keys; numbers may then be text). A verdict is a dict: the target,
where it was judged, what was measured and "met" or "missed"."""
import math

from thinlayer_tools import results

# Prandtl's footing: the default method brackets (2 + pi)c to this share...
ANSWER_TOLERANCE = 0.005
# ...in at most this share of the paper's method's time on its seven fixed
# steps, its time growing no faster than equations to this power.
SHARE_OF_PAPER_FIXED = 1 / 3
EXPONENT = 1.15
# Newton-type iterations of an accepted step away from collapse.
MOST_ITERATIONS_AWAY = 8
# Two runs of a scene give the same answer when they end alike and their
# collapse loads differ by no more than the scenes' collapse resolution.
SAME_ANSWER = 0.005
# Two times closer than this share are the same time: medians of three runs
# of one computation on the 2-core machines differ by up to some percent
# (where the default method's budget never buys Newton, it and accelerated
# initial stress alone do the same iterations).
TIME_NOISE = 0.05
# Outcomes that answer nothing: a run stopped from outside, or one whose
# last step failed without a bracket.
NO_ANSWER = ("interrupted", "not converged")
# The 3D scene of at least this many DoFs, on two ranks: its time and peak
# memory per DoF.
LARGE_DOFS = 250000
LARGE_SECONDS = 900.0
LARGE_KB_PER_DOF = 10.0

# The benchmark's ways these verdicts compare (its labels): on Prandtl,
PAPER_FIXED = "paper's method, 7 fixed steps"
DEFAULT = "default method, automatic stepping"
# on the thin-layer and the 3D scenes, the default method.
SCENE_DEFAULT = "default method"
# The ways that are the default method (with some option of its own) and
# not another method.
DEFAULT_PREFIX = "default method"


def value(row, key):
    """A field as a float (nan where there is none)."""
    return results.number(row.get(key))


def verdict(target, where, measured, met):
    return {"target": target, "where": where, "measured": measured,
            "verdict": "met" if met else "missed"}


def brackets_prandtl(row):
    """Whether a Prandtl row reached the answer: a collapse with both ends
    of its bracket (its plateau under work control, which has none) within
    ANSWER_TOLERANCE of (2 + pi)c."""
    if row["outcome"] != "collapse":
        return False
    ends = [value(row, "bracket_low"), value(row, "bracket_high")]
    if not all(math.isfinite(e) for e in ends):
        ends = [value(row, "last_converged")]
    return all(abs(e - 1) <= ANSWER_TOLERANCE + 1e-9 for e in ends)


def fastest(rows, reaches):
    """The fastest of @p rows that @p reaches the answer (None: none does)."""
    answering = [r for r in rows if reaches(r)]
    return min(answering, key=lambda r: value(r, "wall_median_s"), default=None)


def fastest_method(rows, default_label, reaches, where):
    """The default way (@p default_label) against the fastest way of
    another method that reaches the answer, equal within TIME_NOISE; the
    fastest way of all named."""
    default = next((r for r in rows if r["way"] == default_label), None)
    if default is None:
        return None
    others = [r for r in rows if not r["way"].startswith(DEFAULT_PREFIX)]
    rival = fastest(others, reaches)
    best = fastest(rows, reaches)
    seconds = value(default, "wall_median_s")
    measured = "%s %.2f s" % ("reached the answer in" if reaches(default) else
                              "no answer after", seconds)
    measured += "; fastest other method: " + (
        "%s, %.2f s" % (rival["way"], value(rival, "wall_median_s")) if rival else "none answers")
    if best is not None and best is not default:
        measured += "; fastest way: %s, %.2f s" % (best["way"], value(best, "wall_median_s"))
    met = reaches(default) and (
        rival is None or seconds <= (1 + TIME_NOISE) * value(rival, "wall_median_s"))
    return verdict("the default method is the fastest method to the answer", where,
                   measured, met)


def prandtl(rows, fit_exponent):
    """The verdicts on Prandtl's rows (performance.csv): per size, the
    bracket, the share of the paper's fixed time and the fastest method;
    over the sizes, the exponent (@p fit_exponent: (equations, s) -> power)."""
    verdicts = []
    for cells in sorted({int(r["cells"]) for r in rows}):
        here = [r for r in rows if int(r["cells"]) == cells]
        where = "Prandtl, %d cells" % cells
        default = next((r for r in here if r["way"] == DEFAULT), None)
        fixed = next((r for r in here if r["way"] == PAPER_FIXED), None)
        if default is None:
            continue
        verdicts.append(verdict(
            "the default method brackets (2+pi)c to %.1f%%" % (100 * ANSWER_TOLERANCE), where,
            "%s %s" % (default["outcome"], "%.4f - %.4f" % (
                value(default, "bracket_low"), value(default, "bracket_high"))),
            brackets_prandtl(default)))
        if fixed is not None:
            share = value(default, "wall_median_s") / value(fixed, "wall_median_s")
            verdicts.append(verdict(
                "at most %.2f of the paper's method's time on its fixed steps"
                % SHARE_OF_PAPER_FIXED, where, "%.2f" % share,
                share <= SHARE_OF_PAPER_FIXED))
        verdicts.append(fastest_method(here, DEFAULT, brackets_prandtl, where))
    points = [(value(r, "equations"), value(r, "wall_median_s")) for r in rows
              if r["way"] == DEFAULT]
    growth = fit_exponent(points)
    verdicts.append(verdict(
        "the default method's time grows no faster than equations^%.2f" % EXPONENT,
        "Prandtl, %d size%s" % (len(points), "" if len(points) == 1 else "s"),
        "%.2f" % growth if growth is not None else "one size: no exponent",
        growth is not None and growth <= EXPONENT))
    return verdicts


def same_answer(reference):
    """Whether a row ends as @p reference does, its collapse load within
    SAME_ANSWER of @p reference's."""
    def reaches(row):
        if row["outcome"] != reference["outcome"] or row["outcome"] in NO_ANSWER:
            return False
        a, b = value(row, "collapse_load"), value(reference, "collapse_load")
        if not (math.isfinite(a) and math.isfinite(b)):
            return not math.isfinite(a) and not math.isfinite(b)
        return abs(a - b) <= SAME_ANSWER * abs(b) + 1e-12
    return reaches


def scene_answer(rows):
    """The row whose collapse load the most rows share (same_answer), the
    higher load where as many share two: a scene has no closed form to
    judge by, and one method can stop early (the paper's method at a loose
    tolerance on a thin layer) or find no collapse. None: no row has a
    collapse load."""
    loaded = [r for r in rows if math.isfinite(value(r, "collapse_load"))]
    return max(loaded, default=None,
               key=lambda r: (sum(same_answer(r)(o) for o in rows),
                              value(r, "collapse_load")))


def scenes(rows, iterations=True, default_label=SCENE_DEFAULT):
    """The verdicts on the scenes' rows (performance-scenes.csv or
    performance-3d.csv): per scene, the default method's outcome and
    collapse load against the scene's answer (scene_answer()), the fastest
    method to it and (with @p iterations) the most iterations a step away
    from collapse."""
    verdicts = []
    for scene in dict.fromkeys(r["scene"] for r in rows):
        here = [r for r in rows if r["scene"] == scene]
        default = next((r for r in here if r["way"] == default_label), None)
        if default is None:
            continue
        answer = scene_answer(here) or default
        reaches = same_answer(answer)
        agreeing = [r["way"] for r in here if reaches(r)]
        verdicts.append(verdict(
            "the default method gives the answer most ways agree on (within %.1f%%)"
            % (100 * SAME_ANSWER), scene,
            "%s %s; the answer %s %s (%s)" % (default["outcome"], figure(default),
                                              answer["outcome"], figure(answer),
                                              "; ".join(agreeing) or "no way"),
            reaches(default)))
        verdicts.append(fastest_method(here, default_label, reaches, scene))
        if iterations and "most_iterations_away" in default:
            most = int(value(default, "most_iterations_away"))
            verdicts.append(verdict(
                "at most %d iterations a step away from collapse" % MOST_ITERATIONS_AWAY,
                scene, "%d" % most, most <= MOST_ITERATIONS_AWAY))
    return verdicts


def figure(row):
    load = value(row, "collapse_load")
    return "%.4f" % load if math.isfinite(load) else "(no collapse load)"


def large_3d(rows):
    """The verdicts on the large 3D scene: the rows of at least LARGE_DOFS
    DoFs by the default method; one missed verdict where none was run."""
    large = [r for r in rows if value(r, "dofs") >= LARGE_DOFS and
             r["way"] == SCENE_DEFAULT]
    if not large:
        return [verdict("a 3D scene of at least %d DoFs on 2 ranks in at most %.0f s, "
                        "at most %.0f kB per DoF" % (LARGE_DOFS, LARGE_SECONDS,
                                                      LARGE_KB_PER_DOF),
                        "3D", "not run", False)]
    verdicts = []
    for r in large:
        seconds, memory = value(r, "wall_median_s"), value(r, "peak_kb_per_dof")
        verdicts.append(verdict("at most %.0f s to the answer" % LARGE_SECONDS, r["scene"],
                                "%s after %.0f s" % (r["outcome"], seconds),
                                math.isfinite(value(r, "collapse_load")) and
                                seconds <= LARGE_SECONDS))
        verdicts.append(verdict("at most %.0f kB per DoF" % LARGE_KB_PER_DOF, r["scene"],
                                "%.1f" % memory, memory <= LARGE_KB_PER_DOF))
    return verdicts


# What Solver/Linear solver = automatic picks (benchmarks/linear_solvers.py's
# labels): on one rank, and on several for a 3D mesh and a plane one.
AUTOMATIC_ONE_RANK = "direct"
AUTOMATIC_SEVERAL_RANKS_3D = "direct, block low-rank"
AUTOMATIC_SEVERAL_RANKS_PLANE = "direct"


def automatic_pick(ranks, kinematics):
    """The solver automatic picks on @p ranks for a scene of @p kinematics
    (summary.json's: "3d", "plane strain" or "fourier")."""
    if ranks == 1:
        return AUTOMATIC_ONE_RANK
    return AUTOMATIC_SEVERAL_RANKS_3D if kinematics == "3d" else AUTOMATIC_SEVERAL_RANKS_PLANE


def automatic_solver(rows):
    """Whether Solver/Linear solver = automatic picks the fastest solver per
    solve on each scene and rank count of benchmarks/linear_solvers.py's
    @p rows (times within TIME_NOISE equal); one verdict per group with
    more than one solver. A row's kinematics is its scene's (any row of the
    group that ran gives it)."""
    verdicts = []
    groups = {}
    for r in rows:
        groups.setdefault((r["scene"], int(r["ranks"])), []).append(r)
    for (scene, ranks), group in groups.items():
        kinematics = next((r["kinematics"] for r in group if r.get("kinematics")), "")
        pick = automatic_pick(ranks, kinematics)
        picked = next((r for r in group if r["solver"].split(" (")[0] == pick), None)
        timed = [r for r in group if math.isfinite(value(r, "solve_s"))]
        if len(group) < 2 or picked is None:
            continue
        target = "automatic picks the fastest solver per solve"
        where = "%s, %d rank%s" % (scene, ranks, "" if ranks == 1 else "s")
        if picked not in timed:
            verdicts.append(verdict(target, where, "%s failed" % picked["solver"], False))
            continue
        best = min(timed, key=lambda r: value(r, "solve_s"))
        verdicts.append(verdict(
            target, where, "%s %.4f s; fastest %s %.4f s" % (
                picked["solver"], value(picked, "solve_s"), best["solver"],
                value(best, "solve_s")),
            value(picked, "solve_s") <= (1 + TIME_NOISE) * value(best, "solve_s")))
    return verdicts


def table(verdicts):
    """Markdown lines of @p verdicts."""
    lines = ["| target | where | measured | verdict |", "|---|---|---|---|"]
    lines += ["| %s | %s | %s | %s |" % (v["target"], v["where"], v["measured"], v["verdict"])
              for v in verdicts]
    return lines


def missed(verdicts):
    return [v for v in verdicts if v["verdict"] == "missed"]
