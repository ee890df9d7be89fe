#!/usr/bin/env bash
# Faults during a run (issue 22): each case makes its own study, breaks the run the way real
# machines do, and checks the message, the exit code and which files come back readable.
# Usage: run-faults.sh PATH/TO/stella CASE
#   unwritable   result destinations that cannot be written (a folder, a file as parent, /dev/full,
#                a read-only folder when not root): the others still come back, exit 3, no crash
#   full-disk    IMPR_RESU to MED under a file-size limit (ulimit -f): located error with the OS
#                reason, no crash, no truncated file announced, the earlier IMPR_RESU kept readable
#   signal       SIGTERM after the first converged step of STAT_NON_LINE: stops at the next step,
#                the steps written to a MED file, results copied back, exit 6; a second signal
#                stops at once
#   failed-step  a STAT_NON_LINE that fails at step k before its IMPR_RESU: the steps reach the
#                disk in <study>.<RESU>.incomplete.rmed, readable
#   time-limit   P time_limit stops a long STAT_NON_LINE the same way (exit 7, <S>_CPU_LIMIT)
#   killed       the run process killed (SIGKILL, as the system's out-of-memory killer does):
#                the message file ends with RUN_7 and <F>_ABNORMAL_ABORT, the MED file written
#                before comes back readable, exit 5
#   memory-limit P memory_limit: an allocation beyond it stops the command with MEMORY_1 naming
#                the limit (exit 3), the earlier MED file comes back; a bad value is EXPORT_11
set -uo pipefail
source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/lib.sh"
stella="$(readlink -f "$1")"
case_name="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
dir="$(mktemp -d)"
trap 'rm -rf "$dir" /tmp/stella-faults-work-$$' EXIT
cd "$dir"
work="/tmp/stella-faults-work-$$"

# A plastic square pulled by its top edge: STEPS steps, optionally ITER_GLOB_MAXI=1 to fail.
study() { # name steps mesh-size extra-snl-keywords
  cat > "$1.comm" <<COMM
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
MAT = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3), ECRO_LINE=_F(SY=200.0, D_SIGM_EPSI=1000.0))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BOTTOM', DX=0.0, DY=0.0), _F(GROUP_MA='TOP', DY=0.01)))
RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
LI = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=$2))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH, FONC_MULT=RAMPE),
                     COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', TOUT='OUI'),$4
                     INCREMENT=_F(LIST_INST=LI))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU))
FIN()
COMM
  "$here/faults/mesh.sh" "$3" > "$1.msh"
}

# A MED file is readable when stella reads its mesh back (the HDF5 file and the MED structure).
readable() { # file.rmed
  printf "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\nFIN()\n" > reread.comm
  "$stella" run reread.comm --unit "20=$1" --quiet >/dev/null 2>&1
}
# The number of steps of RESU's displacement written in a MED file: reading it back through the
# MED library is what a user does; stella has no LIRE_RESU yet, so count the NUME_ORDRE keys of
# the field's HDF5 groups (MED names a step group by its NUME_ORDRE and its sub-iteration,
# 20 characters each: 00000000000000000003-0000000000000000001).
steps_in() { # file.rmed
  grep -a -o '[0-9]\{20\}-[0-9]\{19\}' "$1" | sort -u | wc -l
}

unwritable() {
  study s 3 2 ""
  mkdir -p out/asdir.rmed
  touch plainfile
  for kind in folder parent devfull; do
    case $kind in
      folder) dest=out/asdir.rmed ;;
      parent) dest=plainfile/r.rmed ;;
      devfull) dest=/dev/full ;;
    esac
    printf 'F comm s.comm D 1\nF msh s.msh D 20\nF mess out/%s.mess R 6\nF rmed %s R 80\nF resu out/%s.resu R 8\n' \
      "$kind" "$dest" "$kind" > "$kind.export"
    "$stella" run "$kind.export" --quiet --work-dir "$work" >out.txt 2>err.txt; code=$?
    check "$kind: exit 3 (<F>_ERROR), not a crash (got $code)" test $code -eq 3
    check "$kind: the message file came back" test -s "out/$kind.mess"
    check "$kind: the other result file came back" test -e "out/$kind.resu"
    case $kind in
      folder) reason="cannot open .*out/asdir.rmed for writing: Is a directory (EISDIR)" ;;
      parent) reason="cannot make the folder .*plainfile: Not a directory (ENOTDIR)" ;;
      devfull) reason="cannot write /dev/full: No space left on device (ENOSPC)" ;;
    esac
    check "$kind: RUN_5 names the unit, the destination and the OS reason" \
      grep -q "unit 80 could not be copied back: $reason \[RUN_5\]" "out/$kind.mess"
    check "$kind: the work directory is kept and named" grep -q "The work directory is kept: $work" "out/$kind.mess"
    check "$kind: the result is in the work directory" test -s "$work/fort.80"
    check "$kind: the diagnostic says <F>_ERROR" grep -q -- "--- DIAGNOSTIC JOB : <F>_ERROR" "out/$kind.mess"
    check "$kind: standard error names what was not copied" grep -q "NOT copied back: unit 80" err.txt
  done
  # The message file itself in the way: the other results still come back.
  printf 'F comm s.comm D 1\nF msh s.msh D 20\nF mess out/asdir.rmed R 6\nF rmed out/m.rmed R 80\n' > mess.export
  "$stella" run mess.export --quiet --work-dir "$work" >out.txt 2>err.txt; code=$?
  check "message file unwritable: exit 3 (got $code)" test $code -eq 3
  check "message file unwritable: the MED result came back readable" readable out/m.rmed
  check "message file unwritable: standard error names unit 6 and the kept copy" grep -q "NOT copied back: unit 6.*fort.6" err.txt
  # A work directory that cannot be made: a located error before the run, not terminate.
  "$stella" run mess.export --quiet --work-dir plainfile/work >out.txt 2>err.txt; code=$?
  check "work directory under a file: exit 3 (got $code)" test $code -eq 3
  check "work directory under a file: RUN_6 with the path and the OS reason" \
    grep -q "plainfile/work: Not a directory (ENOTDIR) \[RUN_6\]" err.txt
  if [ "$(id -u)" != 0 ]; then
    mkdir -p ro && chmod 555 ro
    printf 'F comm s.comm D 1\nF msh s.msh D 20\nF mess out/ro.mess R 6\nF rmed ro/r.rmed R 80\n' > ro.export
    "$stella" run ro.export --quiet --work-dir "$work" >out.txt 2>err.txt; code=$?
    check "read-only folder: exit 3" test $code -eq 3
    check "read-only folder: Permission denied" grep -q "Permission denied (EACCES) \[RUN_5\]" out/ro.mess
    chmod 755 ro
  else
    echo "skip read-only folder: running as root, which may write anywhere"
  fi
}

full_disk() {
  study s 3 12 ""
  # A first IMPR_RESU of the mesh only (small), then the result (larger than the limit).
  sed -i "s/^IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU))/IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MA))\n&/" s.comm
  printf 'F comm s.comm D 1\nF msh s.msh D 20\nF mess out/s.mess R 6\nF rmed out/s.rmed R 80\n' > s.export
  # 100 blocks of 1024 bytes (the unit of bash's ulimit -f): the mesh fits, the result does not.
  ( ulimit -f 100; "$stella" run s.export --quiet --work-dir "$work" >out.txt 2>err.txt ); code=$?
  check "file-size limit: exit 3, not a crash (got $code)" test $code -eq 3
  check "file-size limit: MESHFILE_7 names the file and the OS reason" \
    grep -q "cannot write the MED file .*File too large (EFBIG) \\[MESHFILE_7\\]" out/s.mess
  check "file-size limit: the advice names the limit, not the unit or FORMAT" grep -q "ulimit -f" out/s.mess
  check "file-size limit: no blame on the FORMAT" bash -c "! grep -q 'FORMAT matches' out/s.mess"
  check "file-size limit: the located command" grep -q "s.comm:13" out/s.mess
  check "file-size limit: the mesh of the first IMPR_RESU came back readable" readable out/s.rmed
  check "file-size limit: no partial file left in the work directory" bash -c "! ls $work | grep -q writing"
  check "file-size limit: the diagnostic says <F>_ERROR" grep -q -- "--- DIAGNOSTIC JOB : <F>_ERROR" out/s.mess
}

signal_stop() {
  study s 4000 6 ""
  printf 'F comm s.comm D 1\nF msh s.msh D 20\nF mess out/s.mess R 6\nF rmed out/s.rmed R 80\n' > s.export
  "$stella" run s.export --quiet --work-dir "$work" >out.txt 2>err.txt &
  pid=$!
  for _ in $(seq 1 600); do
    grep -q "step 1 INST" "$work/fort.6" 2>/dev/null && break
    sleep 0.05
  done
  kill -TERM $pid
  wait $pid; code=$?
  check "SIGTERM: exit 6 (<S>_INTERRUPTED), not a death by signal (got $code)" test $code -eq 6
  check "SIGTERM: the message file came back" test -s out/s.mess
  check "SIGTERM: says the signal, the instant and where the steps are" \
    grep -q "interrupted by signal 15 (SIGTERM) at INST .*: steps kept up to INST .*, written to .*s.RESU.incomplete.rmed" out/s.mess
  check "SIGTERM: the diagnostic <S>_INTERRUPTED" grep -q -- "--- DIAGNOSTIC JOB : <S>_INTERRUPTED" out/s.mess
  check "SIGTERM: the steps came back readable" readable out/s.RESU.incomplete.rmed
  local kept
  kept=$(grep -o "steps kept up to INST [^ ]* (NUME_ORDRE [0-9]*" out/s.mess | grep -o "[0-9]*$")
  check "SIGTERM: stopped early (NUME_ORDRE $kept of 4000)" test "${kept:-0}" -ge 1 -a "${kept:-0}" -lt 4000
  check "SIGTERM: the MED file holds NUME_ORDRE 0..$kept" test "$(steps_in out/s.RESU.incomplete.rmed)" -eq $((kept + 1))
  check "SIGTERM: no IMPR_RESU after the stop (unit 80 not written)" test ! -e out/s.rmed

  # A second signal stops at once. Two signals of one kind sent together merge into one (POSIX
  # does not queue them), so SIGINT then SIGTERM; job control (set -m) so that the background run
  # does not start with SIGINT ignored, which stella would honour (doc/run-faults.md).
  rm -rf out "$work"
  set -m
  "$stella" run s.export --quiet --work-dir "$work" >out.txt 2>err.txt &
  pid=$!
  set +m
  for _ in $(seq 1 600); do
    grep -q "step 1 INST" "$work/fort.6" 2>/dev/null && break
    sleep 0.05
  done
  kill -INT $pid; kill -TERM $pid
  wait $pid; code=$?
  check "second signal: stops at once, killed by the signal (got $code)" test $code -eq 130 -o $code -eq 143
  check "second signal: says so" grep -q "second signal: stopping at once" err.txt
}

failed_step() {
  study s 10 4 "
                     CONVERGENCE=_F(ITER_GLOB_MAXI=1),"
  printf 'F comm s.comm D 1\nF msh s.msh D 20\nF mess out/s.mess R 6\nF rmed out/s.rmed R 80\n' > s.export
  "$stella" run s.export --quiet --work-dir "$work" >out.txt 2>err.txt; code=$?
  check "failed step: exit 4 (<S>_NO_CONVERGENCE) (got $code)" test $code -eq 4
  check "failed step: the message names the MED file of the steps" \
    grep -q "are written to .*out/s.RESU.incomplete.rmed (MED, copied back" out/s.mess
  check "failed step: the MED file came back readable" readable out/s.RESU.incomplete.rmed
  local stored
  stored=$(grep -c "stored as NUME_ORDRE" out/s.mess)
  check "failed step: the MED file holds the $stored converged steps and the initial state" \
    test "$(steps_in out/s.RESU.incomplete.rmed)" -eq $((stored + 1))
  check "failed step: unit 80 explained, not 'was not written by the study'" \
    grep -q "unit 80 (.*s.rmed) was not written: the run stopped before the command that writes it" out/s.mess
  check "failed step: the end of the message file names the file" grep -q "RESU: .* in .*s.RESU.incomplete.rmed" out/s.mess
}

time_limit() {
  study s 4000 6 ""
  printf 'P time_limit 1\nF comm s.comm D 1\nF msh s.msh D 20\nF mess out/s.mess R 6\n' > s.export
  "$stella" run s.export --quiet --work-dir "$work" >out.txt 2>err.txt; code=$?
  check "time limit: exit 7 (<S>_CPU_LIMIT) (got $code)" test $code -eq 7
  check "time limit: says so with the steps kept" \
    grep -q "interrupted by the time limit of 1 s (P time_limit) at INST .*steps kept up to INST" out/s.mess
  check "time limit: the steps came back readable" readable out/s.RESU.incomplete.rmed
  printf 'P time_limit soon\nF comm s.comm D 1\n' > bad.export
  "$stella" run bad.export --quiet >out.txt 2>err.txt; code=$?
  check "time limit: a bad value is refused (exit 65)" test $code -eq 65
  check "time limit: EXPORT_9" grep -q "EXPORT_9" err.txt
}

killed() {
  study s 4000 6 ""
  # the mesh written first, so that a file exists before the kill
  sed -i 's/^RESU = STAT_NON_LINE/IMPR_RESU(FORMAT='"'"'MED'"'"', UNITE=81, RESU=_F(MAILLAGE=MA))\nRESU = STAT_NON_LINE/' s.comm
  printf 'F comm s.comm D 1\nF msh s.msh D 20\nF mess out/s.mess R 6\nF rmed out/s.rmed R 80\nF rmed out/mesh.rmed R 81\n' > s.export
  "$stella" run s.export --quiet --work-dir "$work" >out.txt 2>err.txt &
  pid=$!
  for _ in $(seq 1 600); do
    grep -q "step 1 INST" "$work/fort.6" 2>/dev/null && break
    sleep 0.05
  done
  pkill -KILL -P $pid
  wait $pid; code=$?
  check "killed: exit 5 (<F>_ABNORMAL_ABORT) (got $code)" test $code -eq 5
  check "killed: the message file came back with RUN_7 naming SIGKILL" grep -q "ended on signal 9 (SIGKILL) \[RUN_7\]" out/s.mess
  check "killed: the advice names the out-of-memory killer" grep -q "out-of-memory killer" out/s.mess
  check "killed: the diagnostic <F>_ABNORMAL_ABORT" grep -q -- "--- DIAGNOSTIC JOB : <F>_ABNORMAL_ABORT" out/s.mess
  check "killed: the mesh written before came back readable" readable out/mesh.rmed
  check "killed: the steps before are in the message file" grep -q "step 1 INST" out/s.mess
}

memory_limit() {
  cat > m.comm <<'COMM'
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
MAT = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BOTTOM', DX=0.0, DY=0.0), _F(GROUP_MA='TOP', DY=0.01)))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MA))
RESU = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU))
FIN()
COMM
  "$here/faults/mesh.sh" 400 > m.msh
  printf 'P memory_limit 250\nF comm m.comm D 1\nF msh m.msh D 20\nF mess out/m.mess R 6\nF rmed out/m.rmed R 80\n' > m.export
  "$stella" run m.export --quiet >out.txt 2>err.txt; code=$?
  check "memory limit: exit 3 (<F>_ERROR), not a crash (got $code)" test $code -eq 3
  check "memory limit: the message file says the limit" grep -q "Memory limit of the run: 250 MiB (P memory_limit)" out/m.mess
  check "memory limit: MEMORY_1 at MECA_STATIQUE naming the limit" \
    grep -q "m.comm:8:8: error: not enough memory while running MECA_STATIQUE: the run's limit of 250 MiB (P memory_limit) is reached \[MEMORY_1\]" out/m.mess
  check "memory limit: the mesh written before came back readable" readable out/m.rmed
  sed -i 's/memory_limit 250/memory_limit 4096/' m.export
  "$stella" run m.export --quiet >out.txt 2>err.txt; code=$?
  check "memory limit of 4096 MiB: the same study ends OK (got $code)" test $code -eq 0
  printf 'P memory_limit lots\nF comm m.comm D 1\n' > bad.export
  "$stella" run bad.export --quiet >out.txt 2>err.txt; code=$?
  check "memory limit: a bad value is refused (exit 65)" test $code -eq 65
  check "memory limit: EXPORT_11" grep -q "EXPORT_11" err.txt
}

case "$case_name" in
  unwritable) unwritable ;;
  full-disk) full_disk ;;
  signal) signal_stop ;;
  failed-step) failed_step ;;
  time-limit) time_limit ;;
  killed) killed ;;
  memory-limit) memory_limit ;;
  *) echo "unknown case $case_name"; exit 2 ;;
esac
echo "$fails failure(s)"
[ $fails -eq 0 ]
