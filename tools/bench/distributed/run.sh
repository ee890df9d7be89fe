#!/bin/bash
# The distributed benchmark (doc/bench/distributed.md, issue 21): a 3D elastic study (MECA_STATIQUE
# of a clamped HEXA8 cube under a face load, tools/bench/fem/make-box-mesh.py) and a 3D contact
# study (two stacked HEXA8 blocks pressed together, discrete contact, tools/bench/contact-calculix/
# blocks3d.py) run with `mpirun -n 1` and `-n 2`. Each process runs under /usr/bin/time: its
# elapsed time and its peak resident memory. Prints one line per run:
#   study=... np=... wall_s=... rank_rss_mb=r0,r1 phases=... mumps=...
#
#   run.sh STELLA WORK [N_CUBE [NB NH]]   N_CUBE: cells per side of the cube (default 32: 107 811
#                                         DOFs), NB NH: of the two blocks (default 23 24)
#   NPS="1 2 4" in the environment: the process counts (default "1 2"), STUDIES="elastic" the
#   studies (default "elastic contact"); beyond the cores,
#   --oversubscribe: the times mean nothing then, MUMPS's flops per process (the load balance) do.
# OPENBLAS_NUM_THREADS=1 (one thread per process: the two processes use the two cores).
set -euo pipefail
stella=$(realpath "$1")
work=$(realpath -m "$2")
n=${3:-32}
nb=${4:-23}
nh=${5:-24}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
export OPENBLAS_NUM_THREADS=1
[[ -s $work/cube.msh ]] || /usr/bin/python3 "$here/../fem/make-box-mesh.py" hexa8 "$n" "$work/cube.msh"
[[ -s $work/blocks.msh ]] || /usr/bin/python3 "$here/../contact-calculix/blocks3d.py" "$nb" "$nh" "$work/blocks.msh"

cat > "$work/elastic.comm" << 'COMM'
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=210000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=ACIER))
BLOC = AFFE_CHAR_CINE(MODELE=MO, MECA_IMPO=_F(GROUP_MA='XMIN', DX=0.0, DY=0.0, DZ=0.0))
CHARGE = AFFE_CHAR_MECA(MODELE=MO, FORCE_FACE=_F(GROUP_MA='XMAX', FY=1.0))
RESU = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BLOC), _F(CHARGE=CHARGE)),
                     SOLVEUR=_F(METHODE='MUMPS'))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL', GROUP_NO='XMAX'))
FIN()
COMM
cat > "$work/contact.comm" << 'COMM'
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('BAS', 'HAUT'), PHENOMENE='MECANIQUE', MODELISATION='3D'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=210000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='SYM_X', DX=0.0), _F(GROUP_MA='SYM_Y', DY=0.0),
                                          _F(GROUP_MA='BAS_Z0', DZ=0.0), _F(GROUP_MA='HAUT_Z1', DZ=-0.02)))
RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='BAS_HAUT', GROUP_MA_ESCL='HAUT_BAS'))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CL, FONC_MULT=RAMPE),
                     INCREMENT=_F(LIST_INST=L_INST))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL', GROUP_NO='HAUT_BAS'))
FIN()
COMM

for study in ${STUDIES:-elastic contact}; do
  mesh=cube.msh
  [[ $study == contact ]] && mesh=blocks.msh
  for np in ${NPS:-1 2}; do
    tag="$study.np$np"
    cat > "$work/$tag.export" << EXP
F comm $study.comm D 1
F msh $mesh D 20
F mess $tag.mess R 6
F resu $tag.resu R 8
EXP
    rm -f "$work/$tag".time.*
    launcher=(mpirun -n "$np" --oversubscribe)
    [[ $(id -u) == 0 ]] && launcher+=(--allow-run-as-root)
    start=$(date +%s.%N)
    "${launcher[@]}" sh -c 'exec /usr/bin/time -f "%e %M" -o "$0.$OMPI_COMM_WORLD_RANK" "$@"' \
      "$work/$tag.time" "$stella" run "$work/$tag.export" --quiet > "$work/$tag.out" 2>&1 || true
    end=$(date +%s.%N)
    rss=$(for f in "$work/$tag".time.*; do awk '{printf "%.0f", $2 / 1024}' "$f"; echo -n ","; done)
    phases=$(grep -m1 "phases (s):" "$work/$tag.mess" | sed 's/^ *//' | tr -s ' ' || true)
    mumps=$(grep "MUMPS in core\|MUMPS out of core" "$work/$tag.mess" | tail -1 | sed 's/^ *//' | tr -s ' ' || true)
    diag=$(grep -o "stella: diagnostic [A-Z_<>]*" "$work/$tag.out" | head -1)
    echo "study=$study np=$np wall_s=$(echo "$end - $start" | bc) rank_rss_mb=${rss%,} $diag | $phases | $mumps"
  done
done
# The two runs' printed displacements (IMPR_RESU of the loaded face, the slave face) compared.
for study in ${STUDIES:-elastic contact}; do
  /usr/bin/python3 - "$work/$study.np1.resu" "$work/$study.np2.resu" << 'PY'
import re, sys
numbers = lambda path: [float(x) for x in re.findall(r"[-+]?\d\.\d+[eE][-+]\d+", open(path).read())]
a, b = numbers(sys.argv[1]), numbers(sys.argv[2])
scale = max(abs(x) for x in a) if a else 1.0
diff = max((abs(x - y) for x, y in zip(a, b)), default=float("nan"))
print(f"{sys.argv[1]}: {len(a)} values, np2 vs np1: max |difference| / max |value| = {diff / scale:.1e}"
      + ("" if len(a) == len(b) else f" (counts differ: {len(a)} and {len(b)})"))
PY
done
