# Command-line tests: bad input exits 2 with a message naming file, line and
# key, before any work (STYLE: Tests).  Paths are relative to the source tree.
set(S verify/scenes)
set(B tests/scenes)
gdsmc_add_cli_test(cli_help 0 "usage: gdsmc COMMAND" --help)
gdsmc_add_cli_test(cli_run_help 0 "NAME_ci = 3.2 sqrt" run --help)
gdsmc_add_cli_test(cli_verify_list 0 "grw-ex3" verify --list)
gdsmc_add_cli_test(cli_no_command 2 "usage: gdsmc" "")
gdsmc_add_cli_test(cli_unknown_command 2 "unknown command 'frobnicate'" frobnicate)
gdsmc_add_cli_test(cli_unknown_option 2 "gdsmc run: unknown option '--fast'"
                   run ${S}/grw-ex3.ini --fast)
gdsmc_add_cli_test(cli_missing_file 2
                   "gdsmc run: no/such.ini: cannot open: No such file or directory"
                   run no/such.ini)
gdsmc_add_cli_test(cli_restitution_out_of_range 2
                   "restitution-1.7.ini:6: collisions.restitution: '1.7' is out of range \\(allowed"
                   run ${B}/restitution-1.7.ini)
gdsmc_add_cli_test(cli_unknown_key 2
                   "unknown-key.ini:5: collisions.speed: unknown key"
                   run ${B}/unknown-key.ini)
gdsmc_add_cli_test(cli_negative_temperature 2
                   "--set particles.temperature=-2: particles.temperature"
                   run ${S}/grw-ex3.ini --set particles.temperature=-2)
gdsmc_add_cli_test(cli_n_zero 2 "particles.n" run ${S}/grw-ex3.ini --set particles.n=0)
gdsmc_add_cli_test(cli_unsupported_scheme 2
                   "scene.scheme: the time-step scheme is not implemented yet"
                   run ${S}/grw-ex3.ini --set scene.scheme=timestep --set scene.dt=0.01)
gdsmc_add_cli_test(cli_verify_unknown_case 2 "unknown case 'grw-ex9'" verify --case grw-ex9)
gdsmc_add_cli_test(cli_reference_ex3 0 "t,T_exact,T_finite_n,T_raw_finite_n"
                   reference ${S}/grw-ex3.ini)
gdsmc_add_cli_test(cli_run_small 0 "t,T,T_ci,T_raw,T_raw_ci,ux,ux_ci"
                   run ${S}/grw-ex3.ini --set particles.n=8 --set particles.ensembles=20
                   --quiet)

# Byte-identical output for 1 and 2 threads (hard spheres with heating: the
# majorant, fictitious collisions and Brownian catch-ups all take part).
add_test(NAME cli_threads_identical
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc>
                 -DSCENE=${PROJECT_SOURCE_DIR}/${S}/grw-ex5.ini
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/threads -P ${CMAKE_CURRENT_SOURCE_DIR}/run_threads.cmake)
set_tests_properties(cli_threads_identical PROPERTIES TIMEOUT 120 LABELS unit)
