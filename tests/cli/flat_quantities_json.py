#!/usr/bin/env python3
"""Checks `tessera quantities FLAT --json` against the flat's rooms quantified alone.

usage: flat_quantities_json.py TESSERA FLAT.json OUT_DIR

Each room is written out as a single-room project (its keys with the flat's shared ones, as
flat_render_room.sh does) and run through `tessera quantities ROOM --json`. Then:
- the flat's rooms[i] equal room i alone: its tiles, trims, consumables and bill, every number;
- the flat's total is the sum over the rooms alone: each tile product's counts, areas and
  order, each trim's edges, metres, pieces and metres billed, every consumable amount, each
  bill line's quantity, net, VAT and gross (by product and kind), and the bill's net, VAT and
  gross;
- the quotation (what --xlsx writes) holds every room's lines in turn, and its net, VAT and
  gross are the total's;
- the total bills consumables and labour."""
import json
import os
import subprocess
import sys

tessera, flat_path, out_dir = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out_dir, exist_ok=True)
fails = []


def quantities(path):
    run = subprocess.run([tessera, "quantities", path, "--json", "--date", "2026-12-04"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"quantities {path} failed ({run.returncode}): {run.stderr}")
    return json.loads(run.stdout)


def near(a, b):
    return abs(a - b) <= 1e-6 * max(1.0, abs(a), abs(b))


flat = json.load(open(flat_path))
doc = quantities(flat_path)
alone = []
for i, room in enumerate(flat["rooms"]):
    single = {k: v for k, v in flat.items() if k != "rooms"}
    single.update({k: v for k, v in room.items() if k != "offset"})
    path = os.path.join(out_dir, f"room{i + 1}.json")
    json.dump(single, open(path, "w"), indent=1)
    alone.append(quantities(path))

if len(doc["rooms"]) != len(alone):
    sys.exit(f"{len(doc['rooms'])} rooms in the flat's document, the file has {len(alone)}")
for i, (r, a) in enumerate(zip(doc["rooms"], alone)):
    for key in ("tiles", "trims", "consumables", "bom"):
        if r[key] != a[key]:
            fails.append(f"room {i + 1} ({r['project']}): {key} differs from the room alone")

total = doc["total"]


def summed(items_of, key_of, fields):
    """{key: {field: sum over the rooms alone}} of items_of(room document)."""
    out = {}
    for a in alone:
        for item in items_of(a):
            s = out.setdefault(key_of(item), {f: 0 for f in fields})
            for f in fields:
                s[f] += item[f]
    return out


def compare(what, got_items, key_of, fields, expected):
    got = {key_of(item): item for item in got_items}
    if set(got) != set(expected):
        fails.append(f"{what}: the total lists {sorted(got)}, the rooms {sorted(expected)}")
    for k, sums in expected.items():
        for f, v in sums.items():
            if k in got and not near(got[k][f], v):
                fails.append(f"{what} {k} {f}: rooms alone sum to {v}, the total says {got[k][f]}")


def product(item):
    p = item["product"]
    return (p["manufacturer"], p["article"], p["variant"])


TILE_FIELDS = ("whole", "cut", "reused", "pieces_needed", "area_m2", "length_m",
               "pieces_with_surplus", "boxes", "pieces_to_order", "order_m2")
compare("tiles", total["tiles"]["lines"], product, TILE_FIELDS,
        summed(lambda a: a["tiles"]["lines"], product, TILE_FIELDS))
for f in ("region_m2", "tiled_m2", "grout_m2"):
    v = sum(a["tiles"][f] for a in alone)
    if not near(total["tiles"][f], v):
        fails.append(f"tiles {f}: rooms alone sum to {v}, the total says {total['tiles'][f]}")
TRIM_FIELDS = ("edges", "metres", "pieces", "billed_m")
compare("trims", total["trims"], product, TRIM_FIELDS,
        summed(lambda a: a["trims"], product, TRIM_FIELDS))
for f, v in total["consumables"].items():
    room_sum = sum(a["consumables"][f] for a in alone)
    if not near(v, room_sum):
        fails.append(f"consumables {f}: rooms alone sum to {room_sum}, the total says {v}")
BOM_FIELDS = ("quantity", "net_cents", "vat_cents", "gross_cents")


def line_key(line):
    return product(line) + (line["kind"],)


compare("bill", total["bom"]["lines"], line_key, BOM_FIELDS,
        summed(lambda a: a["bom"]["lines"], line_key, BOM_FIELDS))
quotation = doc["quotation"]
for f in ("net_cents", "vat_cents", "gross_cents"):
    v = sum(a["bom"][f] for a in alone)
    if total["bom"][f] != v or quotation[f] != v or v <= 0:
        fails.append(f"{f}: rooms alone sum to {v}, the total says {total['bom'][f]}, the "
                     f"quotation {quotation[f]}")
if len(quotation["lines"]) != sum(len(a["bom"]["lines"]) for a in alone):
    fails.append("the quotation does not hold every room's lines")
for line, (room, a_line) in zip(quotation["lines"],
                                ((r["project"], l) for r in doc["rooms"] for l in r["bom"]["lines"])):
    if not line["name"].startswith(room + ": ") or line["net_cents"] != a_line["net_cents"]:
        fails.append(f"quotation line {line['position']} {line['name']!r}: not {room}'s line")
kinds = {l["kind"] for l in total["bom"]["lines"]}
if "consumable" not in kinds or "labour" not in kinds or total["consumables"]["adhesive_kg"] <= 0:
    fails.append(f"the total bills no consumables or labour (kinds {sorted(kinds)})")
if fails:
    sys.exit("\n".join(fails))
print(f"flat_quantities_json: PASS: {len(alone)} rooms, {len(total['bom']['lines'])} total lines, "
      f"{len(quotation['lines'])} quotation positions, gross {total['bom']['gross_cents'] / 100:.2f} "
      f"{total['bom']['currency']} = the sum of the rooms alone")
