# Sourced by the tutorial tests (runTutorials.sh, runOpenfoamT106A.sh) with SOURCE_DIR and
# BUILD_DIR as $1 and $2: puts the build's tools on the PATH and makes $work, a throw-away
# tree with etc/ and an empty tutorials/ (the Allrun scripts source etc/ relative to the
# case), removed when the script exits. copyTutorial BLADE copies one tutorial there and
# cleans it.
source="$1"
export PASSAGEMESH_BUILD="$2"
export PATH="$PASSAGEMESH_BUILD/bin:$PATH"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/tutorials"
cp -r "$source/etc" "$work/"
copyTutorial() {
  cp -r "$source/tutorials/$1" "$work/tutorials/"
  (cd "$work/tutorials/$1" && ./Allclean > /dev/null 2>&1 || true)
}
