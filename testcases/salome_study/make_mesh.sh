#!/usr/bin/env bash
# Meshes salome_study.geo with Gmsh (clockwise cells) and writes salome_study.med through
# stella (LIRE_MAILLAGE GMSH -> IMPR_RESU MED), the connectivity kept as Gmsh wrote it.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
stella="${STELLA:-$here/../../build/bin/stella}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
gmsh -2 "$here/salome_study.geo" -format msh22 -o "$tmp/mesh.msh" >/dev/null
cat > "$tmp/convert.comm" <<'COMM'
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=19)
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MA))
FIN()
COMM
"$stella" run "$tmp/convert.comm" --unit 19="$tmp/mesh.msh" --quiet
cp "$tmp/convert.rmed" "$here/salome_study.med"
echo "wrote $here/salome_study.med"
