#!/bin/bash
# Runs every tutorial (blade points -> checked mesh) on a copy in a temporary folder and
# requires `cgnscheck mesh/passage.cgns` to print no warning and no error (issue 3), and
# where OpenFOAM is installed checkMesh "Mesh OK." on the exported polyMesh and the Plot3D
# export read by plot3dToFoam to the same cell count (issue 13), and the shipped policy's
# one-shot Q as recorded in etc/policy/tutorialOneShot.csv (issue 12).
#   runTutorials.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
command -v cgnscheck > /dev/null || { echo "cgnscheck not installed (Debian: cgns-convert)"; exit 1; }
. "$(dirname "$0")/tutorialWorkspace.sh" "$1" "$2"
for blade in LS89 STD10 T106A SIRT; do
  copyTutorial "$blade"
  "$work/tutorials/$blade/Allrun"
  report="$(cgnscheck "$work/tutorials/$blade/mesh/passage.cgns" 2>&1)"
  if grep -Eiq "warning|error" <<< "$report"; then
    echo "$blade: cgnscheck complains:"; echo "$report"; exit 1
  fi
  report="$(cgnscheck "$work/tutorials/$blade/mesh/passageSU2.cgns" 2>&1)"
  if grep -Eiq "warning|error" <<< "$report"; then
    echo "$blade: cgnscheck complains about passageSU2.cgns:"; echo "$report"; exit 1
  fi
  # The exported polyMesh through OpenFOAM's checkMesh (skipped where OpenFOAM is absent).
  status=0
  "$sourceDir/tests/tutorials/checkFoamMesh.sh" "$work/tutorials/$blade" > "$work/checkMesh.out" || status=$?
  if [ "$status" = 1 ]; then echo "$blade: checkMesh fails:"; cat "$work/checkMesh.out"; exit 1; fi
  sed "s/^/$blade: /" "$work/checkMesh.out" | grep -E "Mesh OK|skipped|cells:"
  # The Plot3D export read by OpenFOAM's plot3dToFoam: the same number of cells.
  status=0
  "$sourceDir/tests/tutorials/checkPlot3dMesh.sh" "$work/tutorials/$blade" > "$work/plot3d.out" || status=$?
  if [ "$status" = 1 ]; then echo "$blade: the Plot3D file does not read back:"; cat "$work/plot3d.out"; exit 1; fi
  sed "s/^/$blade: /" "$work/plot3d.out"
  grep -m1 "Q = " "$work/tutorials/$blade/log.checkMeshQuality" | sed "s/^/$blade: /"
  # The shipped policy still meshes the tutorial as recorded (issue 12).
  "$sourceDir/tests/tutorials/checkShippedPolicy.sh" "$sourceDir" "$work/tutorials/$blade" "$blade" ||
    { echo "$blade: the shipped policy's one-shot Q changed (retrain, or record the new value)"; exit 1; }
done
