#!/bin/bash
# Runs OpenFOAM's checkMesh on a case's exported constant/polyMesh (exportMesh -format
# foam) in a throw-away case with the minimal system/ dictionaries checkMesh needs.
# checkMesh exits 0 even when checks fail: this script matches "Mesh OK." instead.
#   checkFoamMesh.sh CASE_DIR     exit 0: Mesh OK; 1: checks failed; 77: no checkMesh
set -uo pipefail
case_dir="$(cd "$1" && pwd)"
. "$(dirname "$0")/foamScratchCase.sh" checkMesh
cp -r "$case_dir/constant/polyMesh" "$work/constant/"
checkMesh -case "$work" > "$work/log.checkMesh" 2>&1
cp "$work/log.checkMesh" "$case_dir/log.checkMesh"
grep -E "^ +(points|cells|faces|internal faces):|Mesh OK|Failed [0-9]+ mesh checks|\*\*\*" "$work/log.checkMesh"
grep -q "Mesh OK." "$work/log.checkMesh"
