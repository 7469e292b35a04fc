#!/usr/bin/env bash
# Every class of bad input of issue 5 exits 2 with a message naming where (file:line, flag
# or key) and the allowed range, prints nothing on stdout and leaves no output file.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# expect_bad "what" "needle1|needle2|..." -- sweetspot args...
expect_bad() {
  local what="$1" needles="$2"; shift 3
  set +e
  "$bin" "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  set -e
  [ $rc -eq 2 ] || fail "$what: exit $rc, want 2 (stderr: $(cat "$tmp/err"))"
  [ ! -s "$tmp/out" ] || fail "$what: printed on stdout: $(cat "$tmp/out")"
  local IFS='|'
  for n in $needles; do
    grep -qF -- "$n" "$tmp/err" || fail "$what: message lacks '$n': $(cat "$tmp/err")"
  done
}

scenario() { printf '%b' "$2" > "$tmp/$1"; }

scenario malformed.toml 'sport = "golf"\n[swing]\nspeed = "113mph\n'
expect_bad "malformed TOML" "malformed.toml:3|malformed TOML" -- shot "$tmp/malformed.toml"
scenario unknown_key.toml 'sport = "golf"\n[swing]\nsped = "113mph"\n'
expect_bad "unknown key" "unknown_key.toml:3|swing.sped|unknown key|swing.speed" -- shot "$tmp/unknown_key.toml"
expect_bad "unknown --set key" "--set swing.sped=1mph|unknown key" -- shot golf/driver --set swing.sped=1mph
scenario wrong_type.toml 'sport = "golf"\n[swing]\nspeed = true\n'
expect_bad "wrong type" "wrong_type.toml:3|swing.speed|wrong type|boolean" -- shot "$tmp/wrong_type.toml"
scenario no_unit.toml 'sport = "golf"\n[swing]\nspeed = "50"\n'
expect_bad "missing unit (file)" "no_unit.toml:3|missing unit|mph" -- shot "$tmp/no_unit.toml"
expect_bad "missing unit (--set)" "--set swing.attack_angle=-2|missing unit|deg" -- shot golf/driver --set swing.attack_angle=-2
expect_bad "unknown unit" "--set swing.speed=50knots|unknown unit 'knots'|m/s" -- shot golf/driver --set swing.speed=50knots
expect_bad "e out of range" "--e 1.5|0 <= impact.e <= 1" -- shot golf/driver --e 1.5
expect_bad "e_t out of range" "--set impact.e_t=-0.2|0 <= impact.e_t <= 1" -- shot golf/driver --set impact.e_t=-0.2
expect_bad "mu out of range" "--mu -0.1|0 <= impact.mu" -- shot golf/driver --mu -0.1
expect_bad "negative speed" "swing.speed|out of range|0.223694 mph <= swing.speed" -- shot golf/driver --set swing.speed=-10mph
expect_bad "speed bound" "swing.speed|201.324 mph|[0.1, 90] m/s" -- shot golf/driver --set swing.speed=400mph
expect_bad "negative mass" "ball.mass|out of range|10 g <= ball.mass" -- shot golf/driver --set ball.mass=-45g
expect_bad "spin bound" "pitch.spin|4000 rpm" -- shot baseball/line-drive --set pitch.spin=25000rpm
expect_bad "NaN" "--set swing.speed=nanmph|NaN" -- shot golf/driver --set swing.speed=nanmph
expect_bad "infinity" "--e inf|infinity" -- shot golf/driver --e inf
scenario nan.toml 'sport = "golf"\n[impact]\nmu = nan\n'
expect_bad "NaN in a file" "nan.toml:3|impact.mu|NaN" -- shot "$tmp/nan.toml"
expect_bad "missing file" "$tmp/absent.toml|not found" -- shot "$tmp/absent.toml"
expect_bad "unknown scenario" "unknown scenario 'golf/drivr'|golf/driver|baseball/line-drive" -- shot golf/drivr
expect_bad "unknown club" "club.name|spoon|driver|7-iron|putter" -- shot golf/driver --set club.name=spoon
expect_bad "unknown bat" "bat.name|corked|maple" -- shot baseball/line-drive --set bat.name=corked
scenario sport.toml 'sport = "cricket"\n'
expect_bad "unknown sport" "sport.toml:1|unknown sport 'cricket'|golf, baseball" -- shot "$tmp/sport.toml"
scenario nosport.toml '[swing]\nspeed = "100mph"\n'
expect_bad "missing sport" "missing key 'sport'|golf, baseball" -- shot "$tmp/nosport.toml"
expect_bad "wrong sport key" "swing.undercut|scenarios that swing a bat" -- shot golf/driver --set swing.undercut=10mm
expect_bad "bad --units" "--units|imperial, metric" -- shot golf/driver --units furlongs
expect_bad "unknown world" "world.name|moon" -- shot golf/driver --set world.name=moon
expect_bad "bad lie" "world.lie|not sand" -- shot golf/sand-wedge --set "world.ball_position=[100m,0m]"

# No partial output files: sweep and regress write nothing when the input is bad.
expect_bad "sweep bad e grid" "--e 0:2:3|<= 1" -- sweep golf/driver --e 0:2:3 --mu 0:1:2 --csv "$tmp/out.csv"
[ ! -e "$tmp/out.csv" ] || fail "sweep left a CSV after bad input"
expect_bad "sweep bad scenario key" "--set swing.speed=1|missing unit" -- sweep golf/driver --e 0:1:2 --mu 0:1:2 --set swing.speed=1 --csv "$tmp/out.csv"
[ ! -e "$tmp/out.csv" ] || fail "sweep left a CSV after bad input"
expect_bad "sweep unwritable csv" "$tmp/missing-dir/out.csv" -- sweep golf/driver --e 0.8:0.8:1 --mu 0.4:0.4:1 --csv "$tmp/missing-dir/out.csv"
expect_bad "fit bad target" "--target spin=30000rpm|20000 rpm" -- fit golf/driver --target spin=30000rpm
expect_bad "fit missing unit" "--target ball_speed=150|missing unit" -- fit golf/driver --target ball_speed=150
expect_bad "regress missing case" "$tmp/none.toml" -- regress "$tmp/none.toml"
[ -z "$(ls -A "$tmp" | grep -v -E '\.toml$|^(out|err)$')" ] || fail "stray files: $(ls -A "$tmp")"
echo "bad_input: ok"
