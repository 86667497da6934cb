# Sourced by the tutorial tests (runTutorials.sh, runOpenfoamT106A.sh) with SOURCE_DIR and
# BUILD_DIR as $1 and $2. Sets sourceDir (the source tree), puts the build's tools on the
# PATH and makes $work, a throw-away tree with etc/ and an empty tutorials/ (the Allrun
# scripts source etc/ relative to the case); it owns the EXIT trap that removes $work.
# copyTutorial BLADE copies one tutorial there and cleans it (exit 1 if that fails: a
# stale mesh left in the copy would be checked instead of this build's).
sourceDir="$1"
export PASSAGEMESH_BUILD="$2"
export PATH="$PASSAGEMESH_BUILD/bin:$PATH"
work="$(mktemp -d)" || exit 1
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/tutorials" && cp -r "$sourceDir/etc" "$work/" || exit 1
copyTutorial() {
  cp -r "$sourceDir/tutorials/$1" "$work/tutorials/" || exit 1
  (cd "$work/tutorials/$1" && ./Allclean > /dev/null 2>&1) || { echo "$1: Allclean failed"; exit 1; }
}
