#!/usr/bin/env python3
"""Holds every group to the "May include:" line of its README.

A group is a folder with a README.md that has a "May include:" paragraph: engine/src/<group>/,
engine/cli/, game/ (its own files: main.cpp, web/), game/<group>/ and any folder below those whose
README has the paragraph (the wings of game/app/: game/app/hud/, game/app/screens/widgets/, …); a
file belongs to the nearest group folder above it. Each `#include "..."` in a group's files (and in
the public headers the group owns) must name the group itself (a file whose nearest group it is), a
group the paragraph lists, or a header it lists. A wing is named as its includes name it, from the
tree's root: `app/hud/` lets a file include "app/hud/overlays.h".

What a README's paragraphs say, in backticks:
  May include:    `math/` a group of the same tree: its own headers and the public headers it owns;
                  `polar/*.h` every public header directly in engine/include/polar/;
                  `polar/render/…` (or `polar/render/`) every public header under that folder;
                  `polar/object_flags.h`, `polarcade_version.h`, `stb/` one header, or a folder.
  Public headers: the public headers (files or folders under engine/include/) the group owns; every
                  public header has exactly one owner.
Anything not in backticks (SDL2, Eigen, "the standard library") is prose: <...> includes are not
checked.

Usage: include_rules.py REPO_ROOT. Prints one line per include outside its rule, naming the file,
the line, the include and the rule; exits 1 when there is any.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
TICKED = re.compile(r"`([^`]+)`")
SOURCES = (".h", ".hpp", ".cpp", ".c", ".inl")


def paragraph(text, opening):
    """The paragraph that starts with `opening`, as one line, or None."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith(opening):
            taken = [line[len(opening):]]
            for more in lines[i + 1:]:
                if not more.strip():
                    break
                taken.append(more)
            return " ".join(s.strip() for s in taken)
    return None


class Group:
    def __init__(self, tree, folder, readme):
        self.tree = tree  # the folder its siblings live in (engine/src, game)
        self.folder = folder
        self.name = folder.name
        self.prefix = folder.relative_to(tree).as_posix() + "/"  # how includes name it: "app/hud/"
        self.readme = readme
        text = readme.read_text(encoding="utf-8")
        self.rule = paragraph(text, "May include:")
        owned = paragraph(text, "Public headers:")
        self.owns = [t.replace("…", "").strip() for t in TICKED.findall(owned)] if owned else []
        self.groups = set()  # group names of the same tree
        self.patterns = []  # other tokens: exact headers, folder prefixes, polar/*.h
        for token in TICKED.findall(self.rule or ""):
            token = token.replace("…", "").strip()
            if token.endswith("/") and "/" not in token[:-1] and (tree / token[:-1]).is_dir():
                self.groups.add(token[:-1])
            else:
                self.patterns.append(token)

    def label(self):
        return self.prefix


def matches(pattern, include):
    if pattern.endswith("*.h"):
        prefix = pattern[:-3]
        rest = include[len(prefix):]
        return include.startswith(prefix) and "/" not in rest and rest.endswith(".h")
    if pattern.endswith("/"):
        return include.startswith(pattern)
    return include == pattern


def main(root):
    root = pathlib.Path(root).resolve()
    public = root / "engine" / "include"
    groups = []
    problems = []
    for readme in sorted((root / "engine" / "src").glob("*/README.md")):
        g = Group(root / "engine" / "src", readme.parent, readme)
        if g.rule is None:
            problems.append(f"{readme.relative_to(root)}: no \"May include:\" line; expected one")
            continue
        groups.append(g)
    trees = {root / "engine" / "cli" / "README.md": root / "engine", root / "game" / "README.md": root}
    # game/<group>/ and the wings below them (game/app/hud/): each named from game/, as included.
    for readme in sorted((root / "game").rglob("*/README.md")):
        trees[readme] = root / "game"
    for readme, tree in trees.items():
        if readme.exists():
            g = Group(tree, readme.parent, readme)
            if g.rule is not None:
                groups.append(g)

    # Who owns each public header.
    owner = {}
    for header in sorted(p for p in public.rglob("*") if p.is_file() and p.suffix in SOURCES):
        name = header.relative_to(public).as_posix()
        claims = [g for g in groups if any(matches(t, name) for t in g.owns)]
        if len(claims) != 1:
            said = ", ".join(g.label() for g in claims) or "no group"
            problems.append(f"engine/include/{name}: owned by {said}; expected exactly one group's "
                            "\"Public headers:\" line to name it")
            continue
        owner[name] = claims[0]

    # A file belongs to the nearest group folder above it (game/ holds main.cpp and web/).
    folders = {g.folder.resolve(): g for g in groups}

    def nearest(path):
        for folder in path.resolve().parents:
            if folder in folders:
                return folders[folder]
        return None

    def allowed(g, path, include):
        """Why `include` in `path` is fine, or None."""
        beside = path.parent / include
        if beside.exists() and beside.resolve().is_relative_to(g.folder.resolve()) and nearest(beside) is g:
            return "own"
        named = g.tree / include
        if include.startswith(g.prefix) and (nearest(named) is g if named.exists() else True):
            return "own"
        if any(matches(t, include) for t in g.patterns):
            return "listed"
        if include.startswith("polar/") and g.tree.name == "src":
            o = owner.get(include)
            if o is not None and (o is g or o.name in g.groups):
                return "listed group"
            return None
        first = include.split("/")[0]
        if "/" in include and (g.tree / first).is_dir() and first in g.groups:
            return "listed group"
        return None

    def check(g, path):
        rel = path.relative_to(root).as_posix()
        for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m or allowed(g, path, m.group(1)):
                continue
            include = m.group(1)
            o = owner.get(include)
            whose = f" ({o.label()}'s)" if o is not None else ""
            problems.append(f"{rel}:{number}: #include \"{include}\"{whose} is outside {g.label()}'s rule "
                            f"({g.readme.relative_to(root).as_posix()}: May include: {g.rule})")

    checked = 0
    for g in groups:
        for path in sorted(g.folder.rglob("*")):
            if path.is_file() and path.suffix in SOURCES and nearest(path) is g:
                check(g, path)
                checked += 1
    for name, g in sorted(owner.items()):
        check(g, public / name)
        checked += 1

    for p in problems:
        print(p)
    print(f"include rules: {len(groups)} groups, {checked} files, {len(problems)} outside their rules")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: include_rules.py REPO_ROOT", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
