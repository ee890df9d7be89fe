#!/usr/bin/env bash
# Bad inputs that runs used to accept (issue 22): each case writes a small study, runs stella on
# it and checks the located error (or warning), the exit code and what came back.
# Usage: faults-input.sh PATH/TO/stella CASE      (CASE: one of the functions case_* below)
set -uo pipefail
source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/lib.sh"
stella="$(readlink -f "$1")"
name="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1

run_study() { # comm file [extra export lines]: runs it with the mesh on unit 20
  local comm="$1"; shift
  local stem="${comm%.comm}"
  { printf 'F comm %s D 1\nF mail bar.mail D 20\nF mess %s.mess R 6\nF resu %s.resu R 8\n' "$comm" "$stem" "$stem"
    for line in "$@"; do printf '%s\n' "$line"; done; } > "$stem.export"
  "$stella" run "$stem.export" --quiet >out.txt 2>err.txt
  code=$?
}

case_list_reel_decreasing() {
  write_bar_mesh
  write_bar_study lr.comm
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
  write_bar_mesh
  write_bar_study li.comm
  cat >> li.comm <<'COMM'
LI = DEFI_LIST_INST(DEFI_LIST=_F(VALE=(0.0, 1.0, 1.0, 2.0)))
FIN()
COMM
  run_study li.comm
  check "DEFI_LIST_INST repeated instant: LIST_INST_2 at VALE" grep -q "li.comm:8:34: error: the instants must increase strictly: 1 follows 1" li.mess
}

elas_refused() { # stem, ELAS content, description, the error expected in stem.mess (grep pattern)
  write_bar_study "$1.comm" "$2"
  echo "FIN()" >> "$1.comm"
  run_study "$1.comm"
  check "$3" grep -q "$4" "$1.mess"
}

case_material_nan() {
  write_bar_mesh
  elas_refused nan "E=float('nan'), NU=0.3" "E=nan refused at E: MATER_4" \
    "nan.comm:4:31: error: ELAS E = nan is not a finite number \[MATER_4\]"
  elas_refused inf "E=1e400, NU=0.3" "E=1e400 (inf) refused at E" \
    "inf.comm:4:31: error: ELAS E = inf is not a finite number"
  elas_refused nu "E=200000.0, NU=0.5" "NU=0.5 refused at NU: MATER_2" \
    "nu.comm:4:43: error: ELAS NU = 0.5: -1 < NU < 0.5"
  elas_refused rho "E=200000.0, NU=0.3, RHO=float('nan')" "RHO=nan refused at RHO: MATER_4" \
    "rho.comm:4:51: error: ELAS RHO = nan is not a finite number"
  elas_refused e0 "E=0.0, NU=0.3" "E=0 refused at E" "e0.comm:4:31: error: ELAS E = 0: E > 0 is expected"
}

case_formule_location() {
  write_bar_mesh
  write_bar_study fo.comm
  cat >> fo.comm <<'COMM'
RAMPE = FORMULE(VALE='1.0/(INST-0.5)', NOM_PARA='INST')
L = DEFI_LIST_REEL(VALE=(0.0, 0.5, 1.0))
RES = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH, FONC_MULT=RAMPE),
                    COMPORTEMENT=_F(RELATION='ELAS'), INCREMENT=_F(LIST_INST=L))
FIN()
COMM
  run_study fo.comm
  check "FORMULE division by zero located in the FORMULE's string (line 8, at '/')" grep -q "fo.comm:8:26: error: formula '1.0/(INST-0.5)': division by zero for INST=0.5 \[FORMULA_DOMAIN\]" fo.mess
  check "the note names the calling command" grep -q "note: while running STAT_NON_LINE at .*fo.comm:10:7" fo.mess
  check "no <expression> location left" test "$(grep -c '<expression>' fo.mess)" -eq 0
  # a formula text built by the command file is not in the file verbatim: the note says where
  write_bar_study fv.comm
  cat >> fv.comm <<'COMM'
texte = '1.0/' + '(INST-0.5)'
RAMPE = FORMULE(VALE=texte, NOM_PARA='INST')
L = DEFI_LIST_REEL(VALE=(0.0, 0.5, 1.0))
RES = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH, FONC_MULT=RAMPE),
                    COMPORTEMENT=_F(RELATION='ELAS'), INCREMENT=_F(LIST_INST=L))
FIN()
COMM
  run_study fv.comm
  check "FORMULE from a variable: the note names the FORMULE's line" grep -q "note: in the formula written at .*fv.comm:9:" fv.mess
  check "FORMULE from a variable: the note names the calling command" grep -q "note: while running STAT_NON_LINE at .*fv.comm:11:7" fv.mess
}

case_unit_formats() {
  write_bar_mesh
  write_bar_study med8.comm
  cat >> med8.comm <<'COMM'
IMPR_RESU(FORMAT='MED', UNITE=8, RESU=_F(MAILLAGE=MA))
FIN()
COMM
  run_study med8.comm
  check "MED to unit 8 (the text result file): UNIT_3 at UNITE" grep -q "med8.comm:8:25: error: IMPR_RESU FORMAT='MED' to unit 8: unit 8 is the text result file, which holds text only \[UNIT_3\]" med8.mess
  check "MED to unit 8: exit 2 (refused at validation)" test "$code" -eq 2
  "$stella" check med8.comm >out.txt 2>err.txt
  check "MED to unit 8: stella check refuses it too" grep -q "UNIT_3" err.txt
  write_bar_study mixed.comm
  cat >> mixed.comm <<'COMM'
T = CREA_TABLE(LISTE=(_F(PARA='INST', LISTE_R=(0.5, 1.0)),))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MA))
IMPR_TABLE(TABLE=T, UNITE=80)
FIN()
COMM
  run_study mixed.comm "F rmed mixed.rmed R 80"
  check "IMPR_TABLE to the MED unit 80: UNIT_3 naming the first writer" grep -q "mixed.comm:10:21: error: IMPR_TABLE text (FORMAT='RESULTAT', IMPR_TABLE) to unit 80, which already receives FORMAT='MED' (at .*mixed.comm:9:" mixed.mess
  write_bar_study resu6.comm
  cat >> resu6.comm <<'COMM'
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
IMPR_RESU(FORMAT='RESULTAT', UNITE=6, RESU=_F(RESULTAT=RES, NOM_CHAM='DEPL', NOM_CMP='DX'))
FIN()
COMM
  run_study resu6.comm
  check "FORMAT='RESULTAT' on unit 6 writes into the message file" grep -q "CHAMP DEPL DU RESULTAT RES NUME_ORDRE 1" resu6.mess
  check "FORMAT='RESULTAT' on unit 6: the table lines of the 6 nodes" test "$(grep -cE '^ *N[1-6] ' resu6.mess)" -ge 6
  check "FORMAT='RESULTAT' on unit 6: the run is OK" grep -q -- "--- DIAGNOSTIC JOB : OK" resu6.mess
}

case_unit_undeclared() {
  write_bar_mesh
  write_bar_study neg.comm
  cat >> neg.comm <<'COMM'
IMPR_RESU(FORMAT='MED', UNITE=-7, RESU=_F(MAILLAGE=MA))
FIN()
COMM
  run_study neg.comm
  check "UNITE=-7 refused: UNIT_2 at UNITE" grep -q "neg.comm:8:25: error: UNITE=-7 is not a unit number \[UNIT_2\]" neg.mess
  check "UNITE=-7: exit 2" test "$code" -eq 2
  "$stella" check neg.comm >out.txt 2>err.txt
  check "UNITE=-7: stella check refuses it" grep -q "neg.comm:8:25: error: UNITE=-7 is not a unit number" err.txt
  write_bar_study undecl.comm
  cat >> undecl.comm <<'COMM'
IMPR_RESU(FORMAT='MED', UNITE=33, RESU=_F(MAILLAGE=MA))
FIN()
COMM
  run_study undecl.comm
  check "undeclared unit 33: UNIT_2 naming the result units" grep -q "undecl.comm:8:25: error: IMPR_RESU writes to unit 33, which the run does not declare: its file would be lost \[UNIT_2\]" undecl.mess
  check "undeclared unit 33: the note lists the export's result units" grep -q "result units of this run: 6, 8" undecl.mess
  "$stella" check undecl.comm >out.txt 2>err.txt
  check "undeclared unit 33: stella check refuses it" grep -q "UNIT_2" err.txt
  "$stella" check undecl.comm --unit 33 >out.txt 2>err.txt
  check "stella check --unit 33 declares it" grep -q "valid" err.txt
  run_study undecl.comm "F rmed undecl.rmed R 33"
  check "declared in the export: written and copied back" test -s undecl.rmed
}

case_confine() {
  mkdir -p study outside
  printf 'DEBUT()\nFIN()\n' > study/ok.comm
  printf 'SECRET-LINE-1 = (\n' > outside/secret.comm
  ln -s ../outside/secret.comm study/link.comm
  printf 'F comm ok.comm D 1\nF mess ok.mess R 6\n' > study/ok.export
  "$stella" run --confine --quiet study/ok.export >out.txt 2>err.txt
  code=$?
  check "confined study inside its folder: runs, exit 1 (no test)" test "$code" -le 1
  check "confined study: message file written" test -s study/ok.mess
  printf 'F comm ../outside/secret.comm D 1\nF mess ok.mess R 6\n' > study/dotdot.export
  "$stella" run --confine --quiet study/dotdot.export >out.txt 2>err.txt
  code=$?
  check "'..' data path refused: CONFINE_1 at the export line" grep -q "dotdot.export:1:1: error: the data file '../outside/secret.comm' resolves outside .*study (--confine) \[CONFINE_1\]" err.txt
  check "'..': exit 65" test "$code" -eq 65
  check "'..': the refused file's content is not printed" test "$(cat out.txt err.txt | grep -c SECRET)" -eq 0
  printf 'F comm %s D 1\nF mess ok.mess R 6\n' "$dir/outside/secret.comm" > study/absolute.export
  "$stella" run --confine --quiet study/absolute.export >out.txt 2>err.txt
  check "absolute data path elsewhere refused" grep -q "absolute.export:1:1: error: the data file '.*outside/secret.comm' resolves outside" err.txt
  check "absolute: the content is not printed" test "$(cat out.txt err.txt | grep -c SECRET)" -eq 0
  printf 'F comm link.comm D 1\nF mess ok.mess R 6\n' > study/link.export
  "$stella" run --confine --quiet study/link.export >out.txt 2>err.txt
  check "symbolic link leading out refused" grep -q "link.export:1:1: error: the data file 'link.comm' resolves outside" err.txt
  check "link: the content is not printed" test "$(cat out.txt err.txt | grep -c SECRET)" -eq 0
  printf 'F comm ok.comm D 1\nF mess ../outside/stolen.mess R 6\n' > study/result.export
  "$stella" run --confine --quiet study/result.export >out.txt 2>err.txt
  check "result path out of the folder refused" grep -q "result.export:2:1: error: the result file '../outside/stolen.mess' resolves outside" err.txt
  check "result path: nothing written outside" test ! -e outside/stolen.mess
  "$stella" run --confine --quiet study/ok.comm --unit 20=../outside/secret.comm >out.txt 2>err.txt
  check "quick run: --unit file out of the folder refused" grep -q "the file of --unit 20 '../outside/secret.comm' resolves outside" err.txt
  "$stella" run --quiet study/dotdot.export >out.txt 2>err.txt
  check "without --confine the same export runs (and shows the file: the reason for --confine)" grep -q "SECRET" study/ok.mess
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
