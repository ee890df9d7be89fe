#!/usr/bin/python3
"""Hertz contact pressure profile from a stella result, against the closed form.

Reads CONT_NOEU of the slave nodes from the IMPR_RESU FORMAT='RESULTAT' block in the .resu file
and their coordinates from the Gmsh mesh, converts the nodal contact forces RN into pressures
p_i = RN_i / A_i (A_i = the integral of the node's shape function over the slave edges: half the
adjacent lengths in plane strain (per unit thickness); sum of l (2 r_i + r_j) / 6 over the adjacent
edges in AXIS, per radian like RN), and plots p(x) with the Hertz profile of the same total force
P = sum |RNY| (x 2 for the symmetric half model in plane strain, x 2 pi per radian in AXIS).
Usage: plot_pressure.py {dplan|axis} RESU MSH PNG
"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

E, NU, R = 210000.0, 0.3, 50.0
E_STAR = E / (2.0 * (1.0 - NU * NU))  # two identical bodies


def read_cont_noeu(path):
    """Last CONT_NOEU block of the file: {node name: {component: value}}."""
    lines = open(path).read().splitlines()
    starts = [i for i, l in enumerate(lines) if "CHAMP CONT_NOEU" in l]
    if not starts:
        sys.exit(f"no CONT_NOEU block in {path}")
    i = starts[-1] + 1
    while not lines[i].split() or lines[i].split()[0] != "NOEUD":
        i += 1
    names = lines[i].split()[1:]
    rows = {}
    for line in lines[i + 1:]:
        parts = line.split()
        if len(parts) != len(names) + 1:
            break
        if all(v == "-" for v in parts[1:]):
            continue  # a node outside the partial field
        rows[parts[0]] = {n: (float(v) if v != "-" else 0.0) for n, v in zip(names, parts[1:])}
    return rows


def main():
    mode, resu, msh, png = sys.argv[1:5]
    mesh = meshio.read(msh)
    rows = read_cont_noeu(resu)
    xy = np.array([mesh.points[int(n[1:]) - 1][:2] for n in rows])
    order = np.argsort(xy[:, 0])
    xy = xy[order]
    vals = [rows[n] for n in np.array(list(rows))[order]]
    rn = np.array([v["RN"] for v in vals])
    seg = np.linalg.norm(np.diff(xy, axis=0), axis=1)
    area = np.zeros(len(xy))
    for k, l in enumerate(seg):
        if mode == "axis":
            ri, rj = xy[k, 0], xy[k + 1, 0]
            area[k] += l * (2 * ri + rj) / 6.0
            area[k + 1] += l * (2 * rj + ri) / 6.0
        else:
            area[k] += l / 2.0
            area[k + 1] += l / 2.0
    p = rn / area
    force = float(np.sum([abs(v["RNY"]) for v in vals]))
    if mode == "axis":
        total = 2.0 * math.pi * force
        a = (3.0 * total * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
        p0 = 3.0 * total / (2.0 * math.pi * a * a)
        label = f"F = 2 pi x {force:.6g} = {total:.6g} N"
    else:
        total = 2.0 * force
        a = math.sqrt(4.0 * total * R / (math.pi * E_STAR))
        p0 = 2.0 * total / (math.pi * a)
        label = f"P = 2 x {force:.6g} = {total:.6g} N/mm"
    active = [v["CONT"] > 0 for v in vals]
    last = max(k for k, on in enumerate(active) if on)
    x_last = xy[last, 0]
    x_next = xy[last + 1, 0] if last + 1 < len(xy) else float("nan")
    print(f"{label}: a = {a:.6g} mm, p0 = {p0:.6g} MPa")
    print(f"computed p(0) = {p[0]:.6g} MPa (error {100 * (p[0] - p0) / p0:+.2f} %), "
          f"last active node x = {x_last:.4g}, next {x_next:.4g} (a inside: {x_last <= a <= x_next or abs(a - x_last) < x_next - x_last})")
    x = np.linspace(0.0, a, 200)
    plt.figure(figsize=(6.4, 4.0))
    plt.plot(x, p0 * np.sqrt(1.0 - (x / a) ** 2), "k-", label="Hertz closed form")
    keep = xy[:, 0] <= 1.6 * a
    plt.plot(xy[keep, 0], p[keep], "o", ms=4, label="stella: RN / tributary " + ("area (per rad)" if mode == "axis" else "length"))
    plt.xlabel("r (mm)" if mode == "axis" else "x (mm)")
    plt.ylabel("contact pressure (MPa)")
    plt.title(("Sphere" if mode == "axis" else "Cylinder") + f" on a flat: {label}")
    plt.grid(alpha=0.3)
    plt.legend()
    plt.tight_layout()
    plt.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
