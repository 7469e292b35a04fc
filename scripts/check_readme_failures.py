#!/usr/bin/env python3
"""The README names every validation case that fails, and only those.

    python3 scripts/check_readme_failures.py SWEETSPOT README.md

Runs `SWEETSPOT validate --json` (the shipped library) and reads the case ids written in
backticks between the README's `<!-- validate-failures -->` and `<!-- /validate-failures -->`
markers (other backticked words there, a scenario or a model name, are not case ids). Exit 1,
naming the ids, when a failing case is missing from the list (a new failure nobody explained)
or the list names a case that passes (a fix the README has not caught up with); exit 0 when
they agree.
"""
import json
import re
import subprocess
import sys

BEGIN, END = "<!-- validate-failures -->", "<!-- /validate-failures -->"


def listed_ids(readme: str) -> set[str]:
    text = open(readme, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        sys.exit(f"{readme}: no '{BEGIN}' ... '{END}' block")
    block = text.split(BEGIN, 1)[1].split(END, 1)[0]
    return set(re.findall(r"`([a-z0-9][a-z0-9.-]*)`", block))


def case_ids(sweetspot: str) -> tuple[set[str], set[str]]:
    """Every case id of the library, and the failing ones."""
    run = subprocess.run([sweetspot, "validate", "--json"], capture_output=True, text=True)
    if run.returncode not in (0, 1):
        sys.exit(f"validate exited {run.returncode}: {run.stderr.strip()}")
    cases = json.loads(run.stdout)["cases"]
    return {c["id"] for c in cases}, {c["id"] for c in cases if not c["passed"]}


def main() -> int:
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    every, failing = case_ids(sys.argv[1])
    listed = listed_ids(sys.argv[2]) & every
    ok = True
    for i in sorted(failing - listed):
        print(f"FAIL: {i} fails but the README's list of failing cases does not name it")
        ok = False
    for i in sorted(listed - failing):
        print(f"FAIL: the README lists {i} as failing, but it passes")
        ok = False
    if ok:
        print(f"README lists the {len(failing)} failing cases")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
