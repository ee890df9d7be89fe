#!/usr/bin/env python3
"""No C++ fallback repeats a catalogue default, and no reader asks for a keyword the catalogue does
not define (issue 15, "one truth per keyword").

Reads the catalogue (`stella catalog --json`) and every `textOr("NAME", x)`, `realOr("NAME", x)`,
`integerOr("NAME", x)` of the C++ sources outside tests. Fails when
  - NAME is a keyword no command of the catalogue defines (a misspelt name silently returns the
    fallback), or
  - x is a default the catalogue gives NAME (the reader should read the validated tree, which
    holds the default: `text("NAME")`),
unless the site is listed in tools/lint/or-fallbacks.allow (`path NAME`, the fallbacks still to
remove: the list only shrinks; a listed site that no longer exists fails too, so the list is kept
exact). Usage: or-fallbacks.py PATH/TO/stella REPOSITORY-ROOT [--list]
"""
import json
import os
import re
import subprocess
import sys


def walk(level, names, defaults):
    for e in level.get("entries", []):
        kind = e.get("kind")
        if kind == "BLOC":
            walk(e, names, defaults)
            continue
        names.add(e["name"])
        if kind == "SIMP" and "default" in e and len(e["default"]) == 1:
            defaults.setdefault(e["name"], []).append(e["default"][0])
        if kind == "FACT":
            walk(e, names, defaults)
        for sub in ("body",):
            if sub in e:
                walk(e[sub], names, defaults)


def same(literal, default):
    if isinstance(default, str):
        return literal == '"' + default + '"'
    try:
        return float(literal.rstrip("fFlL")) == float(default)
    except ValueError:
        return False


def main():
    stella, root = sys.argv[1], sys.argv[2]
    listing = "--list" in sys.argv
    catalogue = json.loads(subprocess.run([stella, "catalog", "--json"], check=True, capture_output=True,
                                          text=True).stdout)
    names, defaults = set(), {}
    commands = catalogue["commands"] if isinstance(catalogue, dict) and "commands" in catalogue else catalogue
    for c in (commands.values() if isinstance(commands, dict) else commands):
        walk(c, names, defaults)
    call = re.compile(r'\b(textOr|realOr|integerOr)\(\s*"([A-Z0-9_]+)"\s*,\s*([^()]+?)\s*\)')
    found = []
    # Every keyword name a reader asks a validated tree for is one the catalogue defines: in the
    # command's own entry for an operator file (STELLA_OPERATOR("NAME", ...)), anywhere otherwise.
    per_command = {}
    for c in (commands.values() if isinstance(commands, dict) else commands):
        own, _ = set(), {}
        walk(c, own, _)
        per_command[c["name"]] = own
    reader = re.compile(r'\.(text|real|integer|texts|reals|integers|conceptValue|conceptValues|value|has|simple|'
                        r'factor|occurrences|locationOf|textOr|realOr|integerOr)\(\s*"([A-Z][A-Z0-9_]*)"')
    operator = re.compile(r'STELLA_OPERATOR\(\s*"([A-Z_0-9]+)"')
    for top in ("solver", "tools", "catalog", "interpreter"):
        for folder, _, files in os.walk(os.path.join(root, top)):
            if "/tests" in folder or "/bench" in folder:
                continue
            for f in files:
                if not f.endswith((".cpp", ".hpp")):
                    continue
                path = os.path.join(folder, f)
                rel = os.path.relpath(path, root)
                text = open(path, encoding="utf-8").read()
                ops = operator.findall(text)
                known = set().union(*(per_command.get(o, set()) for o in ops)) if ops else names
                for m in reader.finditer(text):
                    if m.group(2) not in known:
                        line = text.count("\n", 0, m.start()) + 1
                        where = " of " + "/".join(ops) if ops else ""
                        found.append((rel, line, m.group(2),
                                      f".{m.group(1)}(\"{m.group(2)}\") reads a keyword the catalogue{where} does "
                                      "not define"))
                for m in call.finditer(text):
                    line = text.count("\n", 0, m.start()) + 1
                    name, literal = m.group(2), m.group(3)
                    if name not in names:
                        found.append((rel, line, name, f"{m.group(1)}(\"{name}\") names no catalogue keyword"))
                    elif any(same(literal, d) for d in defaults.get(name, [])):
                        found.append((rel, line, name,
                                      f"{m.group(1)}(\"{name}\", {literal}) repeats the catalogue default"))
    allow_file = os.path.join(root, "tools", "lint", "or-fallbacks.allow")
    allowed = set()
    if os.path.exists(allow_file):
        for raw in open(allow_file, encoding="utf-8"):
            raw = raw.split("#")[0].strip()
            if raw:
                path, name = raw.split()
                allowed.add((path, name))
    if listing:
        for rel, line, name, why in found:
            print(f"{rel} {name}")
        return 0
    failures = [x for x in found if (x[0], x[2]) not in allowed]
    stale = allowed - {(x[0], x[2]) for x in found}
    for rel, line, name, why in failures:
        print(f"{rel}:{line}: {why}")
    for path, name in sorted(stale):
        print(f"tools/lint/or-fallbacks.allow: {path} {name} is fixed: remove it from the list")
    print(f"{len(found)} fallback(s) repeating a catalogue default or naming no keyword, "
          f"{len(found) - len(failures)} of them listed as still to remove")
    return 1 if failures or stale else 0


if __name__ == "__main__":
    sys.exit(main())
