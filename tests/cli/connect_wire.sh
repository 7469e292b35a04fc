#!/usr/bin/env bash
# The Open Connect server from outside, over TCP, as a launch monitor or a hostile client
# meets it (DESIGN §10; docs/robustness.md, "What the launch-monitor server guarantees"):
# no valid shot lost after a broken message, every reply of a half-closed client sent, the
# slot not held by a client that sends nothing whole, reconnects served, one strict value
# rule, --max-shots exact. Every check runs; each failure is listed.
set -euo pipefail
bin=$(realpath "$1")
exec python3 - "$bin" <<'PY'
import json, os, re, socket, subprocess, sys, tempfile, time

BIN = sys.argv[1]
failures = []

def check(name, ok, detail=""):
    print(("ok   " if ok else "FAIL ") + name + ("" if ok else ": " + detail), file=sys.stderr)
    if not ok:
        failures.append(name)

def shot(n, speed=150.0, extra=""):
    return ('{"DeviceID":"wire","Units":"Yards","ShotNumber":%d,"APIversion":"1",'
            '"BallData":{"Speed":%s,"SpinAxis":0,"TotalSpin":2500,"HLA":0,"VLA":12%s},'
            '"ShotDataOptions":{"ContainsBallData":true,"ContainsClubData":false}}' % (n, speed, extra))

class Server:
    def __init__(self, *args):
        self.dir = tempfile.mkdtemp()
        self.err = open(os.path.join(self.dir, "err"), "w+")
        self.out = open(os.path.join(self.dir, "out"), "w+")
        self.p = subprocess.Popen([BIN, "connect", "--headless", "--port", "0", *args],
                                  stdout=self.out, stderr=self.err)
        self.port = None
        for _ in range(100):
            self.err.seek(0)
            m = re.search(r"listening on 127\.0\.0\.1:(\d+)", self.err.read())
            if m:
                self.port = int(m.group(1))
                break
            time.sleep(0.1)
        assert self.port, "no 'listening on' line"

    def connect(self):
        s = socket.create_connection(("127.0.0.1", self.port), timeout=10)
        return s

    def result_lines(self):
        self.out.flush()
        self.out.seek(0)
        return [l for l in self.out.read().splitlines() if l.strip()]

    def stop(self):
        if self.p.poll() is None:
            self.p.terminate()
        try:
            return self.p.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.p.kill()
            return None

def replies(sock, want, seconds):
    """Reads replies until `want` with Code 200 arrived, EOF or `seconds` passed; all codes."""
    buf, codes, msgs = b"", [], []
    end = time.time() + seconds
    while codes.count(200) < want and time.time() < end:
        sock.settimeout(max(0.05, end - time.time()))
        try:
            data = sock.recv(65536)
        except socket.timeout:
            break
        except ConnectionError:
            break
        if not data:
            break
        buf += data
        dec = json.JSONDecoder()
        text = buf.decode("utf-8", "replace")
        i = 0
        while True:
            j = text.find("{", i)
            if j < 0:
                break
            try:
                obj, k = dec.raw_decode(text, j)
            except ValueError:
                break
            codes.append(obj.get("Code"))
            msgs.append(obj.get("Message", ""))
            i = k
        buf = text[i:].encode()
    return codes, msgs

srv = Server()
try:
    # A message cut inside a string, then five shots: all five answered 200, the cut one 501.
    s = srv.connect()
    s.sendall(b'{"DeviceID":"cut here' + "".join(shot(n) for n in range(1, 6)).encode())
    codes, msgs = replies(s, 5, 8)
    check("a message cut inside a string loses none of the 5 shots after it", codes.count(200) == 5, str(codes))
    check("the cut message is answered once with 501", codes.count(501) == 1, str(codes))
    s.close()

    # A stray '{' before a shot: the shot is answered 200.
    s = srv.connect()
    s.sendall(b"{" + shot(6).encode())
    codes, _ = replies(s, 1, 5)
    check("a stray '{' before a shot does not cost the shot", 200 in codes, str(codes))
    s.close()

    # Three shots and a half-close: three 200s before the server closes.
    s = srv.connect()
    s.sendall("".join(shot(n) for n in range(7, 10)).encode())
    s.shutdown(socket.SHUT_WR)
    codes, _ = replies(s, 3, 15)
    check("a half-closed client gets every reply", codes.count(200) == 3, str(codes))
    s.close()

    # A number with a unit, a flag as a string, a key twice: 501 naming the key.
    for name, text, key in [
        ("a speed with a unit is refused", shot(20, '"150 km/h"'), "Speed"),
        ("a flag given as a string is refused",
         shot(21).replace('"ContainsBallData":true', '"ContainsBallData":"true"'), "ContainsBallData"),
        ("a key given twice in another case is refused", shot(22, extra=',"speed":90'), "speed"),
    ]:
        s = srv.connect()
        s.sendall(text.encode())
        codes, msgs = replies(s, 1, 5)
        check(name, 501 in codes and any(key in m for m in msgs) and 200 not in codes, "%s %s" % (codes, msgs))
        s.close()

    # Twenty drops and reconnects at once (the new socket opened right after the old one's
    # close, before the server has read it): each served, none turned away with 503.
    served, seen = 0, []
    old = None
    for n in range(30, 50):
        if old is not None:
            old.close()
        s = srv.connect()
        s.sendall(shot(n).encode())
        codes, _ = replies(s, 1, 5)
        seen.append(codes)
        served += 200 in codes
        old = s
    old.close()
    check("20 quick reconnects are each served", served == 20, "%d of 20: %s" % (served, seen))

    # A client trickling an unfinished message holds the slot no longer than a few seconds
    # against a launch monitor that sends a whole shot.
    hog = srv.connect()
    hog.sendall(b'{"DeviceID":"slow')
    time.sleep(0.5)
    s = srv.connect()
    s.sendall(shot(60).encode())
    start = time.time()
    got = False
    while time.time() - start < 10 and not got:
        try:
            hog.sendall(b"x")
        except OSError:
            pass
        codes, _ = replies(s, 1, 0.5)
        got = 200 in codes
        if 503 in codes:
            break
    check("a trickling client does not hold the slot against a launch monitor", got,
          "no 200 within 10 s (codes %s)" % codes)
    hog.close()
    s.close()
finally:
    srv.stop()

# --max-shots 2 and a burst of four: exactly two shots played, exit 0.
srv = Server("--max-shots", "2")
try:
    s = srv.connect()
    s.sendall("".join(shot(n) for n in range(1, 5)).encode())
    replies(s, 2, 5)
    s.close()
    try:
        rc = srv.p.wait(timeout=20)
    except subprocess.TimeoutExpired:
        rc = "none: still running after 20 s"
    lines = srv.result_lines()
    check("--max-shots 2 plays exactly 2 of a burst of 4", rc == 0 and len(lines) == 2,
          "exit %s, %d result lines" % (rc, len(lines)))
finally:
    srv.stop()

sys.exit(1 if failures else 0)
PY
