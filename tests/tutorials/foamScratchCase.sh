# Sourced by the OpenFOAM checks (checkFoamMesh.sh, checkPlot3dMesh.sh): needs TOOL on
# the PATH (else exit 77, "skipped"), then makes $work, a throw-away OpenFOAM case with
# the minimal system/ dictionaries the utilities need, removed when the script exits.
#   . foamScratchCase.sh TOOL
command -v "$1" > /dev/null || { echo "$1 not installed (Debian: openfoam): skipped"; exit 77; }
export WM_PROJECT_DIR="${WM_PROJECT_DIR:-/usr/share/openfoam}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/constant" "$work/system"
foamHeader() { printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object %s;\n}\n' "$1"; }
{ foamHeader controlDict; printf 'application simpleFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 1;\ndeltaT 1;\nwriteControl timeStep;\nwriteInterval 1;\n'; } > "$work/system/controlDict"
{ foamHeader fvSchemes; for s in ddtSchemes gradSchemes divSchemes laplacianSchemes interpolationSchemes snGradSchemes; do printf '%s {}\n' "$s"; done; } > "$work/system/fvSchemes"
foamHeader fvSolution > "$work/system/fvSolution"
