"""What the scripts that print the figures the documentation quotes have in common
(bench/benchmarks_figures.py, hertz_validation_figures.py, algorithms_figures.py and
performance_model_figures.py, whose output scripts/benchmarks_md.py pastes into the README
and doc/): reading a result file of bench/results, the wording of ranges and counts, and the
command line, which names the section to print. Standard library only, like those scripts.
"""
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The preconditioning benchmarks' sequences (preconditioners-*.json), as the documents name them.
SEQUENCES = {"2d": "2D P1", "3d": "3D P1", "2d-p2": "2D P2", "2d-p3": "2D P3", "3d-p2": "3D P2"}


def results(name):
    """The whole of bench/results/NAME.json."""
    with open(os.path.join(ROOT, "bench", "results", name + ".json")) as f:
        return json.load(f)


def records(name):
    """The runs of bench/results/NAME.json: its "runs", or the file itself where it is a list
    (a file without provenance)."""
    data = results(name)
    return data["runs"] if isinstance(data, dict) else data


def span(values, digits=None, suffix=""):
    """"low–high" of the values printed with that many decimals (as they are where digits is
    None), or the one value where both print alike; then the suffix."""
    form = "{}" if digits is None else f"{{:.{digits}f}}"
    low, high = form.format(min(values)), form.format(max(values))
    return (low if low == high else f"{low}–{high}") + suffix


def count(n):
    """An integer with its thousands apart: 823 875."""
    return f"{n:,}".replace(",", " ")


def run(sections):
    """Calls the function of SECTIONS that the command line names: SCRIPT SECTION."""
    script = os.path.basename(sys.argv[0])
    if len(sys.argv) != 2:
        sys.exit(f"usage: {script} SECTION, where SECTION is one of {', '.join(sections)}")
    if sys.argv[1] not in sections:
        sys.exit(f"{script}: no section {sys.argv[1]!r}; the sections are {', '.join(sections)}")
    sections[sys.argv[1]]()
