#!/usr/bin/env bash
# Plays the batting cage under Xvfb and keeps a screenshot (F12) of each thing a hitter must
# see: the pitcher set, his delivery, the release from the batter's eye, the swing, the ball in
# play with the fielders running to it, and a live at-bat's count. Look at every PNG before calling the cage done.
# Usage: scripts/baseball_screenshots.sh [BUILD/sweetspot] [OUT_DIR]
set -euo pipefail
bin="${1:-build/release/sweetspot}"; out="${2:-$(mktemp -d)}"
mkdir -p "$out"; out=$(cd "$out" && pwd); bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
cat > "$out/drive.sh" <<D
#!/usr/bin/env bash
set -u
"$bin" play --mode baseball --seed 11 --shots-dir "$out" >> "$out/log.txt" 2>&1 &
pid=\$!
wid=""
for _ in \$(seq 1 150); do wid=\$(xdotool search --name Sweetspot 2>/dev/null | head -1 || true); [ -n "\$wid" ] && break; sleep 0.2; done
[ -n "\$wid" ] || { echo "no window"; kill \$pid; exit 1; }
sleep 1.5
xdotool windowfocus --sync "\$wid" 2>/dev/null || true
# 1 set; 2 the leg lift; 3 the arm cocked; 4 the pitch on its way; 5 the swing (the pro's, B);
# 6-8 the ball in play and the fielders running.
xdotool key F12; xdotool key p; sleep 0.5; xdotool key F12; sleep 0.6; xdotool key F12; sleep 0.9; xdotool key F12
xdotool key b; sleep 0.15; xdotool key F12; sleep 1.0; xdotool key F12; sleep 1.5; xdotool key F12; sleep 1.5; xdotool key F12
sleep 3
# A second pitch: the human's swing at the arrival.
xdotool key space; sleep 3.02; xdotool key space; sleep 0.1; xdotool key F12; sleep 2.0; xdotool key F12
# A live at-bat against the league's pitcher (A): swings timed for his ~94 mph fastball, the
# count and the plate appearance in the HUD.
xdotool key a; sleep 0.3
for i in 1 2 3 4 5; do
  xdotool key space; sleep 2.59; xdotool key space; sleep 0.3; xdotool key F12; sleep 2.5
done
xdotool key F12
xdotool key Escape; sleep 0.3; xdotool key q; sleep 0.3; xdotool key q  # Q asks first when play would be lost
for _ in \$(seq 1 50); do kill -0 \$pid 2>/dev/null || break; sleep 0.2; done
wait \$pid
D
chmod +x "$out/drive.sh"
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$out/drive.sh"
echo "screenshots in $out:"; ls "$out"/*.png
