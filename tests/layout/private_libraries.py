#!/usr/bin/env python3
"""Holds third-party libraries that are one place's own business out of everything else.

nlohmann-json parses and writes JSON behind polar::JsonDoc, JsonNode and JsonWriter; only the
engine's sources (engine/src/) may include or name it. The public headers (engine/include/), the
game (game/) and the tools (tools/) use the engine's JSON API, so the parser could change without
any of them noticing. Tests may use it to read tool output independently.

CLI11 parses every executable's command line behind polar::cli::Command (engine/cli/cli.h); only
engine/cli/cli.cpp includes it (its header alone costs seconds a file), and only engine/cli/ names
it. The game and the tools declare their flags through cli.h.

Usage: private_libraries.py REPO_ROOT. Prints one line per use outside its place, naming the file,
the line and the rule; exits 1 when there is any.
"""
import pathlib
import re
import sys

SOURCES = (".h", ".hpp", ".cpp", ".c", ".inl")
# library: (what a use looks like, the folders that may use it)
PRIVATE = {
    "nlohmann-json": (re.compile(r"#\s*include\s*<nlohmann/|\bnlohmann::"), ("engine/src/",),
                      "use polar/json_doc.h, polar/json_writer.h"),
    "CLI11's header": (re.compile(r"#\s*include\s*<CLI/"), ("engine/cli/cli.cpp",), "use cli.h"),
    "CLI11": (re.compile(r"\bCLI::"), ("engine/cli/",), "use polar::cli::Command from cli.h"),
}
CHECKED = ("engine/include", "engine/src", "engine/cli", "game", "tools")


def main(root):
    root = pathlib.Path(root).resolve()
    problems = []
    for top in CHECKED:
        for path in sorted((root / top).rglob("*")):
            if not path.is_file() or path.suffix not in SOURCES:
                continue
            name = path.relative_to(root).as_posix()
            text = path.read_text(encoding="utf-8", errors="replace")
            for library, (use, places, instead) in PRIVATE.items():
                if any(name.startswith(p) for p in places):
                    continue
                for number, line in enumerate(text.splitlines(), 1):
                    if use.search(line):
                        problems.append(f"{name}:{number}: uses {library}; expected it only in "
                                        f"{', '.join(places)} ({instead})")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        sys.exit(0 if len(sys.argv) == 2 else 2)
    sys.exit(main(sys.argv[1]))
