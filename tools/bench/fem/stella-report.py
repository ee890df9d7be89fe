#!/usr/bin/python3
"""Markdown tables and a plot from the lines of run-stella-bench.sh (doc/bench/fem-performance.md).

    stella-report.py RESULTS [PLOT.png]

Table 1: per run, the phase times of MECA_STATIQUE from the message file, the share outside the
factorisation and the solve, the peak memory (the log's getrusage and /usr/bin/time's maximum
RSS), the job's CPU seconds (user + system) and wall time. Table 2: per case and solver, the
least-squares slope against log(DOFs) of log(total), of the phases outside the factorisation and
the solve, and of the job's CPU time.
"""

import math
import sys


def read(path):
    runs = []
    with open(path) as f:
        for line in f:
            if not line.startswith("case="):
                continue
            r = dict(item.split("=", 1) for item in line.split())
            for key in ("numbering", "assembly", "factorisation", "solve", "post", "total"):
                r[key] = float(r[key])
            r["dofs"] = int(r["dofs"])
            r["other"] = r["numbering"] + r["assembly"] + r["post"]
            runs.append(r)
    return runs


def slope(points):
    xs = [math.log(x) for x, _ in points]
    ys = [math.log(y) for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def main():
    runs = read(sys.argv[1])
    print("| case | DOFs | solver (backend) | numbering | assembly | factorisation | solve | post | total |"
          " outside fact.+solve | peak MB (log) | max RSS MB (time -v) | job CPU s (wall) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(runs, key=lambda r: (r["case"], r["dofs"], r["solver"])):
        print(f"| {r['case']} | {r['dofs']} | {r['solver']} ({r['backend']}) | {r['numbering']:.2f} |"
              f" {r['assembly']:.2f} | {r['factorisation']:.2f} | {r['solve']:.2f} | {r['post']:.2f} |"
              f" {r['total']:.2f} | {100 * r['other'] / r['total']:.1f} % | {r['peak_mb']} |"
              f" {int(r['max_rss_kb']) / 1024:.0f} | {r.get('cpu_s', '-')} ({r['job_wall']}) |")
    print()
    print("| case | solver | DOFs | slope of total | slope outside fact.+solve | slope of job CPU |")
    print("|---|---|---|---|---|---|")
    groups = {}
    for r in runs:
        groups.setdefault((r["case"], r["solver"]), []).append(r)
    for (case, solver), rs in sorted(groups.items()):
        rs.sort(key=lambda r: r["dofs"])
        if len(rs) < 2:
            continue
        print(f"| {case} | {solver} | {rs[0]['dofs']} - {rs[-1]['dofs']} |"
              f" {slope([(r['dofs'], r['total']) for r in rs]):.2f} |"
              f" {slope([(r['dofs'], r['other']) for r in rs]):.2f} |"
              f" {slope([(r['dofs'], float(r['cpu_s'])) for r in rs if 'cpu_s' in r]):.2f} |")
    if len(sys.argv) > 2:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 5))
        for (case, solver), rs in sorted(groups.items()):
            style = "-" if solver == "MUMPS" else "--"
            ax.loglog([r["dofs"] for r in rs], [r["total"] for r in rs], style, marker="o",
                      label=f"{case} {solver} (slope {slope([(r['dofs'], r['total']) for r in rs]):.2f})")
        ax.set_xlabel("DOFs")
        ax.set_ylabel("MECA_STATIQUE total of the phases (s)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
