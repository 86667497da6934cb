#!/bin/bash
# The shipped policy (etc/policy/policy.xml) still gives a tutorial its recorded one-shot
# Q (etc/policy/tutorialOneShot.csv, to 1e-6; -1 = the recorded mesh is invalid). Runs
# policyMesh on a copy of the case, which must hold constant/bladeParameters.xml.
#   checkShippedPolicy.sh SOURCE_DIR CASE_DIR BLADE     exit 0: as recorded; 1: not
set -uo pipefail
source="$1"
blade="$3"
. "$source/etc/RunFunctions" || exit 1
q="$(oneShotQ "$2" "$source/etc/policy/policy.xml")" || { echo "$blade: policyMesh failed"; exit 1; }
recorded="$(awk -F, -v b="$blade" '$1 == b {print $2}' "$source/etc/policy/tutorialOneShot.csv")"
[ -n "$recorded" ] || { echo "$blade: no recorded one-shot Q"; exit 1; }
echo "$blade: shipped policy one-shot Q $q (recorded $recorded)"
awk -v a="$q" -v b="$recorded" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6) }'
