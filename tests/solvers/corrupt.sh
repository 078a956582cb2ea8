#!/bin/sh
# A solver whose result is broken on purpose (tests/cli_tests.cmake): the
# built-in engine's result file edited by the sed script EDIT, or emptied
# when EDIT is "empty".  usage: corrupt.sh GDSMC SCENE OUT EDIT
"$1" run "$2" --result "$3" --quiet || exit 1
if [ "$4" = empty ]; then : > "$3"; else sed -i "$4" "$3"; fi
