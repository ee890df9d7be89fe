#!/usr/bin/env bash
# `stella check` equals the run (issue 15): over every command file of the repository (the test
# cases through their .export, the catalogue's example files, the language corpus, and the bad
# inputs below), check says valid if and only if the run does not stop on an input error.
#
# A run stops on an input error when its job diagnostic is <F>_SYNTAX_ERROR, or <F>_ERROR whose
# first error is not about the machine or the files around the study (ids in ENVIRONMENT: a data
# unit with no file, a mesh file that cannot be read, the work directory). A run that is still
# computing after RUN_SECONDS has passed every input check before computing: it counts as "no
# input error" (the test case's own ctest runs it to its end).
# Usage: check-equals-run.sh PATH/TO/stella REPOSITORY-ROOT [RUN_SECONDS]
set -uo pipefail
stella="$(readlink -f "$1")"
root="$(readlink -f "$2")"
run_seconds="${3:-20}"
work="$(mktemp -d)"
trap '[ -n "${KEEP_WORK:-}" ] || rm -rf "$work"' EXIT
ENVIRONMENT='^(UNIT_1|MESH_[0-9]+|MED_[0-9]+|GMSH_[0-9]+|RUN_[0-9]+|EXPORT_[0-9]+)$'

agree=0
disagree=0
environment_stops=0
n=0

# The first error id of a message file ("... [ID]" on the line after "error:").
first_error_id() {
  grep -o 'error: .*\[[A-Z0-9_]*\]' "$1" 2>/dev/null | head -1 | sed 's/.*\[\([A-Z0-9_]*\)\]$/\1/'
}
# The line of the first error of a message file or of check's output ("file:LINE:col: error:").
first_error_line() {
  grep -o ':[0-9]*:[0-9]*: error:' "$1" 2>/dev/null | head -1 | cut -d: -f2
}

# compare NAME CHECK-TARGET RUN-TARGET [--unit ...]
compare() {
  local name="$1" check_target="$2" run_target="$3"
  shift 3
  n=$((n + 1))
  local out="$work/$n"
  mkdir -p "$out"
  "$stella" check "$check_target" "$@" >/dev/null 2>"$out/check.err"
  local check_code=$?
  timeout "$run_seconds" "$stella" run --quiet --output-dir "$out" "$run_target" "$@" \
    >"$out/run.out" 2>&1 </dev/null
  local run_code=$?
  local mess
  mess="$(find "$out" -name '*.mess' | head -1)"
  local input_error=no why="exit $run_code"
  case $run_code in
  124) why="still computing after ${run_seconds} s" ;;
  2) input_error=yes why="<F>_SYNTAX_ERROR $(first_error_id "$mess")" ;;
  3)
    local id
    id="$(first_error_id "$mess")"
    why="<F>_ERROR $id"
    if [[ "$id" =~ $ENVIRONMENT ]]; then
      # The run stopped on its environment (a data file it lacks) at that line: what follows is
      # unknown to it, so check must find no error before that line.
      local stop check_line
      stop="$(first_error_line "$mess")"
      check_line="$(first_error_line "$out/check.err")"
      if [ -n "$stop" ] && [ -n "$check_line" ] && [ "$check_line" -gt "$stop" ]; then
        environment_stops=$((environment_stops + 1))
        agree=$((agree + 1))
        return
      fi
    else
      input_error=yes
    fi
    ;;
  65) input_error=yes why="unreadable input (exit 65)" ;;
  esac
  local check_valid=no
  [ $check_code -eq 0 ] && check_valid=yes
  if { [ $check_valid = yes ] && [ $input_error = no ]; } || { [ $check_valid = no ] && [ $input_error = yes ]; }; then
    agree=$((agree + 1))
  else
    disagree=$((disagree + 1))
    echo "DISAGREE $name: check $([ $check_valid = yes ] && echo valid || echo refuses), run: $why"
    head -5 "$out/check.err"
  fi
}

# The test cases, through their exports (the units they declare, the meshes they read).
while IFS= read -r -d '' export; do
  compare "${export#"$root"/}" "$export" "$export"
done < <(find "$root/testcases" -name '*.export' -print0 | sort -z)

# Command files run on their own (quick mode): the catalogue's examples and the language corpus
# (with an evaluation budget of 10^8 operations, so that the budget cases end in seconds in both).
while IFS= read -r -d '' comm; do
  compare "${comm#"$root"/}" "$comm" "$comm" --max-operations 100000000
done < <(find "$root/catalog/tests/data" "$root/interpreter/corpus" -name '*.comm' -print0 | sort -z)

# Bad inputs, each with several independent errors or an error a definition makes (the mesh
# of a test case on unit 20).
mesh="$root/testcases/hertz_cylinder/hertz_quad4.msh"
bad="$work/bad"
mkdir -p "$bad"
head_comm='DEBUT()
MA = LIRE_MAILLAGE(UNITE=20, FORMAT='"'"'GMSH'"'"')
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('"'"'IND'"'"', '"'"'BLOC'"'"'), PHENOMENE='"'"'MECANIQUE'"'"', MODELISATION='"'"'AXIS'"'"'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.0e5, NU=0.3), ECRO_LINE=_F(D_SIGM_EPSI=1.0e3, SY=200.0))
MAT = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='"'"'OUI'"'"', MATER=ACIER))
L1 = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=2))
'
printf '%sCL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='"'"'NOPE'"'"', DY=0.0))\nFIN()\n' "$head_comm" >"$bad/group.comm"
printf '%sCL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='"'"'BLOC_BASE'"'"', DY=0.0))\nR = STAT_NON_LINE(MODELE=MO, CHAM_MATER=MAT, EXCIT=_F(CHARGE=CL), INCREMENT=_F(LIST_INST=L1),\n    COMPORTEMENT=_F(RELATION='"'"'VMIS_CINE_LINE'"'"', TOUT='"'"'OUI'"'"'))\nFIN()\n' "$head_comm" >"$bad/relation.comm"
printf '%sCL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='"'"'BLOC_BASE'"'"', DY=0.0))\nR = STAT_NON_LINE(MODELE=MO, CHAM_MATER=MAT, EXCIT=_F(CHARGE=CL), INCREMENT=_F(LIST_INST=L1),\n    SUIVI_DDL=_F(NOM_CHAM='"'"'DEPL'"'"', NOM_CMP='"'"'DX'"'"', TOUT='"'"'OUI'"'"', NOM_VARI='"'"'EPSPEQ'"'"'))\nFIN()\n' "$head_comm" >"$bad/suivi_ddl.comm"
printf '%sL2 = DEFI_LIST_INST(DEFI_LIST=_F(VALE=(0.0, 1.0, 1.0)))\nFIN()\n' "$head_comm" >"$bad/list_inst.comm"
printf '%sCL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='"'"'BLOC_BASE'"'"', DY=0.0))\nR = STAT_NON_LINE(MODELE=MO, CHAM_MATER=MAT, EXCIT=_F(CHARGE=CL), INCREMENT=_F(LIST_INST=L1),\n    SUIVI_DDL=_F(NOM_CHAM='"'"'DEPL'"'"', NOM_CMP='"'"'DX'"'"', GROUP_NO='"'"'NOPE'"'"'))\nFIN()\n' "$head_comm" >"$bad/suivi_ddl_group.comm"
printf '%sSOFT = DEFI_MATERIAU(ELAS=_F(E=2.0e5, NU=0.3))\nMS = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='"'"'OUI'"'"', MATER=SOFT))\nCL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='"'"'BLOC_BASE'"'"', DY=0.0))\nR = STAT_NON_LINE(MODELE=MO, CHAM_MATER=MS, EXCIT=_F(CHARGE=CL), INCREMENT=_F(LIST_INST=L1),\n    COMPORTEMENT=_F(RELATION='"'"'VMIS_ISOT_LINE'"'"', TOUT='"'"'OUI'"'"'))\nFIN()\n' "$head_comm" >"$bad/no_ecro_line.comm"
for comm in "$bad"/*.comm; do
  compare "bad input $(basename "$comm")" "$comm" "$comm" --unit "20=$mesh"
done

# Every command's errors in one pass: three commands with an independent error each (and a fourth,
# a group the mesh does not have, found when the mesh is given) give three (four) messages, in the
# order of the file.
cat >"$bad/three.comm" <<'COMM'
DEBUT()
MA = LIRE_MAILLAGE(UNITE=20, FORMAT='GMSH')
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('IND', 'BLOC'), PHENOMENE='MECANIQUE', MODELISATION='AXIS'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.0e5, NU=0.3, RHOO=1.0))
MAT = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='NOPE', DY=0.0))
L1 = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=2))
R = STAT_NON_LINE(MODELE=MO, CHAM_MATER=MAT, EXCIT=_F(CHARGE=CL), INCREMENT=_F(LIST_INST=L1),
    COMPORTEMENT=_F(RELATION='VMIS_CINE_LINE', TOUT='OUI'))
TEST_RESU(RESU=_F(RESULTAT=R, INST=1.0, NOM_CHAM='DEPL', NOM_CMP='DX', GROUP_NO='P0', VALE_CALC=0.0,
                  CRITERE='RELATIVE'))
FIN()
COMM
one_pass() { # expected-ids [--unit ...]
  local expected="$1"
  shift
  "$stella" check "$bad/three.comm" "$@" >/dev/null 2>"$work/three.err"
  local code=$?
  local ids
  ids="$(grep -o 'error: .*\[[A-Z0-9_]*\]$' "$work/three.err" | sed 's/.*\[\([A-Z0-9_]*\)\]$/\1/' | tr '\n' ' ')"
  if [ $code -eq 2 ] && [ "$ids" = "$expected" ]; then
    agree=$((agree + 1))
  else
    disagree=$((disagree + 1))
    echo "ONE PASS: expected errors '$expected' (exit 2), got '$ids' (exit $code)"
    cat "$work/three.err"
  fi
}
one_pass "CATALOG_1 CATALOG_17 CATALOG_3 "
one_pass "CATALOG_1 GROUP_1 CATALOG_17 CATALOG_3 " --unit "20=$mesh"

echo "$agree agree ($environment_stops of them runs stopped by a missing data file after which check found the" \
  "first error), $disagree disagree (of $n command files, and the one-pass checks)"
[ $disagree -eq 0 ]
