#!/bin/bash
# The T106A tutorial through OpenFOAM (issue 13): Allrun.openfoam on a copy in a temporary
# folder (blade points -> mesh -> polyMesh -> simpleFoam -> report). Passes when the
# report's criteria hold (residuals down three orders, inlet/outlet flow within 0.5 %,
# exit angle within 2 deg of 63.2, y+ reported); exit 77 (skipped) without simpleFoam.
#   runOpenfoamT106A.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
command -v simpleFoam > /dev/null || { echo "simpleFoam not installed (Debian: openfoam): skipped"; exit 77; }
. "$(dirname "$0")/tutorialWorkspace.sh" "$1" "$2"
copyTutorial T106A
"$work/tutorials/T106A/Allrun.openfoam" > "$work/allrun.log" 2>&1
status=$?
tail -n 14 "$work/allrun.log"
[ "$status" = 0 ] || { echo "Allrun.openfoam failed (exit $status); log tail:"; tail -n 30 "$work/tutorials/T106A/openfoam/log.simpleFoam" 2>/dev/null; }
exit "$status"
