#!/usr/bin/env bash
# The command line helps a user who mistypes: the nearest subcommand and command name are
# suggested, and `stella --version` names the version and the commit it was built from.
# Usage: cli-usability.sh PATH/TO/stella SOURCE_DIR
set -uo pipefail
source "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/lib.sh"
stella="$(readlink -f "$1")"
source_dir="$2"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT

"$stella" chek x.comm >"$out" 2>&1; code=$?
check "stella chek: exit 64" test $code -eq 64
check "stella chek: suggests check" grep -q 'did you mean `stella check`' "$out"

"$stella" catalog DEFI_CONTAKT >"$out" 2>&1; code=$?
check "catalog DEFI_CONTAKT: exit 64" test $code -eq 64
check "catalog DEFI_CONTAKT: suggests DEFI_CONTACT" grep -q 'did you mean DEFI_CONTACT?' "$out"

"$stella" --version >"$out" 2>&1; code=$?
check "--version: exit 0" test $code -eq 0
check "--version: names the version" grep -Eq '^stella [0-9]+\.[0-9]+' "$out"
if commit="$(git -C "$source_dir" rev-parse --short=12 HEAD 2>/dev/null)"; then
  check "--version: names the commit $commit" grep -q "commit $commit" "$out"
else
  check "--version: says it was not built from git" grep -q "not built from a git checkout" "$out"
fi
[ $fails -eq 0 ]
