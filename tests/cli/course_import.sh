#!/usr/bin/env bash
# `sweetspot course import`: the bundled Sweetspot National (assets/courses/national) is what
# importing its map and raster (assets/courses/sources) writes, byte for byte, so the shipped
# course and an imported one take one path; it plays; its three-hole loop matches it; and bad
# maps and rasters exit 2 naming the file, leaving nothing behind.
set -euo pipefail
bin="$1"
root="${SWEETSPOT_ROOT:?}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
src="$root/assets/courses/sources"
"$bin" course import "$src/national.osm" --dem "$src/national.asc" --cell 8 -o "$tmp/national" > "$tmp/out" || fail "import: $(cat "$tmp/out")"
grep -q "Sweetspot National: 18 holes, par 72" "$tmp/out" || fail "import summary: $(head -1 "$tmp/out")"
for f in course.toml world.toml world.obj.gz world.mtl; do
  cmp -s "$tmp/national/$f" "$root/assets/courses/national/$f" ||
    fail "assets/courses/national/$f differs from a fresh import (run: sweetspot course import assets/courses/sources/national.osm --dem assets/courses/sources/national.asc --cell 8 -o assets/courses/national)"
done
# The loop's three holes are the course's first three.
for n in 1 2 3; do
  want=$(awk -v n=$n '/^\[\[hole\]\]/{h++} h==n && /^(tee|pin|par) =/' "$root/assets/courses/national/course.toml")
  got=$(awk -v n=$n '/^\[\[hole\]\]/{h++} h==n && /^(tee|pin|par) =/' "$root/assets/courses/national_3.toml")
  [ "$want" = "$got" ] || fail "national_3 hole $n: $got, national: $want"
done
"$bin" round national --bot tour --seed 1 > "$tmp/card" || fail "round national"
grep -qE '^total +72 ' "$tmp/card" || fail "no par-72 card: $(tail -2 "$tmp/card")"
"$bin" round national_3 --bot tour --seed 1 > "$tmp/card3" || fail "round national_3"
grep -qE '^total +12 ' "$tmp/card3" || fail "no par-12 card"
# Bad input: exit 2 naming the file, nothing written.
expect2() {  # expect2 WHAT NEEDLE ARGS...
  local what="$1" needle="$2"; shift 2
  set +e; "$bin" course import "$@" > /dev/null 2> "$tmp/err"; local rc=$?; set -e
  [ $rc -eq 2 ] || fail "$what: exit $rc, want 2"
  grep -q -- "$needle" "$tmp/err" || fail "$what: message does not name $needle: $(cat "$tmp/err")"
}
echo "not a map" > "$tmp/notes.osm"
expect2 "not OSM" "notes.osm" "$tmp/notes.osm" -o "$tmp/a"
sed 's/^xllcorner .*/xllcorner 10.0/' "$src/national.asc" > "$tmp/elsewhere.asc"
cp "$src/national.prj" "$tmp/elsewhere.prj"
expect2 "raster of another place" "elsewhere.asc" "$src/national.osm" --dem "$tmp/elsewhere.asc" -o "$tmp/b"
expect2 "existing output" "already exists" "$src/national.osm" -o "$tmp/national"
ln -s "$tmp/nowhere" "$tmp/dangling"
expect2 "a dangling link as output" "already exists (a link)" "$src/national.osm" -o "$tmp/dangling"
# Heights no ground has, cells of no size, cliffs under play: the raster is named with the rule.
awk 'NR <= 6 { print; next } { for (i = 1; i <= NF; i++) $i = 1e30; print }' "$src/national.asc" > "$tmp/spike.asc"
cp "$src/national.prj" "$tmp/spike.prj"
expect2 "a raster of 1e30 m" "spike.asc: cell (column" "$src/national.osm" --dem "$tmp/spike.asc" -o "$tmp/c"
grep -q -- "between -500 and 9000 m" "$tmp/err" || fail "no allowed range: $(cat "$tmp/err")"
sed 's/^cellsize .*/cellsize 0/' "$src/national.asc" > "$tmp/flat.asc"
cp "$src/national.prj" "$tmp/flat.prj"
expect2 "cells of no size" "flat.asc: its cells have no size" "$src/national.osm" --dem "$tmp/flat.asc" -o "$tmp/d"
awk 'NR <= 6 { print; next } { for (i = 1; i <= NF; i++) $i = ((i + NR) % 2) * 400; print }' "$src/national.asc" > "$tmp/cliffs.asc"
cp "$src/national.prj" "$tmp/cliffs.prj"
expect2 "a raster of cliffs" "cliffs.asc: the " "$src/national.osm" --dem "$tmp/cliffs.asc" -o "$tmp/e"
grep -q -- "at most 60 deg on tees, fairways and greens" "$tmp/err" || fail "no allowed slope: $(cat "$tmp/err")"
# libosmium would wrap an exponent this large to ~0 degrees: refused at its line.
sed '0,/lat=.\([0-9.]*\)./s//lat="1e308"/' "$src/national.osm" > "$tmp/far.osm"
line=$(grep -n 'lat="1e308"' "$tmp/far.osm" | cut -d: -f1)
expect2 "a latitude of 1e308" "far.osm:$line: node [0-9]*: lat=\"1e308\" is off the globe (allowed: latitude -90..90 degrees)" "$tmp/far.osm" -o "$tmp/f"
# An editor's unsaved objects (negative ids, as JOSM writes them) import like uploaded ones.
sed -E "s/(node id=['\"])([0-9])/\1-\2/; s/(nd ref=['\"])([0-9])/\1-\2/g" "$src/national.osm" > "$tmp/unsaved.osm"
grep -q "node id=.-" "$tmp/unsaved.osm" || fail "the negative-id map was not made"
"$bin" course import "$tmp/unsaved.osm" -o "$tmp/unsaved" > "$tmp/out" || fail "negative node ids: $(cat "$tmp/out")"
grep -q "Sweetspot National: 18 holes, par 72" "$tmp/out" || fail "negative node ids: $(head -1 "$tmp/out")"
for d in a b c d e f; do [ ! -e "$tmp/$d" ] || fail "a refused import left its output $d"; done
[ ! -e "$tmp/a" ] || fail "a refused import left its output"
ls -A "$tmp" | grep -q '^\.course-import-' && fail "a working directory was left behind"
echo "course_import: ok"
