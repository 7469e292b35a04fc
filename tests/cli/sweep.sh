#!/usr/bin/env bash
# `sweetspot sweep`: grid size and order, identical results for 1 and 2 threads, atomic CSV,
# no progress line when stderr is not a terminal, the grid bound checked before any work.
set -euo pipefail
bin="$1"
root="${SWEETSPOT_ROOT:?}"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" sweep golf/7-iron --e 0.7:0.9:5 --mu 0:0.6:4 --csv "$tmp/one.csv" --threads 1 >/dev/null 2>"$tmp/err1"
"$bin" sweep golf/7-iron --e 0.7:0.9:5 --mu 0:0.6:4 --csv "$tmp/two.csv" --threads 2 >/dev/null 2>"$tmp/err2"
[ "$(wc -l <"$tmp/one.csv")" -eq 21 ] || fail "want header + 20 rows, got $(wc -l <"$tmp/one.csv")"
cmp -s "$tmp/one.csv" "$tmp/two.csv" || fail "1 and 2 threads differ"
[ ! -s "$tmp/err1" ] || fail "stderr is not a terminal, yet got: $(cat "$tmp/err1")"
head -1 "$tmp/one.csv" | grep -q "^e,mu,ball_speed_mps" || fail "csv header"
sed -n 2p "$tmp/one.csv" | grep -q "^0.7,0," || fail "first row is not e=0.7, mu=0"
sed -n 21p "$tmp/one.csv" | grep -q "^0.9,0.6" || fail "last row is not e=0.9, mu=0.6"
python3 - "$tmp/one.csv" <<'PY' || fail "ball speed does not rise with e"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
by_mu = {}
for r in rows:
    by_mu.setdefault(r["mu"], []).append(float(r["ball_speed_mps"]))
for mu, speeds in by_mu.items():
    assert speeds == sorted(speeds), (mu, speeds)
PY
table=$("$bin" sweep baseball/line-drive --e 0.4:0.5:2 --mu 0.5:0.5:1 --no-flight)
[ "$(wc -l <<<"$table")" -eq 3 ] || fail "table rows"
# Units: one per column, named in the header, following --units; the grip threshold shown.
table=$("$bin" sweep golf/driver --e 0.8:0.8:1 --mu 0.01:2:2 --set impact.model=rigid)
head -1 <<<"$table" | grep -qE "ball mph .*mu_eff +mu_grip +carry yd" || fail "imperial header: $(head -1 <<<"$table")"
sed -n 2p <<<"$table" | grep -qE " live +0\.0[0-9]+ " || fail "mu 0.01 below the rigid driver's grip threshold: $(sed -n 2p <<<"$table")"
sed -n 3p <<<"$table" | grep -qE " none +0\.0[0-9]+ " || fail "mu 2 above the grip threshold: $(sed -n 3p <<<"$table")"
"$bin" sweep baseball/line-drive --e 0.5:0.5:1 --mu 0.5:0.5:1 --units metric | head -1 | grep -q "ball m/s .* carry m" || fail "metric header"
python3 - "$tmp/one.csv" <<'PY' || fail "mu_grip/grips columns"
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    g = float(r["mu_grip"])
    assert r["grips"] == ("true" if float(r["mu"]) >= g else "false"), r
PY

# --plot: a 1200 x 940 PNG beside the CSV; never over the scenario file.
"$bin" sweep golf/7-iron --e 0.7:0.9:3 --mu 0:0.3:4 --csv "$tmp/p.csv" --plot "$tmp/p.png" >/dev/null 2>&1
python3 - "$tmp/p.png" <<'PY' || fail "--plot PNG"
import struct, sys
b = open(sys.argv[1], "rb").read()
assert b[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h = struct.unpack(">II", b[16:24])
assert (w, h) == (1200, 940), (w, h)
assert len(b) > 20000, "a nearly blank image: %d bytes" % len(b)
PY
cp "$root/assets/scenarios/golf/7-iron.toml" "$tmp/s.toml"
set +e
"$bin" sweep "$tmp/s.toml" --e 0.7:0.9:2 --mu 0:0.3:2 --plot "$tmp/s.toml" >/dev/null 2>"$tmp/err"; rc=$?
set -e
[ $rc -eq 2 ] && grep -q -- "--plot" "$tmp/err" || fail "--plot over the scenario: exit $rc"
cmp -s "$tmp/s.toml" "$root/assets/scenarios/golf/7-iron.toml" || fail "--plot overwrote the scenario"

set +e
"$bin" sweep golf/driver --e 0:1:1000 --mu 0:1:1000 --csv "$tmp/big.csv" >/dev/null 2>"$tmp/err"; rc=$?
set -e
[ $rc -eq 2 ] || fail "oversized grid gave exit $rc"
grep -q "100000" "$tmp/err" || fail "oversized grid message lacks the limit"
[ ! -e "$tmp/big.csv" ] || fail "oversized grid wrote a file"
echo "sweep: ok"
