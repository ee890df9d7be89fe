#!/usr/bin/env bash
# End-to-end checks of `stella run` on small exports: clear errors naming the export line for
# broken exports, the message and result files written where the export says, the job
# diagnostic words and exit codes.
# Usage: export-errors.sh PATH/TO/stella
set -uo pipefail
source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/lib.sh"
stella="$(readlink -f "$1")"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

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

# Quick run: every unit a command writes comes back, as <stem>.<unit> or to its --unit path; a
# --unit the study only reads is not copied back.
cat > units.comm <<'COMM'
DEBUT()
T = CREA_TABLE(LISTE=(_F(PARA='X', LISTE_R=(1.0, 2.0)),))
IMPR_TABLE(TABLE=T, UNITE=30)
IMPR_TABLE(TABLE=T, UNITE=31)
FIN()
COMM
printf 'read only\n' > input.txt
rm -f units.30 mytab.txt
"$stella" run units.comm --quiet --unit 31=mytab.txt --unit 40=input.txt >out.txt 2>err.txt; code=$?
check "quick run, units 30 and 31: exit 0" test $code -eq 0
check "quick run: unit 30 comes back as units.30" grep -q "2.00000E+00" units.30
check "quick run: unit 31 comes back to its --unit path" grep -q "2.00000E+00" mytab.txt
check "quick run: the written units are listed" grep -q "wrote .*units.30" err.txt
check "quick run: a --unit only read is not copied back" sh -c '! grep -q "input.txt" err.txt'
check "quick run: the data file is unchanged" grep -q "^read only$" input.txt
check "quick run: no RUN_2 alarm for an output --unit" sh -c '! grep -q RUN_2 units.mess'
# A result file of another format (IMPR_RESU FORMAT='GMSH' on unit 37) comes back the same way,
# as <stem>.37, a Gmsh file (issue 15, "What users open").
write_bar_mesh
cat > gmsh.comm <<'COMM'
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)
IMPR_RESU(FORMAT='GMSH', UNITE=37, RESU=_F(MAILLAGE=MA))
FIN()
COMM
rm -f gmsh.37
"$stella" run gmsh.comm --quiet --unit 20=bar.mail >out.txt 2>err.txt; code=$?
check "quick run, GMSH on unit 37: exit 0" test $code -eq 0
check "quick run: unit 37 comes back as gmsh.37, a Gmsh file" grep -q '^\$MeshFormat' gmsh.37
check "quick run: unit 37 is listed" grep -q "wrote .*gmsh.37" err.txt

# --reference-only: VALE_CALC (non-regression) lines are printed with their difference but not
# counted; only the reference lines decide OK / NOOK, and a file without any is NO_TEST_RESU.
cat > refonly.comm <<'COMM'
DEBUT()
T = CREA_TABLE(LISTE=(_F(PARA='INST', LISTE_R=(0.5, 1.0)), _F(PARA='DY', LISTE_R=(-1.0, -2.0))))
TEST_TABLE(TABLE=T, NOM_PARA='DY', TYPE_TEST='MIN', VALE_CALC=-2.1,
           REFERENCE='ANALYTIQUE', VALE_REFE=-2.0, PRECISION=1.0e-6)
FIN()
COMM
printf 'F comm refonly.comm D 1\nF mess results/refonly.mess R 6\nF resu results/refonly.resu R 8\n' > refonly.export
"$stella" run refonly.export --quiet >out.txt 2>err.txt; code=$?
check "wrong VALE_CALC, right reference: NOOK_TEST_RESU without --reference-only" grep -q -- "--- DIAGNOSTIC JOB : NOOK_TEST_RESU" results/refonly.mess
"$stella" run --reference-only refonly.export --quiet >out.txt 2>err.txt; code=$?
check "--reference-only: OK when the reference lines pass" grep -q -- "--- DIAGNOSTIC JOB : OK" results/refonly.mess
check "--reference-only: exit 0" test $code -eq 0
check "--reference-only: non-regression line printed with its difference, not judged" grep -qE "^ -   NON_REGRESSION   DY +-2.1 +-2.0 +4.8%" results/refonly.resu
check "--reference-only: reference line judged" grep -q "^ OK  ANALYTIQUE" results/refonly.resu
sed 's/,$/)/; /REFERENCE=/d' refonly.comm > calconly.comm
printf 'F comm calconly.comm D 1\nF mess results/calconly.mess R 6\n' > calconly.export
"$stella" run --reference-only calconly.export --quiet >out.txt 2>err.txt; code=$?
check "--reference-only without reference lines: NO_TEST_RESU" grep -q -- "--- DIAGNOSTIC JOB : NO_TEST_RESU" results/calconly.mess

# Post-processing on a plane-strain bar of two QUAD4 pulled by a pressure of -100 on its right
# edge: uniform SIXX = 100, SIZZ = nu SIXX = 30, VMIS = sqrt(7900), EPXX = (1 - nu^2) 100 / E.
write_bar_mesh 'GROUP_NO
TOP
  N4
  N5
  N6
FINSF
%'
write_bar_study post.comm
cat >> post.comm <<'COMM'
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
RES = CALC_CHAMP(reuse=RES, RESULTAT=RES, CONTRAINTE=('SIEF_ELNO', 'SIEF_NOEU'),
                 DEFORMATION='EPSI_NOEU', CRITERES='SIEQ_NOEU')
TEST_RESU(RESU=(
    _F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM='SIEF_ELNO', MAILLE='M2', NOEUD='N6', NOM_CMP='SIXX',
       VALE_CALC=100.0, REFERENCE='ANALYTIQUE', VALE_REFE=100.0, PRECISION=1.0e-10),
    _F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM='SIEF_NOEU', NOEUD='N5', NOM_CMP='SIZZ',
       VALE_CALC=30.0, REFERENCE='ANALYTIQUE', VALE_REFE=30.0, PRECISION=1.0e-10),
    _F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM='SIEQ_NOEU', NOEUD='N5', NOM_CMP='VMIS',
       VALE_CALC=88.88194417315589, REFERENCE='ANALYTIQUE', VALE_REFE=88.88194417315589, PRECISION=1.0e-10),
    _F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM='SIEQ_NOEU', NOM_CMP='TRESCA', TYPE_TEST='MAX',
       VALE_CALC=100.0, REFERENCE='ANALYTIQUE', VALE_REFE=100.0, PRECISION=1.0e-10),
    _F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM='EPSI_NOEU', NOEUD='N6', NOM_CMP='EPXX',
       VALE_CALC=4.55e-4, REFERENCE='ANALYTIQUE', VALE_REFE=4.55e-4, PRECISION=1.0e-10),
))
TAB = POST_RELEVE_T(ACTION=(
    _F(OPERATION='MOYENNE', INTITULE='top', RESULTAT=RES, NOM_CHAM='DEPL', GROUP_NO='TOP', NOM_CMP='DX'),
    _F(OPERATION='EXTRACTION', INTITULE='invariants', RESULTAT=RES, NOM_CHAM='SIEF_NOEU', NOEUD='N5',
       INVARIANT='OUI')))
TEST_TABLE(TABLE=TAB, NOM_PARA='DX', FILTRE=(_F(NOM_PARA='INTITULE', VALE_K='top'),
           _F(NOM_PARA='QUANTITE', VALE_K='MOMENT_0')),
           VALE_CALC=4.55e-4, REFERENCE='ANALYTIQUE', VALE_REFE=4.55e-4, PRECISION=1.0e-10)
TEST_TABLE(TABLE=TAB, NOM_PARA='VMIS', FILTRE=_F(NOM_PARA='INTITULE', VALE_K='invariants'),
           VALE_CALC=88.88194417315589, REFERENCE='ANALYTIQUE', VALE_REFE=88.88194417315589, PRECISION=1.0e-10)
IMPR_TABLE(TABLE=TAB, FORMAT='ASTER')
IMPR_TABLE(TABLE=TAB, UNITE=30, SEPARATEUR=',', NOM_PARA=('INTITULE', 'QUANTITE', 'DX'))
FIN()
COMM
printf 'F comm post.comm D 1\nF mail bar.mail D 20\nF mess results/post.mess R 6\nF resu results/post.resu R 8\nF csv results/post.csv R 30\n' > post.export
"$stella" run post.export --quiet >out.txt 2>err.txt; code=$?
check "CALC_CHAMP / POST_RELEVE_T study: OK" grep -q -- "--- DIAGNOSTIC JOB : OK" results/post.mess
check "CALC_CHAMP / POST_RELEVE_T study: 14 OK lines" test "$(grep -c '^ OK ' results/post.resu)" -eq 14
check "CALC_CHAMP: says what it stored" grep -q "CALC_CHAMP: SIEF_ELNO, SIEF_NOEU, EPSI_NOEU, SIEQ_NOEU stored on 1 step(s) of RES" results/post.mess
check "ELNO test header names the cell and the node" grep -qE "^ +RES +1 +SIEF_ELNO +SIXX +M2 +N6" results/post.resu
check "IMPR_TABLE ASTER: markers and type line" grep -q "^#FIN_TABLE" results/post.resu
check "IMPR_TABLE CSV to unit 30" grep -q "^top,MOMENT_0,4.55000E-04" results/post.csv
sed "s/CONTRAINTE=('SIEF_ELNO', 'SIEF_NOEU'),/CONTRAINTE='EFGE_ELNO',/" post.comm > refused.comm
printf 'F comm refused.comm D 1\nF mail bar.mail D 20\nF mess results/refused.mess R 6\n' > refused.export
"$stella" run refused.export --quiet >out.txt 2>err.txt; code=$?
check "CALC_CHAMP option not implemented: refused by name" grep -q "CALC_CHAMP CONTRAINTE='EFGE_ELNO' is not implemented yet" results/refused.mess

# `stella check` runs the language-level operators (FIN, FORMULE, DEFI_FONCTION, DEFI_LIST_REEL).
"$stella" check ok.comm >out.txt 2>err.txt; code=$?
check "check: DEBUT()/FIN() valid, exit 0" test $code -eq 0
check "check: FIN() seen (no missing-FIN alarm)" test "$(grep -c LANG_FIN err.txt)" -eq 0
printf "DEBUT()\nF = FORMULE(VALE='X * (1 + Y', NOM_PARA=('X', 'Y'))\nFIN()\n" > badformula.comm
"$stella" check badformula.comm >out.txt 2>err.txt; code=$?
check "check: broken FORMULE is an error, exit 2" test $code -eq 2
check "check: FORMULE error points inside the string" grep -q "badformula.comm:2:" err.txt
printf "DEBUT()\nF = FORMULE(VALE='X*2', NOM_PARA='X')\nif F(3.0) != 6.0:\n    print(wrong_value)\nFIN()\n" > callformula.comm
"$stella" check callformula.comm >out.txt 2>err.txt; code=$?
check "check: a FORMULE can be called later in the file" test $code -eq 0

printf "DEBUT()\nF = FORMULE(VALE='X*2+Y', NOM_PARA=('X', 'Y'))\nprint('F=', F(3.0, Y=1))\nFIN()\n" > formulacall.comm
"$stella" run formulacall.comm --quiet >out.txt 2>err.txt; code=$?
check "run: F(3.0, Y=1) of a FORMULE by position and by name" grep -q "^F= 7.0" formulacall.mess

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
