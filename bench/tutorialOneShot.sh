#!/bin/bash
# The one-shot Q a policy gives each tutorial at its own condition, as the CSV that
# etc/policy/tutorialOneShot.csv records for the shipped policy (-1: invalid mesh).
#   bench/tutorialOneShot.sh [POLICY.xml]     (default etc/policy/policy.xml; tools on PATH)
# Each tutorial is copied to a temporary folder, fitted (bladeFit) and meshed by policyMesh.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
policy="$(realpath "${1:-$root/etc/policy/policy.xml}")"
. "$root/etc/RunFunctions"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "blade,Q"
for blade in LS89 STD10 T106A SIRT; do
  mkdir -p "$work/$blade"
  cp -r "$root/tutorials/$blade/constant" "$root/tutorials/$blade/system" "$work/$blade/"
  rm -f "$work/$blade/constant/bladeParameters.xml"
  bladeFit -case "$work/$blade" > "$work/$blade/log.bladeFit"
  echo "$blade,$(oneShotQ "$work/$blade" "$policy")"
done
