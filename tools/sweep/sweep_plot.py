#!/usr/bin/python3
"""The figure of `stella sweep` (doc/sweep.md), drawn from its sweep.csv.

Usage: sweep_plot.py sweep.csv sweep.png

Left: the error (column `error`) against the median time (column `time_s`: wall or CPU), log-log, one series per value of
the column `series`, the Pareto front (column `pareto`, computed by stella) drawn as a staircase
and its points named. Right: the error against the mesh size (column `mesh_size`) with the
observed order of each series (least-squares slope of log error on log size).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

FLOOR = 1e-16  # an error of exactly 0 is drawn here (log axes)


def number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def plain_ticks(axis):
    """Log-axis labels as plain numbers (0.5, 20); on less than a decade the minor ticks carry them."""
    low, high = axis.get_view_interval()
    formatter = matplotlib.ticker.FuncFormatter(lambda v, _: "%g" % v)
    axis.set_major_formatter(formatter)
    if low > 0 and high / low < 10:
        axis.set_minor_formatter(formatter)
    else:
        axis.set_minor_formatter(matplotlib.ticker.NullFormatter())


def observed_order(sizes, errors):
    """Slope of log(error) against log(size), least squares; None below two distinct sizes."""
    points = [(math.log(h), math.log(max(e, FLOOR))) for h, e in zip(sizes, errors) if h > 0]
    if len({p[0] for p in points}) < 2:
        return None
    n = len(points)
    mx = sum(p[0] for p in points) / n
    my = sum(p[1] for p in points) / n
    sxx = sum((p[0] - mx) ** 2 for p in points)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in points)
    return sxy / sxx


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    done = [r for r in rows if r.get("finished") == "yes" and number(r.get("error")) is not None
            and number(r.get("time_s")) is not None]
    failed = [r for r in rows if r.get("finished") != "yes"]
    series = []
    for r in done:
        if r["series"] not in series:
            series.append(r["series"])
    names = {r.get("error_of", "") for r in done}
    of = names.pop() if len(names) == 1 else ""  # several: the largest error of each run
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5.5))
    markers = "osD^v<>pP*hX"
    for k, name in enumerate(series):
        mine = [r for r in done if r["series"] == name]
        mine.sort(key=lambda r: (number(r.get("mesh_size")) or 0.0, number(r["time_s"])))
        t = [number(r["time_s"]) for r in mine]
        e = [max(number(r["error"]), FLOOR) for r in mine]
        left.plot(t, e, marker=markers[k % len(markers)], linestyle="-", label=name, alpha=0.8)
        sizes = [number(r.get("mesh_size")) for r in mine]
        if all(h is not None for h in sizes) and sizes:
            order = observed_order(sizes, e)
            label = name if order is None else "%s (order %.2f)" % (name, order)
            right.plot(sizes, e, marker=markers[k % len(markers)], linestyle="-", label=label, alpha=0.8)
    front = sorted((r for r in done if r.get("pareto") == "yes"), key=lambda r: number(r["time_s"]))
    if front:
        t = [number(r["time_s"]) for r in front]
        e = [max(number(r["error"]), FLOOR) for r in front]
        left.step(t, e, where="post", color="black", linewidth=2.2, alpha=0.35, label="Pareto front")
        for k, (r, x, y) in enumerate(zip(front, t, e)):  # alternate sides: neighbours stay readable
            left.annotate(r["label"], (x, y), textcoords="offset points", xytext=(6, 4 if k % 2 == 0 else -11),
                          fontsize=7)
    left.set_xscale("log")
    left.set_yscale("log")
    time_of = done[0].get("time_of", "wall") if done else "wall"
    left.set_xlabel("%s time of the run (s, median)" % ("CPU" if time_of == "cpu" else "wall"))
    left.set_ylabel("relative error of " + of if of else "largest relative error of the run's tests")
    title = "error against time"
    if failed:
        title += " (%d run(s) failed: see the table)" % len(failed)
    left.set_title(title)
    left.grid(True, which="both", alpha=0.3)
    plain_ticks(left.xaxis)
    if series:
        left.legend(fontsize=7)
    if right.lines:
        right.set_xscale("log")
        right.set_yscale("log")
        right.set_xlabel("mesh size")
        right.set_ylabel("relative error")
        right.set_title("error against mesh size (observed order)")
        right.grid(True, which="both", alpha=0.3)
        plain_ticks(right.xaxis)
        right.legend(fontsize=7)
    else:
        right.axis("off")
        right.text(0.5, 0.5, "no mesh_size in the sweep file", ha="center", va="center")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: sweep_plot.py sweep.csv sweep.png")
    main(sys.argv[1], sys.argv[2])
