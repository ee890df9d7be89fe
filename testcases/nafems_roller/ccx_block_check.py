#!/usr/bin/python3
"""Independent check of uy(B) (README.md): CalculiX 2.20 (CPE4, plane strain, no contact) on the
block of nafems_roller.msh alone, loaded on its top by the Hertz pressure p(x) = p0 sqrt(1 - x^2/a^2)
of the force the contact carries in nafems_roller (P = 2 x 17 498.24 N/mm): consistent nodal forces
(the integral of p N_i over the top edges, 200-point Gauss-Legendre per edge), base fixed, DX = 0 on
the axis. Prints uy(B) beside stella's contact result.
Usage: /usr/bin/python3 testcases/nafems_roller/ccx_block_check.py [work directory]"""
import math
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "tools/bench/contact-calculix"))
import ccx_deck  # noqa: E402

E1, E2, NU, R = 70000.0, 210000.0, 0.3, 50.0
P = 2 * 17498.2413125  # N/mm, what the contact carries (the spring takes the rest of 35 000)


def main():
    work = Path(sys.argv[1] if len(sys.argv) > 1 else "/tmp/nafems_roller_ccx")
    work.mkdir(parents=True, exist_ok=True)
    estar = 1.0 / ((1 - NU**2) / E1 + (1 - NU**2) / E2)
    a = math.sqrt(4 * P * R / (math.pi * estar))
    p0 = 2 * P / (math.pi * a)
    mesh = ccx_deck.Mesh(str(HERE / "nafems_roller.msh"))
    xg, wg = np.polynomial.legendre.leggauss(200)
    forces = {}
    for _t, cells in mesh.groups["BLOC_TOP"]:
        for n1, n2 in cells:
            x1, x2 = mesh.points[n1][0], mesh.points[n2][0]
            xs = 0.5 * (x1 + x2) + 0.5 * (x2 - x1) * xg
            p = p0 * np.sqrt(np.clip(1 - (xs / a) ** 2, 0, None))
            w = 0.5 * abs(x2 - x1) * wg
            t = (xs - x1) / (x2 - x1)
            forces[n1] = forces.get(n1, 0.0) + np.sum(w * p * (1 - t))
            forces[n2] = forces.get(n2, 0.0) + np.sum(w * p * t)
    b = int(mesh.group_nodes("B")[0])
    body = ["*BOUNDARY", "BLOC_BASE, 1, 2, 0.", "BLOC_AXE, 1, 1, 0.", "*STEP", "*STATIC", "*CLOAD"]
    body += [f"{n + 1}, 2, {-f:.15g}" for n, f in sorted(forces.items()) if f > 0]
    body += ["*NODE PRINT, NSET=NB", "U", "*END STEP"]
    deck = work / "block.inp"
    ccx_deck.write_deck(mesh, deck, ["BLOC"], {"BLOC": (E1, NU)}, ["BLOC_BASE", "BLOC_AXE"], {},
                        "*NSET, NSET=NB\n" + f"{b + 1}\n" + "\n".join(body))
    subprocess.run(["ccx", "block"], cwd=work, check=True, stdout=subprocess.DEVNULL)
    dat = (work / "block.dat").read_text().split()
    uy = float(dat[dat.index(str(b + 1)) + 2])
    print(f"P = {P:.3f} N/mm, a = {a:.4f} mm, p0 = {p0:.2f} MPa, sum of the nodal forces = {sum(forces.values()):.3f}")
    print(f"uy(B): CalculiX, block under the Hertz pressure = {uy:.6f}; stella, contact = -1.271768; NAFEMS -1.3069")


if __name__ == "__main__":
    main()
