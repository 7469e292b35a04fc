#!/usr/bin/env python3
"""Markdown list of the failing validation cases, grouped by sport and first topic tag, from
`sweetspot validate --json` on stdin: what docs/validation.md's failing list is made of.

    build/release/sweetspot validate --json | python3 scripts/validation_failures.py
"""
import json
import sys


def main() -> int:
    doc = json.load(sys.stdin)
    groups: dict[str, list] = {}
    for c in doc["cases"]:
        if c["passed"]:
            continue
        topic = c["tags"][1] if len(c["tags"]) > 1 else "other"
        groups.setdefault(f"{c['tags'][0]}, {topic}", []).append(c)
    print(f"{doc['passed']} passed, {doc['failed']} failed; not fitted: "
          f"{doc['not_fitted']['passed']} passed, {doc['not_fitted']['failed']} failed\n")
    for name in sorted(groups):
        cases = groups[name]
        print(f"#### {name} ({len(cases)})\n")
        for c in cases:
            fitted = " (fitted)" if c["fitted"] else ""
            print(f"- `{c['id']}`{fitted}: {c['error_in_tolerances']:+.2f} tolerances")
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
