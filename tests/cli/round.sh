#!/usr/bin/env bash
# `sweetspot round`: a bot plays the Sweetspot Links headless; the DESIGN §9 JSON; the same
# seed gives the same card bit for bit; better golfers score lower on average; scripted
# swings; bad input exits 2 naming the file:line and range.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

json=$("$bin" round links --bot tour --seed 3 --json)
[ "$json" = "$("$bin" round links --bot tour --seed 3 --json)" ] || fail "same seed, different output"
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

# Fairways and greens in regulation, derived again from the shots: a par 4's or 5's tee shot
# at rest on the fairway (or holed); on the green (or holed) with par - 2 strokes or fewer,
# penalty strokes counted. The totals and the text card's total row agree with the holes.
for args in "--bot scratch --seed 5" "--bot amateur --seed 2"; do
  # shellcheck disable=SC2086
  "$bin" round national $args --json > "$tmp/fir.json"
  # shellcheck disable=SC2086
  "$bin" round national $args > "$tmp/fir.txt"
  python3 - "$tmp/fir.json" "$tmp/fir.txt" <<'PY' || fail "fairways and greens ($args)"
import json, re, sys
j = json.load(open(sys.argv[1]))
checked = 0
for h in j["holes"]:
    shots = h["shots"]
    if h["par"] == 3:
        assert h["fairway"] is None, h["number"]
    else:
        s0 = shots[0]
        assert h["fairway"] in ("hit", "left", "right"), h["number"]
        if s0["end"] == "holed":
            assert h["fairway"] == "hit"
        elif s0["end"] == "rest" and "relief" not in s0 and not s0.get("unplayable"):
            assert (h["fairway"] == "hit") == (shots[1]["lie"] == "fairway"), (h["number"], h["fairway"], shots[1]["lie"])
            checked += 1
    count, gir = 0, False
    for k, s in enumerate(shots):
        count += 1 + (s["end"] in ("water", "out_of_bounds")) + bool(s.get("unplayable"))
        on = s["end"] == "holed" or (s["end"] == "rest" and k + 1 < len(shots) and shots[k + 1]["lie"] == "green"
                                      and s.get("relief") != "wrong_green")
        gir = gir or (on and count <= h["par"] - 2)
    assert h["green_in_regulation"] == gir, (h["number"], h["green_in_regulation"], gir)
assert checked >= 8, checked
assert j["fairways"] == sum(h["par"] > 3 for h in j["holes"])
assert j["fairways_hit"] == sum(h["fairway"] == "hit" for h in j["holes"])
assert j["greens_in_regulation"] == sum(h["green_in_regulation"] for h in j["holes"])
total = [l.split() for l in open(sys.argv[2]) if l.startswith("total")][0]
# Each nine adds up, and the two nines make the total (par, strokes, putts, penalties).
rows = {l.split()[0]: l.split() for l in open(sys.argv[2]) if l.split() and l.split()[0] in ("out", "in")}
holes = {h["number"]: h for h in j["holes"]}
for name, nine in (("out", range(1, 10)), ("in", range(10, 19))):
    r = rows[name]
    assert int(r[1]) == sum(holes[n]["par"] for n in nine), (name, r)
    assert int(r[2]) == sum(holes[n]["strokes"] for n in nine), (name, r)
    assert int(r[3]) == sum(holes[n]["putts"] for n in nine), (name, r)
for k in (1, 2, 3):
    assert int(rows["out"][k]) + int(rows["in"][k]) == int(total[k]), (k, rows, total)
assert total[4] == "%d/%d" % (j["fairways_hit"], j["fairways"]), total
assert total[5] == "%d/%d" % (j["greens_in_regulation"], len(j["holes"])), total
PY
done

# Better golfers score lower, averaged over seeds (DESIGN §9 skills).
avg() {
  local sum=0
  for seed in 1 2 3 4; do
    sum=$((sum + $("$bin" round links --bot "$1" --seed $seed --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["total_strokes"])')))
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
out=$("$bin" round links --calm --swings "$tmp/swings.toml" --bot tour --json)
python3 - "$out" <<'PY' || fail "scripted water"
import json, sys
j = json.loads(sys.argv[1])
h = j["holes"][0]
assert h["shots"][0]["end"] == "water" and h["penalties"] == 1 and h["strokes"] >= 3, h
PY
# A group's text card marks each hole's penalty strokes ("6 (1) 1p": a 6 with one putt
# reads), the same ones the JSON counts, and its key says what "1p" means.
"$bin" round --bot beginner --bot amateur --seed 6 >"$tmp/card.txt"
"$bin" round --bot beginner --bot amateur --seed 6 --json >"$tmp/card.json"
python3 - "$tmp/card.txt" "$tmp/card.json" <<'PY' || fail "penalties on the group card"
import json, re, sys
rows = [l for l in open(sys.argv[1]) if re.match(r"^ +\d+ +\d+ +\d+ ", l)]
j = json.load(open(sys.argv[2]))
total = 0
for i, row in enumerate(rows):
    cells = re.findall(r"(\d+)\*{0,6} \((\d+)\)(?: (\d+)p)?", row)
    assert len(cells) == 2, row
    for p, (gross, putts, pen) in enumerate(cells):
        h = j["players"][p]["holes"][i]
        assert int(gross) == h["strokes"] and int(putts) == h["putts"], (row, h)
        assert int(pen or 0) == h["penalties"], (row, h["penalties"])
        total += h["penalties"]
assert total > 0, "no penalty in the round: the check saw nothing"
assert "1p a penalty stroke" in open(sys.argv[1]).read()
# The nines: "out" and "in" add each player's strokes and putts over holes 1-9 and 10-18.
text = open(sys.argv[1]).read().splitlines()
for name, nine in (("out", range(0, 9)), ("in", range(9, 18))):
    row = [l for l in text if l.startswith(name + " ")][0]
    cells = re.findall(r"(\d+) \((\d+)\)", row)
    assert len(cells) == 2, row
    for p, (strokes, putts) in enumerate(cells):
        holes = j["players"][p]["holes"]
        assert int(strokes) == sum(holes[i]["strokes"] for i in nine), (row, p)
        assert int(putts) == sum(holes[i]["putts"] for i in nine), (row, p)
PY
# Stableford: each nine's points beside its strokes, from the holes' points, and the two
# nines make the points row.
"$bin" round --bot scratch --bot beginner --handicap 2 --handicap 30 --format stableford --seed 7 >"$tmp/sf.txt"
"$bin" round --bot scratch --bot beginner --handicap 2 --handicap 30 --format stableford --seed 7 --json >"$tmp/sf.json"
python3 - "$tmp/sf.txt" "$tmp/sf.json" <<'PY' || fail "stableford nines"
import json, re, sys
text = open(sys.argv[1]).read().splitlines()
j = json.load(open(sys.argv[2]))
got = [0, 0]
for name, nine in (("out", range(0, 9)), ("in", range(9, 18))):
    row = [l for l in text if l.startswith(name + " ")][0]
    pts = [int(x) for x in re.findall(r"\((?:\d+)\) (\d+)pt", row)]
    assert len(pts) == 2, row
    for p in range(2):
        assert pts[p] == sum(j["players"][p]["holes"][i]["points"] for i in nine), (row, p)
        got[p] += pts[p]
points = [l for l in text if l.startswith("points ")][0].split()[1:]
assert [int(x) for x in points] == got, (points, got)
PY

# A script that runs out mid-round with no bot to play on is an error naming the file, not
# a card with unfinished holes and exit 0.
set +e
msg=$("$bin" round links --calm --swings "$tmp/swings.toml" --json 2>&1 >"$tmp/ran_out.json"); rc=$?
set -e
[ $rc -eq 2 ] || fail "script ran out: exit $rc"
grep -q "swings.toml: the script ran out" <<<"$msg" || fail "script ran out: message '$msg'"
[ ! -s "$tmp/ran_out.json" ] || fail "script ran out: a card was printed"

# Bad input: exit 2, file:line, the allowed range.
printf '[[stroke]]\npower = "140%%"\n' > "$tmp/bad.toml"
set +e
msg=$("$bin" round links --swings "$tmp/bad.toml" 2>&1); rc=$?
set -e
[ $rc -eq 2 ] || fail "power 140%: exit $rc"
grep -q "bad.toml:2" <<<"$msg" && grep -q "110" <<<"$msg" || fail "power 140%: message '$msg'"
set +e
msg=$("$bin" round nowhere 2>&1); rc=$?
set -e
[ $rc -eq 2 ] || fail "missing course: exit $rc"
set +e
msg=$("$bin" round links --bot legend 2>&1); rc=$?
set -e
[ $rc -eq 2 ] && grep -q "tour, scratch, amateur, beginner" <<<"$msg" || fail "unknown skill: $rc '$msg'"

# Players and formats (DESIGN §9): the card a golfer checks by hand. Every sum row adds up,
# the format's result follows from the holes, each hole carries its wind.
for fmt in match stableford skins; do
  if [ $fmt = match ]; then bots="--bot tour --bot amateur --handicap 0 --handicap 12"
  else bots="--bot tour --bot amateur --bot beginner --handicap 0 --handicap 12 --handicap 26"; fi
  # shellcheck disable=SC2086
  out=$("$bin" round links $bots --format $fmt --seed 7 --json)
  # shellcheck disable=SC2086
  [ "$out" = "$("$bin" round links $bots --format $fmt --seed 7 --json)" ] || fail "$fmt: same seed, different output"
  python3 - "$out" "$fmt" <<'PY' || fail "$fmt json"
import json, sys
j = json.loads(sys.argv[1]); fmt = sys.argv[2]
assert j["format"] == fmt and 2 <= len(j["players"]) <= 4, j["format"]
hcp = {p["player"]: p["handicap"] for p in j["players"]}
index = [h["stroke_index"] for h in j["holes_info"]]
n = len(index)
low = min(hcp.values()) if fmt == "match" else 0
def received(h, si):  # WHS: the round's share of the handicap, by stroke index
    total = (2 * (h - low) * n + 18) // 36
    return total // n + (1 if si <= total % n else 0)
nets = []
for p in j["players"]:
    counted = [h for h in p["holes"] if h["counted"]]
    assert fmt == "match" or len(counted) == len(p["holes"]), p["player"]
    assert p["total_strokes"] == sum(h["strokes"] for h in counted), p["player"]
    assert p["total_putts"] == sum(h["putts"] for h in counted), p["player"]
    assert p["to_par"] == p["total_strokes"] - sum(h["par"] for h in counted), p["player"]
    assert p["fairways"] == sum(h["par"] > 3 for h in counted), p["player"]
    assert p["fairways_hit"] == sum(h["fairway"] == "hit" for h in counted), p["player"]
    assert p["greens_in_regulation"] == sum(h["green_in_regulation"] for h in counted), p["player"]
    for h, si in zip(p["holes"], index):
        assert "wind_mps" in h and "wind_toward_deg" in h
        assert h["strokes_received"] == received(p["handicap"], si), (p["player"], h["number"])
        assert h["net"] == h["strokes"] - h["strokes_received"]
        assert h["strokes"] == len(h["shots"]) + h["penalties"], h
    assert p["total_net"] == sum(h["net"] for h in counted)
    nets.append([h["net"] for h in p["holes"]])
r = j["result"]
if fmt == "stableford":
    for e in r["points"]:
        p = next(q for q in j["players"] if q["player"] == e["player"])
        want = [max(0, 2 + h["par"] - h["net"]) if h["holed"] else 0 for h in p["holes"]]  # picked up: no score
        assert e["points"] == want and e["total_points"] == sum(want), e
    assert [e["total_points"] for e in r["points"]] == sorted([e["total_points"] for e in r["points"]], reverse=True)
elif fmt == "skins":
    carried, won = 0, {p["player"]: 0 for p in j["players"]}
    for k, h in enumerate(r["holes"]):
        col = [net[k] for net in nets]; best = min(col); carried += 1
        if col.count(best) > 1: assert h["winner"] is None and h["carried"]
        else:
            w = j["players"][col.index(best)]["player"]
            assert h["winner"] == w and h["skins"] == carried, h
            won[w] += carried; carried = 0
    assert r["carried_unwon"] == carried and {e["player"]: e["skins"] for e in r["skins"]} == won
else:
    lead, decided = 0, None
    for k, h in enumerate(r["holes"]):
        a, b = nets[0][k], nets[1][k]
        # A hole conceded (a bot that could no longer halve it picks up) is lost, whatever
        # its strokes so far.
        if j["players"][0]["holes"][k].get("conceded"): a = float("inf")
        elif j["players"][1]["holes"][k].get("conceded"): b = float("inf")
        if decided is None: lead += (a < b) - (b < a)  # a decided match stands (Rule 3.2a(3))
        assert h["holes_up"] == lead, h
        if decided is None and abs(lead) > n - k - 1: decided = k + 1
    assert r["decided_after_hole"] == decided, r
    assert r["holes_up"] == lead
    # A decided match ends there (Rule 3.2a(3)): the holes left are not played.
    assert all(len(p["holes"]) == (decided or n) for p in j["players"]), (decided, [len(p["holes"]) for p in j["players"]])
PY
done
# The table a player reads adds its putts too (the total row once put the score to par there).
"$bin" round links --bot tour --seed 3 | awk '/^total/ {t=$4} /^[0-9]/ {s+=$4} END {exit !(t==s)}' || fail "putts column does not add up"

# A round saved after a hole and resumed finishes exactly as the round played through.
"$bin" round links --bot tour --bot beginner --format match --seed 9 --json > "$tmp/whole.json"
"$bin" round links --bot tour --bot beginner --format match --seed 9 --stop-after 1 --save "$tmp/r.save" > /dev/null
"$bin" round --resume "$tmp/r.save" --json > "$tmp/resumed.json"
cmp -s "$tmp/whole.json" "$tmp/resumed.json" || fail "resumed round differs from the whole round"
set +e; msg=$("$bin" round --resume "$tmp/r.save" --bot tour 2>&1); rc=$?; set -e
[ $rc -eq 2 ] && grep -q -- "--resume" <<<"$msg" || fail "resume with --bot: $rc $msg"
set +e; msg=$("$bin" round national_3 --resume "$tmp/r.save" 2>&1); rc=$?; set -e
[ $rc -eq 2 ] && grep -q -- "give no COURSE" <<<"$msg" || fail "resume with a course named: $rc $msg"
set +e; msg=$("$bin" round national_3 --stop-after 3 --save "$tmp/s3.save" 2>&1); rc=$?; set -e
[ $rc -eq 2 ] && grep -q "allowed \[1, 2\]" <<<"$msg" && [ ! -e "$tmp/s3.save" ] || fail "stop after the last hole: $rc $msg"
# Skins with every hole so far carried names no leader, nor a tie of everyone.
"$bin" round links --bot tour --bot tour --format skins --seed 2 --stop-after 1 --save "$tmp/sk.save" > "$tmp/sk.txt"
grep -q "^no skins won$" "$tmp/sk.txt" && ! grep -q "^tied:" "$tmp/sk.txt" || fail "skins with none won: $(cat "$tmp/sk.txt")"
# A card stopped after a hole lists that hole alone, and its par and to-par are that hole's.
"$bin" round national_3 --seed 2 --stop-after 1 --save "$tmp/one.save" > "$tmp/one.txt"
[ "$(grep -c '^[0-9]' "$tmp/one.txt")" = 1 ] || fail "a card stopped after hole 1 lists $(grep -c '^[0-9]' "$tmp/one.txt") holes: $(cat "$tmp/one.txt")"
awk '/^total/ {p=$2} END {exit !(p==4)}' "$tmp/one.txt" || fail "a card stopped after hole 1 totals par $(cat "$tmp/one.txt")"
"$bin" round national_3 --seed 2 --stop-after 1 --save "$tmp/one.save" --json | python3 -c '
import json, sys
j = json.load(sys.stdin)
assert j["total_par"] == sum(h["par"] for h in j["holes"]) == 4, j["total_par"]' || fail "a stopped round's JSON total_par"
set +e; msg=$("$bin" round links --bot tour --format match 2>&1); rc=$?; set -e
[ $rc -eq 2 ] && grep -q "two players" <<<"$msg" && grep -q -- "--format match" <<<"$msg" && ! grep -q -- "--human" <<<"$msg" \
  || fail "match of one (names round's own flags, not play's --human): $rc $msg"
set +e; msg=$("$bin" round links --bot tour --bot amateur --handicap 60 --handicap 1 2>&1); rc=$?; set -e
[ $rc -eq 2 ] && grep -q "54" <<<"$msg" || fail "handicap 60: $rc $msg"

# Bag gapping: the range writes the player's bag; with it the caddie picks other clubs
# (a beginner's carries are shorter: more club for the same distance).
"$bin" range --bot beginner --shots 3 --bag-out "$tmp/bag.toml" | grep -q "^7-iron" || fail "range table"
grep -q '^name = "7-iron"' "$tmp/bag.toml" || fail "bag file"
"$bin" range --bot amateur --shots 2 --json | python3 -c '
import json, sys
j = json.load(sys.stdin)
c = [x["carry_m"] for x in j["clubs"]]
assert len(c) == 13 and c == sorted(c, reverse=True), c' || fail "range json"
clubs() { python3 -c 'import json,sys; print(" ".join(s["club"] for h in json.load(sys.stdin)["holes"] for s in h["shots"] if s["lie"] != "green"))'; }
plain=$("$bin" round links --bot tour --calm --seed 4 --json | clubs)
bagged=$("$bin" round links --bot tour --calm --seed 4 --bag "$tmp/bag.toml" --json | clubs)
echo "clubs: stock [$plain], with the beginner's bag [$bagged]"
[ "$plain" != "$bagged" ] || fail "the bag did not change the caddie's clubs"

# The contests.
"$bin" round links --mode ctp --balls 3 --json | python3 -c '
import json, sys
j = json.load(sys.stdin); assert j["mode"] == "ctp" and len(j["balls"]) == 3 and "best_to_pin_m" in j, j' || fail "ctp"
"$bin" round links --mode long-drive --balls 3 --json | python3 -c '
import json, sys
j = json.load(sys.stdin); assert j["mode"] == "long-drive" and j["best_distance_m"] > 200, j' || fail "long drive"
# --plot: the session's dispersion as a 900 x 800 PNG, with the scorecard as usual.
plot_dir=$(mktemp -d)
"$bin" round links --bot amateur --seed 2 --plot "$plot_dir/d.png" | grep -q "^total" || fail "--plot lost the scorecard"
"$bin" round links --mode long-drive --balls 4 --plot "$plot_dir/ld.png" >/dev/null || fail "long-drive --plot"
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
[ $rc -eq 2 ] && grep -q "pond.toml:14: pin .* lies on water (allowed: green)" <<<"$msg" || fail "a pin in the pond: exit $rc, $msg"
# A ball lodged in a tree's branches is unplayable (Rule 19.2c): one penalty stroke, and the
# next stroke is played from the ground below it. Only strokes with the putter count as putts.
# On the National's 10th a full driver 16 deg left of the line lodges in the crown of a tree
# in the left rough (a tee shot that never reaches the cup: nothing at the hole moves it); the
# amateur bot plays on after the script.
cat > "$plot_dir/tree.toml" <<TOML
name = "The National's 10th"
[[hole]]
number = 1
par = 4
index = 1
world = "$SWEETSPOT_ROOT/assets/courses/national/world.toml"
tee = ["480.616m", "-419.993m"]
pin = ["93.454m", "-422.677m"]
TOML
printf '[[stroke]]\nclub = "driver"\npower = "100%%"\naim = "-16deg"\n' > "$plot_dir/tree_swing.toml"
check_card='
import json, sys
j = json.load(sys.stdin)
lodged = 0
for p in j["players"]:
    for h in p["holes"]:
        shots = h["shots"]
        assert h["putts"] == sum(1 for s in shots if s["lie"] == "green" and s["club"] == "putter"), h
        assert h["strokes"] == len(shots) + h["penalties"], h
        for a, b in zip(shots, shots[1:]):
            if a.get("unplayable"):
                lodged += 1
                assert h["penalties"] >= 1, h
                assert abs(b["start_m"][0] - a["rest_m"][0]) < 0.01 and abs(b["start_m"][2] - a["rest_m"][2]) < 0.01, (a, b)
                assert b["start_m"][1] < a["rest_m"][1] - 5.0, (a, b)  # from the ground, not the branches
assert lodged >= int(sys.argv[1]), "lodged %d" % lodged'
"$bin" round "$plot_dir/tree.toml" --calm --swings "$plot_dir/tree_swing.toml" --bot amateur --json | python3 -c "$check_card" 1 || fail "a ball lodged in a tree"
"$bin" round national --format match --bot scratch --bot amateur --handicap 0 --handicap 14 --seed 48 --json | python3 -c "$check_card" 0 || fail "match card: putts and strokes"
# Into a 20 mph wind the tour bot's stock club for National's 169 yd par 3 drops into the water
# short of the green: he takes more club up the bag, never a wedge laid up 80 yd short.
for seed in 11 40 56; do
  "$bin" round national --bot tour --seed "$seed" --json | python3 -c '
import json, sys
h = json.load(sys.stdin)["holes"][2]
first = h["shots"][0]
assert h["par"] == 3 and first["club"] not in ("pw", "sw", "lw", "9-iron"), first["club"]
assert first["carry_m"] > 0.8 * 154.7, first["carry_m"]' || fail "seed $seed: a wedge off a long par 3 into the wind"
done
rm -rf "$plot_dir"
echo "round: ok"
