#!/usr/bin/env bash
# Hostile outputs and arguments: every output goes through the one atomic writer.
# Symlinks are written through (the link stays), the mode is kept, a device is written in
# place (never replaced), an output that is the input is refused, a file-size limit or a
# full or closed stdout is an error (exit 2) that keeps the old file and leaves no temporary;
# seeds and sweep grids are checked, not clamped; non-UTF-8 file names do not break JSON.
set -euo pipefail
bin=$(realpath "$1")
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cp "$SWEETSPOT_ROOT/assets/scenarios/golf/pw.toml" s.toml
grid=(--e 0.7:0.8:2 --mu 0.3:0.4:2)

expect_rc() {  # expect_rc RC PATTERN -- command...
  local want="$1" pattern="$2"; shift 3
  local rc=0
  "$@" >out.txt 2>err.txt || rc=$?
  [ "$rc" = "$want" ] || fail "$*: exit $rc (want $want): $(cat err.txt)"
  [ -z "$pattern" ] || grep -q -- "$pattern" err.txt || fail "$*: message '$(cat err.txt)' lacks '$pattern'"
}

# A symlink is written through and stays a symlink; the target keeps its mode.
echo old > real.csv; chmod 640 real.csv; ln -s real.csv link.csv
expect_rc 0 "" -- "$bin" sweep s.toml "${grid[@]}" --csv link.csv
[ -L link.csv ] || fail "the symlink was replaced by a file"
grep -q "^e,mu\|e,\|mu" real.csv || fail "the link's target was not written: $(head -2 real.csv)"
[ "$(stat -c %a real.csv)" = 640 ] || fail "mode changed to $(stat -c %a real.csv)"

# A device is written in place, never replaced by a regular file.
expect_rc 0 "" -- "$bin" sweep s.toml "${grid[@]}" --csv /dev/null
[ -c /dev/null ] || fail "/dev/null is no longer a device"
if [ -e /dev/full ]; then
  expect_rc 2 "/dev/full" -- "$bin" sweep s.toml "${grid[@]}" --csv /dev/full
  [ -c /dev/full ] || fail "/dev/full is no longer a device"
  # stdout that cannot be written is an error too.
  rc=0; "$bin" shot golf/pw >/dev/full 2>err.txt || rc=$?
  [ "$rc" = 2 ] && grep -q "stdout" err.txt || fail "stdout to /dev/full: exit $rc $(cat err.txt)"
fi
rc=0; "$bin" list >&- 2>err.txt || rc=$?
[ "$rc" = 2 ] || fail "closed stdout: exit $rc"
mkfifo pipe
expect_rc 2 "not a regular file" -- timeout 20 "$bin" sweep s.toml "${grid[@]}" --csv pipe

# The output is the input: refused, the scenario untouched (also through a link).
cp s.toml s.before; ln -s s.toml s_link.toml
expect_rc 2 "is the input file" -- "$bin" sweep s.toml "${grid[@]}" --csv s.toml
expect_rc 2 "is the input file" -- "$bin" sweep s_link.toml "${grid[@]}" --csv ./s.toml
expect_rc 2 "name it FILE.png" -- "$bin" render s.toml -o s.toml --width 64 --height 64
ln -s s.toml s_as.png
expect_rc 2 "is the input file" -- "$bin" render s.toml -o s_as.png --width 64 --height 64
cmp -s s.toml s.before || fail "the scenario was overwritten"

# Two outputs that are one file (a link to the other, dangling or not) are refused.
ln -s real.csv alias.png
expect_rc 2 "overwrite each other" -- "$bin" sweep s.toml "${grid[@]}" --csv real.csv --plot alias.png
expect_rc 2 "name it FILE.png" -- "$bin" sweep s.toml "${grid[@]}" --plot grid.csv
ln -s not_yet.csv dangling.png
expect_rc 2 "overwrite each other" -- "$bin" sweep s.toml "${grid[@]}" --csv not_yet.csv --plot dangling.png
[ ! -e not_yet.csv ] || fail "the refused sweep wrote its CSV"
expect_rc 2 "does not exist" -- "$bin" sweep s.toml "${grid[@]}" --plot nodir/x.png
# Window-only flags are refused headless instead of being ignored (connect would serve on).
expect_rc 2 "--frames" -- env -u DISPLAY -u WAYLAND_DISPLAY timeout 20 "$bin" connect --port 0 --frames 1
expect_rc 2 "--screenshot" -- timeout 20 "$bin" connect --headless --port 0 --screenshot x.png
# A session's shot numbers rise: an explicit number at or below its last is refused.
expect_rc 0 "" -- "$bin" shot golf/pw --gspro --session sess.jsonl
expect_rc 2 "already holds shot 1" -- "$bin" shot golf/pw --gspro --session sess.jsonl --shot-number 1
[ "$(wc -l < sess.jsonl)" = 1 ] || fail "the refused shot was appended to the session"
# A regress folder whose *.toml is a FIFO or a dangling link is refused, not skipped.
mkdir cases; cp "$SWEETSPOT_ROOT/tests/regression/trackman_pw_launch.toml" cases/
mkfifo cases/fifo.toml
expect_rc 2 "not a regular file" -- timeout 20 "$bin" regress cases
rm cases/fifo.toml; ln -s nowhere cases/dangling.toml
expect_rc 2 "dangling.toml" -- "$bin" regress cases
if [ -e /dev/full ]; then  # help and version are output too
  rc=0; "$bin" --help >/dev/full 2>err.txt || rc=$?
  [ "$rc" = 2 ] || fail "--help to /dev/full: exit $rc"
  rc=0; "$bin" --version >/dev/full 2>err.txt || rc=$?
  [ "$rc" = 2 ] || fail "--version to /dev/full: exit $rc"
fi

# No output replaces a file the command read, however it is named: the course, the world's
# mesh behind a scenario, the scenario under play --screenshot.
cp "$SWEETSPOT_ROOT/assets/courses/links.toml" c.toml; cp c.toml c.before; ln -s c.toml c_as.png
expect_rc 2 "input file of this command" -- "$bin" round c.toml --plot c_as.png
cmp -s c.toml c.before || fail "round --plot replaced the course"
"$bin" range --bot tour --shots 1 --bag-out bag.toml > /dev/null; cp bag.toml bag.before
expect_rc 2 "is the input file" -- "$bin" round national_3 --bag bag.toml --save bag.toml
cmp -s bag.toml bag.before || fail "round --save replaced the bag it read"
mkdir w; printf 'usemtl fairway\nv -30 0 -70\nv -30 0 70\nv 450 0 70\nv 450 0 -70\nf 1 2 3\nf 1 3 4\n' > w/flat.obj
printf 'sport = "golf"\nmesh = "flat.obj"\n' > w/flat.toml; cp w/flat.obj w/flat.before; ln -s flat.obj w/mesh_as.png
printf 'sport = "golf"\n[world]\nname = "w/flat.toml"\n' > on_flat.toml
expect_rc 2 "input file of this command" -- "$bin" render on_flat.toml -o w/mesh_as.png --width 64 --height 64
cmp -s w/flat.obj w/flat.before || fail "render -o replaced the world's mesh"
ln -s s.toml s_shot.png
expect_rc 2 "input file of this command" -- env -u DISPLAY -u WAYLAND_DISPLAY "$bin" play s.toml --screenshot s_shot.png
[ ! -s out.txt ] || fail "a refused play printed on stdout: $(head -3 out.txt)"
cmp -s s.toml s.before || fail "play --screenshot replaced the scenario"
# A material library must lie beside the mesh (or below it).
printf 'mtllib ../../../../../../etc/passwd\nusemtl fairway\nv -30 0 -70\nv -30 0 70\nv 450 0 70\nf 1 2 3\n' > w/far.obj
printf 'sport = "golf"\nmesh = "far.obj"\n' > w/far.toml
expect_rc 2 "outside the mesh's folder" -- "$bin" shot golf/driver --set world.name=w/far.toml

# A world's own pin sits on its green: one over the fairway, or 300 m above it, is refused
# naming the world file's line (the hole would be unfinishable).
printf 'usemtl fairway\nv -30 0 -70\nv -30 0 70\nv 300 0 70\nv 300 0 -70\nf 1 2 3\nf 1 3 4\nusemtl green\nv 300 0 -70\nv 300 0 70\nv 450 0 70\nv 450 0 -70\nf 5 6 7\nf 5 7 8\n' > w/hole.obj
printf 'sport = "golf"\nmesh = "hole.obj"\npin = ["100m", "0m", "0m"]\n' > w/pin_fairway.toml
expect_rc 2 "pin_fairway.toml:3" -- "$bin" shot golf/pw --set world.name=w/pin_fairway.toml
printf 'sport = "golf"\nmesh = "hole.obj"\npin = ["400m", "300m", "0m"]\n' > w/pin_high.toml
expect_rc 2 "green's surface" -- "$bin" shot golf/pw --set world.name=w/pin_high.toml
printf 'sport = "golf"\nmesh = "hole.obj"\npin = ["400m", "0m", "0m"]\n' > w/pin_ok.toml
expect_rc 0 "" -- "$bin" shot golf/pw --set world.name=w/pin_ok.toml

# A mesh of more objects than the OBJ reader reads in reasonable time is refused with the
# limit (assimp looks each object up among all before it: 40 000 took 10.7 s).
python3 -c '
import sys
with open("w/many.obj", "w") as f:
    f.write("usemtl fairway\n")
    for i in range(10001):
        x = (i % 100) * 3.0 - 150; z = (i // 100) * 3.0 - 150
        f.write(f"o part{i}\nv {x} 0 {z}\nv {x} 0 {z+3}\nv {x+3} 0 {z+3}\nf -3 -2 -1\n")'
printf 'sport = "golf"\nmesh = "many.obj"\n' > w/many.toml
expect_rc 2 "over 10000 objects" -- "$bin" shot golf/pw --set world.name=w/many.toml

# Balls the models cannot fly are refused naming the keys, not integrated into NaN or put to
# rest after 1e-14 s: as light as a balloon (10 g, radius 10 cm), denser than osmium, a
# Reynolds number past the aero models' range (500 g, radius 8 cm, at a drive's speed), a
# surface spun past it (20 000 rpm at radius 8 cm).
expect_rc 2 "100 times the air" -- "$bin" shot golf/driver --set ball.mass=10g --set ball.radius=0.1m
expect_rc 2 "ball.mass" -- "$bin" flight --ball-speed 30m/s --launch-angle 10deg --spin 0rpm --set ball.mass=500g --set ball.radius=10mm
expect_rc 2 "ball.radius" -- "$bin" flight --ball-speed 70m/s --launch-angle 10deg --spin 2000rpm --set ball.mass=500g --set ball.radius=80mm
expect_rc 2 "spin Reynolds" -- "$bin" flight --ball-speed 5m/s --launch-angle 45deg --spin 20000rpm --spin-axis 180deg --set ball.mass=500g --set ball.radius=80mm

# A flag is checked before any work: a bad one prints its message and nothing else. An
# unknown mode names the flag and every mode; a saved round with a number past a double is
# bad input naming the file (it was an internal error, exit 4).
expect_rc 2 "give --min-pass-rate too" -- "$bin" validate --min-unfitted-pass-rate 50
[ -s out.txt ] && fail "validate printed a scorecard before refusing its flags"
expect_rc 2 "allowed: derby, at-bat, practice, game" -- "$bin" derby --mode x
expect_rc 2 "\-\-bot: unknown batter skill 'god'" -- "$bin" derby --bot god
expect_rc 2 "\-\-bot: unknown golfer skill 'god'" -- "$bin" round --bot god
expect_rc 2 "\-\-format: format 'x'" -- "$bin" round --format x
expect_rc 2 "\-\-handicap: .*54" -- "$bin" round --handicap 99
expect_rc 2 "\-\-gimme: " -- "$bin" round --gimme 5
"$bin" round --bot tour --stop-after 1 --save r.json >/dev/null
python3 -c 'import sys; t=open("r.json").read(); open("r.json","w").write(t.replace("{", "{\"gimme_m\": 1e999, ", 1))'
expect_rc 2 "r.json" -- "$bin" round --resume r.json

# A file-size limit: exit 2 naming the file, the old file kept, no temporary left behind.
echo old > big.csv
rc=0; (ulimit -f 1; exec "$bin" sweep s.toml --e 0.5:0.9:6 --mu 0.2:0.6:6 --csv big.csv) >/dev/null 2>err.txt || rc=$?
[ "$rc" = 2 ] && grep -q "big.csv" err.txt || fail "ulimit -f: exit $rc $(cat err.txt)"
[ "$(cat big.csv)" = old ] || fail "ulimit -f: the old file was lost"
# Two outputs of one command are replaced together: the clip over the size limit keeps the
# image old too, and so does a plot with the saved round; no temporary is left.
echo old > two.png; echo old > two.mp4
rc=0; (ulimit -f 20; exec "$bin" render golf/driver -o two.png --video two.mp4 --width 64 --height 64) >/dev/null 2>err.txt || rc=$?
[ "$rc" = 2 ] && grep -q "two.mp4" err.txt || fail "render pair: exit $rc $(cat err.txt)"
[ "$(cat two.png)" = old ] && [ "$(cat two.mp4)" = old ] || fail "render pair: an output was replaced though the other failed"
echo old > pair.json; echo old > pair.png
rc=0; (ulimit -f 4; exec "$bin" round links --bot tour --save pair.json --plot pair.png --stop-after 1) >/dev/null 2>err.txt || rc=$?
[ "$rc" = 2 ] || fail "round pair: exit $rc $(cat err.txt)"
[ "$(cat pair.json)" = old ] && [ "$(cat pair.png)" = old ] || fail "round pair: an output was replaced though the other failed"
ls -A | grep -q '\.tmp' && fail "a temporary was left: $(ls -A | grep '\.tmp')"
ls -A | grep -q '\.tmp' && fail "a temporary file was left: $(ls -A)"

# Seeds and grids are checked, not wrapped or clamped; a --set the grid overrides is refused.
expect_rc 2 "--seed" -- "$bin" round --seed -1
expect_rc 2 "--seed" -- "$bin" round --seed 18446744073709551616
expect_rc 2 "--seed" -- "$bin" derby --seed 1.5
expect_rc 2 "drop B" -- "$bin" sweep s.toml --e 0.7:0.8:1 --mu 0.3:0.4:2
expect_rc 2 "--set impact.mu" -- "$bin" sweep s.toml "${grid[@]}" --set impact.mu=0.5
expect_rc 2 "out of range" -- "$bin" shot golf/driver --set swing.speed=1e-300mph

# Two outputs of one run that name one file however they are spelt (relative, "./",
# absolute) are refused before anything is written.
rm -f same.png
expect_rc 2 "overwrite each other" -- "$bin" sweep s.toml "${grid[@]}" --csv ./same.png --plot same.png
expect_rc 2 "overwrite each other" -- "$bin" sweep s.toml "${grid[@]}" --csv "$PWD/same.png" --plot same.png
[ ! -e same.png ] || fail "a refused pair of outputs wrote same.png"
expect_rc 2 "overwrite each other" -- "$bin" round --save ./r.png --plot r.png
[ ! -e r.png ] || fail "a refused pair of outputs wrote r.png"
# A read-only output is refused, not replaced (rename would replace it: the folder is ours).
echo keep > ro.csv
chmod a-w ro.csv
expect_rc 2 "read-only" -- "$bin" sweep s.toml "${grid[@]}" --csv ro.csv
[ "$(cat ro.csv)" = keep ] || fail "a read-only output was replaced"
chmod u+w ro.csv

# A file name that is not UTF-8 does not break the JSON writer.
cp s.toml "$(printf 'd\xff.toml')"
expect_rc 0 "" -- "$bin" shot "$(printf 'd\xff.toml')" --json
python3 -c 'import json,sys; json.load(open("out.txt"))' || fail "--json output is not JSON"
echo "hostile_output: ok"
