#!/bin/bash
# tutorials/policyTrainTwoStage/Allrun on a copy whose three dicts ask for a few batches
# (the recipe's settings otherwise): the three stages run in order, each from the one
# before (-actorFrom stage 1's policy, -startFrom A's checkpoint), and a second Allrun
# trains nothing; a stage with a checkpoint but no `finished` mark is resumed. Then the
# tournament of seeds (Allrun -seeds "1 2" -trial 64) on a second copy: both seeds run to
# the trial length, the one with the better validation goes on to stage 1's length with
# the weights of one straight run of that seed, and stage 2 starts from it.
#   runPolicyTrainTwoStage.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
. "$(dirname "$0")/tutorialWorkspace.sh" "$1" "$2"
copyTutorial policyTrainTwoStage
case="$work/tutorials/policyTrainTwoStage"
. "$(dirname "$0")/shrinkRecipe.sh"
shrinkStages "$case"
fail() { echo "runPolicyTrainTwoStage: $*"; exit 1; }

"$case/Allrun" > "$work/first.out" 2>&1 || { cat "$work/first.out"; fail "Allrun failed"; }
for stage in stage1 stage2A stage2B; do
  [ -f "$case/$stage/finished" ] || fail "$stage has no finished mark"
  [ -f "$case/$stage/policy/checkpoint.pt" ] || fail "$stage wrote no checkpoint"
done
for stage in stage1 stage2A; do [ -f "$case/$stage/policy/policy.xml" ] || fail "$stage wrote no policy"; done
result="$(sed -n 's#^Allrun: the policy is \([^ ]*\) .*#\1#p' "$work/first.out")"
[ -f "$case/$result" ] || { cat "$work/first.out"; fail "Allrun names no policy that exists: '$result'"; }
grep -q "the actor starts as stage1/policy/policy.xml's (10 actions" "$case/stage2A/log.policyTrain" ||
  fail "stage 2A did not start from stage 1's policy"
grep -q "started at episode 64 from stage2A/policy/checkpoint.pt" "$case/stage2B/log.policyTrain" ||
  fail "stage 2B did not continue A's checkpoint"
grep -q "last validation (episode 128)" "$case/stage2B/log.policyTrain" || fail "stage 2B did not end at 128"

# Again: nothing to train, nothing rewritten.
before="$(md5sum "$case/stage2B/policy/checkpoint.pt")"
"$case/Allrun" > "$work/second.out" 2>&1 || { cat "$work/second.out"; fail "the second Allrun failed"; }
[ "$(grep -c "has finished" "$work/second.out")" = 3 ] || { cat "$work/second.out"; fail "a finished stage ran again"; }
[ "$before" = "$(md5sum "$case/stage2B/policy/checkpoint.pt")" ] || fail "the second Allrun rewrote B's checkpoint"

# A stage with a checkpoint and no mark (stopped by Ctrl-C) is resumed, not started anew.
rm "$case/stage2B/finished"
"$case/Allrun" > "$work/third.out" 2>&1 || { cat "$work/third.out"; fail "the resuming Allrun failed"; }
grep -q "policyTrain -case stage2B -resume" "$work/third.out" || { cat "$work/third.out"; fail "stage 2B was not resumed"; }
grep -q "resumed at episode 128" "$case/stage2B/log.policyTrain" || fail "stage 2B did not resume at 128"

# The tournament of seeds.
tour="$work/tutorials/tournament"
cp -r "$sourceDir/tutorials/policyTrainTwoStage" "$tour" && (cd "$tour" && ./Allclean > /dev/null) || fail "no copy for the tournament"
shrinkStages "$tour"
"$tour/Allrun" -seeds "1 2" -trial 64 > "$work/tour.out" 2>&1 || { cat "$work/tour.out"; fail "Allrun -seeds failed"; }
scores="$(sed -n 's#^Allrun: seed \([0-9]*\), best validation \([^ ]*\) at 64 episodes$#\2 \1#p' "$work/tour.out")"
[ "$(echo "$scores" | wc -l)" = 2 ] || { cat "$work/tour.out"; fail "the tournament did not score both seeds"; }
expected="$(echo "$scores" | sort -g -r -k1,1 | head -1 | cut -d' ' -f2)"
[ "$(cat "$tour/chosen")" = "$expected" ] || fail "chose seed $(cat "$tour/chosen"), the better validation is seed $expected's: $scores"
chosen="$tour/stage1-seed$expected"
for s in 1 2; do
  grep -q "last validation (episode 64)" "$tour/stage1-seed$s/log.policyTrain" || fail "seed $s's trial did not end at 64"
done
grep -q "resumed at episode 64" "$chosen/log.policyTrain" || fail "the chosen seed was not resumed from its trial"
grep -q "last validation (episode 96)" "$chosen/log.policyTrain" || fail "the chosen seed did not go on to 96"
grep -q "the actor starts as stage1-seed$expected/policy/policy.xml's" "$tour/stage2A/log.policyTrain" ||
  fail "stage 2A did not start from the chosen seed"
# The chosen seed's weights are those of one straight run of it.
straight="$work/straight"
mkdir -p "$straight/system" && sed "s#<seed>[0-9]*</seed>#<seed>$expected</seed>#" \
  "$tour/stage1/system/policyTrainDict.xml" > "$straight/system/policyTrainDict.xml"
policyTrain -case "$straight" > "$work/straight.out" 2>&1 || { cat "$work/straight.out"; fail "the straight run failed"; }
cmp -s "$straight/policy/final.pt" "$chosen/policy/final.pt" || fail "the tournament's stage 1 differs from a straight run of seed $expected"
# A plain Allrun goes on with the tournament's stages: nothing left to train.
"$tour/Allrun" > "$work/tour2.out" 2>&1 || { cat "$work/tour2.out"; fail "the second Allrun of the tournament failed"; }
grep -q "stage 1 is stage1-seed$expected" "$work/tour2.out" || { cat "$work/tour2.out"; fail "a plain Allrun forgot the tournament"; }
[ "$(grep -c "has finished" "$work/tour2.out")" = 3 ] || { cat "$work/tour2.out"; fail "a finished stage of the tournament ran again"; }
"$tour/Allrun" -seeds "1 3" > "$work/tour3.out" 2>&1 && fail "another tournament in the same case was not refused"
"$tour/Allrun" -seeds "1 2" -trial 96 > "$work/tour4.out" 2>&1 && fail "a trial as long as stage 1 was not refused"
grep -q "below stage 1's 96" "$work/tour4.out" || { cat "$work/tour4.out"; fail "no clear error for a trial as long as stage 1"; }
"$tour/Allrun" -seeds "1 2" -trial 70 > "$work/tour5.out" 2>&1 && fail "a trial of part of a batch was not refused"
grep -q "a multiple of stage 1's <batchEpisodes> 32" "$work/tour5.out" || { cat "$work/tour5.out"; fail "no clear error for a trial of part of a batch"; }
echo "runPolicyTrainTwoStage: three stages in order, finished ones kept, a stopped one resumed; the tournament" \
  "chose the better seed, whose weights are a straight run's"
