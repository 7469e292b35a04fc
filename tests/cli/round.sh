#!/usr/bin/env bash
# `sweetspot round`: a bot plays the Sweetspot Links headless; the DESIGN §9 JSON; the same
# seed gives the same card bit for bit; better golfers score lower on average; scripted
# swings; bad input exits 2 naming the file:line and range.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

json=$("$bin" round --bot tour --seed 3 --json)
[ "$json" = "$("$bin" round --bot tour --seed 3 --json)" ] || fail "same seed, different output"
python3 - "$json" <<'PY' || fail "json"
import json, sys
j = json.loads(sys.argv[1])
assert j["course"] == "Sweetspot Links" and j["seed"] == 3 and j["player"] == "tour bot", j
assert j["total_par"] == 12 and len(j["holes"]) == 3
total = 0
for h in j["holes"]:
    for k in ("number", "par", "strokes", "putts", "penalties", "holed", "shots"):
        assert k in h, k
    assert h["holed"], h
    assert h["strokes"] == len(h["shots"]) + h["penalties"], h
    assert h["putts"] == sum(1 for s in h["shots"] if s["lie"] == "green"), h
    for s in h["shots"]:
        assert s["lie"] in ("tee", "fairway", "rough", "sand", "green"), s
        assert s["end"] in ("rest", "holed", "water", "out_of_bounds"), s
        assert len(s["start_m"]) == 3 and len(s["rest_m"]) == 3 and s["to_pin_m"] >= 0
    assert h["shots"][-1]["end"] == "holed"
    total += h["strokes"]
assert j["total_strokes"] == total
PY

# Better golfers score lower, averaged over seeds (DESIGN §9 skills).
avg() {
  local sum=0
  for seed in 1 2 3 4; do
    sum=$((sum + $("$bin" round --bot "$1" --seed $seed --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["total_strokes"])')))
  done
  echo "$sum"
}
tour=$(avg tour); amateur=$(avg amateur); beginner=$(avg beginner)
echo "strokes over 4 rounds: tour $tour, amateur $amateur, beginner $beginner (par 48)"
[ "$tour" -lt "$amateur" ] || fail "tour $tour not below amateur $amateur"
[ "$amateur" -lt "$beginner" ] || fail "amateur $amateur not below beginner $beginner"
[ "$tour" -le 56 ] || fail "tour bot $tour strokes over 4 rounds: far above par 48"

# Scripted swings: a duffed tee shot into the pond on hole 1 (power 72 %): a penalty.
cat > "$tmp/swings.toml" <<'T'
[[stroke]]
club = "7-iron"
power = "72%"
T
out=$("$bin" round --swings "$tmp/swings.toml" --json)
python3 - "$out" <<'PY' || fail "scripted water"
import json, sys
j = json.loads(sys.argv[1])
h = j["holes"][0]
assert h["shots"][0]["end"] == "water" and h["penalties"] == 1 and h["strokes"] == 2, h
PY

# Bad input: exit 2, file:line, the allowed range.
printf '[[stroke]]\npower = "140%%"\n' > "$tmp/bad.toml"
set +e
msg=$("$bin" round --swings "$tmp/bad.toml" 2>&1); rc=$?
set -e
[ $rc -eq 2 ] || fail "power 140%: exit $rc"
grep -q "bad.toml:2" <<<"$msg" && grep -q "110" <<<"$msg" || fail "power 140%: message '$msg'"
set +e
msg=$("$bin" round nowhere 2>&1); rc=$?
set -e
[ $rc -eq 2 ] || fail "missing course: exit $rc"
set +e
msg=$("$bin" round --bot legend 2>&1); rc=$?
set -e
[ $rc -eq 2 ] && grep -q "tour, scratch, amateur, beginner" <<<"$msg" || fail "unknown skill: $rc '$msg'"

# The contests.
"$bin" round --mode ctp --balls 3 --json | python3 -c '
import json, sys
j = json.load(sys.stdin); assert j["mode"] == "ctp" and len(j["balls"]) == 3 and "best_to_pin_m" in j, j' || fail "ctp"
"$bin" round --mode long-drive --balls 3 --json | python3 -c '
import json, sys
j = json.load(sys.stdin); assert j["mode"] == "long-drive" and j["best_distance_m"] > 200, j' || fail "long drive"
# --plot: the session's dispersion as a 900 x 800 PNG, with the scorecard as usual.
plot_dir=$(mktemp -d)
"$bin" round --bot amateur --seed 2 --plot "$plot_dir/d.png" | grep -q "^total" || fail "--plot lost the scorecard"
"$bin" round --mode long-drive --balls 4 --plot "$plot_dir/ld.png" >/dev/null || fail "long-drive --plot"
python3 - "$plot_dir/d.png" "$plot_dir/ld.png" <<'PY' || fail "--plot PNG"
import struct, sys
for f in sys.argv[1:]:
    b = open(f, "rb").read()
    assert b[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", b[16:24]) == (900, 800), f
PY

# A course's `pin` moves the cup itself, not just the target: with hole 1's pin moved 4 m
# short of the world's own (still on the green) the bots hole out there (with the cup left
# at the world's pin, every putt would roll over the moved one until the pick-up).
sed '0,/^tee = \["0m", "0m"\] .*/s//tee = ["0m", "0m"]\npin = ["150m", "0m"]/' "$SWEETSPOT_ROOT/assets/courses/links.toml" > "$plot_dir/moved.toml"
grep -q '^pin = \["150m"' "$plot_dir/moved.toml" || fail "the moved-pin course was not made"
for seed in 1 2 3; do
  "$bin" round "$plot_dir/moved.toml" --seed $seed --json | python3 -c '
import json, sys
h = json.load(sys.stdin)["holes"][0]
assert h["holed"] and h["putts"] <= 3, h' || fail "moved pin, seed $seed: not holed"
done
# ... and a cup off the green is refused at its line.
sed '0,/^tee = \["0m", "0m"\] .*/s//tee = ["0m", "0m"]\npin = ["100m", "0m"]/' "$SWEETSPOT_ROOT/assets/courses/links.toml" > "$plot_dir/pond.toml"
set +e; msg=$("$bin" round "$plot_dir/pond.toml" 2>&1); rc=$?; set -e
[ $rc -eq 2 ] && grep -q "pond.toml:11: pin .* lies on water (allowed: green)" <<<"$msg" || fail "a pin in the pond: exit $rc, $msg"
rm -rf "$plot_dir"
echo "round: ok"
