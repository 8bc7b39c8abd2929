# Shared by the shell tests of the command line (sourced): a scratch folder removed on exit, pass/fail
# counters, and the two checks.
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fails=0; passes=0
check() {  # check NAME EXPECTED_RC ACTUAL_RC
  if [ "$2" -eq "$3" ]; then passes=$((passes + 1)); else echo "FAIL $1: exit $3, expected $2"; fails=$((fails + 1)); fi
}
ok() {  # ok NAME CONDITION...
  if "${@:2}"; then passes=$((passes + 1)); else echo "FAIL $1"; fails=$((fails + 1)); fi
}
