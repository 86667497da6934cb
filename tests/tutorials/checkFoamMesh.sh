#!/bin/bash
# Runs OpenFOAM's checkMesh on a case's exported constant/polyMesh (exportMesh -format
# foam) in a throw-away case with the minimal system/ dictionaries checkMesh needs.
# checkMesh exits 0 even when checks fail: this script matches "Mesh OK." instead.
#   checkFoamMesh.sh CASE_DIR     exit 0: Mesh OK; 1: checks failed; 77: no checkMesh
set -uo pipefail
case_dir="$(cd "$1" && pwd)"
command -v checkMesh > /dev/null || { echo "checkMesh not installed (Debian: openfoam): skipped"; exit 77; }
export WM_PROJECT_DIR="${WM_PROJECT_DIR:-/usr/share/openfoam}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/constant" "$work/system"
cp -r "$case_dir/constant/polyMesh" "$work/constant/"
header() { printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object %s;\n}\n' "$1"; }
{ header controlDict; printf 'application simpleFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 1;\ndeltaT 1;\nwriteControl timeStep;\nwriteInterval 1;\n'; } > "$work/system/controlDict"
{ header fvSchemes; for s in ddtSchemes gradSchemes divSchemes laplacianSchemes interpolationSchemes snGradSchemes; do printf '%s {}\n' "$s"; done; } > "$work/system/fvSchemes"
header fvSolution > "$work/system/fvSolution"
checkMesh -case "$work" > "$work/log.checkMesh" 2>&1
cp "$work/log.checkMesh" "$case_dir/log.checkMesh"
grep -E "^ +(points|cells|faces|internal faces):|Mesh OK|Failed [0-9]+ mesh checks|\*\*\*" "$work/log.checkMesh"
grep -q "Mesh OK." "$work/log.checkMesh"
