#!/usr/bin/env bash
# `sweetspot list`: every built-in scenario, one line each with a description.
set -euo pipefail
bin="$1"
out=$("$bin" list)
fail() { echo "FAIL: $*"; echo "$out"; exit 1; }
for name in golf/driver golf/3-wood golf/7-iron golf/pw golf/sand-wedge golf/toe-hook golf/heel-slice \
            golf/into-wind golf/altitude baseball/line-drive baseball/home-run \
            baseball/grounder baseball/pop-up baseball/opposite-field; do
  line=$(grep -E "^$name " <<<"$out") || fail "$name missing"
  desc=$(sed -E "s|^$name +||" <<<"$line")
  [ ${#desc} -ge 10 ] || fail "$name has no description"
done
[ "$(wc -l <<<"$out")" -ge 14 ] || fail "fewer than 14 scenarios"
# Golf first, then baseball.
first_baseball=$(grep -n '^baseball/' <<<"$out" | head -1 | cut -d: -f1)
last_golf=$(grep -n '^golf/' <<<"$out" | tail -1 | cut -d: -f1)
[ "$last_golf" -lt "$first_baseball" ] || fail "golf scenarios not listed first"
# Without the assets the command says where it looked, exit 2.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
set +e
SWEETSPOT_ASSETS=/nonexistent "$bin" list 2>"$tmp/err"; rc=$?
set -e
[ $rc -eq 2 ] || fail "missing assets gave exit $rc, want 2"
grep -q "/nonexistent/" "$tmp/err" || fail "missing assets error does not name the folder it looked in"
echo "list: ok"
