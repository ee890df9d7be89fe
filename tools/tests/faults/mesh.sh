#!/usr/bin/env bash
# Writes a Gmsh 2.2 mesh of the unit square cut into N x N QUAD4, groups BOTTOM, TOP (edges)
# and ALL (the cells): mesh.sh N > square.msh
n="$1"
awk -v n="$n" 'BEGIN {
  print "$MeshFormat\n2.2 0 8\n$EndMeshFormat"
  print "$PhysicalNames\n3\n1 1 \"BOTTOM\"\n1 2 \"TOP\"\n2 3 \"ALL\"\n$EndPhysicalNames"
  print "$Nodes"; print (n + 1) * (n + 1)
  for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) printf "%d %.12g %.12g 0\n", j * (n + 1) + i + 1, i / n, j / n
  print "$EndNodes"
  print "$Elements"; print 2 * n + n * n
  k = 0
  for (i = 0; i < n; i++) printf "%d 1 2 1 1 %d %d\n", ++k, i + 1, i + 2
  for (i = 0; i < n; i++) printf "%d 1 2 2 2 %d %d\n", ++k, n * (n + 1) + i + 1, n * (n + 1) + i + 2
  for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
    a = j * (n + 1) + i + 1
    printf "%d 3 2 3 3 %d %d %d %d\n", ++k, a, a + 1, a + n + 2, a + n + 1
  }
  print "$EndElements"
}'
