#!/usr/bin/env bash
# The README's "Running your own study" works as written for a study without TEST_RESU: the
# export block of that section is taken from README.md verbatim, beside a plain study (a bar in
# traction, no test) and its MED mesh; the run must end OK with exit 0, the result files come
# back where the export says, and the MED results read by meshio hold the closed form.
# Usage: readme-study.sh PATH/TO/stella SOURCE_DIR
set -uo pipefail
source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/lib.sh"
stella="$(readlink -f "$1")"
readme="$(readlink -f "$2")/README.md"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cd "$dir"

# The first fenced block after the section's heading, as the user copies it.
awk '/^## Running your own study/ {section = 1; next}
     section && /^```/ {if (inside) exit; inside = 1; next}
     inside {print}' "$readme" > study.export
check "README: the section has an export block" grep -q '^F comm study.comm D 1$' study.export

# mesh.med: the ASTER bar of lib.sh written as MED by stella (a study of its own, before).
write_bar_mesh
printf 'DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='"'"'ASTER'"'"', UNITE=20)\nIMPR_RESU(FORMAT='"'"'MED'"'"', UNITE=80, RESU=_F(MAILLAGE=MA))\nFIN()\n' > convert.comm
"$stella" run convert.comm --quiet --unit 20=bar.mail --unit 80=mesh.med >out.txt 2>&1
check "mesh.med written" test -s mesh.med

write_bar_study study.comm
sed -i "s/LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)/LIRE_MAILLAGE(UNITE=20)/" study.comm
cat >> study.comm <<'COMM'
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RES))
FIN()
COMM
"$stella" run study.export --quiet >out.txt 2>err.txt; code=$?
check "README study: exit 0" test $code -eq 0
check "README study: job diagnostic OK" grep -q -- "--- DIAGNOSTIC JOB : OK" results/study.mess
check "README study: result file back" test -e results/study.resu
check "README study: MED results back" test -s results/study.rmed

# Plane strain, traction 100 along x, free in y: u_x = (1 - nu^2) 100 x / E, u_y = -nu (1 + nu)
# 100 y / E (linear cells hold it exactly). Read with doc/post.md's read_med, copied from the page
# (meshio alone cannot read SIEF_ELGA given on the QUAD4 and not on the pressure edge).
awk '/^def read_med/ {inside = 1} inside && /^```/ {exit} inside {print}' "$(dirname "$readme")/doc/post.md" > read_med.py
cat > depl.py <<'PY'
import sys, numpy as np, h5py, meshio
import meshio.med._med as med
exec(open("read_med.py").read())
m = read_med(sys.argv[1])
d = m.point_data["RES_____DEPL"]
x, y = m.points[:, 0], m.points[:, 1]
assert np.allclose(d[:, 0], (1 - 0.3**2) * 100.0 * x / 200000.0, rtol=1e-10, atol=1e-15), d
assert np.allclose(d[:, 1], -0.3 * 1.3 * 100.0 * y / 200000.0, rtol=1e-10, atol=1e-15), d
types = [c.type for c in m.cells]
sief = m.cell_data["RES_____SIEF_ELGA"]
assert np.isnan(sief[types.index("line")]).all(), sief
quad = sief[types.index("quad")]
assert np.allclose(quad[..., 0], 100.0) and np.allclose(quad[..., 1], 0.0, atol=1e-9), quad
print("OK")
PY
check "README study: DEPL and SIEF_ELGA read by meshio (doc/post.md read_med) = closed form" /usr/bin/python3 depl.py results/study.rmed
# The quick run the README gives next: `stella run study.comm --unit 20=mesh.med`, results beside
# the command file.
mkdir quick && cp study.comm mesh.med quick/
(cd quick && "$stella" run study.comm --unit 20=mesh.med --quiet >out.txt 2>&1); code=$?
check "README quick run: exit 0" test $code -eq 0
check "README quick run: study.mess OK" grep -q -- "--- DIAGNOSTIC JOB : OK" quick/study.mess
check "README quick run: study.resu and study.rmed" test -e quick/study.resu -a -s quick/study.rmed
[ $fails -eq 0 ]
