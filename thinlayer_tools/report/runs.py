"""The runs of a reproduction, as the sections read them."""
import json
import os
import platform
import subprocess

from thinlayer_tools import results

# The solver entries of the paper's method and of thinlayer's default one.
PAPER = ("Solver/Method=viscoplastic", "Solver/Convergence criterion=body loads")
DEFAULT = ("Solver/Method=accelerated with newton fallback",
           "Solver/Convergence criterion=default")


class Runs:
    """DIR/runs/NAME of a reproduction: summaries, sweeps and histories."""

    def __init__(self, directory):
        self.directory = directory

    def path(self, name, run=None):
        """A run's directory; with @p run, that run of a sweep."""
        base = os.path.join(self.directory, "runs", name)
        return base if run is None else os.path.join(base, "run-%03d" % int(run))

    def has(self, name):
        return os.path.isdir(self.path(name))

    def summary(self, name, run=None):
        with open(os.path.join(self.path(name, run), "summary.json")) as f:
            return json.load(f)

    def sweep(self, name):
        """The rows of a sweep.csv."""
        return results.read_csv(os.path.join(self.path(name), "sweep.csv"))

    def find(self, name, **values):
        """The sweep row whose swept entries have @p values (compared as numbers)."""
        rows = [r for r in self.sweep(name)
                if all(float(r[key.replace("__", "/")]) == float(value)
                       for key, value in values.items())]
        if len(rows) != 1:
            raise KeyError("%s: %d rows with %s" % (name, len(rows), values))
        return rows[0]

    def seconds(self, *names):
        """The wall time of runs and sweeps, summed."""
        total = 0.0
        for name in names:
            if os.path.exists(os.path.join(self.path(name), "sweep.csv")):
                total += sum(results.number(r["wall_seconds"]) for r in self.sweep(name))
            else:
                total += self.summary(name)["wall_seconds"]
        return total

    @staticmethod
    def machine():
        cpu = "unknown processor"
        try:
            with open("/proc/cpuinfo") as f:
                cpu = next(line.split(":", 1)[1].strip() for line in f
                           if line.startswith("model name"))
        except (OSError, StopIteration):
            pass
        return "%s, %d cores, %s" % (cpu, os.cpu_count() or 0, platform.platform())

    def version(self):
        top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        done = subprocess.run(["git", "-C", top, "describe", "--always", "--dirty"],
                              capture_output=True, text=True)
        return done.stdout.strip() or "(not a git checkout)"
