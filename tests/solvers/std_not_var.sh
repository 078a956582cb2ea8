#!/bin/sh
# An adapter that writes the standard deviation where the protocol asks for
# the sample variance (tests/cli_tests.cmake): the built-in engine's result
# with every NAME_var of the rows replaced by its square root.
# usage: std_not_var.sh GDSMC SCENE OUT
"$1" run "$2" --result "$3.full" --quiet || exit 1
awk -F, -v OFS=, '/^[0-9]/ && !steady { for (i = 3; i <= NF; i += 2) $i = sqrt($i) }
                  /^# steady/ { steady = 1 } { print }' "$3.full" > "$3"
