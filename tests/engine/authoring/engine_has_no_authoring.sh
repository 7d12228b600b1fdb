#!/bin/sh
# Usage: engine_has_no_authoring.sh NM ENGINE_LIBRARY AUTHORING_LIBRARY
#
# The runtime library (polar_engine) holds what a running game needs and nothing else: no bounds
# generator, bounds check, pixel truth, alpha mask or random scene. Fails when `nm -C` finds one of
# their names among ENGINE_LIBRARY's symbols (defined or referenced). Each name must also be found in
# AUTHORING_LIBRARY, so a name that matches nothing (misspelt, or its code renamed) fails instead of
# passing unseen.
set -u

if [ $# -ne 3 ]; then
    echo "usage: $0 NM ENGINE_LIBRARY AUTHORING_LIBRARY" >&2
    exit 2
fi
nm_tool=$1
engine=$2
authoring=$3

# Authoring names, one a line: types and functions of polar/authoring/ and of its private headers.
names='generateBounds
BoundsGenOptions
GeneratedBounds
measureFit
splitAlongPrincipalAxis
PixelSet
RadialField
fitBound
envelope
suspiciousBounds
spriteCandidates
OpaquePixels
opaquePixelsOverlap
SparseMatrix
AlphaMask
alphaMaskOf
SceneRandom
makeRockBounds
makeRockField
buildRockField
makeMixedScene
GeneratedScene'

symbols() {
    if [ ! -f "$1" ]; then
        echo "FAIL: no library $1" >&2
        exit 1
    fi
    if ! out=$("$nm_tool" -C "$1"); then
        echo "FAIL: $nm_tool -C $1 failed" >&2
        exit 1
    fi
    if [ -z "$out" ]; then
        echo "FAIL: $nm_tool -C $1 printed no symbols" >&2
        exit 1
    fi
    printf '%s\n' "$out"
}

engine_symbols=$(symbols "$engine") || exit 1
authoring_symbols=$(symbols "$authoring") || exit 1

status=0
for name in $names; do
    # The name as a whole identifier: polar::generateBounds(...), polar::PixelSet::count() const.
    pattern="(^|[^A-Za-z0-9_])$name([^A-Za-z0-9_]|\$)"
    if ! printf '%s\n' "$authoring_symbols" | grep -Eq "$pattern"; then
        echo "FAIL: $name is not in $authoring, so this check could not see it in the engine" >&2
        status=1
    fi
    hits=$(printf '%s\n' "$engine_symbols" | grep -E "$pattern")
    if [ -n "$hits" ]; then
        echo "FAIL: the runtime library $engine holds authoring code ($name):" >&2
        printf '%s\n' "$hits" | head -n 5 >&2
        status=1
    fi
done
if [ $status -eq 0 ]; then
    echo "ok: none of $(printf '%s\n' "$names" | wc -l) authoring names in $engine"
fi
exit $status
