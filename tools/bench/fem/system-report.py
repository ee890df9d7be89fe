#!/usr/bin/python3
"""Formats the key=value lines of stella-bench-system (run-system-bench.sh) as the markdown
tables of doc/bench/fem-performance.md: one row per run (phase CPU-clock seconds and peak MB),
then the log-log slope of the total time against the DOFs per case and solver (least squares
over the sizes run), and the share of the phases other than the factorisation and the solve.

Usage: /usr/bin/python3 tools/bench/fem/system-report.py RESULTS.txt
"""
import math
import sys
from collections import defaultdict


def parse(path):
    rows = []
    for line in open(path):
        if "FAILED" in line or "=" not in line:
            continue
        r = dict(kv.split("=", 1) for kv in line.split())
        rows.append(r)
    return rows


def slope(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den > 0 else float("nan")


def main():
    rows = parse(sys.argv[1])
    print("| case | solver (backend) | check | DOFs | numbering | assembly | factorise | solve | post | total "
          "| other share | peak MB after assembly | peak MB |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    groups = defaultdict(list)
    for r in rows:
        f = lambda k: float(r[k])
        print(f"| {r['case']} n={r['divisions']} | {r['solver']} ({r['backend']}) | {'yes' if r['check'] == '1' else 'no'} "
              f"| {r['dofs']} | {f('t_numbering'):.3f} | {f('t_assembly'):.3f} | {f('t_factorise'):.3f} "
              f"| {f('t_solve'):.3f} | {f('t_post'):.3f} | {f('total'):.2f} | {100 * f('other_share'):.0f} % "
              f"| {f('mem_assembly'):.0f} | {f('mem_post'):.0f} |")
        groups[(r["case"], r["solver"], r["check"])].append(r)
    print()
    print("| case | solver | check | sizes (DOFs) | slope of total time vs DOFs | slope of assembly + post |")
    print("|---|---|---|---|---|---|")
    for (case, solver, check), g in sorted(groups.items()):
        if len(g) < 2:
            continue
        g.sort(key=lambda r: int(r["dofs"]))
        dofs = [float(r["dofs"]) for r in g]
        total = [float(r["total"]) for r in g]
        other = [float(r["t_assembly"]) + float(r["t_post"]) + 1e-9 for r in g]
        print(f"| {case} | {solver} | {'yes' if check == '1' else 'no'} | {', '.join(r['dofs'] for r in g)} "
              f"| {slope(dofs, total):.2f} | {slope(dofs, other):.2f} |")


if __name__ == "__main__":
    main()
