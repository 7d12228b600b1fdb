#!/usr/bin/env bash
# The game in a real X window: Xvfb, openbox, xdotool. Starts it with a settings.json of a window
# size, opens Options, lowers the master volume and binds fire's second key to F there, moves the
# window, toggles fullscreen and back (the picture must stay centred in the screen while
# fullscreen, and the window come back to its place), quits, and checks that settings.json kept the
# volume, the key and the window's new place; then starts again and
# checks the window opens there. Nothing is skipped: a missing tool fails the test.
# usage: real_window_test.sh POLARCADE_EXE
set -euo pipefail
exe=$1
for tool in Xvfb openbox xdotool xdpyinfo xwd convert python3; do
    command -v "$tool" >/dev/null || { echo "FAIL: $tool is missing (tools/setup installs it)"; exit 1; }
done
work=$(mktemp -d)
display=:$((90 + RANDOM % 400))
pids=()
cleanup() {
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    wait 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }

Xvfb "$display" -screen 0 1600x900x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
pids+=($!)
export DISPLAY=$display
for _ in $(seq 50); do xdpyinfo >/dev/null 2>&1 && break; sleep 0.1; done
openbox >"$work/openbox.log" 2>&1 &
pids+=($!)
sleep 1

mkdir -p "$work/data"
"$exe" --help >/dev/null
cat >"$work/data/settings.json" <<'JSON'
{"format": 1, "window": {"width": 800, "height": 450}}
JSON

start() {
    "$exe" --mute --data "$work/data" >"$work/game.log" 2>&1 &
    game=$!
    pids+=($game)
    for _ in $(seq 100); do
        win=$(xdotool search --sync --onlyvisible --name '^Polarcade' 2>/dev/null | head -1) && [ -n "$win" ] && break
        sleep 0.1
    done
    [ -n "${win:-}" ] || fail "no Polarcade window appeared: $(cat "$work/game.log")"
    sleep 1
}
geometry() { xdotool getwindowgeometry --shell "$win" | tr '\n' ' '; }
quit() {
    # Esc on the title asks "Quit?" (NO above YES): down to YES, Enter.
    xdotool windowactivate --sync "$win" key --delay 200 Escape Down Return
    for _ in $(seq 50); do kill -0 "$game" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$game" 2>/dev/null && fail "Esc, YES on the title did not quit"
    wait "$game" || fail "the game exited with $?: $(cat "$work/game.log")"
}
# The margins of the lit picture on the whole screen (ImageMagick's trim box of the black border),
# as "left top right bottom".
margins() {
    xwd -root -silent >"$work/shot.xwd"
    local box size
    box=$(convert "xwd:$work/shot.xwd" -format '%@' info:)  # the trim box, WxH+X+Y
    size=$(convert "xwd:$work/shot.xwd" -format '%w %h' info:)
    python3 -c "
import re, sys
w, h, x, y = map(int, re.match(r'(\d+)x(\d+)\+(\d+)\+(\d+)', '$box').groups())
sw, sh = map(int, '$size'.split())
print(x, y, sw - x - w, sh - y - h)"
}

start
eval "$(geometry)"
[ "$WIDTH" = 800 ] && [ "$HEIGHT" = 450 ] || fail "the window opened at ${WIDTH}x${HEIGHT}, not settings.json's 800x450"
# Title: PLAY SCENES REPLAYS OPTIONS. Options: master volume 80 -> 60 (left twice); down 18 rows
# to FIRE KEY 2 (eleven settings, then two slots for each of turn left, turn right, thrust), Enter,
# F; Esc back to the title.
xdotool windowactivate --sync "$win" key --delay 200 Down Down Down Return Left Left \
    Down Down Down Down Down Down Down Down Down Down Down Down Down Down Down Down Down Down Return f Escape
xdotool windowmove --sync "$win" 200 150
sleep 0.5
eval "$(geometry)"
moved_x=$X moved_y=$Y
xdotool windowactivate --sync "$win" key F11
sleep 1.5
read -r left top right bottom < <(margins)
echo "fullscreen margins: $left $top $right $bottom; window: $(geometry)"
[ $((left - right)) -le 1 ] && [ $((right - left)) -le 1 ] || fail "fullscreen picture not centred across: $left vs $right"
[ $((top - bottom)) -le 1 ] && [ $((bottom - top)) -le 1 ] || fail "fullscreen picture not centred down: $top vs $bottom"
xdotool windowactivate --sync "$win" key F11
sleep 1.5
eval "$(geometry)"
[ "$WIDTH" = 800 ] && [ "$HEIGHT" = 450 ] || fail "back from fullscreen at ${WIDTH}x${HEIGHT}, not 800x450"
quit

s=$(cat "$work/data/settings.json")
echo "$s"
python3 - "$work/data/settings.json" "$moved_x" "$moved_y" <<'PY' || fail "settings.json did not keep the settings"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["master_volume"] == 60, s
assert s["keys"]["fire"] == ["space", "f"], s
assert s["fullscreen"] is False, s
assert (s["window"]["width"], s["window"]["height"]) == (800, 450), s
# Window managers report the client's place or the frame's: within a title bar of the move.
assert abs(s["window"]["x"] - int(sys.argv[2])) <= 40 and abs(s["window"]["y"] - int(sys.argv[3])) <= 40, s
PY

start
eval "$(geometry)"
# Within a title bar: SDL places the client area, the window manager may place the frame there.
dx=$((X - moved_x)) dy=$((Y - moved_y))
[ ${dx#-} -le 40 ] && [ ${dy#-} -le 40 ] ||
    fail "the second start opened at $X,$Y, not where the window was left ($moved_x,$moved_y)"
quit
echo "PASS"
