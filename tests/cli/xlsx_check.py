#!/usr/bin/env python3
"""Runs `tessera quantities PROJECT --xlsx OUT.xlsx --json` and checks the workbook against the
JSON of the same run: reads the sheet with zipfile and the XML alone (no extra packages).

usage: xlsx_check.py OUT.xlsx -- TESSERA quantities PROJECT [ARGS...]
       (PROJECT may be a flat: then the sheet is checked against the JSON's "quotation")
       xlsx_check.py OUT.xlsx -- TESSERA print PROJECT -o OUT.pdf [ARGS...]
(print: the JSON comes from `TESSERA quantities PROJECT --json` with the same --company and
--date, so the print set's spreadsheet is checked against the quantities of the same project.)

Checks: the file is a zip with one worksheet; no temporary file is left beside it; each
position row holds the article, the quantity, the unit price, a ROUND(qty*price,2) formula for
the net whose cached value is the JSON line's net, and a ROUND(net*rate/100,2) VAT formula; the
net total is a SUM over the net column, each VAT rate a SUMIF, the gross their sum, each with
the JSON's value; the amounts carry a number format naming the currency; the header holds the
quote number and the customer."""
import json
import os
import re
import subprocess
import sys
import zipfile
import xml.etree.ElementTree as ET

NS = {"m": "http://schemas.openxmlformats.org/spreadsheetml/2006/main"}
failures = 0


def check(cond, what):
    global failures
    if not cond:
        failures += 1
        print("FAILED:", what, file=sys.stderr)


def col_row(ref):
    m = re.match(r"([A-Z]+)(\d+)$", ref)
    return m.group(1), int(m.group(2))


def main():
    sep = sys.argv.index("--")
    out, command = sys.argv[1], sys.argv[sep + 1:]
    if os.path.exists(out):
        os.remove(out)
    if command[1] == "print":
        run = subprocess.run(command + ["--xlsx", out], capture_output=True, text=True)
        same = []
        for opt in ("--company", "--date"):
            if opt in command:
                same += [opt, command[command.index(opt) + 1]]
        if run.returncode == 0:
            run = subprocess.run([command[0], "quantities", command[2], "--json"] + same,
                                 capture_output=True, text=True)
    else:
        run = subprocess.run(command + ["--xlsx", out, "--json"], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stderr, file=sys.stderr)
        sys.exit(1)
    doc = json.loads(run.stdout)
    # A flat's spreadsheet is its quotation: every room's positions in turn (the JSON's
    # "quotation"), each description led by its room's name.
    bom = doc["quotation"] if "rooms" in doc else doc["bom"]
    rooms = [r["project"] for r in doc.get("rooms", [])]
    folder = os.path.dirname(os.path.abspath(out))
    leftovers = [f for f in os.listdir(folder)
                 if f.startswith(os.path.basename(out) + ".part")]
    check(not leftovers, "no temporary file left: %s" % leftovers)

    z = zipfile.ZipFile(out)
    sheets = [n for n in z.namelist() if n.startswith("xl/worksheets/sheet")]
    check(len(sheets) == 1, "one worksheet, got %s" % sheets)
    strings = []
    if "xl/sharedStrings.xml" in z.namelist():
        root = ET.fromstring(z.read("xl/sharedStrings.xml"))
        for si in root.findall("m:si", NS):
            strings.append("".join(t.text or "" for t in si.iter("{%s}t" % NS["m"])))
    styles = ET.fromstring(z.read("xl/styles.xml"))
    numfmts = {nf.get("numFmtId"): nf.get("formatCode")
               for nf in styles.iter("{%s}numFmt" % NS["m"])}
    xfs = [xf.get("numFmtId") for xf in styles.find("m:cellXfs", NS).findall("m:xf", NS)]

    cells = {}
    for c in ET.fromstring(z.read(sheets[0])).iter("{%s}c" % NS["m"]):
        ref, kind = c.get("r"), c.get("t")
        f, v = c.find("m:f", NS), c.find("m:v", NS)
        value = v.text if v is not None else None
        if kind == "s" and value is not None:
            value = strings[int(value)]
        fmt = numfmts.get(xfs[int(c.get("s", "0"))], "")
        cells[ref] = (value, f.text if f is not None else None, fmt)

    def text(ref):
        return cells.get(ref, (None,))[0]

    check(any(v[0] == doc["quote"]["number"] for v in cells.values()), "the quote number")
    name = doc["quote"]["customer"]["name"]
    check(not name or any(v[0] == name for v in cells.values()), "the customer " + name)

    # The header row, then one row per position in the quote's currency.
    head = [r for r, v in cells.items() if v[0] == "Pos" and r.startswith("A")]
    check(len(head) == 1, "one header row")
    row = col_row(head[0])[1] + 1
    lines = [l for l in bom["lines"] if l["in_total"]]
    cur = bom["currency"]
    first = row
    for l in lines:
        r = str(row)
        check(text("A" + r) == str(l["position"]) or float(text("A" + r)) > 0, "position " + r)
        check(text("B" + r) == l["product"]["article"], "article in B" + r)
        check(not rooms or any(l["name"].startswith(n + ": ") and n in text("C" + r)
                               for n in rooms), "the room's name in C" + r)
        check(abs(float(text("D" + r)) - l["quantity"]) < 1e-9, "quantity in D" + r)
        check(abs(float(text("F" + r)) * 100 - l["unit_price_cents"]) < 1e-6, "price F" + r)
        net = cells["H" + r]
        check(net[1] == "ROUND(D%s*F%s,2)" % (r, r), "net formula H%s: %s" % (r, net[1]))
        check(abs(float(net[0]) * 100 - l["net_cents"]) < 1e-6, "net value H" + r)
        check(cur in net[2], "H%s formatted in %s: %r" % (r, cur, net[2]))
        vat = cells["I" + r]
        check(vat[1] == "ROUND(H%s*G%s/100,2)" % (r, r), "VAT formula I" + r)
        check(abs(float(vat[0]) * 100 - l["vat_cents"]) < 1e-6, "VAT value I" + r)
        # the formula's own arithmetic, recomputed
        check(abs(round(float(text("D" + r)) * float(text("F" + r)) + 1e-9, 2) -
                  float(net[0])) < 1e-9, "net = qty x price in row " + r)
        row += 1
    last = row - 1
    row += 1
    total = cells["H%d" % row]
    check(total[1] == "SUM(H%d:H%d)" % (first, last), "net total formula: %s" % total[1])
    check(abs(float(total[0]) * 100 - bom["net_cents"]) < 1e-6, "net total value")
    for k, rate in enumerate(bom["vat_by_rate"]):
        r = row + 1 + k
        v = cells["H%d" % r]
        check(v[1] == "SUMIF(G%d:G%d,G%d,I%d:I%d)" % (first, last, r, first, last),
              "VAT formula row %d: %s" % (r, v[1]))
        check(abs(float(v[0]) * 100 - rate["vat_cents"]) < 1e-6, "VAT %g value" % rate["percent"])
        check(text("F%d" % r) == "VAT %g %%" % rate["percent"], "VAT label row %d" % r)
    gross = cells["H%d" % (row + 1 + len(bom["vat_by_rate"]))]
    check(gross[1].startswith("H%d+SUM(" % row), "gross formula: %s" % gross[1])
    check(abs(float(gross[0]) * 100 - bom["gross_cents"]) < 1e-6, "gross value")
    check(cur in gross[2], "gross formatted in " + cur)
    check(any(l["kind"] == "labour" for l in lines), "labour lines in the quotation")
    check(any(l["kind"] == "consumable" for l in lines), "consumable lines in the quotation")
    print("xlsx_check: %d positions, net %.2f, gross %.2f %s, %d failure(s)"
          % (len(lines), bom["net_cents"] / 100, bom["gross_cents"] / 100, cur, failures))
    sys.exit(1 if failures else 0)


main()
