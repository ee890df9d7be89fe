#!/bin/bash
# One performance run of MECA_STATIQUE through the real path: the `stella` executable runs a .comm
# through an .export (LIRE_MAILLAGE of a Gmsh mesh made by make-box-mesh.py, AFFE_MODELE, clamped
# face x = 0 by AFFE_CHAR_CINE, FORCE_FACE / FORCE_CONTOUR FY = 1 on x = 1, E = 210000, NU = 0.3),
# under /usr/bin/time -v for the peak memory. Prints one "key=value ..." line: the phase times
# and the peak memory the message file reports, the job's elapsed time and maximum RSS.
#
#   run-stella-bench.sh STELLA CASE N METHODE WORKDIR [EXTRA [LABEL]]
#     CASE     hexa8 | tetra10 | quad4 | quad8 (see make-box-mesh.py)
#     METHODE  MUMPS | MULT_FRONT | LDLT | GCPC | PETSC_GAMG | PETSC_BOOMER (PETSC: ALGORITHME='CG',
#              PRE_COND='GAMG' or 'BOOMER', RESI_RELA=1e-8; iterations= in the output line)
#     EXTRA    more SOLVEUR keywords, e.g. "ACCELERATION='FR'" or
#              "PRE_COND='LDLT_SP', RESI_RELA=1e-8"; LABEL names the study's files (default METHODE)
#   MEMORY_LIMIT=MiB in the environment adds "P memory_limit" to the export.
set -euo pipefail
stella=$1
case_name=$2
n=$3
method=$4
work=$5
extra=${6:-}
label=${7:-$method}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
mesh="$work/${case_name}_${n}.msh"
if [[ ! -s $mesh ]]; then
  /usr/bin/python3 "$here/make-box-mesh.py" "$case_name" "$n" "$mesh"
fi
study="$work/${case_name}_${n}_${label}"
case $method in
  PETSC_GAMG | PETSC_BOOMER) solveur="METHODE='PETSC', ALGORITHME='CG', PRE_COND='${method#PETSC_}', RESI_RELA=1.0e-8" ;;
  *) solveur="METHODE='$method'" ;;
esac
case $case_name in
  hexa8 | tetra10)
    modelling=3D
    fixed="DX=0.0, DY=0.0, DZ=0.0"
    load="FORCE_FACE=_F(GROUP_MA='XMAX', FY=1.0)"
    ;;
  *)
    modelling=D_PLAN
    fixed="DX=0.0, DY=0.0"
    load="FORCE_CONTOUR=_F(GROUP_MA='XMAX', FY=1.0)"
    ;;
esac
cat > "$study.comm" << EOF
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='$modelling'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=210000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=ACIER))
BLOC = AFFE_CHAR_CINE(MODELE=MO, MECA_IMPO=_F(GROUP_MA='XMIN', $fixed))
CHARGE = AFFE_CHAR_MECA(MODELE=MO, $load)
RESU = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BLOC), _F(CHARGE=CHARGE)),
                     SOLVEUR=_F($solveur${extra:+, $extra}))
FIN()
EOF
cat > "$study.export" << EOF
P testlist bench
F comm $(basename "$study").comm D 1
F msh $(basename "$mesh") D 20
F mess $(basename "$study").mess R 6
EOF
if [[ -n ${MEMORY_LIMIT:-} ]]; then
  echo "P memory_limit $MEMORY_LIMIT" >> "$study.export"
fi
/usr/bin/time -v -o "$study.time" "$stella" run "$study.export" --quiet --work-dir "$study.work" \
  --output-dir "$work" > /dev/null 2>&1 || true
mess="$study.mess"
phases=$(grep -m1 "phases (s):" "$mess")
num() { echo "$phases" | grep -oE "$1 [0-9.]+" | head -1 | awk '{print $2}'; }
dofs=$(grep -m1 "equations:" "$mess" | sed -E 's/.*\(([0-9]+) displacement DOFs.*/\1/')
backend=$(grep -m1 "linear solver:" "$mess" | sed -E 's/.*linear solver: ([A-Z]+).*/\1/')
peak=$(grep -m1 "peak memory:" "$mess" | sed -E 's/.*peak memory: ([0-9.]+) MB.*/\1/')
mecaTime=$(grep -E "^  [0-9]+ +MECA_STATIQUE" "$mess" | awk '{print $(NF-1)}')
readTime=$(grep -E "^  [0-9]+ +LIRE_MAILLAGE" "$mess" | awk '{print $(NF-1)}')
wall=$(grep "Elapsed (wall clock)" "$study.time" | awk '{print $NF}')
rss=$(grep "Maximum resident set size" "$study.time" | awk '{print $NF}')
cpu=$(awk -F': ' '/User time|System time/ {s += $2} END {printf "%.1f", s}' "$study.time")
maxu=$(grep -m1 "max |u|" "$mess" | sed -E 's/.*max \|u\| = ([-0-9.e+]+).*/\1/')
iterations=$( (grep -m1 -oE "[0-9]+ conjugate gradient iterations" "$mess" || true) | awk '{print $1}')
if [[ -z $iterations ]]; then
  iterations=$( (grep -m1 "iterative solver:" "$mess" || true) | sed -E 's/.*iterative solver: ([0-9]+) .*/\1/')
fi
summary=$( (grep -m1 "solver summary:" "$mess" || true) | sed -E 's/.*solver summary: //; s/ /_/g')
echo "case=$case_name n=$n solver=$label backend=$backend dofs=$dofs numbering=$(num numbering)" \
  "assembly=$(num assembly) factorisation=$(num factorisation) solve=$(num solve) post=$(num post)" \
  "total=$(num total) peak_mb=$peak meca_statique=$mecaTime lire_maillage=$readTime job_wall=$wall" \
  "max_rss_kb=$rss cpu_s=$cpu max_u=$maxu iterations=${iterations:-0} summary=${summary:--}"
