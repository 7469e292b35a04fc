#!/usr/bin/env python3
"""Fails when a source includes a header of a higher layer (DESIGN §1: layers depend downward).

The order is CMakeLists.txt's SWEETSPOT_LAYERS (physics, then game/<layer>), with game/cli on
top; a file may include its own layer and any lower one. Prints each include that runs back
up as `file:line: includes path (layer -> higher layer)`, then the count; exit 1 when any.
Usage: scripts/check_layers.py [SOURCE_ROOT]
"""
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
with open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8") as f:
    m = re.search(r"set\(SWEETSPOT_LAYERS ([^)]*)\)", f.read())
names = m.group(1).split()
rank = {("physics" if n == "physics" else "game/" + n): i for i, n in enumerate(names)}
rank["game/cli"] = len(names)
include = re.compile(r'^\s*#\s*include\s*"((?:physics|game)/[^"]+)"')


def layer(path):
    for name in sorted(rank, key=len, reverse=True):
        if path == name or path.startswith(name + "/"):
            return name
    return None


bad = []
for top in ("physics", "game"):
    for dirpath, _, files in os.walk(os.path.join(root, top)):
        for name in sorted(files):
            if not name.endswith((".hpp", ".cpp")):
                continue
            rel = os.path.relpath(os.path.join(dirpath, name), root)
            src = layer(rel)
            if src is None:
                bad.append(f"{rel}: not in a layer (add its folder to SWEETSPOT_LAYERS)")
                continue
            with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
                for n, line in enumerate(f, 1):
                    inc = include.match(line)
                    if inc and (dst := layer(inc.group(1))) is not None and rank[dst] > rank[src]:
                        bad.append(f"{rel}:{n}: includes {inc.group(1)} ({src} -> higher layer {dst})")
for b in bad:
    print(b)
print(f"layers: {len(bad)} includes run back up")
sys.exit(1 if bad else 0)
