#!/usr/bin/env bash
# The batting cage under Xvfb, driven by key presses (xdotool): call for a pitch, swing when
# it reaches the plate, watch the call; the window closes itself after the pitch and its
# last frame is checked. $1 = sweetspot, $2 = check_screenshot.
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
"$bin" play --mode baseball --seed 11 --pitches 1 --exit-when-done --screenshot "$work/cage.png" > "$work/log.txt" 2>&1 &
pid=$!
wid=""
for _ in $(seq 1 150); do wid=$(xdotool search --name Sweetspot 2>/dev/null | head -1 || true); [ -n "$wid" ] && break; sleep 0.2; done
[ -n "$wid" ] || { echo "no window"; kill $pid; exit 1; }
sleep 2
xdotool windowfocus --sync "$wid" 2>/dev/null || true
# The pitcher winds up for 0.9 s and the batting-practice pitch takes 0.62 s, both shown at
# half speed: swing 3.0 s after calling it.
xdotool key space; sleep 3.02; xdotool key space
for _ in $(seq 1 80); do kill -0 $pid 2>/dev/null || break; sleep 0.25; done
kill $pid 2>/dev/null && { echo "the window did not close after the pitch"; exit 1; }
wait $pid
D
chmod +x "$work/drive.sh"
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$work/drive.sh" "$bin" "$work" || { cat "$work/log.txt"; exit 1; }
cat "$work/log.txt"
grep -Eq "^swing: (strike|foul|out|single|double|triple|home_run)" "$work/log.txt" || { echo "no call for the swing"; exit 1; }
"$check" "$work/cage.png" 1280 800
[ -n "${SWEETSPOT_GAME_ARTIFACTS:-}" ] && cp "$work/cage.png" "$SWEETSPOT_GAME_ARTIFACTS/" || true
echo "play baseball test passed"
