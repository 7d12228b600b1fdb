#!/usr/bin/env python3
"""Damages every line of every golden replay, one character at a time, and checks that
polarcade-replay catches each damage, blames it on its own line and says which kind it is.

Each damaged copy changes one character of one line into a plausible neighbour: a digit into the
next digit, a letter into the next letter, an action into the next action, a trace character into
the next one of the trace alphabet, anything else into '~'. Every line of every golden is damaged,
every kind of line, and the first and the last line (the end line) of each golden at every
character. The header lines are cheap to check (most are refused before the game starts): a short
one is damaged at every character, a longer one at its first and last, the first of each word and
value, and one more. A line of the recorded game (in, trace, check, objects) costs the game up to
there: it is damaged at one character, chosen by a digest of its place so that over a golden's
many lines of one kind every part of the line is hit, and the first and the last line of each kind
also at their first and last character (a check line at one of its values too). A comment's text
is free, so only its '#' is damaged. --every-character damages every character of every line
(about 66 000 copies, a one-off look). All copies go into one folder, which polarcade-replay
verifies in one run, as CI would, with a JUnit report; the report says, for each copy, the verdict
and the first line of its report.

A damage is caught when the verdict is not PASS, blamed on its own line when that first line
starts with FILE:LINE: of the damaged line, and names its kind when it names the kind of line that
is damaged (or the damaged word of a line it cannot read). A damaged game version is not a failure
(an older or newer version may play a replay), but a note that names its line: it counts as caught
there. A damage that changes nothing in the recorded game (a turn while the ship explodes, a tuning
value the game never reached) passes, as it must: the replay still reproduces its game bit for bit.
Those are listed, and the test fails only when such a damage is in a line whose every value the game
or the parser checks. A damage is told from a changed game: only a trace, check or objects line may
read as DAMAGED, and only an input, seed, tick rate or tuning value as a DESYNC.

Each golden is also cut short, as an interrupted recording leaves it (after every 40th line, before
and after its begin line, before its end line, in the middle of its last trace line and of its end
line): a cut in the header cannot start, a later one fails as INCOMPLETE where its end line is
missing. A whole copy of each golden is the control: it must pass.

Usage: damage_every_line.py POLARCADE_REPLAY REPLAY_DIR ASSET_DIR SCRATCH_DIR [--every-character]
       [--table] [--jobs N] [--only NAME.replay]
--table prints the tables of tests/README.md; --only damages one golden (the sanitizer build, where
a tick costs a hundred times more). Exit 0 when every damage is as required, 1 otherwise (each
problem is printed). The copies are written in memory (/dev/shm) where there is such a folder and
removed after a pass; after a failure they are kept in SCRATCH_DIR.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zlib

SHORT = 16  # a header line up to this long is damaged at every character
# The lines that record the game tick by tick: playing a damaged copy of one costs the game up to
# that line, so most get one damage (ctest runs this on every build; --every-character is the
# one-off full run).
GAME_LINES = {"in", "trace", "check", "objects"}
CUT_EVERY = 40  # a golden is cut after every this many lines
TRACE_ALPHABET = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"
ACTIONS = "LRTF"

# What a report's first line says for each kind of line (any of these words).
KIND_WORDS = {
    "first": ["replay", "format"],
    "comment": ["header line"],
    "game": ["game version", "recorded by polarcade"],
    "scene": ["scene"],
    "scene-file": ["scene"],
    "seed": ["seed"],
    "tick-rate": ["tick rate", "tick-rate"],
    "tuning": ["tuning"],
    "rules": ["rules"],  # rules 2 and on (none of the goldens yet)
    "speed": ["speed"],
    "mod": ["mod"],
    "asset": ["asset", "file hash", "recorded with", "recording read"],
    "screenshot": ["screenshot"],
    "begin": ["begin"],
    "in": ["input", "action", "run"],
    "trace": ["trace"],
    "check": ["checkpoint"],
    "objects": ["object"],
    "end": ["end"],
}
# Lines whose values play into the game only as far as the game uses them: a damage there that
# changes nothing passes, as it must.
MAY_CHANGE_NOTHING = {"in", "tuning"}
# Header values no other line records: a changed seed, tick rate or tuning value makes another game,
# which the trace finds where it first differs (a desync, pointed at that tick's input; from tick 1
# on, the report names these lines). Format 1 holds no digest of the header to tell them from a
# changed game, so their damages must be caught, but cannot be blamed on their own line.
UNPROTECTED_VALUES = {"seed", "tick-rate", "tuning"}
# A damage is told from a changed game: only these lines, which record the game a second time, may
# be reported as DAMAGED, and only an input or one of UNPROTECTED_VALUES (another game) as a DESYNC.
RECORD_LINES = {"trace", "check", "objects"}
DESYNC_LINES = {"in"} | UNPROTECTED_VALUES


def line_kind(number, text):
    if number == 1:
        return "first"
    word = text.split(" ", 1)[0]
    if word.startswith("#"):
        return "comment"
    return word if word in KIND_WORDS else "unknown"


def replacement(kind, text, column):
    """The plausible neighbour of the character at `column` (0-based)."""
    c = text[column]
    if kind == "trace" and column >= len("trace "):
        return TRACE_ALPHABET[(TRACE_ALPHABET.index(c) + 1) % len(TRACE_ALPHABET)]
    if kind == "in" and column >= len("in "):
        if c in ACTIONS:
            return ACTIONS[(ACTIONS.index(c) + 1) % len(ACTIONS)]
        if c == ".":
            return "F"
    if c.isdigit():
        return str((int(c) + 1) % 10)
    if "a" <= c <= "z":
        return chr((ord(c) - ord("a") + 1) % 26 + ord("a"))
    if "A" <= c <= "Z":
        return chr((ord(c) - ord("A") + 1) % 26 + ord("A"))
    return "~"


def columns_to_damage(kind, text, every, turn, end_of_kind):
    """The 0-based columns damaged in a line: all with `every`. Else, of a comment only its '#' (its
    text is free). Of a header line (cheap: refused before the game starts, or another game from its
    first ticks on) every character when it is short, else its first and last, the first of each
    word and value and one that `turn` picks. Of a line of the recorded game (in, trace, check,
    objects: playing a damaged copy costs the game up to there) one character that `turn` picks, and
    when it is the first or the last line of its kind in the golden (`end_of_kind`) also its first
    and last, and of a check line the first of one of its values. `turn` is a digest of the golden's
    name and the line's number: over the many lines of one kind, the damages fall on every part."""
    if kind == "comment":
        return [0]
    if every or (kind not in GAME_LINES and len(text) <= SHORT):
        return list(range(len(text)))
    chosen = {turn % len(text)}
    if kind not in GAME_LINES:
        chosen.update([0, len(text) - 1])
        chosen.update(m.start() for m in re.finditer(r"(?<=[ =:])\S", text))
    elif end_of_kind:
        chosen.update([0, len(text) - 1])
        if kind == "check":
            starts = [text.index(" ", len("check ")) + 1] + [m.start() for m in re.finditer(r"(?<==)\S", text)]
            chosen.add(starts[(turn // 7) % len(starts)])
    return sorted(chosen)


def value_at(kind, text, column):
    """The value that holds the character at `column`: a trace token (two characters), else the
    word or the value after '=' or ':' around it, as a report writes it."""
    if kind == "trace" and column >= len("trace "):
        start = column - (column - len("trace ")) % 2
        return text[start : start + 2]
    start, end = column, column + 1
    while start > 0 and text[start - 1] not in " =:":
        start -= 1
    while end < len(text) and text[end] not in " =:":
        end += 1
    value = text[start:end]
    # A number is shown as a number: "score=010" holds 10.
    return str(int(value)) if value.isdigit() else value


def make_copies(replay_dir, out_dir, every):
    """Writes the damaged copies; returns one record per copy."""
    damages = []
    for name in sorted(os.listdir(replay_dir)):
        if not name.endswith(".replay"):
            continue
        lines = open(os.path.join(replay_dir, name), encoding="utf-8").read().split("\n")
        assert lines[-1] == "", name + " ends with a newline"
        lines = lines[:-1]
        stem = name[: -len(".replay")]
        kinds = [line_kind(index + 1, text) for index, text in enumerate(lines)]
        for index, text in enumerate(lines):
            number = index + 1
            kind = kinds[index]
            end_of_kind = kind not in kinds[:index] or kind not in kinds[index + 1 :]
            turn = zlib.crc32(("%s:%d" % (name, number)).encode())
            # The first and the last line (the end line) of a golden: every character.
            whole = every or number in (1, len(lines))
            for column in columns_to_damage(kind, text, whole, turn, end_of_kind):
                damaged = text[:column] + replacement(kind, text, column) + text[column + 1 :]
                assert damaged != text
                copy = "%s-L%03d-C%03d.replay" % (stem, number, column + 1)
                with open(os.path.join(out_dir, copy), "w", encoding="utf-8", newline="\n") as f:
                    f.write("\n".join(lines[:index] + [damaged] + lines[index + 1 :]) + "\n")
                damages.append(
                    {"was_value": value_at(kind, text, column), "now_value": value_at(kind, damaged, column),"golden": name, "line": number, "kind": kind, "column": column + 1, "copy": copy,
                     "last": number == len(lines), "was": text[column], "now": damaged[column]}
                )
    return damages


def make_cuts(replay_dir, out_dir):
    """Writes each golden whole (a control: it must pass) and cut short as an interrupted
    recording leaves it: after every CUT_EVERY-th line, before and after its begin line, before its
    end line, and in the middle of its last trace line and of its end line. Returns one record per
    copy."""
    cuts = []
    for name in sorted(os.listdir(replay_dir)):
        if not name.endswith(".replay"):
            continue
        text = open(os.path.join(replay_dir, name), encoding="utf-8").read()
        lines = text.split("\n")[:-1]
        stem = name[: -len(".replay")]
        begin = lines.index("begin") + 1
        shutil.copy(os.path.join(replay_dir, name), os.path.join(out_dir, stem + "-whole.replay"))
        cuts.append({"golden": name, "copy": stem + "-whole.replay", "expect": "pass", "line": 0})
        last_trace = max(i for i, line in enumerate(lines) if line.startswith("trace ")) + 1
        points = [(n, 0) for n in range(CUT_EVERY, len(lines), CUT_EVERY)] + [(len(lines) - 1, 0)]
        points += [(begin - 1, 0), (begin, 0)]  # without its begin line; with it and no tick
        points += [(last_trace - 1, len(lines[last_trace - 1]) // 2), (len(lines) - 1, len(lines[-1]) // 2)]
        for whole, part in sorted(set(points)):
            # `whole` complete lines, then `part` characters of the next one.
            body = "".join(line + "\n" for line in lines[:whole]) + lines[whole][:part]
            copy = "%s-cut-L%03d-C%03d.replay" % (stem, whole, part)
            with open(os.path.join(out_dir, copy), "w", encoding="utf-8", newline="\n") as f:
                f.write(body)
            # Cut inside the header, the replay cannot start; after it, it is incomplete, blamed on
            # the line where the end line is missing (the cut one, when a line was cut).
            expect = "unplayable" if whole < begin else "incomplete"
            cuts.append({"golden": name, "copy": copy, "expect": expect, "line": whole + 1})
    return cuts


def verdicts(exe, folder, jobs, scratch):
    """Runs polarcade-replay over the folder; returns {file name: (verdict, first line, notes,
    report)}."""
    report = os.path.join(scratch, "report.xml")
    # The assets by the link's path, so that the files a scene next to the copies names by
    # ../../assets/ lie inside the asset folder, as they do for the goldens.
    env = dict(os.environ, POLARCADE_ASSETS=os.path.join(scratch, "assets"))
    run = subprocess.run(
        [exe, "-q", "-j", str(jobs), "--failures", os.path.join(scratch, "failures"), "--junit", report, folder],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
    )
    if run.returncode not in (0, 1, 2) or not os.path.exists(report):
        sys.exit("polarcade-replay failed to run (exit %d): %s" % (run.returncode, run.stderr))
    found = {}
    for case in ET.parse(report).getroot().iter("testcase"):
        failure = case.find("failure")
        if failure is None:
            failure = case.find("error")
        out = case.find("system-out")
        notes = out.text if out is not None and out.text else ""
        if failure is None:
            found[case.get("name")] = ("pass", "", notes, "")
        else:
            found[case.get("name")] = (failure.get("type"), failure.get("message"), notes, failure.text or "")
    return found


def judge(damage, verdict, message, notes, report, folder):
    """Fills in caught, own line, kind named and values shown for one damage."""
    prefix = os.path.join(folder, damage["copy"]) + ":"
    own = prefix + str(damage["line"]) + ":"
    if verdict == "pass":
        # A damaged game version is a note on its own line, not a failure.
        noted = "(line %d)" % damage["line"]
        line = next((n for n in notes.split("\n") if noted in n), "")
        damage.update(caught=bool(line), own=bool(line), named=bool(line) and kind_named(damage, line),
                      verdict="note" if line else "pass", message=line)
        return
    damage.update(caught=True, own=message.startswith(own), verdict=verdict, message=message)
    damage["named"] = kind_named(damage, message)
    # A damaged record shows the value it holds and the game's, each in full.
    damage["shown"] = verdict != "damaged" or (damage["now_value"] in report and damage["was_value"] in report)


def kind_named(damage, message):
    text = message.lower()
    if any(word in text for word in KIND_WORDS.get(damage["kind"], [])):
        return True
    # A damaged first word: the line is not recognised, and the message quotes the word.
    return re.search(r"unknown (header )?line", text) is not None


# How polarcade-replay's JUnit failure types read in the table.
VERDICT_WORDS = {"unplayable": "ERROR", "damaged": "DAMAGED", "desync": "DESYNC", "screenshot": "SCREENSHOT",
                 "incomplete": "INCOMPLETE", "note": "note", "pass": "PASS"}


def table(damages):
    rows = ["| golden | lines | damages tried | caught | blamed on own line | kind named | pass (changes nothing) |",
            "|---|---:|---:|---:|---:|---:|---:|"]
    goldens = sorted({d["golden"] for d in damages})
    for golden in goldens + ["all"]:
        mine = [d for d in damages if golden in ("all", d["golden"])]
        lines = len({(d["golden"], d["line"]) for d in mine})
        rows.append("| %s | %d | %d | %d | %d | %d | %d |" % (
            golden, lines, len(mine), sum(d["caught"] for d in mine), sum(d["own"] for d in mine),
            sum(d["named"] for d in mine), sum(not d["caught"] for d in mine)))
    rows += ["", "| kind of line | lines | damages tried | caught | blamed on own line | kind named | "
             "pass (changes nothing) | verdicts |",
             "|---|---:|---:|---:|---:|---:|---:|---|"]
    for kind in list(KIND_WORDS) + ["unknown"]:
        mine = [d for d in damages if d["kind"] == kind]
        if not mine:
            continue
        lines = len({(d["golden"], d["line"]) for d in mine})
        counts = {}
        for d in mine:
            counts[d["verdict"]] = counts.get(d["verdict"], 0) + 1
        verdict_words = ", ".join("%s %d" % (VERDICT_WORDS.get(v, v), n) for v, n in sorted(counts.items()))
        rows.append("| %s | %d | %d | %d | %d | %d | %d | %s |" % (
            kind, lines, len(mine), sum(d["caught"] for d in mine), sum(d["own"] for d in mine),
            sum(d["named"] for d in mine), sum(not d["caught"] for d in mine), verdict_words))
    return "\n".join(rows)


def cut_table(cuts):
    rows = ["| golden | whole copy | cut copies | INCOMPLETE at the missing end line | refused (cut in the header) |",
            "|---|---|---:|---:|---:|"]
    for golden in sorted({c["golden"] for c in cuts}):
        mine = [c for c in cuts if c["golden"] == golden]
        whole = next(c for c in mine if c["expect"] == "pass")
        rows.append("| %s | %s | %d | %d | %d |" % (
            golden, "passes" if whole["right"] else "FAILS", len(mine) - 1,
            sum(c["right"] and c["expect"] == "incomplete" for c in mine),
            sum(c["right"] and c["expect"] == "unplayable" for c in mine)))
    return "\n".join(rows)


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    every = "--every-character" in argv
    jobs = 2
    if "--jobs" in argv:
        jobs = int(argv[argv.index("--jobs") + 1])
        args.remove(str(jobs))
    only = None
    if "--only" in argv:
        only = argv[argv.index("--only") + 1]
        args.remove(only)
    if len(args) != 4:
        sys.exit(__doc__)
    exe, replay_dir, asset_dir, kept = args
    shutil.rmtree(kept, ignore_errors=True)
    # Thousands of small files are written and removed: in memory where the system has a folder
    # there (on a disk shared with busy builds, removing them alone took 13 s), moved to SCRATCH_DIR
    # when the test fails.
    ram = "/dev/shm"
    if os.path.isdir(ram) and os.access(ram, os.W_OK):
        scratch = tempfile.mkdtemp(prefix="polar-replay-damage-", dir=ram)
    else:
        scratch = kept
        os.makedirs(scratch)
    try:
        return check(exe, replay_dir, asset_dir, scratch, every, jobs, only, "--table" in argv, kept)
    finally:
        if os.path.isdir(scratch) and scratch != kept:  # a failure: the copies are kept
            shutil.move(scratch, kept)


def check(exe, replay_dir, asset_dir, scratch, every, jobs, only, tables, kept):
    """Makes the copies, verifies them and judges the verdicts; 0 when all is as required."""
    # The copies sit two folders below a link to the assets, as the goldens sit in tests/replays/:
    # a scene file next to them names its sprites by ../../assets/.
    folder = os.path.join(scratch, "damaged", "replays")
    os.makedirs(folder)
    os.symlink(os.path.abspath(asset_dir), os.path.join(scratch, "assets"))
    goldens = os.path.join(scratch, "goldens")
    os.makedirs(goldens)
    for name in os.listdir(replay_dir):
        if not name.endswith(".replay"):
            shutil.copy(os.path.join(replay_dir, name), folder)
        elif only in (None, name):
            shutil.copy(os.path.join(replay_dir, name), goldens)
    if not os.listdir(goldens):
        sys.exit("no golden replay %s in %s" % (only or "", replay_dir))
    damages = make_copies(goldens, folder, every)
    cuts = make_cuts(goldens, folder)
    found = verdicts(exe, folder, jobs, scratch)
    for d in damages:
        verdict, message, notes, report = found[d["copy"]]
        judge(d, verdict, message, notes, report, folder)
    cut_problems = []
    for c in cuts:
        verdict, message, _, _ = found[c["copy"]]
        c["verdict"] = verdict
        c["right"] = verdict == c["expect"] and (
            verdict == "pass" or message.startswith(os.path.join(folder, c["copy"]) + ":%d:" % c["line"]))
        if not c["right"]:
            cut_problems.append("%s: expected %s at line %d, got %s: %s" % (
                c["copy"], c["expect"], c["line"], verdict, message))

    problems = []
    for d in damages:
        where = "%s:%d:%d (%s line, %r -> %r)" % (d["golden"], d["line"], d["column"], d["kind"], d["was"], d["now"])
        if not d["caught"]:
            if d["kind"] not in MAY_CHANGE_NOTHING:
                problems.append(where + ": not caught")
        elif d["verdict"] == "desync" and d["kind"] not in DESYNC_LINES:
            problems.append(where + ": a damaged line read as a desync of the game: " + d["message"])
        elif d["verdict"] == "damaged" and d["kind"] not in RECORD_LINES:
            problems.append(where + ": a changed game blamed on a damaged record: " + d["message"])
        elif not d["own"] and not (d["kind"] in UNPROTECTED_VALUES and d["verdict"] == "desync"):
            problems.append(where + ": blamed elsewhere: " + d["message"])
        elif not d.get("shown", True):
            problems.append(where + ": the values %r (recorded) and %r (the game's) not both shown in full: %s" % (
                d["now_value"], d["was_value"], d["message"]))
        elif not d["named"] and not (d["kind"] in UNPROTECTED_VALUES and d["verdict"] == "desync"):
            problems.append(where + ": kind not named: " + d["message"])
    # Every kind of line of the goldens, the first and the last line of each, and every line.
    kinds = {d["kind"] for d in damages}
    for required in ("first", "game", "scene", "seed", "tick-rate", "tuning", "asset", "begin", "in", "trace",
                     "check", "objects", "end"):
        if required not in kinds:
            problems.append("no %s line was damaged" % required)
    if tables:
        print(table(damages))
        print("")
        print(cut_table(cuts))
    passed = [d for d in damages if not d["caught"]]
    print("%d damages in %d lines of %d goldens: %d caught, %d blamed on their own line, %d name their kind, "
          "%d change nothing in the game" % (
              len(damages), len({(d["golden"], d["line"]) for d in damages}), len({d["golden"] for d in damages}),
              sum(d["caught"] for d in damages), sum(d["own"] for d in damages), sum(d["named"] for d in damages),
              len(passed)))
    for d in passed:
        print("  changes nothing: %s:%d:%d (%s line, %r -> %r)" % (d["golden"], d["line"], d["column"], d["kind"],
                                                                   d["was"], d["now"]))
    print("%d cut copies and %d whole ones: %d as expected" % (
        sum(c["expect"] != "pass" for c in cuts), sum(c["expect"] == "pass" for c in cuts),
        sum(c["right"] for c in cuts)))
    for p in problems + cut_problems:
        print("PROBLEM " + p)
    if problems or cut_problems:
        print("the damaged copies are kept in " + os.path.join(kept, "damaged", "replays"))
        return 1
    shutil.rmtree(scratch)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
