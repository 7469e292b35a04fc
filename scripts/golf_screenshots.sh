#!/usr/bin/env bash
# Plays the golf game under Xvfb like a newcomer and keeps a screenshot (F12) of each thing a
# player must see: the flyover, the map (M), a stroke in the air with the HUD still on the
# stroke played, the ball at rest with the result told, the putt preview on the green, the
# final card, the practice range's bag table. Look at every PNG before calling the game done.
# Usage: scripts/golf_screenshots.sh [BUILD/sweetspot] [OUT_DIR]
set -euo pipefail
bin="${1:-build/release/sweetspot}"; out="${2:-$(mktemp -d)}"
mkdir -p "$out"; out=$(cd "$out" && pwd); bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
drive() {  # $1 = play arguments, $2 = the keys script (xdotool lines), run in a fresh window
  cat > "$out/drive.sh" <<D
#!/usr/bin/env bash
set -u
SWEETSPOT_SETTINGS="$out/settings.toml" "$bin" play $1 --shots-dir "$out" >> "$out/log.txt" 2>&1 &
pid=\$!
wid=""
for _ in \$(seq 1 150); do wid=\$(xdotool search --name Sweetspot 2>/dev/null | head -1 || true); [ -n "\$wid" ] && break; sleep 0.2; done
[ -n "\$wid" ] || { echo "no window"; kill \$pid; exit 1; }
sleep 1.5
xdotool windowfocus --sync "\$wid" 2>/dev/null || true
$2
xdotool key Escape; sleep 0.3; xdotool key q; sleep 0.3; xdotool key q  # Q asks first when play would be lost
for _ in \$(seq 1 50); do kill -0 \$pid 2>/dev/null || break; sleep 0.2; done
wait \$pid
D
  chmod +x "$out/drive.sh"
  xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$out/drive.sh"
}
# 1-2 the flyover, 3 the map, 4 the golfer at address, 5 his follow-through as the ball
# leaves, 6 in the air, 7 at rest (the result told).
drive "--mode golf --holes 1" '
xdotool key F12; sleep 2.0; xdotool key F12; sleep 4.5
xdotool key m; sleep 0.5; xdotool key F12; xdotool key m; sleep 0.3; xdotool key F12
xdotool key space; sleep 0.85; xdotool key space; sleep 0.55; xdotool key space; sleep 0.15; xdotool key F12; sleep 1.05
xdotool key F12; xdotool key Return; sleep 0.6; xdotool key F12'
# 6.. alone: the caddie plays to the green; each turn a shot, then the putt preview mid-stroke.
drive "--mode golf --holes 1 --no-flyover --bot none" '
for i in 1 2 3 4 5; do
  xdotool key b; sleep 0.3; xdotool key Return; sleep 1.8
  xdotool key F12; sleep 0.2; xdotool key space; sleep 0.5; xdotool key F12; sleep 0.2
  xdotool key Escape; sleep 0.3
done
for i in 1 2 3 4 5 6; do xdotool key b; sleep 0.3; xdotool key Return; sleep 1.0; done
xdotool key F12'
# alone: the caddie's tee shot, then its replay (R): the strike slowed from behind the
# golfer, alongside the flight; R again ends it, back at address.
drive "--mode golf --holes 1 --no-flyover --bot none" '
xdotool key b; sleep 0.3; xdotool key Return; sleep 2.5
xdotool key r; sleep 0.6; xdotool key F12; sleep 2.5; xdotool key F12; xdotool key r; sleep 0.5; xdotool key F12'
# the range: a few swings per club, the table.
drive "--mode range --bag $out/bag.toml" '
for i in 1 2 3 4 5 6 7; do xdotool key b; sleep 0.3; xdotool key Return; sleep 0.3; done
xdotool key s; sleep 0.5; xdotool key F12'
echo "screenshots in $out:"; ls "$out"/*.png
