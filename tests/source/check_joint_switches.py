#!/usr/bin/env python3
"""Every switch over a joint type is exhaustive: it names every JointType and has no `default:`,
so that adding a type fails to compile (-Wswitch, an error in the test build) at each place that
must say what the new type does (docs/guides.md, "Adding a joint type"). Exits 1 naming each
switch that has a `default:`, 0 with the count of switches checked.

    check_joint_switches.py SOURCE_DIR
"""

import pathlib
import re
import sys

FOLDERS = ("include", "src", "apps", "python/src")


def block_after(text, start):
    """The text of the brace block that begins at the first '{' at or after `start`."""
    open_at = text.index("{", start)
    depth = 0
    for k in range(open_at, len(text)):
        if text[k] == "{":
            depth += 1
        elif text[k] == "}":
            depth -= 1
            if depth == 0:
                return text[open_at + 1:k]
    raise ValueError("unbalanced braces")


def top_level(body):
    """The body with every nested brace block (and nested switch) blanked out."""
    out, depth = [], 0
    for ch in body:
        if ch == "{":
            depth += 1
        if depth == 0:
            out.append(ch)
        if ch == "}":
            depth -= 1
    return "".join(out)


def main():
    root = pathlib.Path(sys.argv[1])
    checked, problems = 0, []
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".cpp", ".hpp"):
                continue
            text = path.read_text(encoding="utf-8")
            for match in re.finditer(r"\bswitch\s*\(", text):
                body = top_level(block_after(text, match.end()))
                if not re.search(r"case\s+(model::)?JointType::", body):
                    continue
                checked += 1
                if re.search(r"\bdefault\s*:", body):
                    line = text.count("\n", 0, match.start()) + 1
                    problems.append(f"{path.relative_to(root)}:{line}: a switch over JointType has a "
                                    "default: name every type instead")
    for problem in problems:
        print(problem)
    if checked < 10:
        print(f"only {checked} switches over JointType found: is the source tree at {root}?")
        return 1
    print(f"{checked} switches over JointType, {len(problems)} with a default")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
