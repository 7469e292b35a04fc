#!/usr/bin/env bash
# `sweetspot regress`: passes on the repository's cases, exit 1 on drift with a FAIL row,
# --update rewrites pinned values atomically and leaves reference cases alone, exit 2 on a
# bad case with no file touched.
set -euo pipefail
bin="$1"
root="${SWEETSPOT_ROOT:?}"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

out=$("$bin" regress) || fail "regress on tests/regression failed: $out"
for c in bourg_billiards_exact bourg_bat_ball_printed friction_plane_textbook trackman_driver_launch golf_driver baseball_line_drive; do
  grep -q "^$c " <<<"$out" || fail "case $c missing from the table"
done
head -1 <<<"$out" | grep -qE "^case +quantity +expected +got +delta +tol +pass" || fail "table header"

cp "$root/tests/regression/golf_7-iron.toml" "$tmp/drift.toml"
cp "$root/tests/regression/bourg_billiards_printed.toml" "$tmp/ref.toml"
sed -i 's/^spin = "[0-9.]*rpm"/spin = "6000rpm"/' "$tmp/drift.toml"
set +e
out=$("$bin" regress "$tmp"); rc=$?
set -e
[ $rc -eq 1 ] || fail "drift gave exit $rc, want 1"
grep -E "^drift +spin " <<<"$out" | grep -q FAIL || fail "no FAIL row for the drifted spin"

cp "$tmp/ref.toml" "$tmp/ref.before"
"$bin" regress --update "$tmp" >/dev/null || fail "--update failed"
"$bin" regress "$tmp" >/dev/null || fail "still drifting after --update"
cmp -s "$tmp/ref.toml" "$tmp/ref.before" || fail "--update rewrote a reference case"
grep -q '^# Launch spin and velocity' "$tmp/drift.toml" || fail "--update lost the comments"
[ -z "$(ls -A "$tmp" | grep -v -E '^(drift.toml|ref.toml|ref.before)$')" ] || fail "temporary files left: $(ls -A "$tmp")"

# A bad case aborts before any file is written.
cp "$tmp/drift.toml" "$tmp/drift.before"
sed -i 's/^spin = "[0-9.]*rpm"/spin = "6000rpm"/' "$tmp/drift.toml"; cp "$tmp/drift.toml" "$tmp/drift.before"
printf 'sport = "golf"\n[swing]\nspeed = "fast"\n[expect]\nspin = "1rpm"\nspin_tol = "1rpm"\n' > "$tmp/zbad.toml"
set +e
"$bin" regress --update "$tmp" >/dev/null 2>"$tmp/err"; rc=$?
set -e
[ $rc -eq 2 ] || fail "bad case gave exit $rc, want 2"
grep -q "zbad.toml:3" "$tmp/err" || fail "bad case error lacks file:line: $(cat "$tmp/err")"
cmp -s "$tmp/drift.toml" "$tmp/drift.before" || fail "a file was rewritten although a case was bad"
echo "regress: ok"
