# Helpers shared by the shell tests in this folder; source it (after `set -uo pipefail`) with
#   source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/lib.sh"
# shellcheck shell=bash

fails=0
passes=0
check() { # description, condition...: prints ok/FAIL and counts them in $passes and $fails
  local what="$1"; shift
  if "$@"; then echo "ok   $what"; passes=$((passes + 1)); else echo "FAIL $what"; fails=$((fails + 1)); fi
}

# bar.mail: a plane-strain bar of two QUAD4 (2 x 1) with the groups LEFT (N1, N4), BOTTOM (N1)
# and RIGHT (M3, its right edge); $1, when given, is more ASTER blocks written before FIN.
write_bar_mesh() {
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
MAIL
  if [ $# -gt 0 ]; then printf '%s\n' "$1" >> bar.mail; fi
  echo FIN >> bar.mail
}

# The start of a study on the bar of write_bar_mesh (read on unit 20), written to the file $1:
# the model (D_PLAN), the material (ELAS content $2, by default E=200000.0, NU=0.3) and the load
# CH (LEFT fixed in X, BOTTOM in Y, a pressure of -100 on RIGHT).
write_bar_study() {
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
