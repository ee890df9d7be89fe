#!/usr/bin/env python3
"""The diagnostics library (stella_diagnostics, interpreter/CMakeLists.txt) is a leaf: its files
include one another and the standard library only, so that the interpreter, the catalogue and the
solver can all link it without depending on each other. Prints every other include and fails.
Usage: diagnostics-leaf.py SOURCE_DIR"""
import pathlib
import re
import sys

LEAF = ["Diagnostics", "SourceFile", "SourceEncoding"]

root = pathlib.Path(sys.argv[1]) / "interpreter"
allowed = {f"{name}.hpp" for name in LEAF} | {f"interpreter/{name}.hpp" for name in LEAF}
problems = []
for name in LEAF:
    for suffix in (".hpp", ".cpp"):
        path = root / (name + suffix)
        for number, line in enumerate(path.read_text().splitlines(), 1):
            include = re.match(r'\s*#\s*include\s*"([^"]+)"', line)
            if include and include.group(1) not in allowed:
                problems.append(f"{path}:{number}: includes {include.group(1)}: the diagnostics library "
                                "includes only its own files and the standard library")
cmake = (root / "CMakeLists.txt").read_text()
for name in LEAF:
    if f"{name}.cpp" not in cmake:
        problems.append(f"interpreter/CMakeLists.txt: {name}.cpp is not in STELLA_DIAGNOSTICS_SOURCES")
print("\n".join(problems) if problems else f"ok: {len(LEAF)} diagnostics files include nothing else")
sys.exit(1 if problems else 0)
