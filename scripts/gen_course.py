#!/usr/bin/env python3
"""Authors the bundled 18-hole course as real courses are kept in OpenStreetMap, plus the
ground under it as an elevation raster, for `sweetspot course import` (DESIGN §9):

  assets/courses/sources/national.osm   golf=hole lines (ref, par, handicap, dist), tees,
                                         fairways, greens, bunkers, ponds and a lateral burn,
                                         pins on some greens, the leisure=golf_course boundary,
                                         tree rows between holes, corner trees, two woods
                                         and a cart path along each hole
  assets/courses/sources/national.asc   an ESRI ASCII grid of heights (m), WGS84 degrees,
  assets/courses/sources/national.prj   with its reference system beside it

Two nines side by side on a kilometre square of gently rolling ground (a few metres of
relief, slopes of 1-4 %), the front nine running up the west half in rows, the back nine
down the east half. Run from the repository root; `--dem-cell` sets the raster's cell in
metres (default 4; 1 for the import timing of issue 43), `--out` another folder. Then:
  sweetspot course import assets/courses/sources/national.osm --dem assets/courses/sources/national.asc \
      --cell 8 -o assets/courses/national"""
import argparse
import math
import os
import random

LAT0, LON0 = 56.3300, -2.7800      # open farmland's latitude; the course is fictional
M_LAT = 111132.954 - 559.822 * math.cos(2 * math.radians(LAT0))   # m per degree of latitude
M_LON = 111412.84 * math.cos(math.radians(LAT0))                  # m per degree of longitude
WGS84_WKT = ('GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],'
             'PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433],AXIS["Latitude",NORTH],'
             'AXIS["Longitude",EAST],AUTHORITY["EPSG","4326"]]')

# number, par, length (m), handicap; front nine west, back nine east.
HOLES = [(1, 4, 365, 7), (2, 5, 470, 3), (3, 3, 165, 17), (4, 4, 350, 11), (5, 4, 405, 1),
         (6, 3, 190, 13), (7, 5, 465, 5), (8, 4, 330, 15), (9, 4, 395, 9),
         (10, 4, 385, 8), (11, 3, 175, 16), (12, 5, 460, 4), (13, 4, 345, 12), (14, 4, 415, 2),
         (15, 3, 150, 18), (16, 4, 370, 10), (17, 5, 455, 6), (18, 4, 400, 14)]
ROW = 105.0


def ground(e, n):
    """Heights (m): a slow rise to the north-east and two crossing swells."""
    return (30.0 + 0.004 * e + 0.006 * n + 3.5 * math.sin(e / 160.0) * math.cos(n / 190.0)
            + 2.5 * math.sin((e + 0.6 * n) / 230.0))


class Map:
    def __init__(self):
        self.nodes, self.ways, self.relations, self.next = [], [], [], 10000

    def id(self):
        self.next += 1
        return self.next

    def node(self, e, n, tags=None):
        i = self.id()
        self.nodes.append((i, LAT0 + n / M_LAT, LON0 + e / M_LON, tags or {}))
        return i

    def way(self, pts, tags, closed=False):
        ids = [self.node(e, n) for e, n in pts]
        if closed:
            ids.append(ids[0])
        i = self.id()
        self.ways.append((i, ids, tags))
        return i

    def write(self, path):
        with open(path, "w") as f:
            f.write("<?xml version='1.0' encoding='UTF-8'?>\n<osm version='0.6' generator='scripts/gen_course.py'>\n")
            for i, lat, lon, tags in self.nodes:
                if tags:
                    f.write(f"  <node id='{i}' lat='{lat:.8f}' lon='{lon:.8f}'>\n")
                    f.writelines(f"    <tag k='{k}' v='{v}'/>\n" for k, v in tags.items())
                    f.write("  </node>\n")
                else:
                    f.write(f"  <node id='{i}' lat='{lat:.8f}' lon='{lon:.8f}'/>\n")
            for i, ids, tags in self.ways:
                f.write(f"  <way id='{i}'>\n")
                f.writelines(f"    <nd ref='{r}'/>\n" for r in ids)
                f.writelines(f"    <tag k='{k}' v='{v}'/>\n" for k, v in tags.items())
                f.write("  </way>\n")
            for i, members, tags in self.relations:
                f.write(f"  <relation id='{i}'>\n")
                f.writelines(f"    <member type='way' ref='{r}' role='{role}'/>\n" for r, role in members)
                f.writelines(f"    <tag k='{k}' v='{v}'/>\n" for k, v in tags.items())
                f.write("  </relation>\n")
            f.write("</osm>\n")


def blob(ce, cn, a, b, turn, rng, k=28, wobble=0.08):
    """A mapped outline: an ellipse with a little irregularity, as greens and bunkers are drawn."""
    out = []
    phase = rng.uniform(0, 2 * math.pi)
    for t in range(k):
        th = 2 * math.pi * t / k
        r = 1.0 + wobble * math.sin(3 * th + phase)
        x, y = a * r * math.cos(th), b * r * math.sin(th)
        out.append((ce + x * math.cos(turn) - y * math.sin(turn), cn + x * math.sin(turn) + y * math.cos(turn)))
    return out


def corridor(line, half, rng, step=12.0):
    """A fairway along a polyline: both edges offset by `half` m with a gentle wobble."""
    pts = []
    for (e0, n0), (e1, n1) in zip(line, line[1:]):
        seg = math.dist((e0, n0), (e1, n1))
        k = max(1, int(seg / step))
        for j in range(k):
            u = j / k
            pts.append((e0 + u * (e1 - e0), n0 + u * (n1 - n0), (e1 - e0) / seg, (n1 - n0) / seg))
    e, n = line[-1]
    pts.append((e, n, pts[-1][2], pts[-1][3]))
    left, right = [], []
    for i, (e, n, de, dn) in enumerate(pts):
        w = half * (1.0 + 0.12 * math.sin(i * 0.7 + rng.uniform(0, 0.3)))
        left.append((e - dn * w, n + de * w))
        right.append((e + dn * w, n - de * w))
    return left + right[::-1]


def along(line, dist):
    """The point `dist` m along a polyline, and its direction there."""
    for (e0, n0), (e1, n1) in zip(line, line[1:]):
        seg = math.dist((e0, n0), (e1, n1))
        if dist <= seg:
            u = dist / seg
            return (e0 + u * (e1 - e0), n0 + u * (n1 - n0)), ((e1 - e0) / seg, (n1 - n0) / seg)
        dist -= seg
    (e0, n0), (e1, n1) = line[-2], line[-1]
    seg = math.dist((e0, n0), (e1, n1))
    return (e1, n1), ((e1 - e0) / seg, (n1 - n0) / seg)


def build():
    rng = random.Random(20261129)
    m = Map()
    for num, par, length, hcp in HOLES:
        front = num <= 9
        row = (num - 1) if front else (18 - num)
        east = (row % 2 == 0) if front else (row % 2 == 1)
        x0, x1 = (20.0, 480.0) if front else (520.0, 980.0)
        n = 60.0 + row * ROW
        start = x0 if east else x1
        sgn = 1.0 if east else -1.0
        tee = (start, n)
        if par == 5:     # a dogleg: the line bends 12 m off at 260 m
            bend = (start + sgn * 260.0, n + (12.0 if row % 3 else -12.0))
            rest = length - math.dist(tee, bend)
            end = (bend[0] + sgn * math.sqrt(max(rest ** 2 - (n - bend[1]) ** 2, 1.0)), n)
            line = [tee, bend, end]
        else:
            line = [tee, (start + sgn * length, n)]
        green = line[-1]
        # Three tee sets: blue round the line's first node, white and red further on (a par 3's closer together).
        m.way([(tee[0] - 11 * sgn, n - 6), (tee[0] + 11 * sgn, n - 6), (tee[0] + 11 * sgn, n + 6), (tee[0] - 11 * sgn, n + 6)],
              {"golf": "tee", "tee": "blue"}, closed=True)
        for name, ahead in (("white", 22.0 if par > 3 else 14.0), ("red", 48.0 if par > 3 else 30.0)):
            c = tee[0] + sgn * ahead
            m.way([(c - 5 * sgn, n - 5), (c + 5 * sgn, n - 5), (c + 5 * sgn, n + 5), (c - 5 * sgn, n + 5)],
                  {"golf": "tee", "tee": name}, closed=True)
        if par > 3:
            from_ = 105.0 if par == 4 else 120.0
            pts = [along(line, d)[0] for d in range(int(from_), int(length - 18), 15)] + [along(line, length - 18)[0]]
            m.way(corridor(pts, 16.0, rng), {"golf": "fairway"}, closed=True)
            (fe, fn), (de, dn) = along(line, 245.0 if par == 4 else 270.0)
            side = 1.0 if rng.random() < 0.5 else -1.0
            m.way(blob(fe - dn * side * 21, fn + de * side * 21, 9, 4.5, math.atan2(dn, de), rng), {"golf": "bunker", "natural": "sand"}, closed=True)
        turn = rng.uniform(-0.5, 0.5)
        m.way(blob(green[0], green[1], 15.0, 12.0, turn, rng, 32, 0.06), {"golf": "green"}, closed=True)
        for side in (1.0, -1.0):
            if side < 0 or rng.random() < 0.7:
                m.way(blob(green[0] - sgn * 3, green[1] + side * 17.5, 6.5, 3.2, rng.uniform(-0.3, 0.3), rng), {"golf": "bunker", "natural": "sand"}, closed=True)
        if num % 3 == 1:   # a pin mapped on every third green
            m.node(green[0] + sgn * rng.uniform(-4, 4), green[1] + rng.uniform(-3, 3), {"golf": "pin", "ref": str(num)})
        # A cart path from the tee to the green along the side the line does not bend to, in the rough.
        side = -1.0 if (par == 5 and row % 3) or num == 14 else 1.0   # the 14th: its burn lies on the other side
        m.way([(tee[0] + sgn * 15, n + side * 30), (green[0] - sgn * 25, n + side * 30)], {"golf": "cart_path", "surface": "asphalt"})
        dist = round(sum(math.dist(a, b) for a, b in zip(line, line[1:])))
        ids = [m.node(*p) for p in line]
        hid = m.id()
        m.ways.append((hid, ids, {"golf": "hole", "ref": str(num), "par": str(par), "handicap": str(hcp), "dist": str(dist)}))
    # Water: ponds short of the 3rd and 15th greens, a pond right of the 7th, a burn along the 14th.
    for ce, cn in ((20 + 165 - 45, 60 + 2 * ROW - 2), (520 + 150 - 45 + 310, 60 + 3 * ROW)):
        pass
    m.way(blob(20 + 165 - 48, 60 + 2 * ROW, 16, 11, 0.2, rng), {"golf": "water_hazard", "natural": "water"}, closed=True)
    m.way(blob(980 - 150 + 48, 60 + 3 * ROW, 14, 10, -0.3, rng), {"golf": "water_hazard", "natural": "water"}, closed=True)
    m.way(blob(480 - 300, 60 + 6 * ROW - 34, 30, 9, 0.0, rng), {"golf": "water_hazard", "natural": "water"}, closed=True)
    m.way([(560, 60 + 4 * ROW + 30), (930, 60 + 4 * ROW + 30), (930, 60 + 4 * ROW + 36), (560, 60 + 4 * ROW + 36)],
          {"golf": "lateral_water_hazard"}, closed=True)
    m.way([(-10, 0), (1010, 0), (1010, 60 + 8 * ROW + 60), (-10, 60 + 8 * ROW + 60)],
          {"leisure": "golf_course", "name": "Sweetspot National"}, closed=True)
    # Trees as a parkland course has them: rows between neighbouring holes with gaps, a few
    # single trees guarding corners, and woods along the north and south boundaries.
    for x0, x1 in ((20.0, 480.0), (520.0, 980.0)):
        for row in range(8):
            n = 60.0 + row * ROW + ROW / 2
            e = x0 + 70.0
            while e < x1 - 90.0:
                length = rng.uniform(90.0, 150.0)
                end = min(e + length, x1 - 70.0)
                wob = rng.uniform(-6.0, 6.0)
                m.way([(e, n + wob), ((e + end) / 2, n - wob), (end, n + wob * 0.5)],
                      {"natural": "tree_row", "height": str(rng.choice((10, 12, 14, 16)))})
                e = end + rng.uniform(30.0, 60.0)
    for num, par, length, hcp in HOLES:
        if par == 5:   # a tree inside each dogleg's bend, 45 m short of it
            front = num <= 9
            row = (num - 1) if front else (18 - num)
            east = (row % 2 == 0) if front else (row % 2 == 1)
            sgn = 1.0 if east else -1.0
            start = (20.0 if east else 480.0) if front else (520.0 if east else 980.0)
            n = 60.0 + row * ROW
            m.node(start + sgn * 215.0, n + (30.0 if row % 3 else -30.0), {"natural": "tree", "height": "18"})
    m.way([(0, 8), (1000, 8), (1000, 30), (0, 30)], {"natural": "wood"}, closed=True)
    m.way([(0, 60 + 8 * ROW + 30), (1000, 60 + 8 * ROW + 30), (1000, 60 + 8 * ROW + 55), (0, 60 + 8 * ROW + 55)],
          {"natural": "wood"}, closed=True)
    return m


def write_dem(path, cell_m, margin=80.0):
    """The ground under the course and its ring of out of bounds, `cell_m` m north-south."""
    d_lat = cell_m / M_LAT
    s, n = -margin, 60 + 8 * ROW + 60 + margin
    w, e = -10 - margin, 1010 + margin
    rows = int((n - s) / cell_m) + 1
    cols = int((e - w) / (d_lat * M_LON)) + 1
    with open(path + ".asc", "w") as f:
        f.write(f"ncols {cols}\nnrows {rows}\nxllcorner {LON0 + w / M_LON:.9f}\nyllcorner {LAT0 + s / M_LAT:.9f}\n"
                f"cellsize {d_lat:.10f}\nNODATA_value -9999\n")
        for r in range(rows):
            nn = n - (r + 0.5) * cell_m
            f.write(" ".join(f"{ground(w + (c + 0.5) * d_lat * M_LON, nn):.2f}" for c in range(cols)) + "\n")
    with open(path + ".prj", "w") as f:
        f.write(WGS84_WKT + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="assets/courses/sources")
    ap.add_argument("--dem-cell", type=float, default=4.0)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    build().write(os.path.join(a.out, "national.osm"))
    write_dem(os.path.join(a.out, "national"), a.dem_cell)


if __name__ == "__main__":
    main()
