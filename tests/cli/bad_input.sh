#!/usr/bin/env bash
# Every class of bad input exits 2 with a message naming where (file:line, flag
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
expect_bad "splash off the sand" "swing.sand_entry|a splash is played from sand" -- shot golf/pw --set swing.sand_entry=1in
expect_bad "splash past 6 in" "swing.sand_entry|6 in" -- shot golf/sand-wedge --set swing.sand_entry=7in
expect_bad "splash too slow" "swing.speed: the sand before the ball takes 45 %" -- shot golf/sand-wedge --set swing.speed=0.3mph --set swing.sand_entry=6in

# No partial output files: sweep and regress write nothing when the input is bad.
expect_bad "sweep bad e grid" "--e 0:2:3|<= 1" -- sweep golf/driver --e 0:2:3 --mu 0:1:2 --csv "$tmp/out.csv"
[ ! -e "$tmp/out.csv" ] || fail "sweep left a CSV after bad input"
expect_bad "sweep bad scenario key" "--set swing.speed=1|missing unit" -- sweep golf/driver --e 0:1:2 --mu 0:1:2 --set swing.speed=1 --csv "$tmp/out.csv"
[ ! -e "$tmp/out.csv" ] || fail "sweep left a CSV after bad input"
expect_bad "sweep unwritable csv" "$tmp/missing-dir/out.csv" -- sweep golf/driver --e 0.8:0.8:1 --mu 0.4:0.4:1 --csv "$tmp/missing-dir/out.csv"
expect_bad "fit bad target" "--target spin=30000rpm|20000 rpm" -- fit golf/driver --target spin=30000rpm
expect_bad "fit missing unit" "--target ball_speed=150|missing unit" -- fit golf/driver --target ball_speed=150
expect_bad "regress missing case" "$tmp/none.toml" -- regress "$tmp/none.toml"

# One rule for empty values, repeated keys, ignored flags and partial launches.
expect_bad "empty --world" "--world|an empty value" -- flight --ball-speed 160mph --launch-angle 10deg --spin 2500rpm --world ""
expect_bad "empty --spin-axis" "--spin-axis|an empty value" -- flight --ball-speed 160mph --launch-angle 10deg --spin 2500rpm --spin-axis ""
expect_bad "empty --plot" "--plot|an empty value" -- derby --plot ""
expect_bad "empty --host" "--host|an empty value" -- send --host "" "$tmp/none.jsonl"
expect_bad "key set twice" "--set impact.e=0.5|already set by --set impact.e=2" -- shot golf/driver --set impact.e=2 --set impact.e=0.5
expect_bad "--e over --set" "--e 0.5|already set by --set impact.e=2" -- shot golf/driver --set impact.e=2 --e 0.5
expect_bad "fit --set e" "--set impact.e=0.5|the fit solves" -- fit golf/driver --target ball_speed=160mph --set impact.e=0.5
expect_bad "fit stray comma" "stray comma" -- fit golf/driver --target ball_speed=160mph,
expect_bad "round --balls in stroke play" "--balls|ctp or long-drive" -- round --balls 5
expect_bad "derby --swings" "--swings|practice" -- derby --swings 5
expect_bad "practice --outs" "--outs|only the derby" -- derby --mode practice --outs 5
expect_bad "derby --outs range" "--outs: 0 is out of range|[1, 50]" -- derby --outs 0
# A count refused in one wording, whether it is out of range or no whole number at all.
expect_bad "game --games range" "--games: 2000000 is out of range|[1, 1000]" -- derby --mode game --games 2000000
expect_bad "game --games not whole" "--games: '1e20' is not a whole number|[1, 1000]" -- derby --mode game --games 1e20
# An option given twice is named, with how often, not CLI11's "At Most 1 required".
expect_bad "derby --seed twice" "--seed: given 2 times|give it once" -- derby --seed 1 --seed 2
expect_bad "game --swings" "--swings: a game counts innings" -- derby --mode game --swings 5
expect_bad "render partial launch" "--launch-angle is required" -- render --ball-speed 100mph -o "$tmp/x.png"
[ ! -e "$tmp/x.png" ] || fail "render wrote a PNG for a partial launch"
scenario half_launch.toml 'sport = "golf"\n[launch]\nball_speed = "100mph"\n'
expect_bad "launch without angle" "half_launch.toml:3|launch.vertical_angle is missing" -- shot "$tmp/half_launch.toml"
scenario club_launch.toml 'sport = "golf"\n[club]\nname = "7-iron"\n[launch]\nball_speed = "100mph"\nvertical_angle = "10deg"\nspin = "3000rpm"\n'
expect_bad "club and launch" "club_launch.toml:3|club.name|no strike" -- shot "$tmp/club_launch.toml"
expect_bad "unknown command" "unknown command 'fly'|shot, flight" -- fly
expect_bad "pitch range in its unit" "--spin 9000rpm|[0, 4000] rpm" -- pitch four-seam --spin 9000rpm
expect_bad "course path" "/dev/zero|not a regular file" -- round /dev/zero
expect_bad "unknown course" "unknown course 'linx'|links" -- round linx
printf 'sport = "golf"\nname = "x"\nmesh = "x.obj"\n' > "$tmp/sport_world.toml"
sed -i 's/sport = "golf"/sport = "tennis"/' "$tmp/sport_world.toml"
expect_bad "world sport" "sport_world.toml:1|unknown sport 'tennis'" -- shot golf/driver --set world.name="$tmp/sport_world.toml"
printf 'sport = "golf"\nmesh = "x.obj"\npin = ["1e300m", "0m", "0m"]\n' > "$tmp/far_world.toml"
expect_bad "world pin far away" "far_world.toml:3|pin|out of range" -- shot golf/driver --set world.name="$tmp/far_world.toml"
long=$(head -c 100000 /dev/zero | tr '\0' 9)
expect_bad "a 100 kB value" "more characters" -- shot golf/driver --set "swing.speed=${long}mph"
[ "$(wc -c < "$tmp/err")" -lt 2000 ] || fail "a 100 kB value is echoed whole: $(wc -c < "$tmp/err") bytes"
expect_bad "a newline in a value" 'swing.speed=113mph\n' -- shot golf/driver --set $'swing.speed=113mph\n'
[ "$(wc -l < "$tmp/err")" = 1 ] || fail "a newline in a value split the message: $(cat "$tmp/err")"
expect_bad "usage error on one line" "--world|run with --help" -- flight --ball-speed 160mph --launch-angle 10deg --spin 2500rpm --world ""
[ "$(wc -l < "$tmp/err")" = 1 ] || fail "a usage error takes $(wc -l < "$tmp/err") lines"
expect_bad "play's game options headless" "--mode needs the game window" -- play --mode golf
expect_bad "play: a negative gimme" "--gimme|-1" -- play --mode golf --gimme -1
expect_bad "round: skins alone" "--format skins|2 to 4 players|not 1" -- round --format skins --bot tour
# The course, its tee set and the quality are checked at start, display or not.
expect_bad "play: an unknown course" "--course: unknown course 'nope'|national" -- play --mode golf --course nope
expect_bad "play: an unknown tee set" "--tees|'purple'|blue, white, red" -- play --mode golf --tees purple
expect_bad "play: an unknown quality" "--quality ultra|auto, low, high" -- play --quality ultra
expect_bad "play: one handicap too many" "--handicap: 2 given for 1 player (yours)" -- play --mode golf --bot none --handicap 3 --handicap 4
expect_bad "play: a save into a missing folder" "--save|does not exist" -- play --mode golf --save "$tmp/no/such/r.json"
expect_bad "play: screenshots into a missing folder" "--shots-dir|no such folder" -- play --shots-dir "$tmp/no/such"
expect_bad "play: a resumed round's course set again" "--resume|--course cannot change" -- play --mode golf --resume "$tmp/none.json" --course links
expect_bad "play: a resumed round's bots set again" "--resume|--bot cannot change" -- play --mode golf --resume "$tmp/none.json" --bot tour
# A clip too large to draw is refused before anything is drawn or written, the image included.
expect_bad "render: a clip of hours" "--video|pixels|lower --fps" -- render golf/driver -o "$tmp/big.png" --video "$tmp/big.mp4" --width 8192 --height 8192 --fps 240 --slow-motion 1000
[ ! -e "$tmp/big.png" ] && [ ! -e "$tmp/big.mp4" ] || fail "render wrote part of a refused clip"
expect_bad "render: a clip's setting without a clip" "--fps|give it with --video" -- render golf/driver -o "$tmp/a.png" --fps 10
expect_bad "render: a launch flag with a scenario" "--spin-axis|sets its own" -- render golf/driver -o "$tmp/a.png" --spin-axis 30deg
expect_bad "a golf shot on the ballpark" "'ballpark' is a baseball world" -- flight --ball-speed 100mph --launch-angle 20deg --spin 2000rpm --world ballpark
# regress --update writes all the case files it changes or none: a read-only one among them
# is refused before the first is touched.
cp "$SWEETSPOT_ROOT/tests/regression/golf_pw.toml" "$tmp/a_case.toml"
cp "$SWEETSPOT_ROOT/tests/regression/golf_driver.toml" "$tmp/b_case.toml"
sed -i 's/^\(ball_speed = "\)[0-9.]*/\1100/' "$tmp/a_case.toml" "$tmp/b_case.toml"
chmod 444 "$tmp/b_case.toml"
before=$(md5sum "$tmp/a_case.toml")
set +e; "$bin" regress "$tmp/a_case.toml" "$tmp/b_case.toml" --update >"$tmp/out" 2>"$tmp/err"; rc=$?; set -e
[ $rc -eq 2 ] || fail "regress --update with a read-only case: exit $rc, want 2 ($(cat "$tmp/err"))"
grep -qF "no case file was changed" "$tmp/err" || fail "regress --update: $(cat "$tmp/err")"
[ "$(md5sum "$tmp/a_case.toml")" = "$before" ] || fail "regress --update rewrote one case before refusing another"
chmod 644 "$tmp/b_case.toml"
expect_bad "a case given twice" "given twice" -- regress "$SWEETSPOT_ROOT/tests/regression/golf_pw.toml" "$SWEETSPOT_ROOT/tests/regression/golf_pw.toml"
export SWEETSPOT_ASSETS=""
expect_bad "empty SWEETSPOT_ASSETS" "SWEETSPOT_ASSETS is set but empty" -- list
unset SWEETSPOT_ASSETS
# A broken data file of the assets is named itself, not the scenario that led to it.
assets_copy=$(mktemp -d)
cp -r "$SWEETSPOT_ROOT/assets/." "$assets_copy/"
sed -i '0,/^mu = /s/^mu = .*/mu = 9/' "$assets_copy/materials.toml"
export SWEETSPOT_ASSETS="$assets_copy"
expect_bad "a broken materials.toml" "materials.toml:|mu = 9|[0, 2]" -- shot golf/driver
grep -q "driver.toml" "$tmp/err" && fail "a broken materials.toml blamed on the scenario: $(cat "$tmp/err")"
cp "$SWEETSPOT_ROOT/assets/materials.toml" "$assets_copy/materials.toml"
sed -i '0,/^layer_drag = /s/^layer_drag = .*/layer_drag = 0.5/' "$assets_copy/materials.toml"
expect_bad "a turf layer beyond its range" "materials.toml:|layer_drag|0.5|0.1" -- shot golf/driver
cp "$SWEETSPOT_ROOT/assets/materials.toml" "$assets_copy/materials.toml"
# with_broken FILE SED_EXPR expect_bad-args...: FILE of the assets copy broken by SED_EXPR for
# one expect_bad, then restored.
with_broken() {
  local file="$1" expr="$2"; shift 2
  sed -i "$expr" "$assets_copy/$file"
  expect_bad "$@"
  cp "$SWEETSPOT_ROOT/assets/$file" "$assets_copy/$file"
}
# sports.toml's names are checked against the other assets at their own line.
with_broken sports.toml '0,/^rules = "golf"/s//rules = "baseball"/' \
  "golf played by baseball's rules" "sports.toml:|rules|does not go with impactor 'club'" -- round links --calm
with_broken sports.toml '0,/^ball = "tour"/s//ball = "nope"/' \
  "a sport's unknown ball" "sports.toml:7|ball|unknown ball 'nope'|tour, mlb" -- flight --sport golf --ball-speed 100mph --launch-angle 10deg --spin 2000rpm
with_broken sports.toml '0,/^default_world = "golf_hole"/s//default_world = "ballpark"/' \
  "golf's world a ballpark" "sports.toml:|default_world|a baseball world" -- shot golf/driver
with_broken sports.toml '0,/"club_speed", "ball_speed"/s//"nope", "ball_speed"/' \
  "an unknown launch-monitor row" "sports.toml:|report|unknown launch-monitor metric 'nope'" -- shot golf/driver
# A pitcher whose every pitch type is thrown 0 % of the time has nothing to throw.
with_broken pitches.toml 's/^usage = .*/usage = "0%"/' \
  "no pitch type thrown" "pitches.toml:|usage|at least one must be thrown" -- derby --mode at-bat
# A club's face size is checked as written, at face_size's line; a message names its club once.
with_broken equipment/clubs.toml '0,/face_size = \["110mm", "56mm"\]/s//face_size = ["0mm", "56mm"]/' \
  "a face of no width" "clubs.toml:|face_size[0] (width)|[0.01, 0.2] m" -- shot golf/driver
with_broken equipment/clubs.toml '0,/inertia = \["2843g/s//inertia = ["-2843g/' \
  "a head of negative inertia" "clubs.toml:|club 'driver'.inertia|positive definite" -- shot golf/driver
grep -qF "club 'driver': club 'driver'" "$tmp/err" && fail "the club named twice: $(cat "$tmp/err")"
unset SWEETSPOT_ASSETS
rm -rf "$assets_copy"
sed 's/^number = 1$/number = 1.5/' "$SWEETSPOT_ROOT/assets/courses/links.toml" > "$tmp/course.toml"
expect_bad "a fractional hole number" "course.toml:|number|whole number" -- round "$tmp/course.toml"
printf 'sport = "baseball"\nmesh = "x.obj"\nfence_height = "3m"\n' > "$tmp/fence.toml"
expect_bad "a fence without its line" "fence.toml:3|fence_line" -- shot baseball/home-run --set world.name="$tmp/fence.toml"
printf 'sport = "golf"\nmesh = "x.obj"\nbounds_max = ["450m", "400m", "70m"]\npin = ["9000m", "0m", "0m"]\n' > "$tmp/pin.toml"
expect_bad "a pin outside the world" "pin.toml:4|outside the world" -- shot golf/driver --set world.name="$tmp/pin.toml"
expect_bad "a plot that is not a PNG" "name it FILE.png" -- derby --plot "$tmp/spray.jpg"
# A face laid open to the swing's direction (90 deg of spin loft) grazes: no 0 mph "shot".
expect_bad "an elevation raster that is not there" "$tmp/none.tif: no such file" -- course import "$SWEETSPOT_ROOT/assets/courses/sources/national.osm" -o "$tmp/course_out" --dem "$tmp/none.tif"
expect_bad "a map that is not a file" "/dev/null: not a regular file|.osm" -- course import /dev/null -o "$tmp/course_out"
expect_bad "a map that is not there" "$tmp/none.osm: no such file" -- course import "$tmp/none.osm" -o "$tmp/course_out"
expect_bad "a gimme in a contest" "--gimme|not part of --mode ctp" -- round links --mode ctp --gimme 3
expect_bad "a pin set the course lacks" "--pins 9|has 4 pin sets|allowed 0..4" -- round national_3 --pins 9
expect_bad "a seed for a saved round" "--resume|--seed" -- round --resume "$tmp/none.json" --seed 3
expect_bad "a pin set for a long drive" "--pins|not part of --mode long-drive" -- round links --mode long-drive --pins 3
expect_bad "a grazing strike" "the strike misses|1 deg out of its own plane" -- shot golf/driver --set club.name=lw --set swing.attack_angle=-30deg --set swing.dynamic_loft=60deg
expect_bad "a strike off the 7-iron's face" "on the 7-iron's face|[-0.023, 0.023] m" -- shot golf/7-iron --set "swing.impact_offset=[0mm,28mm]"
expect_bad "sweep mu without friction" "--mu|friction model is none" -- sweep golf/driver --e 0.7:0.8:2 --mu 0.2:0.4:2 --set impact.friction=none --no-flight
# A sport switched by --set: the file's club keys are not blamed alone.
expect_bad "--set sport" "club.name|--set sport=baseball|pick a scenario of that sport" -- shot golf/driver --set sport=baseball
# A ball the flight model cannot carry, refused once it flies: the keys' own --set named.
expect_bad "light large ball" "ball.mass from --set ball.mass=10g|ball.radius from --set ball.radius=10cm" -- shot golf/driver --set ball.mass=10g --set ball.radius=10cm
# A ball placed off the world says where the ground is.
expect_bad "ball off the world" "world.ball_position|no ground|its ground spans x" -- shot golf/driver --set "world.ball_position=[0m,300m]"
# A number flag given text says what the flag takes, with its range.
expect_bad "text for a number flag" "--balls: 'x'|1..100" -- round --mode ctp --balls x
expect_bad "text for the port" "--port: 'abc'|0..65535" -- connect --headless --port abc
[ -z "$(ls -A "$tmp" | grep -v -E '\.toml$|^(out|err)$')" ] || fail "stray files: $(ls -A "$tmp")"
echo "bad_input: ok"
