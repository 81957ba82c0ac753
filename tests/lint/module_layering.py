#!/usr/bin/env python3
"""The modules' layering, checked on every #include "..." of the library's sources and headers.
A file of one module includes headers of its own module and of the modules it may use only:

    core      nothing
    solver    core                     (knows nothing of meshes, assembly, problems or output)
    fe        core                     (meshes and elements know nothing of the solver)
    assembly  core, solver, fe
    problem   core, solver, fe, assembly
    io        core, solver, assembly, problem   (writes what assembly computed: no mechanics)
    driver    every module

An installed header names no private type: a class it declares at namespace scope without
defining it must be defined in an installed header. Includes are rooted at src/
or include/ (no "../"); an installed header (include/signorini/) includes installed headers
only. The umbrella header include/signorini/signorini.hpp stands above every module.
Prints every violation; exit status 1 if there is one.

    tests/lint/module_layering.py SOURCE_DIR
"""
import os
import re
import sys

USES = {
    "core": [],
    "solver": ["core"],
    "fe": ["core"],
    "assembly": ["core", "solver", "fe"],
    "problem": ["core", "solver", "fe", "assembly"],
    "io": ["core", "solver", "assembly", "problem"],
    "driver": ["core", "solver", "fe", "assembly", "problem", "io"],
}
ORDER = list(USES)
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
FORWARD = re.compile(r'^(?:class|struct)\s+(\w+)\s*;', re.M)  # at namespace scope: not indented
DEFINITION = re.compile(r'^\s*(?:class|struct)\s+(\w+)\b(?:\s+final)?\s*[:{]', re.M)


def module_of_file(root, path):
    """The module of a library file: src/<module>/... or include/signorini/<module>/..."""
    rel = os.path.relpath(path, root).split(os.sep)
    if rel == ["include", "signorini", "signorini.hpp"]:
        return ORDER[-1]
    if rel[0] == "src":
        return rel[1]
    if rel[:2] == ["include", "signorini"] and len(rel) > 3:
        return rel[2]
    return None


def module_of_include(target):
    """The module of an included header: "signorini/<module>/X.hpp" or "<module>/.../X.hpp"."""
    parts = target.split("/")
    if parts[0] == "signorini":
        parts = parts[1:]
    return parts[0] if len(parts) > 1 and parts[0] in ORDER else None


def violations(root):
    for top in ("src", os.path.join("include", "signorini")):
        for directory, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if not name.endswith((".hpp", ".cpp")):
                    continue
                path = os.path.join(directory, name)
                rel = os.path.relpath(path, root)
                module = module_of_file(root, path)
                installed = rel.startswith(os.path.join("include", "signorini"))
                if module not in ORDER:
                    yield "%s: not in a module folder (%s)" % (rel, ", ".join(ORDER))
                    continue
                with open(path) as f:
                    text = f.read()
                for target in INCLUDE.findall(text):
                    if ".." in target.split("/"):
                        yield '%s: includes "%s" by a relative path' % (rel, target)
                        continue
                    if installed and not target.startswith("signorini/"):
                        yield '%s: installed header includes the private "%s"' % (rel, target)
                    used = module_of_include(target)
                    if used is None:
                        yield '%s: includes "%s", which is in no module' % (rel, target)
                    elif used != module and used not in USES[module]:
                        yield '%s: %s includes "%s" from %s, which %s may not use' % (rel, module, target, used, module)


def private_types(root):
    """Forward declarations in installed headers of classes no installed header defines."""
    texts = {}
    for directory, _, names in os.walk(os.path.join(root, "include", "signorini")):
        for name in sorted(names):
            if name.endswith(".hpp"):
                path = os.path.join(directory, name)
                with open(path) as f:
                    texts[os.path.relpath(path, root)] = f.read()
    defined = {name for text in texts.values() for name in DEFINITION.findall(text)}
    for rel, text in sorted(texts.items()):
        for name in FORWARD.findall(text):
            if name not in defined:
                yield "%s: installed header names the private type %s" % (rel, name)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))
    found = list(violations(root)) + list(private_types(root))
    for line in found:
        print(line)
    print("module layering: %d violation(s)" % len(found))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
