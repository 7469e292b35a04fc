#!/usr/bin/env bash
# `sweetspot shot`: the table in both unit systems, DESIGN §6 JSON keys, GSPro and CSV
# output, overrides that move the numbers the right way, determinism.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }

table=$("$bin" shot golf/driver)
for s in "Ball speed" "mph" "Carry" "yd" "Spin rate" "rpm" "Smash factor" "coulomb"; do
  grep -q "$s" <<<"$table" || fail "table lacks '$s'"
done
metric=$("$bin" shot golf/driver --units metric)
grep -q "m/s" <<<"$metric" || fail "metric table lacks m/s"
grep -q " yd" <<<"$metric" && fail "metric table shows yards"

json=$("$bin" shot golf/driver --json)
python3 - "$json" <<'PY' || fail "json keys / values"
import json, sys
j = json.loads(sys.argv[1])
assert j["scenario"] == "golf/driver" and j["sport"] == "golf"
for k in ("ball_speed_mps", "vertical_angle_deg", "horizontal_angle_deg", "spin_rpm", "backspin_rpm",
          "sidespin_rpm", "spin_axis_deg", "smash_factor"):
    assert k in j["launch"], k
for k in ("e", "mu", "friction", "contact", "normal_impulse_Ns", "tangential_impulse_Ns", "energy_loss_J"):
    assert k in j["impact"], k
for k in ("carry_m", "total_m", "apex_m", "landing_angle_deg", "hang_time_s", "lateral_m", "end", "rest_position_m"):
    assert k in j["flight"], k
L = j["launch"]
assert 65 < L["ball_speed_mps"] < 80, L            # TrackMan tour driver: 74.7 m/s
assert 8 < L["vertical_angle_deg"] < 14, L
assert 2000 < L["spin_rpm"] < 3500, L
assert 1.35 < L["smash_factor"] < 1.52, L
assert j["impact"]["contact"] in ("grip", "slip")
assert j["flight"]["end"] == "rest"
assert len(j["flight"]["rest_position_m"]) == 3
PY
[ "$json" = "$("$bin" shot golf/driver --json)" ] || fail "two runs differ"

# --e and --mu are shorthands of --set impact.e / impact.mu; a lower e gives less ball speed.
speed() { "$bin" shot golf/driver --json "$@" | python3 -c 'import json,sys; print(json.load(sys.stdin)["launch"]["ball_speed_mps"])'; }
lo=$(speed --e 0.7); hi=$(speed --e 0.9)
python3 -c "import sys; sys.exit(0 if $lo < $hi else 1)" || fail "--e 0.7 ($lo) not slower than --e 0.9 ($hi)"
[ "$(speed --e 0.7)" = "$(speed --set impact.e=0.7)" ] || fail "--e differs from --set impact.e"
fric=$("$bin" shot golf/7-iron --json --mu 0.1 --set impact.friction=textbook)
python3 -c 'import json,sys; j=json.loads(sys.argv[1]); assert j["impact"]["friction"]=="textbook" and j["impact"]["mu"]==0.1' "$fric" \
  || fail "--mu / impact.friction not applied"
fast=$("$bin" shot golf/driver --set swing.speed=120mph --json)
python3 -c "import json,sys; assert json.loads(sys.argv[1])['launch']['ball_speed_mps'] > $(speed)" "$fast" || fail "--set swing.speed"

gspro=$("$bin" shot golf/7-iron --gspro)
python3 - "$gspro" <<'PY' || fail "gspro message"
import json, sys
j = json.loads(sys.argv[1])
assert j["APIversion"] == "1"
for k in ("Speed", "SpinAxis", "TotalSpin", "BackSpin", "SideSpin", "HLA", "VLA", "CarryDistance"):
    assert k in j["BallData"], k
for k in ("Speed", "AngleOfAttack", "FaceToTarget", "Lie", "Loft", "Path", "SpeedAtImpact",
          "VerticalFaceImpact", "HorizontalFaceImpact", "ClosureRate"):
    assert k in j["ClubData"], k
assert abs(j["ClubData"]["Speed"] - 90) < 1e-9 and abs(j["ClubData"]["AngleOfAttack"] + 4.3) < 1e-9
assert 100 < j["BallData"]["Speed"] < 140
PY

csv=$("$bin" shot baseball/line-drive --csv)
head -1 <<<"$csv" | grep -q "launch_speed,launch_angle,spray_angle" || fail "baseball csv header"
head -1 <<<"$csv" | grep -q "hit_distance_sc" || fail "baseball csv distance column"
[ "$(wc -l <<<"$csv")" -eq 2 ] || fail "csv should be header + one row"
hdr=$(head -1 <<<"$csv" | tr ',' '\n' | wc -l); row=$(tail -1 <<<"$csv" | tr ',' '\n' | wc -l)
[ "$hdr" -eq "$row" ] || fail "csv header has $hdr columns, row $row"
"$bin" shot golf/driver --csv --units metric | head -1 | grep -q "carry_m" || fail "metric golf csv"

# Baseball: the home run clears the fence on the ballpark.
"$bin" shot baseball/home-run --json | python3 -c 'import json,sys; j=json.load(sys.stdin); assert j["flight"]["end"]=="home_run", j["flight"]' \
  || fail "home run"
# Output modes are exclusive.
set +e
"$bin" shot golf/driver --json --csv >/dev/null 2>&1; rc=$?
set -e
[ $rc -eq 2 ] || fail "--json --csv accepted (exit $rc)"
# world.ball_position is measured from the world's origin, its x and z included.
wdir=$(mktemp -d); trap 'rm -rf "$wdir"' EXIT
printf 'usemtl fairway\nv -200 0 -100\nv -200 0 100\nv 600 0 100\nv 600 0 -100\nf 1 2 3\nf 1 3 4\n' > "$wdir/p.obj"
printf 'sport = "golf"\nmesh = "p.obj"\n' > "$wdir/at0.toml"
printf 'sport = "golf"\nmesh = "p.obj"\norigin = ["100m", "0m", "0m"]\n' > "$wdir/at100.toml"
x0=$("$bin" shot golf/driver --set world.name="$wdir/at0.toml" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["flight"]["rest_position_m"][0])')
x100=$("$bin" shot golf/driver --set world.name="$wdir/at100.toml" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["flight"]["rest_position_m"][0])')
python3 -c "assert abs(($x100) - ($x0) - 100.0) < 1e-6, ($x0, $x100)" || fail "the world's origin does not move the ball ($x0 -> $x100)"

# --sound: the strike's sound as a WAV, the same bytes for the same shot; refused, naming the
# flag, where there is no strike to sound or no file can be written.
tmp="$wdir/sound"; mkdir "$tmp"
"$bin" shot baseball/line-drive --sound "$tmp/crack.wav" > /dev/null || fail "--sound"
"$bin" shot baseball/line-drive --sound "$tmp/again.wav" > /dev/null
cmp -s "$tmp/crack.wav" "$tmp/again.wav" || fail "--sound: not deterministic"
python3 - "$tmp/crack.wav" <<'PY' || fail "--sound: not a 48 kHz 16-bit mono WAV of 0.6 s"
import sys, wave
w = wave.open(sys.argv[1])
assert (w.getnchannels(), w.getsampwidth(), w.getframerate(), w.getnframes()) == (1, 2, 48000, 28800)
PY
set +e
msg=$("$bin" shot baseball/line-drive --sound "$tmp" 2>&1); rc=$?
[ $rc -eq 2 ] && echo "$msg" | grep -q -- "--sound" || fail "--sound to a folder: rc $rc: $msg"
msg=$("$bin" shot golf/driver --set impact.model=rigid --sound "$tmp/rigid.wav" 2>&1); rc=$?
[ $rc -eq 2 ] && echo "$msg" | grep -q -- "--sound" || fail "--sound without a contact time: rc $rc: $msg"
msg=$("$bin" shot golf/driver --sound "$tmp/crack.mp3" 2>&1); rc=$?
[ $rc -eq 2 ] && echo "$msg" | grep -q -- "name it FILE.wav" || fail "--sound to an .mp3 name: rc $rc: $msg"
# e_t is the rigid solve's input: set under the compliant contact, the table says it is unused.
"$bin" shot golf/driver --set impact.e_t=1 | grep -q "warning: impact.e_t acts in the rigid model only" ||
  fail "impact.e_t under the compliant contact passed unremarked"
set -e
[ ! -e "$tmp/rigid.wav" ] && [ ! -e "$tmp/crack.mp3" ] || fail "--sound wrote a file it refused"
echo "shot: ok"
