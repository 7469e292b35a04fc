#!/usr/bin/env python3
"""Writes tests/data/osm/nine_holes.osm: a nine-hole course mapped the way OpenStreetMap maps
real ones (golf=hole lines from tee to green with ref, par, handicap and dist; golf=tee,
fairway, green, bunker, water_hazard and lateral_water_hazard areas; golf=pin nodes on some
greens; a leisure=golf_course boundary; one green drawn as a multipolygon relation with a
bunker cut into it; trees, a tree row and a wood in the rough; a cart path). The holes run east and west in rows 90 m apart, so the test can check
each one's length and par against the map. Run from the repository root."""
import math

LAT0, LON0 = 56.3400, -2.8000          # an open field's latitude; the course is fictional
M_LAT = 111132.954 - 559.822 * math.cos(2 * math.radians(LAT0))   # m per degree of latitude
M_LON = 111412.84 * math.cos(math.radians(LAT0))                  # m per degree of longitude

nodes, ways, relations = [], [], []
next_id = [1000]


def nid():
    next_id[0] += 1
    return next_id[0]


def node(e, n, tags=None):
    i = nid()
    nodes.append((i, LAT0 + n / M_LAT, LON0 + e / M_LON, tags or {}))
    return i


def way(points, tags, closed=False):
    ids = [node(e, n) for e, n in points]
    if closed:
        ids.append(ids[0])
    i = nid()
    ways.append((i, ids, tags))
    return i


def ellipse(ce, cn, a, b, k=24, turn=0.0):
    return [(ce + a * math.cos(2 * math.pi * t / k + turn), cn + b * math.sin(2 * math.pi * t / k)) for t in range(k)]


def rect(e0, n0, e1, n1):
    return [(e0, n0), (e1, n0), (e1, n1), (e0, n1)]


# number, par, length (m), handicap
HOLES = [(1, 4, 365, 5), (2, 3, 155, 9), (3, 5, 470, 1), (4, 4, 340, 6), (5, 4, 395, 3),
         (6, 3, 175, 8), (7, 4, 380, 4), (8, 5, 490, 2), (9, 4, 355, 7)]
ROW = 90.0
for num, par, length, hcp in HOLES:
    row = num - 1
    east = row % 2 == 0
    n = row * ROW
    e0 = 0.0 if east else 520.0
    sgn = 1.0 if east else -1.0
    tee = (e0, n)
    green = (e0 + sgn * length, n)
    if num == 1:   # two named tee sets on the 1st: white at the line's first node, red 40 m on
        way(rect(e0 - 12, n - 6, e0 + 12, n + 6), {"golf": "tee", "tee": "white"}, closed=True)
        way(rect(e0 + 34, n - 4, e0 + 46, n + 4), {"golf": "tee", "tee": "red"}, closed=True)
    else:
        way(rect(e0 - 12, n - 6, e0 + 12, n + 6), {"golf": "tee"}, closed=True)
    if par > 3:   # a fairway from 140 m out to 15 m short of the green
        f0, f1 = e0 + sgn * 140, e0 + sgn * (length - 15)
        way(rect(min(f0, f1), n - 17, max(f0, f1), n + 17), {"golf": "fairway"}, closed=True)
    gn = (green[0] + sgn * 0.0, n)
    if num == 5:
        # The green as a multipolygon: an outer ring with a pot bunker cut into it.
        outer = way(ellipse(gn[0], gn[1], 16, 13), {}, closed=True)
        inner = way(ellipse(gn[0] - sgn * 6, gn[1] + 5, 3, 3, 12), {"golf": "bunker"}, closed=True)
        rid = nid()
        relations.append((rid, [("way", outer, "outer"), ("way", inner, "inner")], {"type": "multipolygon", "golf": "green"}))
    else:
        way(ellipse(gn[0], gn[1], 16, 13), {"golf": "green"}, closed=True)
    way(ellipse(gn[0] - sgn * 4, gn[1] - 18, 7, 4, 16), {"golf": "bunker"}, closed=True)
    if num in (1, 4, 7):   # a pin mapped on the green, 4 m past its centre
        node(gn[0] + sgn * 4, gn[1], {"golf": "pin"})
    line = [tee, green] if par != 5 else [tee, (e0 + sgn * 250, n + 8), green]
    ids = [node(*p) for p in line]
    hid = nid()
    ways.append((hid, ids, {"golf": "hole", "ref": str(num), "par": str(par), "handicap": str(hcp),
                            "dist": str(round(sum(math.dist(a, b) for a, b in zip(line, line[1:]))))}))
# A pond short of the 2nd green, and a burn along the north of the 8th.
way(ellipse(40 + 520 - 155 + 40, ROW, 14, 10), {"golf": "water_hazard"}, closed=True)
way(rect(60, 7 * ROW + 26, 420, 7 * ROW + 32), {"golf": "lateral_water_hazard"}, closed=True)
way(rect(-40, -40, 560, 8 * ROW + 40), {"leisure": "golf_course", "name": "Fixture Nine"}, closed=True)
# Trees, in the rough between holes: a row between the 2nd and 3rd, two single trees (one
# with its height), and a small wood north of the 8th's burn.
way([(60, 1.5 * ROW), (420, 1.5 * ROW)], {"natural": "tree_row"})
node(250, 0.5 * ROW, {"natural": "tree", "height": "16"})
node(300, 2.5 * ROW, {"natural": "tree"})
way(rect(150, 7 * ROW + 42, 350, 7 * ROW + 68), {"natural": "wood"}, closed=True)
# A cart path up the north side of the 1st, 3 m wide.
way([(-20, 28), (200, 30), (480, 30)], {"golf": "cart_path", "width": "3"})

with open("tests/data/osm/nine_holes.osm", "w") as f:
    f.write("<?xml version='1.0' encoding='UTF-8'?>\n<osm version='0.6' generator='scripts/gen_osm_fixture.py'>\n")
    for i, lat, lon, tags in nodes:
        if tags:
            f.write(f"  <node id='{i}' lat='{lat:.8f}' lon='{lon:.8f}'>\n")
            for k, v in tags.items():
                f.write(f"    <tag k='{k}' v='{v}'/>\n")
            f.write("  </node>\n")
        else:
            f.write(f"  <node id='{i}' lat='{lat:.8f}' lon='{lon:.8f}'/>\n")
    for i, ids, tags in ways:
        f.write(f"  <way id='{i}'>\n")
        for r in ids:
            f.write(f"    <nd ref='{r}'/>\n")
        for k, v in tags.items():
            f.write(f"    <tag k='{k}' v='{v}'/>\n")
        f.write("  </way>\n")
    for i, members, tags in relations:
        f.write(f"  <relation id='{i}'>\n")
        for t, r, role in members:
            f.write(f"    <member type='{t}' ref='{r}' role='{role}'/>\n")
        for k, v in tags.items():
            f.write(f"    <tag k='{k}' v='{v}'/>\n")
        f.write("  </relation>\n")
    f.write("</osm>\n")
