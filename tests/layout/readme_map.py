#!/usr/bin/env python3
"""Holds the top README's "Map of the code" to the tree.

The map is the table under "## Map of the code": its first column names folders in backticks
(`engine/src/world/`, or a script such as `tools/play`; a name with no slash after one with slashes is its sibling: `tools/play`,
`test` means tools/test). Fails when a folder the map names does not exist, or when a folder of
engine/src/ or of game/app/ (its wings, at any depth) is missing from the map, as include_rules.py
reads the group READMEs.

Usage: readme_map.py REPO_ROOT. Prints one line per problem; exits 1 when there is any.
"""
import pathlib
import re
import sys

TICKED = re.compile(r"`([^`]+)`")


def map_rows(readme):
    """The first cells of the map's table, in order."""
    lines = readme.read_text(encoding="utf-8").splitlines()
    try:
        start = lines.index("## Map of the code")
    except ValueError:
        return None
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("## "):
            break
        if line.startswith("|") and not line.startswith("|---"):
            rows.append(line.strip("|").split("|")[0])
    return rows[1:]  # the first row is the heading


def folders_named(cell):
    """The folders a first cell names, as paths relative to the root."""
    named, parent = [], None
    for token in TICKED.findall(cell):
        token = token.strip().rstrip("/")
        if "/" in token:
            named.append(token)
            parent = token.rsplit("/", 1)[0]
        elif parent is not None:
            named.append(f"{parent}/{token}")
    return named


def main(root):
    root = pathlib.Path(root).resolve()
    rows = map_rows(root / "README.md")
    if rows is None:
        print("README.md: no \"## Map of the code\" section")
        return 1
    problems = []
    mapped = set()
    for cell in rows:
        for folder in folders_named(cell):
            mapped.add(folder)
            if not (root / folder).exists():
                problems.append(f"README.md: the map names `{folder}/`, which is not in the tree")
    wanted = [p for p in sorted((root / "engine" / "src").iterdir()) if p.is_dir()]
    wanted += [p for p in sorted((root / "game" / "app").rglob("*")) if p.is_dir()]
    for folder in wanted:
        rel = folder.relative_to(root).as_posix()
        if rel not in mapped:
            problems.append(f"README.md: the map lacks `{rel}/`; add a row saying what it holds")
    for p in problems:
        print(p)
    print(f"readme map: {len(mapped)} folders named, {len(wanted)} required, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: readme_map.py REPO_ROOT", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
