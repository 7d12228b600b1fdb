#!/usr/bin/env python3
"""kill -9 of polarcade-server, 20 times, during a stream of submissions (SQLite).

Each round starts the server over the same database file, starts `polarcade-boards submit` of
every golden replay, and kills the server with SIGKILL after a delay that grows from 0 to about
half a second across the rounds. Then: every run the server acknowledged (a "verified ... run N"
line) in any round is there after a restart, with the very bytes submitted; `PRAGMA
integrity_check` is ok; and the runs stored are exactly the distinct ones acknowledged or refused as
duplicates, never half of one.

Usage: kill9_test.py SERVER_EXE BOARDS_EXE REPLAY_DIR
"""
import os
import pathlib
import re
import signal
import sqlite3
import subprocess
import sys
import tempfile
import time

server_exe, boards_exe, replay_dir = sys.argv[1:4]
ROUNDS = 20
replays = sorted(str(p) for p in pathlib.Path(replay_dir).glob("*.replay") if p.name != "crowded.replay")


def start_server(db):
    proc = subprocess.Popen([server_exe, "--db", f"sqlite:{db}", "--port", "0"], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    line = proc.stdout.readline()
    match = re.search(r"listening on (http://127\.0\.0\.1:\d+)", line)
    if not match:
        proc.kill()
        sys.exit(f"FAIL: the server did not start: {line}")
    return proc, match.group(1)


with tempfile.TemporaryDirectory(prefix="polar-kill9-") as tmp:
    db = os.path.join(tmp, "runs.sqlite")
    data = os.path.join(tmp, "data")
    acknowledged = {}  # run id -> replay file
    for round_ in range(ROUNDS):
        proc, url = start_server(db)
        client = subprocess.Popen([boards_exe, "--server", url, "--data", data, "submit", "--name", "Ada", *replays],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(round_ * 0.025)
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        out, _ = client.communicate(timeout=120)
        for line in out.splitlines():
            match = re.match(r"verified (\S+)  run (\d+) ", line)
            if match:
                acknowledged[int(match.group(2))] = match.group(1)

    proc, url = start_server(db)
    problems = []
    try:
        for run, replay in sorted(acknowledged.items()):
            target = os.path.join(tmp, f"run-{run}.replay")
            result = subprocess.run([boards_exe, "--server", url, "fetch", str(run), "-o", target],
                                    capture_output=True, text=True, timeout=60)
            if result.returncode != 0 or pathlib.Path(target).read_bytes() != pathlib.Path(replay).read_bytes():
                problems.append(f"run {run} ({replay}) was acknowledged but is not there: {result.stdout}")
    finally:
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=20)

    con = sqlite3.connect(db)
    integrity = con.execute("PRAGMA integrity_check").fetchone()[0]
    stored = con.execute("SELECT COUNT(*), COUNT(DISTINCT run_hash) FROM runs").fetchone()
    con.close()
    if integrity != "ok":
        problems.append(f"integrity_check: {integrity}")
    if stored[0] != stored[1] or stored[0] > len(replays):
        problems.append(f"{stored[0]} runs stored, {stored[1]} distinct, of {len(replays)} replays")
    if not acknowledged:
        problems.append("no run was acknowledged in any round: the kills came too early to test anything")
    for p in problems:
        print("FAIL:", p)
    if problems:
        sys.exit(1)
    print(f"{ROUNDS} kills: {len(acknowledged)} acknowledged runs all there, {stored[0]} stored, integrity ok")
