#!/usr/bin/env python3
"""Rewrites the reference tables of docs/scenario.md from the declarations in the code
(`sanet list --markdown`): every block between `<!-- fields: NAME -->` and `<!-- /fields -->`.
The test `docs_scenario_fields` fails when the two disagree; run this after changing a field.

    tools/update_scenario_reference.py [build/sanet] [docs/scenario.md] [--check]

With --check it changes nothing and exits 1, saying which tables differ (the test runs that)."""
import re
import subprocess
import sys

BLOCK = re.compile(r"<!-- fields: (\S+) -->\n.*?<!-- /fields -->\n", re.S)


def blocks(text):
    return {m.group(1): m.group(0) for m in BLOCK.finditer(text)}


def main():
    check = "--check" in sys.argv
    args = [a for a in sys.argv[1:] if a != "--check"]
    sanet = args[0] if args else "build/sanet"
    doc = args[1] if len(args) > 1 else "docs/scenario.md"
    generated = blocks(subprocess.run([sanet, "list", "--markdown"], check=True, capture_output=True,
                                      text=True).stdout)
    text = open(doc).read()
    missing = set(generated) - set(blocks(text))
    if missing:
        sys.exit("%s has no place for: %s (add `<!-- fields: NAME -->` ... `<!-- /fields -->`)" % (doc, ", ".join(sorted(missing))))
    if check:
        stale = [name for name, block in blocks(text).items() if generated.get(name) != block]
        unknown = set(blocks(text)) - set(generated)
        if stale or unknown:
            sys.exit("%s disagrees with the declarations in tables: %s%s\nrun tools/update_scenario_reference.py"
                     % (doc, ", ".join(sorted(stale)), "; unknown: " + ", ".join(sorted(unknown)) if unknown else ""))
        print("ok: %d tables of %s match the declarations" % (len(generated), doc))
        return
    text = BLOCK.sub(lambda m: generated.get(m.group(1), m.group(0)), text)
    open(doc, "w").write(text)
    print("updated %d tables in %s" % (len(generated), doc))


if __name__ == "__main__":
    main()
