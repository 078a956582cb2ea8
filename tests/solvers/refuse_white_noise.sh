#!/bin/sh
# A solver that cannot do white-noise heating (tests/cli_tests.cmake): it
# refuses such scenes by the protocol's channel (exit status 3, the reason as
# the last line of standard error) and runs the built-in engine on the rest.
# usage: refuse_white_noise.sh GDSMC SCENE OUT
if grep -q '^type = white-noise' "$2"; then
    echo "some diagnostic line first" >&2
    echo "white-noise heating is not implemented" >&2
    exit 3
fi
exec "$1" run "$2" --result "$3" --quiet
