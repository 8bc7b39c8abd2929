#!/bin/bash
# `sph lesson show|check FILE`: exit codes and messages on bad input (6: malformed lesson file, naming the
# file and the key, nothing on stdout; 7: a false claim, with the measured numbers), and show's text.
# Usage: lesson_cli_test.sh SPH REPO
sph=$1; repo=$2
source "$(dirname "$0")/test_lib.sh"

bad_lesson() {  # bad_lesson NAME WORD JSON: exit 6, one stderr line naming the file and WORD, no stdout
  local name=$1 word=$2
  printf '%s' "$3" > "$work/$name.json"
  "$sph" lesson check "$work/$name.json" > "$work/$name.out" 2> "$work/$name.err"; check "$name" 6 $?
  ok "$name: names the file" grep -q "$name.json" "$work/$name.err"
  ok "$name: names '$word'" grep -q -- "$word" "$work/$name.err"
  ok "$name: one line" test "$(wc -l < "$work/$name.err")" -eq 1
  ok "$name: nothing on stdout" test ! -s "$work/$name.out"
}
step='"title": "s", "text": "t", "scene": "sod"'
below='"check": {"type": "below", "metric": "L1_rho", "until": 0.01, "limit": 1}'
bad_lesson not_json "not valid JSON" '{"title": "x", "steps": ['
bad_lesson no_steps "steps" '{"title": "x"}'
bad_lesson unknown_key "steps\[0\].colour" "{\"title\": \"x\", \"steps\": [{$step, \"colour\": 1, $below}]}"
bad_lesson no_check "steps\[0\].check" "{\"title\": \"x\", \"steps\": [{$step}]}"
bad_lesson bad_type "steps\[0\].check.type" "{\"title\": \"x\", \"steps\": [{$step, \"check\": {\"type\": \"rises\", \"metric\": \"L1_rho\"}}]}"
bad_lesson bad_factor "check.factor" "{\"title\": \"x\", \"steps\": [{$step, \"check\": {\"type\": \"below\", \"metric\": \"L1_rho\", \"limit\": 1, \"factor\": 0.5}}]}"
bad_lesson bad_metric "check.metric" "{\"title\": \"x\", \"steps\": [{$step, \"check\": {\"type\": \"below\", \"metric\": \"L9\", \"limit\": 1}}]}"
bad_lesson bad_set "kernel.type" "{\"title\": \"x\", \"steps\": [{$step, \"set\": {\"kernel.type\": \"M9\"}, $below}]}"
bad_lesson bad_scene "no_such_scene" "{\"title\": \"x\", \"steps\": [{\"title\": \"s\", \"text\": \"t\", \"scene\": \"no_such_scene\", $below}]}"
bad_lesson falls_without_values "check.values" "{\"title\": \"x\", \"steps\": [{$step, \"check\": {\"type\": \"falls\", \"metric\": \"L1_rho\", \"key\": \"scene.n_left\"}}]}"
"$sph" lesson check "$work/none.json" > /dev/null 2> "$work/none.err"; check "missing file" 6 $?
ok "missing file: named" grep -q "none.json" "$work/none.err"
"$sph" lesson frobnicate "$repo/assets/lessons/shock_tube.json" > /dev/null 2>&1; check "unknown action" 2 $?

# a false claim: L1_rho of Sod at t = 0.05 is ~1e-2, not below 1e-6; a true one beside it
printf '%s' "{\"title\": \"x\", \"steps\": [{$step, \"set\": {\"scene.n_left\": 100}, \"check\": {\"type\": \"below\", \"metric\": \"L1_rho\", \"until\": 0.05, \"limit\": 1e-6}},
  {$step, \"set\": {\"scene.n_left\": 100}, \"check\": {\"type\": \"below\", \"metric\": \"L1_rho\", \"until\": 0.05, \"limit\": 1}}]}" > "$work/false.json"
"$sph" lesson check "$work/false.json" > "$work/false.out" 2> "$work/false.err"; check "false claim" 7 $?
ok "false claim: measured value printed" grep -q "L1_rho=[0-9.e-]* > 1e-06" "$work/false.out"
ok "false claim: marked false" grep -q "FALSE" "$work/false.out"
ok "true claim: checked" grep -q "L1_rho=[0-9.e-]* < 1 " "$work/false.out"
ok "false claim: counted" grep -q "1 of 2 claims are false" "$work/false.err"

# show: every step and its claim, no run
"$sph" lesson show "$repo/assets/lessons/shock_tube.json" > "$work/show.out"; check "show" 0 $?
ok "show: steps" grep -q "Step 3/3" "$work/show.out"
ok "show: claim" grep -q "claim: L1_rho at t = 0.2 falls by at least 1.5x" "$work/show.out"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
