#!/bin/bash
# tutorials/policyTrainEnsemble/Allrun -seeds "1 2" on copies whose recipe dicts
# (tutorials/policyTrainTwoStage) ask for a few batches: each member is the two-stage recipe
# with its seed (member 2's weights are those of policyTrainTwoStage/Allrun -case DIR -seed 2
# run on its own), policy.xml names both members' results and holds the ensemble's mean
# reward as policyEvaluation gives it on the validation passages; a second Allrun trains
# nothing and writes the same file; other seeds in the same case, -seed without -case and
# an existing case of another seed are refused.
#   runPolicyTrainEnsemble.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
. "$(dirname "$0")/tutorialWorkspace.sh" "$1" "$2"
copyTutorial policyTrainTwoStage
copyTutorial policyTrainEnsemble
recipe="$work/tutorials/policyTrainTwoStage"
ensemble="$work/tutorials/policyTrainEnsemble"
. "$(dirname "$0")/shrinkRecipe.sh"
shrinkStages "$recipe"
fail() { echo "runPolicyTrainEnsemble: $*"; exit 1; }

"$ensemble/Allrun" -seeds "1 2" > "$work/first.out" 2>&1 || { cat "$work/first.out"; fail "Allrun failed"; }
for s in 1 2; do
  member="$ensemble/seed$s"
  [ -f "$member/result" ] || fail "member seed$s names no result"
  for stage in stage1 stage2A stage2B; do
    [ -f "$member/$stage/finished" ] || fail "seed$s/$stage has no finished mark"
    grep -q "<seed>$s</seed>" "$member/$stage/system/policyTrainDict.xml" || fail "seed$s/$stage's dict is not seed $s"
  done
  grep -q "seed $s, 2 rollout threads" "$member/stage1/log.policyTrain" || fail "seed$s's stage 1 did not train seed $s"
done
members="$(sed -n 's#.*<members>\(.*\)</members>.*#\1#p' "$ensemble/policy.xml")"
[ "$members" = "seed1/$(cat "$ensemble/seed1/result") seed2/$(cat "$ensemble/seed2/result")" ] ||
  fail "policy.xml's members are '$members'"

# The mean reward written is the ensemble's own on the validation passages.
written="$(sed -n 's#.*<validationMeanReward>\(.*\)</validationMeanReward>.*#\1#p' "$ensemble/policy.xml")"
evaluated="$("$PASSAGEMESH_BUILD/bench/policyEvaluation" "$ensemble/policy.xml" 20261202 4 0 - 2>/dev/null |
  sed -n 's#.*: mean reward \([^,]*\),.*#\1#p')"
[ -n "$written" ] && [ "$written" = "$evaluated" ] || fail "policy.xml's validationMeanReward '$written', policyEvaluation's '$evaluated'"

# Member 2 is the recipe with seed 2, bit for bit.
"$recipe/Allrun" -case "$work/straight" -seed 2 > "$work/straight.out" 2>&1 || { cat "$work/straight.out"; fail "the straight run failed"; }
result="$(cat "$work/straight/result")"
cmp -s "$work/straight/${result%.xml}.pt" "$ensemble/seed2/${result%.xml}.pt" || fail "member seed2 differs from the recipe run with seed 2"

# Again: nothing trained, the same file.
before="$(md5sum < "$ensemble/policy.xml")"
"$ensemble/Allrun" -seeds "1 2" > "$work/second.out" 2>&1 || { cat "$work/second.out"; fail "the second Allrun failed"; }
[ "$(grep -c "has finished" "$work/second.out")" = 6 ] || { cat "$work/second.out"; fail "a finished member's stage ran again"; }
[ "$before" = "$(md5sum < "$ensemble/policy.xml")" ] || fail "the second Allrun wrote another policy.xml"

"$ensemble/Allrun" -seeds "1 3" > "$work/other.out" 2>&1 && fail "other seeds in the same case were not refused"
grep -q "this case's members are seeds '1 2'" "$work/other.out" || { cat "$work/other.out"; fail "no clear error for other seeds"; }
"$ensemble/Allrun" -seeds "2 1 2" > "$work/twice.out" 2>&1 && fail "a seed named twice was not refused"
grep -q "names seed 2 twice" "$work/twice.out" || { cat "$work/twice.out"; fail "no clear error for a seed named twice"; }
"$recipe/Allrun" -seed 2 > "$work/noCase.out" 2>&1 && fail "-seed without -case was not refused"
"$recipe/Allrun" -case "$ensemble/seed1" -seed 2 > "$work/wrongSeed.out" 2>&1 && fail "a seed-1 case run as seed 2 was not refused"
grep -q "has <seed>1, not 2" "$work/wrongSeed.out" || { cat "$work/wrongSeed.out"; fail "no clear error for a case of another seed"; }
echo "runPolicyTrainEnsemble: two members, each the recipe with its seed (seed 2 bit for bit), the ensemble's file" \
  "with its validation; a second Allrun trains nothing; wrong seeds refused"
