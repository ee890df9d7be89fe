#!/usr/bin/env python3
"""Counts the clockwise and counter-clockwise face cells of Gmsh 2.2 meshes (signed area of the
vertex polygon), to show that the meshes of this case are numbered clockwise."""
import sys

VERTICES = {2: 3, 3: 4, 9: 3, 16: 4, 10: 4}  # TRIA3, QUAD4, TRIA6, QUAD8, QUAD9


def count(path):
    lines = open(path).read().split('\n')
    i = lines.index('$Nodes')
    n = int(lines[i + 1])
    xy = {}
    for line in lines[i + 2:i + 2 + n]:
        f = line.split()
        xy[int(f[0])] = (float(f[1]), float(f[2]))
    i = lines.index('$Elements')
    cw = ccw = 0
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        f = [int(v) for v in line.split()]
        if f[1] not in VERTICES:
            continue
        nodes = f[3 + f[2]:][:VERTICES[f[1]]]
        p = [xy[k] for k in nodes]
        area = sum(p[k][0] * p[(k + 1) % len(p)][1] - p[(k + 1) % len(p)][0] * p[k][1] for k in range(len(p)))
        if area < 0:
            cw += 1
        else:
            ccw += 1
    return cw, ccw


for path in sys.argv[1:]:
    cw, ccw = count(path)
    print(f'{path}: {cw} clockwise, {ccw} counter-clockwise face cells')
