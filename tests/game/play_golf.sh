#!/usr/bin/env bash
# Play mode under Xvfb, driven by key presses like a player (Debian's xdotool): the first
# stroke with the three meter clicks, the rest by the caddie key; the hole ends in the cup
# or at the pick-up, the final scorecard shows, the window closes itself (--exit-when-done)
# and its last frame is checked. $1 = sweetspot, $2 = check_screenshot.
set -euo pipefail
bin="$1"; check="$2"
if ! command -v xvfb-run >/dev/null || ! command -v xdotool >/dev/null; then
  echo "xvfb-run and xdotool are needed (scripts/dev installs xvfb and xdotool)" >&2; exit 1
fi
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cat > "$work/drive.sh" <<'D'
#!/usr/bin/env bash
set -u
bin="$1"; work="$2"
"$bin" play --mode golf --seed 1 --course links --holes 1 --no-flyover --exit-when-done --screenshot "$work/golf.png" > "$work/log.txt" 2>&1 &
pid=$!
wid=""
for _ in $(seq 1 150); do wid=$(xdotool search --name Sweetspot 2>/dev/null | head -1 || true); [ -n "$wid" ] && break; sleep 0.2; done
[ -n "$wid" ] || { echo "no window"; kill $pid; exit 1; }
sleep 2
xdotool windowfocus --sync "$wid" 2>/dev/null || true
# The tee shot: start, power at ~85 %, the accuracy click near the mark.
xdotool key space; sleep 0.85; xdotool key space; sleep 0.5; xdotool key space; sleep 0.8
xdotool key Return; sleep 0.8
for _ in $(seq 1 16); do
  kill -0 $pid 2>/dev/null || break
  xdotool key b; sleep 1.0; xdotool key Return; sleep 0.7; xdotool key Return; sleep 0.5
done
for _ in $(seq 1 50); do kill -0 $pid 2>/dev/null || break; sleep 0.2; done
kill $pid 2>/dev/null && { echo "the window did not close after the round"; exit 1; }
wait $pid
D
chmod +x "$work/drive.sh"
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$work/drive.sh" "$bin" "$work" || { cat "$work/log.txt"; exit 1; }
cat "$work/log.txt"
grep -q "Sweetspot Links" "$work/log.txt"
grep -Eq "^ +1 +3 +[0-9]+ +[0-9]+\*? \([0-9]+\)" "$work/log.txt" || { echo "no scorecard line for hole 1"; exit 1; }
grep -Eq "^putts " "$work/log.txt" || { echo "no putts row"; exit 1; }
grep -q "ms per frame" "$work/log.txt"
"$check" "$work/golf.png" 1280 800 40  # a green under a scorecard: few colours
# Match play against a bot: the panel's match line before any hole is decided (it read the
# last decided hole's status of an empty list and crashed on the first frame).
cat > "$work/match.sh" <<'D'
#!/usr/bin/env bash
set -u
bin="$1"; work="$2"
"$bin" play --mode golf --seed 1 --course links --holes 1 --no-flyover --format match --bot scratch > "$work/match_log.txt" 2>&1 &
pid=$!
wid=""
for _ in $(seq 1 150); do wid=$(xdotool search --name Sweetspot 2>/dev/null | head -1 || true); [ -n "$wid" ] && break; sleep 0.2; done
[ -n "$wid" ] || { echo "no window"; kill $pid; exit 1; }
sleep 3
kill -0 $pid 2>/dev/null || { echo "match play: the window died"; exit 1; }
xdotool windowfocus --sync "$wid" 2>/dev/null || true
xdotool key Escape; sleep 0.3; xdotool key q; sleep 0.3; xdotool key q
for _ in $(seq 1 50); do kill -0 $pid 2>/dev/null || break; sleep 0.2; done
kill $pid 2>/dev/null && { echo "the match window did not quit"; exit 1; }
wait $pid
D
chmod +x "$work/match.sh"
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$work/match.sh" "$bin" "$work" || { cat "$work/match_log.txt"; exit 1; }
[ -n "${SWEETSPOT_GAME_ARTIFACTS:-}" ] && cp "$work/golf.png" "$SWEETSPOT_GAME_ARTIFACTS/" || true
echo "play golf test passed"
