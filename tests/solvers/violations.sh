#!/bin/sh
# A solver that raises its majorant after each step (tests/cli_tests.cmake):
# the built-in engine's result claiming 30 majorant violations, and declaring
# that its algorithm lets through at most ALLOWED.
# usage: violations.sh GDSMC SCENE OUT ALLOWED
"$1" run "$2" --result "$3.full" --quiet || exit 1
sed "s/^# violations = 0\$/# violations = 30\n# violations_allowed = $4/" "$3.full" > "$3"
