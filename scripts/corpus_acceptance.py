#!/usr/bin/env python3
"""How many listings of a corpus `tierlift check` takes, by profile and by first refusal.

Usage: scripts/corpus_acceptance.py TIERLIFT DIR... [--ext .vsh,.psh,...] [--list]

Every file under the folders whose extension is listed is checked on its own (so that one
refusal says which file), with its own folder searched by #include. The profile is read
from the listing's version line, or from the version token of a token stream; a file
with neither counts as "unknown". Prints a table: profile, files, taken; then the rules
of the first error of each refused file, most frequent first.
"""
import collections
import json
import os
import re
import subprocess
import sys

VERSION = re.compile(rb"^\s*((?:vs|ps)[._][0-9][._][0-9x])\b", re.I | re.M)


def profile_name(kind: str, major: int, minor: int) -> str:
    return f"{kind}_{major}_{'x' if (major, minor) == (2, 1) else minor}"


def profile_of(data: bytes) -> str:
    if len(data) >= 4 and data[3] == 0xFF and data[2] in (0xFE, 0xFF):  # raw token stream
        return profile_name("vs" if data[2] == 0xFE else "ps", data[1], data[0])
    text_version = VERSION.search(data)
    if text_version:
        return text_version.group(1).decode().lower().replace(".", "_")
    dword = re.search(rb"0x(ffff|fffe)0([1-3])0([0-4])", data, re.I)
    if dword:
        kind = "vs" if dword.group(1).lower() == b"fffe" else "ps"
        return profile_name(kind, int(dword.group(2)), int(dword.group(3)))
    byte = re.search(rb"\{\s*(\d+),\s*(\d+),\s*(25[45]),\s*255\b", data)
    if byte:
        kind = "vs" if byte.group(3) == b"254" else "ps"
        return profile_name(kind, int(byte.group(2)), int(byte.group(1)))
    return "unknown"


def main() -> int:
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    exts = (".vsh", ".psh", ".nvv", ".nvp", ".inc", ".c", ".tok")
    for a in sys.argv[1:]:
        if a.startswith("--ext="):
            exts = tuple(a[len("--ext="):].split(","))
    show = "--list" in sys.argv
    tierlift, dirs = args[0], args[1:]
    files = []
    for d in dirs:
        for root, _, names in os.walk(d):
            files += [os.path.join(root, n) for n in sorted(names) if n.lower().endswith(exts)]
    table = collections.OrderedDict()
    reasons = collections.Counter()
    for f in sorted(files):
        with open(f, "rb") as fh:
            prof = profile_of(fh.read())
        r = subprocess.run([tierlift, "check", "--json", "-I", os.path.dirname(f), f],
                           capture_output=True, text=True, errors="replace")
        taken = r.returncode == 0
        row = table.setdefault(prof, [0, 0])
        row[0] += 1
        row[1] += taken
        if not taken:
            rule = "?"
            try:
                doc = json.loads(r.stdout)
                diags = [d for d in find_diags(doc) if d.get("severity") == "error"]
                if diags:
                    rule = f"{diags[0].get('rule')}: {diags[0].get('message')[:90]}"
            except (ValueError, AttributeError):
                rule = (r.stderr.strip().splitlines() or ["?"])[0][:100]
            reasons[rule] += 1
        if show:
            print(f"{'taken  ' if taken else 'REFUSED'} {prof:8} {f}")
    total = [0, 0]
    print(f"{'profile':10} {'files':>6} {'taken':>6}")
    for prof in sorted(table):
        n, t = table[prof]
        total[0] += n
        total[1] += t
        print(f"{prof:10} {n:6} {t:6}")
    print(f"{'all':10} {total[0]:6} {total[1]:6}")
    for rule, n in reasons.most_common():
        print(f"  {n:4}  {rule}")
    return 0


def find_diags(doc):
    """Every diagnostic object anywhere in the --json document."""
    out = []
    if isinstance(doc, dict):
        if "severity" in doc and "rule" in doc:
            out.append(doc)
        for v in doc.values():
            out += find_diags(v)
    elif isinstance(doc, list):
        for v in doc:
            out += find_diags(v)
    return out


if __name__ == "__main__":
    sys.exit(main())
