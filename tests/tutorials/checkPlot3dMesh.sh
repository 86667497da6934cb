#!/bin/bash
# Reads a case's Plot3D export (exportMesh -format plot3d: mesh/passage.xyz) with OpenFOAM's
# plot3dToFoam in a throw-away case and requires the same cell count as the case's
# exported constant/polyMesh (both counts from the owner file's note line).
#   checkPlot3dMesh.sh CASE_DIR     exit 0: counts agree; 1: they differ or the read
#                                   failed; 77: no plot3dToFoam
set -uo pipefail
case_dir="$(cd "$1" && pwd)"
. "$(dirname "$0")/foamScratchCase.sh" plot3dToFoam
plot3dToFoam -case "$work" -noBlank "$case_dir/mesh/passage.xyz" > "$work/log.plot3dToFoam" 2>&1 ||
  { echo "plot3dToFoam failed:"; tail -5 "$work/log.plot3dToFoam"; exit 1; }
cells() { grep -m1 -o 'nCells: *[0-9]*' "$1" | grep -o '[0-9]*$'; }
fromPlot3d="$(cells "$work/constant/polyMesh/owner")"
fromExport="$(cells "$case_dir/constant/polyMesh/owner")"
echo "plot3dToFoam cells: $fromPlot3d, exported polyMesh cells: $fromExport"
[ -n "$fromPlot3d" ] && [ "$fromPlot3d" = "$fromExport" ]
