#!/usr/bin/env bash
# Bad inputs that runs used to accept (issue 22): each case writes a small study, runs stella on
# it and checks the located error (or warning), the exit code and what came back.
# Usage: faults-input.sh PATH/TO/stella CASE      (CASE: one of the functions case_* below)
set -uo pipefail
stella="$(readlink -f "$1")"
name="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
fails=0
check() { # description, condition...
  local what="$1"; shift
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; fails=$((fails + 1)); fi
}

# A plane-strain bar of two QUAD4 (LEFT fixed in X, BOTTOM in Y, RIGHT loaded).
write_mesh() {
  cat > bar.mail <<'MAIL'
TITRE
 bar of two QUAD4
FINSF
%
COOR_2D
N1 0 0
N2 1 0
N3 2 0
N4 0 1
N5 1 1
N6 2 1
FINSF
%
QUAD4
M1 N1 N2 N5 N4
M2 N2 N3 N6 N5
FINSF
%
SEG2
M3 N3 N6
FINSF
%
GROUP_MA
RIGHT
  M3
FINSF
%
GROUP_NO
LEFT
  N1
  N4
FINSF
%
GROUP_NO
BOTTOM
  N1
FINSF
%
FIN
MAIL
}

# The start of a study on the bar; $1 is the DEFI_MATERIAU ELAS content.
write_study_start() {
  cat > "$1" <<COMM
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(${2:-E=200000.0, NU=0.3}))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_NO='LEFT', DX=0.0), _F(GROUP_NO='BOTTOM', DY=0.0)),
                    PRES_REP=_F(GROUP_MA='RIGHT', PRES=-100.0))
COMM
}

run_study() { # comm file [extra export lines]: runs it with the mesh on unit 20
  local comm="$1"; shift
  local stem="${comm%.comm}"
  { printf 'F comm %s D 1\nF mail bar.mail D 20\nF mess %s.mess R 6\nF resu %s.resu R 8\n' "$comm" "$stem" "$stem"
    for line in "$@"; do printf '%s\n' "$line"; done; } > "$stem.export"
  "$stella" run "$stem.export" --quiet >out.txt 2>err.txt
  code=$?
}

case_list_reel_decreasing() {
  write_mesh
  write_study_start lr.comm
  cat >> lr.comm <<'COMM'
L = DEFI_LIST_REEL(VALE=(0.0, 0.5, 0.3, 1.0))
FIN()
COMM
  run_study lr.comm
  check "DEFI_LIST_REEL VALE not increasing: LIST_4" grep -q "LIST_4" lr.mess
  check "located at VALE, line 8" grep -q "lr.comm:8:20: error: VALE must increase strictly: value 3 (0.3) follows value 2 (0.5)" lr.mess
  check "exit code of an error (3)" test "$code" -eq 3
}

case_list_inst_repeated() {
  write_mesh
  write_study_start li.comm
  cat >> li.comm <<'COMM'
LI = DEFI_LIST_INST(DEFI_LIST=_F(VALE=(0.0, 1.0, 1.0, 2.0)))
FIN()
COMM
  run_study li.comm
  check "DEFI_LIST_INST repeated instant: LIST_INST_2 at VALE" grep -q "li.comm:8:34: error: the instants must increase strictly: 1 follows 1" li.mess
}

case_material_nan() {
  write_mesh
  write_study_start nan.comm "E=float('nan'), NU=0.3"
  echo "FIN()" >> nan.comm
  run_study nan.comm
  check "E=nan refused at E: MATER_4" grep -q "nan.comm:4:31: error: ELAS E = nan is not a finite number \[MATER_4\]" nan.mess
  write_study_start inf.comm "E=1e400, NU=0.3"
  echo "FIN()" >> inf.comm
  run_study inf.comm
  check "E=1e400 (inf) refused at E" grep -q "inf.comm:4:31: error: ELAS E = inf is not a finite number" inf.mess
  write_study_start nu.comm "E=200000.0, NU=0.5"
  echo "FIN()" >> nu.comm
  run_study nu.comm
  check "NU=0.5 refused at NU: MATER_2" grep -q "nu.comm:4:43: error: ELAS NU = 0.5: -1 < NU < 0.5" nu.mess
  write_study_start rho.comm "E=200000.0, NU=0.3, RHO=float('nan')"
  echo "FIN()" >> rho.comm
  run_study rho.comm
  check "RHO=nan refused at RHO: MATER_4" grep -q "rho.comm:4:51: error: ELAS RHO = nan is not a finite number" rho.mess
  write_study_start e0.comm "E=0.0, NU=0.3"
  echo "FIN()" >> e0.comm
  run_study e0.comm
  check "E=0 refused at E" grep -q "e0.comm:4:31: error: ELAS E = 0: E > 0 is expected" e0.mess
}

case_budget() {
  cat > loop.comm <<'COMM'
DEBUT()
total = 0
for i in range(10**15):
    total = total + i
FIN()
COMM
  "$stella" run loop.comm --quiet --max-operations 1000000 >out.txt 2>err.txt
  code=$?
  check "run: for over range(10**15) stops on the budget, LANG_BUDGET at the loop" grep -q "loop.comm:3:1: error: the evaluation budget of 1 000 000 operations" loop.mess
  check "run: the note names the loop" grep -q "in the for loop \`for i in range(10\*\*15)\` (line 3)" loop.mess
  check "run: exit code of an error (3)" test "$code" -eq 3
  "$stella" check loop.comm --max-operations 1000000 >out.txt 2>err.txt
  code=$?
  check "check: the same error" grep -q "loop.comm:3:1: error: the evaluation budget of 1 000 000 operations" err.txt
  check "check: exit 2" test "$code" -eq 2
  cat > memory.comm <<'COMM'
DEBUT()
kept = []
while True:
    kept.append([0.0] * 1000000)
FIN()
COMM
  "$stella" run memory.comm --quiet --max-memory 200 >out.txt 2>err.txt
  code=$?
  check "run: a while loop keeping 40 MiB per turn stops on a 200 MiB budget at the loop" grep -q "memory.comm:3:1: error: the values of the command file hold .* MiB, more than the budget of 200 MiB \[LANG_BUDGET\]" memory.mess
  check "run: the note says where it ran out" grep -q "the budget ran out at .*memory.comm:4:" memory.mess
  check "run: exit code of an error (3)" test "$code" -eq 3
}

"case_$name"
[ $fails -eq 0 ]
