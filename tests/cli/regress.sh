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

# --junit: valid XML, one testcase per check; the failure shows expected, actual, tolerance.
# --json: the same checks, SI beside the case's units. Both written even on drift (exit 1).
set +e
"$bin" regress "$tmp" --junit "$tmp/report.xml" --json >"$tmp/report.json"; rc=$?
set -e
[ $rc -eq 1 ] || fail "--junit/--json on drift gave exit $rc, want 1"
python3 - "$tmp/report.xml" "$tmp/report.json" <<'PY' || fail "JUnit/JSON report"
import json, sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag == "testsuites", root.tag
cases = root.findall("./testsuite/testcase")
assert len(cases) == int(root.get("tests")) and len(cases) > 10, len(cases)
bad = [c for c in cases if c.find("failure") is not None]
assert len(bad) == 1 == int(root.get("failures")), len(bad)
f = bad[0].find("failure")
assert bad[0].get("name") == "spin" and bad[0].get("classname") == "regress.drift"
for word in ("expected 6000 rpm", "actual", "tolerance"):
    assert word in f.get("message"), f.get("message")
j = json.load(open(sys.argv[2]))
assert j["failed"] == 1 and j["checks"] == len(cases)
spin = [c for k in j["cases"] for c in k["checks"] if not c["pass"]][0]
assert spin["quantity"] == "spin" and spin["si_unit"] == "rad/s" and abs(spin["expected_si"] - 628.3185) < 0.01
PY
set +e
"$bin" regress "$tmp" --junit "$tmp/drift.toml" >/dev/null 2>"$tmp/err"; rc=$?
set -e
[ $rc -eq 2 ] && grep -q -- "--junit" "$tmp/err" || fail "--junit over a case file: exit $rc, $(cat "$tmp/err")"
rm -f "$tmp/report.xml" "$tmp/report.json" "$tmp/err"

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
