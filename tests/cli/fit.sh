#!/usr/bin/env bash
# `sweetspot fit`: reaches the TrackMan 7-iron launch, prints e, mu and residuals; says so
# and exits 1 when the target cannot be reached.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }

out=$("$bin" fit golf/7-iron --target ball_speed=120mph,launch_angle=16.3deg,spin=7097rpm) || fail "fit failed: $out"
grep -qE "e = 0\.[0-9]{4}, mu = [0-9.]+" <<<"$out" || fail "no e/mu line: $out"
for q in ball_speed launch_angle spin; do grep -q "^  $q " <<<"$out" || fail "no residual row for $q"; done
grep -q "target reached" <<<"$out" || fail "not reached: $out"
python3 - "$out" <<'PY' || fail "residuals too large"
import re, sys
rows = {m[0]: float(m[1]) for m in re.findall(r"^  (\w+) +\S+ \S+ +\S+ \S+ +(-?[0-9.]+) ", sys.argv[1], re.M)}
assert abs(rows["ball_speed"]) <= 1.0 and abs(rows["launch_angle"]) <= 0.5 and abs(rows["spin"]) <= 100, rows
PY

set +e
out=$("$bin" fit golf/driver --target ball_speed=200mph); rc=$?
set -e
[ $rc -eq 1 ] || fail "unreachable target gave exit $rc, want 1"
grep -q "cannot be reached" <<<"$out" || fail "unreachable target not reported: $out"
echo "fit: ok"
