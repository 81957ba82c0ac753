#!/usr/bin/env python3
"""No function of the library's sources longer than 80 lines, from its signature to its
closing brace (lambdas count with the function that holds them). Universal Ctags finds the
definitions and their ends. Prints every function over the limit; exit status 1 if there is one.

    tests/lint/function_length.py SOURCE_DIR [CTAGS]
"""
import os
import subprocess
import sys

LIMIT = 80


def long_functions(root, ctags):
    out = subprocess.run([ctags, "-R", "--languages=C++", "--kinds-C++=f", "--fields=+ne", "-x",
                          "--_xformat=%{name}\t%{input}\t%{line}\t%{end}", "src"],
                         cwd=root, check=True, capture_output=True, text=True).stdout
    for row in out.splitlines():
        name, path, start, end = row.split("\t")
        if not end:
            yield "%s:%s: %s: ctags found no end" % (path, start, name)
            continue
        length = int(end) - int(start) + 1
        if length > LIMIT:
            yield "%s:%s: %s has %d lines (at most %d)" % (path, start, name, length, LIMIT)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))
    ctags = sys.argv[2] if len(sys.argv) > 2 else "ctags-universal"
    found = sorted(long_functions(root, ctags))
    for line in found:
        print(line)
    print("function length: %d function(s) over %d lines" % (len(found), LIMIT))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
