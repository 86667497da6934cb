#!/bin/bash
# The shipped policy's one-shot mesh, then a short iterOptimize (CMA-ES, seed 1) started
# from the policy's parameters: how far a few more meshes take each tutorial towards the
# best of iterOptimize -budget 1000 (docs/policy-history.md "One shot, then a short search").
#   bench/policyPolish.sh BUDGET [POLICY.xml | defaults]      (tools on PATH)
# Prints blade,oneShotQ,polishedQ,seconds (seconds: the polish alone, wall time).
# `defaults`: the same short search from etc/meshDictDefaults.xml instead (the baseline).
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: bench/policyPolish.sh BUDGET [POLICY.xml | defaults]" >&2; exit 1; }
budget="$1"
root="$(cd "$(dirname "$0")/.." && pwd)"
policy="${2:-$root/etc/policy/policy.xml}"
[ "$policy" = defaults ] || policy="$(realpath "$policy")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "blade,oneShotQ,polishedQ,seconds"
for blade in LS89 STD10 T106A SIRT; do
  dir="$work/$blade"
  mkdir -p "$dir"
  cp -r "$root/tutorials/$blade/constant" "$root/tutorials/$blade/system" "$dir/"
  rm -f "$dir/constant/bladeParameters.xml" "$dir/system/meshDict.xml"
  bladeFit -case "$dir" > "$dir/log.bladeFit"
  # iterOptimize starts from system/meshDict.xml (from the defaults without one). policyMesh
  # writes it with a valid mesh only, so where the one-shot mesh is invalid the parameters
  # it prints ("    name value", yIn and yOut in metres) are written as the start here.
  if [ "$policy" != defaults ] && ! policyMesh -case "$dir" -policy "$policy" > "$dir/log.policyMesh" 2>&1; then
    { echo "<meshDict>"
      sed -n 's#^    \([A-Za-z]*\) *\([^ ]*\)$#  <\1>\2</\1>#p' "$dir/log.policyMesh"
      echo "</meshDict>"; } > "$dir/system/meshDict.xml"
  fi
  start=$(date +%s.%N)
  log="$(iterOptimize -case "$dir" -budget "$budget" -seed 1 2>/dev/null)"
  end=$(date +%s.%N)
  # The start's Q is the one-shot Q (-1 for an invalid mesh; iterOptimize prints that).
  oneShot="$(sed -n 's/.*start Q \([^ ,]*\), best Q.*/\1/p' <<< "$log")"
  polished="$(sed -n 's/.*best Q \([^ ]*\) .*/\1/p' <<< "$log")"
  echo "$blade,$oneShot,$polished,$(echo "$end - $start" | bc)"
done
