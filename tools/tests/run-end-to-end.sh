#!/usr/bin/env bash
# End-to-end checks of `stella run` on small exports: clear errors naming the export line for
# broken exports, the message and result files written where the export says, the job
# diagnostic words and exit codes.
# Usage: export-errors.sh PATH/TO/stella
set -uo pipefail
stella="$(readlink -f "$1")"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
fails=0
passes=0
check() { # description, condition...
  local what="$1"; shift
  if "$@"; then echo "ok   $what"; passes=$((passes + 1)); else echo "FAIL $what"; fails=$((fails + 1)); fi
}

cd "$dir"
printf 'DEBUT()\nFIN()\n' > ok.comm

printf 'F comm ok.comm D 1\nX nonsense here\n' > unknown.export
"$stella" run unknown.export >out.txt 2>err.txt; code=$?
check "unknown line type: exit 65" test $code -eq 65
check "unknown line type: names file, line and type" grep -q "unknown.export:2:1: error: unknown line type 'X' \[EXPORT_1\]" err.txt
check "unknown line type: suggests the line types" grep -q "note: an export line starts with P" err.txt

printf 'P ncpus 1\nF comm absent.comm D 1\n' > missing.export
"$stella" run missing.export >out.txt 2>err.txt; code=$?
check "missing command file: exit 65" test $code -eq 65
check "missing command file: names line 2" grep -q "missing.export:2:1: error: the command file 'absent.comm' does not exist" err.txt

printf 'F comm ok.comm D 1\nF mmed mesh.med D 6\n' > reserved.export
"$stella" run reserved.export >out.txt 2>err.txt; code=$?
check "reserved unit: exit 65 and EXPORT_5" grep -q "EXPORT_5" err.txt

mkdir -p results
printf 'P testlist verification\nF comm ok.comm D 1\nF mess results/ok.mess R 6\nF resu results/ok.resu R 8\n' > study.export
"$stella" run study.export --quiet >out.txt 2>err.txt; code=$?
check "minimal study: message file written where the export says" test -s results/ok.mess
check "minimal study: result file written" test -e results/ok.resu
check "minimal study: NO_TEST_RESU for a test case without tests" grep -q -- "--- DIAGNOSTIC JOB : NO_TEST_RESU" results/ok.mess
check "minimal study: NO_TEST_RESU exits 1" test $code -eq 1

printf 'F comm ok.comm D 1\nF mess results/alarm.mess R 6\nF datg absent.datg D 16\n' > alarm.export
"$stella" run alarm.export --quiet >out.txt 2>err.txt; code=$?
check "unopened missing data file: <A>_ALARM" grep -q -- "--- DIAGNOSTIC JOB : <A>_ALARM" results/alarm.mess
check "unopened missing data file: exit 0" test $code -eq 0

printf 'DEBUT()\nx = = 1\nFIN()\n' > bad.comm
printf 'F comm bad.comm D 1\nF mess results/bad.mess R 6\n' > bad.export
"$stella" run bad.export --quiet >out.txt 2>err.txt; code=$?
check "syntax error: <F>_SYNTAX_ERROR" grep -q -- "--- DIAGNOSTIC JOB : <F>_SYNTAX_ERROR" results/bad.mess
check "syntax error: exit 2" test $code -eq 2
check "syntax error: located in the command file" grep -q "bad.comm:2:" results/bad.mess

cat > table.comm <<'COMM'
DEBUT()
T = CREA_TABLE(LISTE=(_F(PARA='INST', LISTE_R=(0.5, 1.0)), _F(PARA='DY', LISTE_R=(-1.0, -2.0))))
TEST_TABLE(TABLE=T, NOM_PARA='DY', FILTRE=_F(NOM_PARA='INST', VALE=1.0),
           VALE_CALC=-2.0, REFERENCE='ANALYTIQUE', VALE_REFE=-2.0)
TEST_TABLE(TABLE=T, NOM_PARA='DY', TYPE_TEST='MIN', VALE_CALC=-2.0)
IMPR_TABLE(TABLE=T)
FIN()
this text after FIN() is ignored (
COMM
printf 'P testlist verification\nF comm table.comm D 1\nF mess results/table.mess R 6\nF resu results/table.resu R 8\n' > table.export
"$stella" run table.export --quiet >out.txt 2>err.txt; code=$?
check "table study: OK" grep -q -- "--- DIAGNOSTIC JOB : OK" results/table.mess
check "table study: exit 0" test $code -eq 0
check "table study: OK lines in the result file" test "$(grep -c '^ OK ' results/table.resu)" -eq 3
check "table study: IMPR_TABLE in the result file" grep -q "INST" results/table.resu
check "table study: command echoed with its location" grep -q "Command #0002   CREA_TABLE   (.*table.comm:2:" results/table.mess

sed 's/VALE_REFE=-2.0/VALE_REFE=-2.5/' table.comm > nook.comm
printf 'F comm nook.comm D 1\nF mess results/nook.mess R 6\n' > nook.export
"$stella" run nook.export --quiet >out.txt 2>err.txt; code=$?
check "failing test: NOOK_TEST_RESU" grep -q -- "--- DIAGNOSTIC JOB : NOOK_TEST_RESU" results/nook.mess
check "failing test: exit 1" test $code -eq 1
check "failing test: NOOK line" grep -q "^NOOK ANALYTIQUE" results/nook.mess

"$stella" run ok.comm --quiet >out.txt 2>err.txt; code=$?
check "quick run of a .comm: message file beside it" test -s ok.mess
check "quick run of a .comm: exit 0" test $code -eq 0
"$stella" run ok.comm --unit 20 >out.txt 2>err.txt; code=$?
check "bad --unit: usage exit 64" test $code -eq 64

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
