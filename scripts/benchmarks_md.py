#!/usr/bin/env python3
"""Refreshes the generated blocks of the README and doc/ (the documents of DOCS) from
bench/results.

    scripts/benchmarks_md.py [--check] [DOC ...]

A generated table sits between two markers that name its source:

    <!-- generated from bench/results/table2.md -->
    | ... |
    <!-- end generated -->

The source is a result file that a benchmark script wrote from its JSON (its first Markdown
table is taken) or a script under bench/ that prints Markdown computed from the JSON, a table
or the figures a paragraph quotes (its whole output is taken; "bench/x.py:word" runs it with
the argument word). --check compares instead of writing and exits 1 if a block is not current.
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = ["doc/benchmarks.md", "doc/performance-model.md", "doc/hertz-validation.md", "doc/algorithms.md", "README.md"]
BLOCK = re.compile(r"(<!-- generated from (\S+) -->\n)(.*?)(<!-- end generated -->)", re.S)


def first_table(text):
    lines, table = text.splitlines(), []
    for line in lines:
        if line.startswith("|"):
            table.append(line)
        elif table:
            break
    return "\n".join(table) + "\n"


def table_from(source):
    name, _, argument = source.partition(":")
    path = os.path.join(ROOT, name)
    if not os.path.isfile(path):
        sys.exit(f"benchmarks_md: {name}, named in a generated table's marker, does not exist")
    if name.endswith(".py"):
        command = [sys.executable, path] + ([argument] if argument else [])
        text = subprocess.run(command, check=True, capture_output=True, text=True).stdout.strip()
        if not text:
            sys.exit(f"benchmarks_md: {source} prints nothing")
        return text + "\n"
    with open(path) as f:
        table = first_table(f.read())
    if table == "\n":
        sys.exit(f"benchmarks_md: {source} holds no Markdown table")
    return table


def refreshed(text):
    return BLOCK.sub(lambda m: m.group(1) + table_from(m.group(2)) + m.group(4), text)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true", help="exit 1 if a generated table is not current")
    parser.add_argument("docs", nargs="*", metavar="DOC", help=f"refresh or check only these (default: {' '.join(DOCS)})")
    args = parser.parse_args()
    unknown = [doc for doc in args.docs if doc not in DOCS]
    if unknown:
        sys.exit(f"benchmarks_md: {', '.join(unknown)} is not one of {', '.join(DOCS)}")
    stale = []
    for doc in args.docs or DOCS:
        with open(os.path.join(ROOT, doc)) as f:
            current = f.read()
        new = refreshed(current)
        if args.check:
            if new != current:
                stale.append(doc)
            else:
                print(f"{doc}: {len(BLOCK.findall(current))} generated tables current")
        elif new != current:
            with open(os.path.join(ROOT, doc), "w") as f:
                f.write(new)
    if stale:
        print(f"{', '.join(stale)} not current: run scripts/benchmarks_md.py", file=sys.stderr)
        return 1
    return 0

if __name__ == "__main__":
    sys.exit(main())
