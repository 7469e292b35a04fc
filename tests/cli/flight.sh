#!/usr/bin/env bash
# `sweetspot flight`: JSON keys of DESIGN §6, determinism, the TrackMan driver row, and bad
# input -> exit 2 with the flag named.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }

out=$("$bin" flight --sport golf --ball-speed 167mph --launch-angle 10.9deg --spin 2686rpm --json)
python3 - "$out" <<'PY' || fail "json keys / values"
import json, sys
j = json.loads(sys.argv[1])
for k in ("scenario", "sport", "launch", "flight"):
    assert k in j, k
for k in ("ball_speed_mps", "vertical_angle_deg", "horizontal_angle_deg", "spin_rpm", "backspin_rpm",
          "sidespin_rpm", "spin_axis_deg", "smash_factor"):
    assert k in j["launch"], k
f = j["flight"]
for k in ("carry_m", "total_m", "apex_m", "landing_angle_deg", "hang_time_s", "lateral_m", "end", "rest_position_m"):
    assert k in f, k
assert j["sport"] == "golf"
assert j["world"] == "golf_hole", j["world"]  # the sport's default world
assert abs(j["launch"]["ball_speed_mps"] - 74.65) < 0.01
# TrackMan PGA driver: 275 yd carry (251.5 m) within 4 %
assert abs(f["carry_m"] - 251.46) / 251.46 < 0.04, f["carry_m"]
assert f["total_m"] >= f["carry_m"]
assert f["end"] == "rest"
assert len(f["rest_position_m"]) == 3
PY

again=$("$bin" flight --sport golf --ball-speed 167mph --launch-angle 10.9deg --spin 2686rpm --json)
[ "$out" = "$again" ] || fail "repeated runs differ"

# --world none: the flat fairway; the carry is the same to within the hole's undulation.
flat=$("$bin" flight --sport golf --ball-speed 167mph --launch-angle 10.9deg --spin 2686rpm --world none --json)
python3 - "$out" "$flat" <<'PY' || fail "--world none"
import json, sys
hole, flat = (json.loads(a) for a in sys.argv[1:3])
assert flat["world"] == "none"
assert abs(hole["flight"]["carry_m"] - flat["flight"]["carry_m"]) < 0.01 * flat["flight"]["carry_m"]
PY

# Baseball, thinner air goes farther; wind from --set. The air is compared on flat ground
# (--world none): the ballpark's bounds end at 130 m, and Denver's 450 ft leaves the world
# there (a step whose contact search ran before the bounds check would let it "land" at
# 137 m, past the bounds).
park=$("$bin" flight --sport baseball --ball-speed 103mph --launch-angle 28deg --spin 2000rpm --json)
sea=$("$bin" flight --sport baseball --ball-speed 103mph --launch-angle 28deg --spin 2000rpm --world none --json)
den=$("$bin" flight --sport baseball --ball-speed 103mph --launch-angle 28deg --spin 2000rpm --world none \
  --set environment.altitude=1609m --json)
head=$("$bin" flight --sport baseball --ball-speed 103mph --launch-angle 28deg --spin 2000rpm --world none \
  --set environment.wind_speed=10mph --set environment.wind_direction=180deg --json)
python3 - "$sea" "$den" "$head" "$park" <<'PY' || fail "baseball altitude / wind"
import json, sys
sea, den, head, park = (json.loads(a)["flight"]["carry_m"] for a in sys.argv[1:5])
assert 415 <= sea / 0.3048 <= 425, sea / 0.3048
assert abs(park - sea) < 0.01, (park, sea)
assert 1.05 <= den / sea <= 1.08, den / sea
assert head < sea - 5, (head, sea)
assert json.loads(sys.argv[4])["flight"]["end"] == "home_run"
PY

# The readable table uses display units.
table=$("$bin" flight --sport golf --ball-speed 120mph --launch-angle 16.3deg --spin 7097rpm)
echo "$table" | grep -q "Carry" || fail "table has no carry"
echo "$table" | grep -q " yd" || fail "table not in yards"

# Bad input: exit 2, message names the flag and the allowed range.
expect_bad() {
  local want="$1"; shift
  set +e
  err=$("$bin" flight "$@" 2>&1 >/dev/null)
  code=$?
  set -e
  [ "$code" -eq 2 ] || fail "exit $code (want 2) for: $*"
  echo "$err" | grep -qF -- "$want" || fail "message '$err' does not mention '$want' for: $*"
}
expect_bad "--ball-speed" --sport golf --ball-speed 500mph --launch-angle 10deg --spin 2500rpm
expect_bad "[0, 150] m/s" --sport golf --ball-speed 500mph --launch-angle 10deg --spin 2500rpm
expect_bad "--launch-angle" --sport golf --ball-speed 150mph --launch-angle 10 --spin 2500rpm
expect_bad "missing unit" --sport golf --ball-speed 150 --launch-angle 10deg --spin 2500rpm
# Topspin flies: a grounder's own launch numbers replay (spin axis 180 deg).
"$bin" flight --sport baseball --ball-speed 95mph --launch-angle -5deg --spin 1500rpm --spin-axis 180deg --json >/dev/null \
  || fail "topspin launch refused"
expect_bad "--spin" --sport golf --ball-speed 150mph --launch-angle 10deg --spin 2500furlongs
expect_bad "humidity" --sport golf --ball-speed 150mph --launch-angle 10deg --spin 2500rpm --set environment.humidity=150%
expect_bad "allowed" --sport golf --ball-speed 150mph --launch-angle 10deg --spin 2500rpm --set environment.colour=blue
expect_bad "ferguson2022" --sport golf --ball-speed 150mph --launch-angle 10deg --spin 2500rpm --aero magic
expect_bad "--world" --sport golf --ball-speed 150mph --launch-angle 10deg --spin 2500rpm --world moon
expect_bad "golf_hole" --sport golf --ball-speed 150mph --launch-angle 10deg --spin 2500rpm --world moon
expect_bad "sport" --sport cricket --ball-speed 150mph --launch-angle 10deg --spin 2500rpm
echo "ok"
