#!/usr/bin/env bash
# `sweetspot validate`: the scorecard ends with "validate: N passed, M failed" and the exit
# code follows it (0 all pass, 1 any fails, --min-pass-rate relaxes that to a rate); --json
# and --junit carry every case; a bad library, tag or rate is exit 2 with nothing written.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cat >"$tmp/lib.toml" <<'TOML'
[sources.tm]
authors = "TrackMan"
title = "PGA Tour averages"
year = 2009
where = "https://blog.trackmangolf.com/trackman-average-tour-stats/"

[[case]]
id = "tm-driver-launch"
source = "tm"
tags = ["golf", "launch"]
fitted = true
scenario = "golf/driver"
quantity = "vertical_angle"
published = "10.9deg"
tolerance = "1.5deg"
why = "TrackMan's launch band"

[[case]]
id = "tm-driver-carry-wrong"
source = "tm"
tags = ["golf", "carry"]
scenario = "golf/driver"
set = ["world.name=none"]
quantity = "carry"
published = "350yd"
tolerance = "5yd"
why = "deliberately wrong: the test needs a failing case"
TOML

set +e
out=$("$bin" validate --library "$tmp/lib.toml" --junit "$tmp/v.xml"); rc=$?
set -e
[ $rc -eq 1 ] || fail "one failing case gave exit $rc, want 1"
tail -1 <<<"$out" | grep -qx "validate: 1 passed, 1 failed" || fail "last line: $(tail -1 <<<"$out")"
grep -q "tm-driver-carry-wrong .*FAIL" <<<"$out" || fail "failing case not listed"
python3 - "$tmp/v.xml" <<'PY' || fail "JUnit"
import sys, xml.etree.ElementTree as ET
r = ET.parse(sys.argv[1]).getroot()
assert r.get("tests") == "2" and r.get("failures") == "1", r.attrib
f = r.findall(".//failure")
assert len(f) == 1 and "350 yd" in f[0].get("message"), [x.attrib for x in f]
PY

"$bin" validate --library "$tmp/lib.toml" --min-pass-rate 50 >/dev/null || fail "50 % of 2 passing should meet --min-pass-rate 50"
set +e
"$bin" validate --library "$tmp/lib.toml" --min-pass-rate 51 >/dev/null; rc=$?
set -e
[ $rc -eq 1 ] || fail "--min-pass-rate 51 gave exit $rc, want 1"
# The one unfitted case fails: 0 % of them pass.
"$bin" validate --library "$tmp/lib.toml" --min-pass-rate 50 --min-unfitted-pass-rate 0 >/dev/null || fail "unfitted floor 0"
set +e
"$bin" validate --library "$tmp/lib.toml" --min-pass-rate 50 --min-unfitted-pass-rate 1 >/dev/null; rc=$?
set -e
[ $rc -eq 1 ] || fail "--min-unfitted-pass-rate 1 gave exit $rc, want 1"

set +e
"$bin" validate --library "$tmp/lib.toml" --json >"$tmp/v.json"; rc=$?
set -e
[ $rc -eq 1 ] || fail "--json exit $rc"
python3 - "$tmp/v.json" <<'PY' || fail "JSON"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["passed"] == 1 and j["failed"] == 1, j
c = {x["id"]: x for x in j["cases"]}
for k in ("id", "source", "tags", "fitted", "published", "got", "tolerance", "passed"):
    assert k in c["tm-driver-launch"], k
assert c["tm-driver-launch"]["fitted"] is True and c["tm-driver-carry-wrong"]["passed"] is False
assert abs(c["tm-driver-carry-wrong"]["published"] - 350 * 0.9144) < 1e-9
assert j["not_fitted"] == {"passed": 0, "failed": 1}, j["not_fitted"]
PY

"$bin" validate --library "$tmp/lib.toml" --filter launch | tail -1 | grep -qx "validate: 1 passed, 0 failed" || fail "--filter launch"

# Bad input: exit 2, a message naming the flag or file:line, no JUnit written.
expect2() {
  local what="$1" pattern="$2"; shift 2
  set +e
  msg=$("$bin" validate "$@" 2>&1 >/dev/null); rc=$?
  set -e
  [ $rc -eq 2 ] || fail "$what: exit $rc, want 2 ($msg)"
  grep -q -- "$pattern" <<<"$msg" || fail "$what: message '$msg' lacks '$pattern'"
}
expect2 "unknown tag" "--filter" --library "$tmp/lib.toml" --filter swimming
expect2 "rate out of range" "min-pass-rate" --library "$tmp/lib.toml" --min-pass-rate 101
expect2 "missing library" "nope" --library "$tmp/nope"
expect2 "unfitted floor alone" "min-pass-rate" --library "$tmp/lib.toml" --min-unfitted-pass-rate 10
sed 's/published = "350yd"/published = "350"/' "$tmp/lib.toml" >"$tmp/bad.toml"
expect2 "unitless value" "bad.toml:25" --library "$tmp/bad.toml" --junit "$tmp/bad.xml"
[ ! -e "$tmp/bad.xml" ] || fail "JUnit written for a bad library"
sed 's/set = \["world.name=none"\]/set = ["swing.speed=900mph"]/' "$tmp/lib.toml" >"$tmp/bad2.toml"
expect2 "condition out of range" "swing.speed" --library "$tmp/bad2.toml"

# The shipped library loads and runs (its pass rate is the CI's business).
set +e
out=$("$bin" validate); rc=$?
set -e
[ $rc -le 1 ] || fail "the shipped library: exit $rc"
tail -1 <<<"$out" | grep -qE "^validate: [0-9]+ passed, [0-9]+ failed$" || fail "shipped library's last line"
echo "validate: ok"
