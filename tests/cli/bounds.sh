#!/usr/bin/env bash
# Resource bounds: absurd sizes (10^9 m/s, 10^9 rpm, a sweep of 10^9 points, a
# 10^9-pixel-wide image) are refused before any work starts: exit 2 within seconds, the
# limit named on stderr, nothing on stdout, no output file.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# expect_refused "what" "needle1|needle2|..." -- sweetspot args...
expect_refused() {
  local what="$1" needles="$2"; shift 3
  local t0 t1 rc
  t0=$(date +%s)
  set +e
  timeout 20 "$bin" "$@" >"$tmp/out" 2>"$tmp/err"; rc=$?
  set -e
  t1=$(date +%s)
  [ $rc -ne 124 ] || fail "$what: still running after 20 s (the bound is not checked before the work)"
  [ $rc -eq 2 ] || fail "$what: exit $rc, want 2 (stderr: $(cat "$tmp/err"))"
  [ ! -s "$tmp/out" ] || fail "$what: printed on stdout: $(cat "$tmp/out")"
  [ $((t1 - t0)) -le 10 ] || fail "$what: took $((t1 - t0)) s to refuse"
  local IFS='|'
  for n in $needles; do
    grep -qF -- "$n" "$tmp/err" || fail "$what: message lacks '$n': $(cat "$tmp/err")"
  done
}

expect_refused "club speed 1e9 m/s" "swing.speed|[0.1, 90] m/s" -- shot golf/driver --set 'swing.speed=1e9m/s'
expect_refused "bat speed 1e9 m/s" "swing.speed|[0.5, 60] m/s" -- shot baseball/line-drive --set 'swing.speed=1e9m/s'
expect_refused "pitch spin 1e9 rpm" "pitch.spin|4000 rpm" -- shot baseball/line-drive --set 'pitch.spin=1e9rpm'
expect_refused "pitch speed 1e9 m/s" "pitch.speed|[0, 49.1744] m/s" -- shot baseball/line-drive --set 'pitch.speed=1e9m/s'
expect_refused "flight ball speed 1e9 m/s" "ball-speed" -- flight --sport golf --ball-speed 1e9m/s --launch-angle 10deg --spin 2500rpm
expect_refused "flight spin 1e9 rpm" "spin" -- flight --sport golf --ball-speed 70m/s --launch-angle 10deg --spin 1e9rpm
expect_refused "wind 1e9 m/s" "environment.wind_speed" -- shot golf/driver --set 'environment.wind_speed=1e9m/s'
expect_refused "sweep axis of 1e9 points" "--e|100000" -- sweep golf/driver --e 0.5:0.9:1000000000 --mu 0.3:0.5:2 --csv "$tmp/s.csv"
expect_refused "sweep grid of 1e10 points" "100000" -- sweep golf/driver --e 0.5:0.9:100000 --mu 0.3:0.5:100000 --csv "$tmp/s.csv"
[ ! -e "$tmp/s.csv" ] || fail "a refused sweep wrote its CSV"
expect_refused "render 1e9 px wide" "8192" -- render golf/driver -o "$tmp/big.png" --width 1000000000 --height 720
expect_refused "render 1e9 px high" "8192" -- render golf/driver -o "$tmp/big.png" --width 1280 --height 1000000000
expect_refused "render width beyond int" "--width|8192" -- render golf/driver -o "$tmp/big.png" --width 99999999999999 --height 720
[ ! -e "$tmp/big.png" ] || fail "a refused render wrote its image"
echo "bounds: all absurd sizes refused with their limits"
