#!/usr/bin/env python3
"""Checks `tessera quantities FLAT --csv`: the flat's total equals the sum of its rooms'.

Usage: flat_quantities_sum.py TESSERA FLAT.json ROOMS
Every tile count (whole, cut, pieces needed), laid area, and the net, VAT and gross totals of
the flat's section must be the sum over the room sections; there must be ROOMS rooms."""
import csv
import io
import subprocess
import sys

tessera, flat, rooms_expected = sys.argv[1], sys.argv[2], int(sys.argv[3])
run = subprocess.run([tessera, "quantities", flat, "--csv"], capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"quantities failed ({run.returncode}): {run.stderr}")

sections = []  # [kind, name, {"tiles": {article: [whole, cut, needed, area]}, "total": [...]}]
for row in csv.reader(io.StringIO(run.stdout)):
    if not row:
        continue
    if row[0] in ("room", "flat"):
        sections.append([row[0], row[1], {"tiles": {}, "total": None}])
    elif row[0] == "tiles" and sections:
        key = (row[2], row[3], row[4])
        sections[-1][2]["tiles"][key] = [int(row[8]), int(row[9]), int(row[11]), float(row[12])]
    elif row[0] == "total" and sections:
        sections[-1][2]["total"] = [round(float(x) * 100) for x in row[10:13]]

rooms = [s for s in sections if s[0] == "room"]
flats = [s for s in sections if s[0] == "flat"]
if len(rooms) != rooms_expected or len(flats) != 1 or sections[-1][0] != "flat":
    sys.exit(f"expected {rooms_expected} room sections then one flat section, got "
             f"{[s[0] + ':' + s[1] for s in sections]}")
total = flats[0][2]
fails = []
for i, name in enumerate(("net", "VAT", "gross")):
    room_sum = sum(r[2]["total"][i] for r in rooms)
    if room_sum != total["total"][i] or room_sum <= 0:
        fails.append(f"{name}: rooms sum to {room_sum} cents, the flat says {total['total'][i]}")
articles = set(k for r in rooms for k in r[2]["tiles"])
if set(total["tiles"]) != articles or not articles:
    fails.append(f"tile products: rooms {sorted(articles)}, flat {sorted(total['tiles'])}")
for key in articles:
    for i, what in enumerate(("whole", "cut", "pieces needed", "area m2")):
        room_sum = sum(r[2]["tiles"].get(key, [0, 0, 0, 0])[i] for r in rooms)
        got = total["tiles"].get(key, [0, 0, 0, 0])[i]
        if abs(room_sum - got) > (0.0005 * len(rooms) if i == 3 else 0):
            fails.append(f"{key[1]} {what}: rooms sum to {room_sum}, the flat says {got}")
if fails:
    sys.exit("\n".join(fails))
tiles = sum(v[0] + v[1] for v in total["tiles"].values())
print(f"flat_quantities_sum: PASS: {len(rooms)} rooms, {tiles} tiles, "
      f"net {total['total'][0] / 100:.2f} = the sum of the rooms'")
