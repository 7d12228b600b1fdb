#!/usr/bin/env python3
"""polarcade-server and polarcade-boards as a club runs them, on loopback.

Starts `polarcade-server --db sqlite:TMP/runs.sqlite --port 0` (a free port, read from its first
line), submits every golden replay with `polarcade-boards submit`, and checks: one verdict line per
replay, crowded.replay (a scene of its own) refused and the exit code 1 for it; the key file made
with mode 0600; the runs on `top` and `around`; `fetch` writes the very bytes submitted; an edited
replay refused with exit code 1; then SIGTERM stops the server, and a second start over the same
file still has every run.

Usage: boards_cli_test.py SERVER_EXE BOARDS_EXE REPLAY_DIR
"""
import os
import pathlib
import re
import signal
import subprocess
import sys
import tempfile

server_exe, boards_exe, replay_dir = sys.argv[1:4]
problems = []


def check(condition, what):
    if not condition:
        problems.append(what)
        print("FAIL:", what)


def start_server(folder):
    proc = subprocess.Popen([server_exe, "--db", f"sqlite:{folder}/runs.sqlite", "--port", "0"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    line = proc.stdout.readline()
    match = re.search(r"listening on (http://127\.0\.0\.1:\d+)", line)
    if not match:
        proc.kill()
        sys.exit(f"FAIL: the server did not start: {line}{proc.stdout.read()}")
    return proc, match.group(1)


def stop_server(proc):
    proc.send_signal(signal.SIGTERM)
    try:
        out, _ = proc.communicate(timeout=20)
    except subprocess.TimeoutExpired:
        proc.kill()
        check(False, "the server did not stop on SIGTERM within 20 s")
        return
    check(proc.returncode == 0 and "stopped" in out, f"the server stopped with {proc.returncode}: {out}")


def boards(url, data, *args):
    result = subprocess.run([boards_exe, "--server", url, "--data", data, *args], capture_output=True, text=True,
                            timeout=120)
    return result.returncode, result.stdout, result.stderr


for exe in (server_exe, boards_exe):
    result = subprocess.run([exe, "--help"], capture_output=True, text=True, timeout=30)
    check(result.returncode == 0 and "--help" in result.stdout, f"{exe} --help")

with tempfile.TemporaryDirectory(prefix="polar-boards-") as tmp:
    data = os.path.join(tmp, "data")
    replays = sorted(str(p) for p in pathlib.Path(replay_dir).glob("*.replay"))
    proc, url = start_server(tmp)
    try:
        code, out, err = boards(url, data, "submit", "--name", "Club Ada", *replays)
        lines = out.splitlines()
        check(len(lines) == len(replays), f"one line per replay: {out}")
        for replay, line in zip(replays, lines):
            # crowded.replay's scene is its own file; minefield and saucers start with nine lives
            refused = ("crowded.replay", "minefield.replay", "saucers.replay")
            verdict = "refused " if replay.endswith(refused) else "verified"
            check(line.startswith(verdict) and replay in line, f"{replay}: {line}")
        check(code == 1, f"exit code {code} with a refused run, expected 1")
        key = os.path.join(data, "online-key")
        check(os.path.exists(key) and (os.stat(key).st_mode & 0o777) == 0o600, "the key file has mode 0600")

        code, out, _ = boards(url, data, "submit", "--name", "Club Ada", os.path.join(replay_dir, "short.replay"))
        check(code == 1 and "duplicate" in out, f"the same run again: {code} {out}")

        code, out, _ = boards(url, data, "top", "--unranked", "--mode", "rules-1", "--scene", "scenes/storm.json")
        check(code == 0 and re.search(r"#1 +Club Ada +5790", out) is not None, f"top: {out}")
        code, out, _ = boards(url, data, "around", "Club Ada", "--unranked", "--mode", "rules-1")
        check(code == 0 and "Club Ada" in out, f"around: {out}")

        fetched = os.path.join(tmp, "fetched.replay")
        code, out, _ = boards(url, data, "fetch", "1", "-o", fetched)
        check(code == 0 and pathlib.Path(fetched).read_bytes() == pathlib.Path(replays[1]).read_bytes(),
              f"fetch 1 gives {replays[1]} back: {out}")
        code, out, _ = boards(url, data, "fetch", "999")
        check(code == 1 and "no-run" in out, f"fetch of an unknown run: {out}")

        short = pathlib.Path(replay_dir, "short.replay").read_text()
        edited = os.path.join(tmp, "edited.replay")
        pathlib.Path(edited).write_text(short.replace("check 600 996519cb1ae926ab rng=3d57156828b2ffe6 score=340",
                                                      "check 600 996519cb1ae926ab rng=3d57156828b2ffe6 score=999"))
        code, out, _ = boards(url, data, "submit", "--name", "Club Ada", edited)
        check(code == 1 and out.startswith("refused") and "damaged" in out and edited in out, f"edited: {out}")
    finally:
        stop_server(proc)

    proc, url = start_server(tmp)
    try:
        code, out, _ = boards(url, data, "top", "--unranked", "--mode", "rules-1", "--scene", "scenes/storm.json")
        check("5790" in out, f"the runs are there after a restart: {out}")
    finally:
        stop_server(proc)

if problems:
    sys.exit(f"{len(problems)} problems")
print("polarcade-server and polarcade-boards: all checks passed")
