#!/usr/bin/env bash
# The WebAssembly replay verifier on files it cannot use, and on one whose trace is damaged: each gets the
# native verifier's file:line:column message and exit code. Usage: bad_input_test.sh REPLAY.js GOLDEN.replay [NATIVE]
# With NATIVE (build/bin/polarcade-replay) the two outputs must be the same bytes; without it, the
# message must name the file, line and column, and the exit code be 2.
set -uo pipefail
wasm=$(realpath "$1") golden=$(realpath "$2") native=${3:+$(realpath -m "$3")}
[ -n "$native" ] && [ ! -x "$native" ] && native=""  # no native build: check the messages alone
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0

# Bad files made from the golden one: a number that is not one, a line that is no field, a
# scene that is not there, a scene file that is not JSON.
sed 's/^seed 1$/seed one/' "$golden" >"$work/bad-number.replay"
sed 's/^tick-rate 60$/tick-rate sixty and more/' "$golden" >"$work/bad-tick-rate.replay"
sed '4a\this is not a field' "$golden" >"$work/bad-line.replay"
sed 's|^scene scenes/cave.json$|scene scenes/no-such-cave.json|' "$golden" >"$work/missing-scene.replay"
printf '{"objects": [ {"name": "rock", ' >"$work/broken-scene.json"
sed "s|^scene scenes/cave.json\$|scene $work/broken-scene.json|" "$golden" >"$work/broken-scene.replay"
head -c 300 "$golden" >"$work/cut-off.replay"
# And one that reads but does not match: a recorded trace token changed, a damaged trace (exit 1).
sed '0,/^trace ./s/^trace ./trace 0/' "$golden" >"$work/desync-trace.replay"

for file in "$work"/*.replay; do
    name=$(basename "$file")
    got=$(cd "$work" && node --no-experimental-fetch "$wasm" --quiet "$name" 2>&1)
    code=$?
    if [ -n "$native" ]; then
        want=$(cd "$work" && "$native" --quiet "$name" 2>&1)
        wantCode=$?
        if [ "$got" != "$want" ] || [ "$code" -ne "$wantCode" ]; then
            echo "FAIL $name: WebAssembly (exit $code) and native (exit $wantCode) differ:"
            diff <(echo "$want") <(echo "$got")
            fails=$((fails + 1))
            continue
        fi
    elif [ "$code" -ne "$(case $name in desync-*) echo 1 ;; *) echo 2 ;; esac)" ] ||
        ! grep -Eq "$name:[0-9]+:[0-9]+: " <<<"$got"; then
        echo "FAIL $name: exit $code, expected 2 (1 for a damaged trace) and a $name:LINE:COLUMN message; it said:"
        echo "$got"
        fails=$((fails + 1))
        continue
    fi
    echo "PASS $name (exit $code): $(grep -m1 -E "$name:[0-9]+" <<<"$got" | sed 's/^ *//')"
done
[ "$fails" -eq 0 ]
