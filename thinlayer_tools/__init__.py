"""thinlayer's Python side: reading results, closed forms, the cases'
meshes, plots and the reproduction report.

Run its programs as modules from the repository's top folder (or with it on
PYTHONPATH), with Debian's own python3 and matplotlib:

    /usr/bin/python3 -m thinlayer_tools.reproduce [--quick]
    /usr/bin/python3 -m thinlayer_tools.plots.scene output/prandtl-strip-footing "(2 + pi) c"
    /usr/bin/python3 -m benchmarks.outcomes --quick

results       history.csv, summary.json, sweep.csv read as every script should
closed_form   the analytic collapse loads and bounds the cases are checked against
cases         the benchmark cases' parameter files and mesh levels, defined once
plots         one chart program per study
report        the sections of the reproduction report, and its check in Chromium
reproduce     the paper reproduced into one report
"""
import json
import os
import subprocess

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
"""The repository's top folder."""

THINLAYER = os.environ.get("THINLAYER", os.path.join(TOP, "build", "thinlayer"))
"""The thinlayer executable (the Release build unless $THINLAYER names another)."""


def mpirun(ranks):
    """The command prefix that runs thinlayer on RANKS MPI ranks: nothing
    for one (no mpirun at all), else Open MPI's mpirun; with more ranks
    than cores, allowed to oversubscribe and with waiting ranks yielding
    their core instead of spinning (with no more ranks than cores yielding
    only slows: 40% on 2 ranks of Prandtl at 8192 cells); and, as root
    (containers, CI), allowed to run as root."""
    if ranks == 1:
        return []
    prefix = ["mpirun", "-np", str(ranks)]
    if ranks > (os.cpu_count() or 1):
        prefix += ["--oversubscribe", "--mca", "mpi_yield_when_idle", "1"]
    if os.geteuid() == 0:
        prefix.append("--allow-run-as-root")
    return prefix


def run_module(module, arguments, **options):
    """Run `python3 -m MODULE ARGUMENTS` (a plot, a benchmark) as a child
    process that imports this package as its parent does; OPTIONS go to
    subprocess.run."""
    environment = dict(os.environ)
    path = environment.get("PYTHONPATH")
    environment["PYTHONPATH"] = TOP + (os.pathsep + path if path else "")
    return subprocess.run(["/usr/bin/python3", "-m", module] + list(arguments),
                          env=environment, **options)


def run_for_summary(command, directory):
    """Run the thinlayer COMMAND (its Output/Directory DIRECTORY; an error
    ends the caller) and return the run's summary.json."""
    subprocess.run(command, capture_output=True, text=True, check=True)
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def overrides(entries):
    """The command line's ["-s", entry, ...] for @p entries
    ("Section/Entry=value"), a later entry replacing an earlier one for the
    same Section/Entry where it stood: the program refuses an entry given
    twice, as a user's mistake."""
    chosen = {}
    for entry in entries:
        chosen[entry.split("=", 1)[0].strip()] = entry
    return [word for entry in chosen.values() for word in ("-s", entry)]
