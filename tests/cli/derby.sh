#!/usr/bin/env bash
# `sweetspot pitch` and `sweetspot derby`: the DESIGN §9 JSON, better batters hit more home
# runs, same seed same output, the spray chart, bad input exits 2 with the range.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" pitch four-seam --json | python3 -c '
import json, sys
j = json.load(sys.stdin)
for k in ("type", "release_speed_mps", "spin_rpm", "flight_time_s", "plate_position_m", "induced_vertical_break_m", "horizontal_break_m"):
    assert k in j, k
assert j["type"] == "four-seam" and 0.38 < j["flight_time_s"] < 0.43, j
assert 0.30 < j["induced_vertical_break_m"] < 0.52, j' || fail "pitch json"
# The sinker's seam-shifted wake: a share of its run and drop (arm side, down), tan 22.1° of
# its ~14.5 in of Magnus movement across it (4.5 in of run, 3.6 in of drop).
"$bin" pitch sinker --json | python3 -c '
import json, sys
j = json.load(sys.stdin)
assert -0.14 < j["seam_wake_horizontal_m"] < -0.08 and -0.12 < j["seam_wake_vertical_m"] < -0.06, j' || fail "sinker wake json"
fast=$("$bin" pitch four-seam --speed 100mph --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["flight_time_s"])')
slow=$("$bin" pitch four-seam --speed 85mph --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["flight_time_s"])')
python3 -c "assert $fast < $slow" || fail "a faster pitch must arrive sooner ($fast vs $slow)"

for args in "pitch four-seam --speed 130mph" "pitch knuckler" "derby --outs 0" "derby --bot legend" "derby --mode tee-ball"; do
  set +e
  msg=$("$bin" $args 2>&1); rc=$?
  set -e
  [ $rc -eq 2 ] || fail "$args: exit $rc"
  grep -Eq "allowed|out of range" <<<"$msg" || fail "$args: no range in '$msg'"
done

json=$("$bin" derby --bot pro --seed 4 --outs 5 --json)
[ "$json" = "$("$bin" derby --bot pro --seed 4 --outs 5 --json)" ] || fail "same seed, different derby"
python3 - "$json" <<'PY' || fail "derby json"
import json, sys
j = json.loads(sys.argv[1])
assert j["seed"] == 4 and j["outs"] == 5 and "home_runs" in j
for s in j["swings"]:
    for k in ("pitch", "timing_ms", "contact", "launch", "flight", "outcome", "barrel", "hard_hit"):
        assert k in s, k
    for k in ("type", "speed_mps", "spin_rpm", "plate_position_m"):
        assert k in s["pitch"], k
    assert (s["launch"] is None) == (not s["contact"])
    assert s["outcome"] in ("strike", "foul", "out", "single", "double", "triple", "home_run"), s["outcome"]
assert j["home_runs"] == sum(1 for s in j["swings"] if s["outcome"] == "home_run")
assert len(j["swings"]) == j["outs"] + j["home_runs"]
PY

# Better batters hit more home runs, over several seeds.
hrs() {
  local sum=0
  for seed in 1 2 3 4; do
    sum=$((sum + $("$bin" derby --bot "$1" --seed $seed --outs 8 --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["home_runs"])')))
  done
  echo $sum
}
pro=$(hrs pro); amateur=$(hrs amateur)
echo "home runs over 4 derbies of 8 outs: pro $pro, amateur $amateur"
[ "$pro" -gt "$amateur" ] || fail "pro $pro not above amateur $amateur"

"$bin" derby --seed 2 --outs 4 --plot "$tmp/spray.png" > /dev/null
[ -s "$tmp/spray.png" ] || fail "no spray chart"
"$bin" derby --mode at-bat --seed 3 --json | python3 -c '
import json, sys
j = json.load(sys.stdin); assert j["mode"] == "at-bat" and j["result"] and j["balls"] <= 4 and j["strikes"] <= 3, j' || fail "at-bat"
# The at-bat's text gives each pitch's count, from 0-0; a derby's fair balls say where they went.
"$bin" derby --mode at-bat --seed 3 | head -1 | grep -q '^0-0 ' || fail "at-bat: no count before the first pitch"
"$bin" derby --bot pro --seed 2 | grep -E ' (home_run|double|single|triple|out)' | grep -vqE ' to (LF|CF|RF|P|C|1B|2B|3B|SS)' \
  && fail "a derby's fair ball without its direction"
# In a derby a fair ball short of the fence is an out, whatever it would have been in a game.
"$bin" derby --seed 3 | grep -qE 'ft  (single|double|triple)' && fail "a derby's hit called a hit, not an out"
"$bin" derby --seed 3 | grep -qE 'ft  out  \(in a game: (Single|Double|Triple) ' || fail "a derby's out that was a hit does not say so"
echo "derby: ok"
