#!/usr/bin/env python3
"""The keyword tree stays in the inputs layer (issue 15): the files that read a command's keywords
are the operators (solver/operators/), the readers beside them (solver/inputs/), the session and
the job that call them (solver/session/, solver/job/), the catalogue and the command-line tools.
Numerics (model, fem, mesh, assembly, nonlinear, contact, linalg, behaviour, post, io, functions, database)
receive plain structs: none of their files may include catalog/KeywordTree.hpp, directly or
through another header (catalog/Catalog.hpp, solver/session/OperatorRegistry.hpp...).

The include graph layers operators -> inputs -> numerics: besides the keyword tree, no numerics
file reaches any header of the catalogue (catalog/), of the readers (solver/inputs/) or of the
operators (solver/operators/), and no reader includes an operator's header. The readers, the
result database and the post-processing (solver/inputs/, solver/database/, solver/post/) do not
reach the session (solver/session/): concept data comes from solver/database/ConceptStore.hpp,
TEST_RESU / TEST_TABLE report through solver/post/TestReportSink.hpp. These have no allow-list:
they hold today and fail on the first file that breaks them.

The files still to move are listed in tools/lint/keyword-tree-layers.allow; the list only shrinks
(a listed file that no longer reaches the tree fails too, so the list stays exact).
Usage: keyword-tree-layers.py REPOSITORY-ROOT [--list]
"""
import os
import re
import sys

INPUTS_LAYER = ("catalog/", "tools/", "interpreter/", "solver/operators/", "solver/inputs/", "solver/session/",
                "solver/job/")
TREE = "catalog/KeywordTree.hpp"
ABOVE_NUMERICS = ("catalog/", "solver/inputs/", "solver/operators/")
BELOW_SESSION = ("solver/inputs/", "solver/database/", "solver/post/")


def main():
    root = sys.argv[1]
    listing = "--list" in sys.argv
    include = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
    files = {}
    for top in ("solver", "catalog", "interpreter", "tools"):
        for folder, _, names in os.walk(os.path.join(root, top)):
            for n in names:
                if n.endswith((".cpp", ".hpp")):
                    path = os.path.join(folder, n)
                    rel = os.path.relpath(path, root)
                    text = open(path, encoding="utf-8", errors="replace").read()
                    deps = []
                    for inc in include.findall(text):
                        local = os.path.normpath(os.path.join(os.path.dirname(rel), inc))
                        deps.append(local if os.path.exists(os.path.join(root, local)) else inc)
                    files[rel] = deps
    reaches = {}

    def reach(f, seen=()):
        if f in reaches:
            return reaches[f]
        if f == TREE:
            return [TREE]
        if f in seen:
            return None
        for d in files.get(f, []):
            chain = reach(d, seen + (f,))
            if chain:
                reaches[f] = [d] + chain if d != TREE else [TREE]
                return reaches[f]
        reaches[f] = None
        return None

    found = {}
    for f in sorted(files):
        if f.startswith(INPUTS_LAYER) or "/tests/" in f:
            continue
        chain = reach(f)
        if chain:
            found[f] = chain
    layering = layer_failures(files)
    allow_file = os.path.join(root, "tools", "lint", "keyword-tree-layers.allow")
    allowed = set()
    if os.path.exists(allow_file):
        for raw in open(allow_file, encoding="utf-8"):
            raw = raw.split("#")[0].strip()
            if raw:
                allowed.add(raw)
    if listing:
        for f in found:
            print(f)
        return 0
    failures = [f for f in found if f not in allowed]
    stale = sorted(allowed - set(found))
    for f in failures:
        print(f"{f}: reaches {TREE} through " + " -> ".join(found[f]) + " (a numerics file: take a plain struct)")
    for f in stale:
        print(f"tools/lint/keyword-tree-layers.allow: {f} no longer reaches the keyword tree: remove it")
    for line in layering:
        print(line)
    direct = sum(1 for f in found if found[f] == [TREE])
    print(f"{len(found)} file(s) below the inputs layer reach the keyword tree ({direct} include it directly), "
          f"{len(found) - len(failures)} of them listed as still to move; {len(layering)} layering failure(s)")
    return 1 if failures or stale or layering else 0


def layer_failures(files):
    """Numerics files reaching a header above them (catalogue, readers, operators), and readers
    including an operator's header: one message each, with the include chain."""

    def chain_to(f, above):
        parent, todo = {f: None}, [f]
        while todo:
            x = todo.pop(0)
            for d in files.get(x, []):
                if d in parent:
                    continue
                parent[d] = x
                if d.startswith(above):
                    path = [d]
                    while parent[path[-1]] != f:
                        path.append(parent[path[-1]])
                    return list(reversed(path))
                todo.append(d)
        return None

    out = []
    for f in sorted(files):
        if "/tests/" in f:
            continue
        if f.startswith(BELOW_SESSION):
            chain = chain_to(f, ("solver/session/",))
            if chain:
                out.append(f"{f}: reaches the session through " + " -> ".join(chain) +
                           " (concept data: solver/database/ConceptStore.hpp)")
        if f.startswith("solver/inputs/"):
            chain = chain_to(f, ("solver/operators/",))
            if chain:
                out.append(f"{f}: a reader reaches an operator through " + " -> ".join(chain))
        elif not f.startswith(INPUTS_LAYER):
            chain = chain_to(f, ABOVE_NUMERICS)
            if chain:
                out.append(f"{f}: a numerics file reaches {chain[-1]} through " + " -> ".join(chain) +
                           " (operators -> inputs -> numerics: take a plain struct)")
    return out


if __name__ == "__main__":
    sys.exit(main())
