#!/usr/bin/env python3
"""Runs tessera commands that write --stats FILE.json and checks each file's values.

usage: stats_check.py FILE.json KEY=VALUE... -- COMMAND [ARGS...]
                      [--then FILE.json KEY=VALUE... -- COMMAND [ARGS...]]...
KEY is a dotted path into the JSON object (settings.room_probe, frame.room_probe); VALUE is
compared as text ("on", "0"), or ">0" for any positive number, or "<X" for a number below X. Each command must exit 0 and
write its file anew. With --then, several runs (a switch on, then off) are checked in turn, so
one test can show that a stage ran in one render and not in the other."""
import json
import os
import subprocess
import sys


def check_run(args):
    sep = args.index("--")
    path, checks, command = args[0], args[1:sep], args[sep + 1:]
    if os.path.exists(path):
        os.remove(path)
    print(f"--- {' '.join(command)}", flush=True)
    rc = subprocess.call(command)
    if rc != 0:
        print(f"FAIL: exit code {rc} from {' '.join(command)}")
        return 1
    with open(path) as f:
        stats = json.load(f)
    status = 0
    for check in checks:
        key, want = check.split("=", 1)
        value = stats
        for part in key.split("."):
            value = value.get(part) if isinstance(value, dict) else None
        text = str(int(value)) if isinstance(value, (int, float)) else str(value)
        number = isinstance(value, (int, float))
        if want == ">0":
            ok = number and value > 0
        elif want.startswith("<"):
            ok = number and value < float(want[1:])
            text = str(value) if number else text
        else:
            ok = text == want
        print(f"{'ok' if ok else 'FAIL'}: {key} = {text} (want {want})")
        status |= not ok
    return status


def main():
    runs, current = [], []
    for arg in sys.argv[1:]:
        if arg == "--then":
            runs.append(current)
            current = []
        else:
            current.append(arg)
    runs.append(current)
    status = 0
    for run in runs:
        if "--" not in run or run.index("--") < 1:
            print(__doc__)
            return 2
        status |= check_run(run)
    return status


if __name__ == "__main__":
    sys.exit(main())
