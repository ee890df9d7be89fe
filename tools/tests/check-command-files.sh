#!/usr/bin/env bash
# `stella check` on every command file of the repository (test cases, catalogue examples,
# language corpus files that are valid studies): each must validate against the catalogue.
# Usage: check-command-files.sh PATH/TO/stella REPOSITORY-ROOT
set -uo pipefail
stella="$(readlink -f "$1")"
root="$2"
passed=0
failed=0
while IFS= read -r -d '' comm; do
  if "$stella" check "$comm" >/dev/null 2>"${TMPDIR:-/tmp}/stella-check.err"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAIL $comm"
    cat "${TMPDIR:-/tmp}/stella-check.err"
  fi
done < <(find "$root/testcases" "$root/catalog/tests/data" -name '*.comm' -print0 2>/dev/null)
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
