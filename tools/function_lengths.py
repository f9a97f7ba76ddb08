#!/usr/bin/env python3
"""Lists the functions of src/ and controllers/ longer than a limit (60 lines, from the line of
their opening brace to the closing one), so that none grows past what reads at once.

  tools/function_lengths.py [--limit N] [ROOT]    exit status 1 when one is over the limit

A function is a brace block whose head ends with a parameter list (and qualifiers), that is not
inside another function (lambdas count as part of theirs). Strings, characters and comments are
skipped; it is a reader of this project's formatted code, not a C++ parser."""
import argparse
import os
import re
import sys

HEAD_END = re.compile(r"\)\s*(const\s*)?(noexcept\s*)?(override\s*)?(final\s*)?(->\s*[\w:<>,\s&*]+)?$")
CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|else|do)\b|\b(namespace|class|struct|enum|union)\b")
CODE = re.compile(r'"(\\.|[^"\\])*"|\'(\\.|[^\'\\])*\'|//.*|/\*.*?\*/')


def functions(text):
    """(first line, last line, head) of every outermost function body in `text`."""
    stack = []  # per open brace: (is a function, line it opened, its head)
    head = ""
    for number, raw in enumerate(text.split("\n"), 1):
        line = CODE.sub(lambda m: '""' if m.group(0)[:1] in "\"'" else "", raw)
        for ch in line:
            if ch == "{":
                inside = any(entry[0] for entry in stack)
                statement = " ".join(head.split())
                is_function = not inside and not CONTROL.search(statement) and (
                    HEAD_END.search(statement) or re.search(r"\)\s*:\s*\w.*\)$", statement))
                stack.append((bool(is_function), number, statement))
                head = ""
            elif ch == "}":
                if stack:
                    is_function, first, statement = stack.pop()
                    if is_function:
                        yield first, number, statement
                head = ""
            elif ch == ";":
                head = ""
            else:
                head += ch
        head += " "


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--limit", type=int, default=60)
    args = parser.parse_args()
    over = []
    for folder in ("src", "controllers"):
        for dirpath, _, names in os.walk(os.path.join(args.root, folder)):
            for name in sorted(names):
                if not name.endswith((".cc", ".h")):
                    continue
                path = os.path.join(dirpath, name)
                with open(path, encoding="utf-8", errors="replace") as f:
                    for first, last, head in functions(f.read()):
                        if last - first + 1 > args.limit:
                            over.append(f"{os.path.relpath(path, args.root)}:{first}: {last - first + 1} lines: {head[:70]}")
    for line in over:
        print(line)
    print(f"{len(over)} function(s) over {args.limit} lines" if over else f"ok: no function over {args.limit} lines")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
