#!/usr/bin/env python3
"""Runs a tessera command that writes --stats FILE.json and checks the file's values.

usage: stats_check.py FILE.json KEY=VALUE... -- COMMAND [ARGS...]
KEY is a dotted path into the JSON object (settings.room_probe, frame.room_probe); VALUE is
compared as text ("on", "0"), or ">0" for any positive number. The command must exit 0 and
write the file anew."""
import json
import os
import subprocess
import sys


def main():
    args = sys.argv[1:]
    sep = args.index("--")
    path, checks, command = args[0], args[1:sep], args[sep + 1:]
    if os.path.exists(path):
        os.remove(path)
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
        ok = (isinstance(value, (int, float)) and value > 0) if want == ">0" else text == want
        print(f"{'ok' if ok else 'FAIL'}: {key} = {text} (want {want})")
        status |= not ok
    return status


if __name__ == "__main__":
    sys.exit(main())
