#!/usr/bin/python3
"""Contact pressure of the NAFEMS roller against Hertz: p_i = RN_i / A_i on the slave nodes (A_i =
half the adjacent slave edge lengths, CONT_NOEU of the .resu files of nafems_roller and
nafems_roller_mu01), and p(x) = p0 sqrt(1 - x^2/a^2) for P = 2 x 17 498.24 N/mm.
Usage: /usr/bin/python3 plot_pressure.py <dir with nafems_roller.resu [and nafems_roller_mu01.resu]>
       [output.png] (default: pressure.png next to this script)"""
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

HERE = Path(__file__).resolve().parent


def tributary():
    m = meshio.read(HERE / "nafems_roller.msh")
    tag = m.field_data["BLOC_TOP"][0]
    area, xs = {}, {}
    for block, phys in zip(m.cells, m.cell_data["gmsh:physical"]):
        if block.type != "line":
            continue
        for n1, n2 in block.data[phys == tag]:
            h = abs(m.points[n2][0] - m.points[n1][0])
            for n in (n1, n2):
                area[f"N{n + 1}"] = area.get(f"N{n + 1}", 0.0) + h / 2
                xs[f"N{n + 1}"] = m.points[n][0]
    return area, xs


def pressures(resu, area, xs):
    text = resu.read_text().split("CHAMP CONT_NOEU")[-1].splitlines()
    header = text[1].split()
    rn = header.index("RN")
    pts = [(xs[r[0]], float(r[rn]) / area[r[0]]) for r in (line.split() for line in text[2:] if line.startswith(" N"))]
    return np.array(sorted(pts))


def main():
    runs = Path(sys.argv[1])
    out = Path(sys.argv[2]) if len(sys.argv) > 2 else HERE / "pressure.png"
    estar = 1.0 / (0.91 / 70000.0 + 0.91 / 210000.0)
    p_load = 2 * 17498.2413125
    a = math.sqrt(4 * p_load * 50.0 / (math.pi * estar))
    p0 = 2 * p_load / (math.pi * a)
    area, xs = tributary()
    x = np.linspace(0, a, 400)
    plt.figure(figsize=(7, 4.2))
    plt.plot(x, p0 * np.sqrt(1 - (x / a) ** 2), "k-", label=f"Hertz (a = {a:.3f} mm, p0 = {p0:.1f} MPa)")
    for name, mark, label in (("nafems_roller.resu", "o", "stella, discrete CONTRAINTE, mu = 0"),
                              ("nafems_roller_mu01.resu", "x", "stella, discrete penalised, mu = 0.1")):
        if (runs / name).exists():
            pts = pressures(runs / name, area, xs)
            pts = pts[pts[:, 0] <= 8.0]
            plt.plot(pts[:, 0], pts[:, 1], mark, ms=4, label=label)
    plt.xlabel("x (mm)")
    plt.ylabel("contact pressure RN / A (MPa)")
    plt.title("NAFEMS benchmark 1, cylindrical roller (half model)")
    plt.legend()
    plt.grid(alpha=0.3)
    plt.tight_layout()
    plt.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
