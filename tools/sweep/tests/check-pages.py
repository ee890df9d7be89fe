#!/usr/bin/env python3
"""Checks the accuracy-cost pages (doc/accuracy-cost/, issue 18) against what makes them.

Usage: check-pages.py REPO [--testcases]

For every folder of doc/accuracy-cost/ with a README.md (a page):
  * the index doc/accuracy-cost/README.md links it (<page>/README.md), and README.md links the index;
  * it has exactly one sweep file, its sweep.csv, sweep.md and sweep.png;
  * its README gives the one command that makes them:
    build/bin/stella sweep doc/accuracy-cost/<page>/<file>.sweep --output-dir doc/accuracy-cost/<page>
  * the series of sweep.csv are those of the sweep file's [series] section (a table made by the
    sweep file as it is, not by an earlier one).
With --testcases: every folder of testcases/ whose command files test against a reference
(VALE_REFE) is named in the index (its table of cases and pages, or its list of cases without a page).
Exit 1 with one line per problem.
"""
import csv
import os
import re
import sys


def sweep_series(path):
    """The names of the [series] lines of a sweep file (NAME: ...), in order; None without [series]."""
    names, section = None, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            text = line.strip()
            if not text or text.startswith("#"):
                continue
            if text.startswith("[") and text.endswith("]"):
                section = text[1:-1].strip()
                if section == "series":
                    names = []
                continue
            if section == "series" and ":" in text:
                names.append(text.split(":", 1)[0].strip())
    return names


def check_pages(repo):
    problems = []
    root = os.path.join(repo, "doc", "accuracy-cost")
    index = open(os.path.join(root, "README.md"), encoding="utf-8").read()
    readme = open(os.path.join(repo, "README.md"), encoding="utf-8").read()
    if "doc/accuracy-cost/README.md" not in readme:
        problems.append("README.md does not link doc/accuracy-cost/README.md")
    pages = sorted(d for d in os.listdir(root) if os.path.isfile(os.path.join(root, d, "README.md")))
    if not pages:
        problems.append("no page in doc/accuracy-cost/")
    for page in pages:
        where = os.path.join(root, page)
        if f"({page}/README.md)" not in index:
            problems.append(f"doc/accuracy-cost/README.md does not link {page}/README.md")
        sweeps = sorted(f for f in os.listdir(where) if f.endswith(".sweep"))
        if len(sweeps) != 1:
            problems.append(f"{page}: {len(sweeps)} sweep files (one expected): {sweeps}")
            continue
        for out in ("sweep.csv", "sweep.md", "sweep.png"):
            if not os.path.isfile(os.path.join(where, out)):
                problems.append(f"{page}: no {out}")
        text = open(os.path.join(where, "README.md"), encoding="utf-8").read()
        command = (f"build/bin/stella sweep doc/accuracy-cost/{page}/{sweeps[0]} "
                   f"--output-dir doc/accuracy-cost/{page}")
        if command not in text:
            problems.append(f"{page}/README.md does not give the command '{command}'")
        names = sweep_series(os.path.join(where, sweeps[0]))
        table = os.path.join(where, "sweep.csv")
        if names is not None and os.path.isfile(table):
            with open(table, newline="", encoding="utf-8") as f:
                made = []
                for row in csv.DictReader(f):
                    if row["series"] not in made:
                        made.append(row["series"])
            if made != names:
                problems.append(f"{page}: the series of sweep.csv {made} are not those of {sweeps[0]} {names}: "
                                f"run the page's command again")
    return problems


def check_testcases(repo):
    problems = []
    index = open(os.path.join(repo, "doc", "accuracy-cost", "README.md"), encoding="utf-8").read()
    cases = os.path.join(repo, "testcases")
    for case in sorted(os.listdir(cases)):
        folder = os.path.join(cases, case)
        if not os.path.isdir(folder):
            continue
        referenced = False
        for name in os.listdir(folder):
            if name.endswith(".comm"):
                with open(os.path.join(folder, name), encoding="utf-8", errors="replace") as f:
                    if "VALE_REFE" in f.read():
                        referenced = True
                        break
        if referenced and not re.search(r"(?<![\w])" + re.escape(case) + r"(?![\w])", index):
            problems.append(f"testcases/{case} has references but doc/accuracy-cost/README.md does not name it: "
                            f"give it a page (or a row of one), or add it to the cases without a page and why")
    return problems


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 64
    repo = sys.argv[1]
    problems = check_testcases(repo) if "--testcases" in sys.argv[2:] else check_pages(repo)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
