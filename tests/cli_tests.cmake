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
                   "collisions.kernel: the time-step scheme implements hard spheres only"
                   run ${S}/grw-ex3.ini --set scene.scheme=timestep --set scene.dt=0.01)
gdsmc_add_cli_test(cli_gaussian_needs_timestep 2
                   "heating.type: gaussian heating needs scene.scheme = timestep"
                   run ${S}/grw-ex5.ini --set heating.type=gaussian)
gdsmc_add_cli_test(cli_splitting_needs_timestep 2
                   "--set scene.splitting: only used with scheme = timestep"
                   run ${S}/grw-ex5.ini --set scene.splitting=strang)
gdsmc_add_cli_test(cli_timestep_small 0 "t,T,T_ci,T_raw"
                   run ${S}/grw-ex5.ini --set scene.scheme=timestep --set scene.dt=0.01
                   --set scene.splitting=strang --set particles.n=16
                   --set particles.ensembles=10 --set scene.t_end=0.5 --set scene.outputs=6
                   --quiet)
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

# gdsmc sonine (SPEC §5, §9): paper C's Sonine values as CSV name,value.  Bad
# input: the message and nothing else (anchored: standard output comes first).
gdsmc_add_cli_test(cli_sonine_help 0 "usage: gdsmc sonine --alpha A" sonine --help)
gdsmc_add_cli_test(cli_sonine_mu4_0 0 "name,value.*mu4_0,10\\.9248886721"
                   sonine --alpha 0.2)
gdsmc_add_cli_test(cli_sonine_tails 0 "A_white_noise,1\\.98767.*A_gaussian,4\\.41153"
                   sonine --alpha 0.4)
gdsmc_add_cli_test(cli_sonine_out 0 "^$"
                   sonine --alpha 0.2 --out ${CMAKE_CURRENT_BINARY_DIR}/sonine-0.2.csv)
gdsmc_add_cli_test(cli_sonine_d2 0 "beta_1,2[^.0-9].*a2_nongaussian_fit,nan"
                   sonine --alpha 0.5 --d 2)
gdsmc_add_cli_test(cli_sonine_alpha_range 2
                   "^gdsmc sonine: --alpha: '1\\.5' is out of range \\(allowed 0 <= alpha <= 1\\)[^!-~]*$"
                   sonine --alpha 1.5)
gdsmc_add_cli_test(cli_sonine_alpha_negative 2 "^gdsmc sonine: --alpha: '-0\\.1' is out of range"
                   sonine --alpha -0.1)
gdsmc_add_cli_test(cli_sonine_alpha_nan 2 "^gdsmc sonine: --alpha: 'nan' is not a number"
                   sonine --alpha nan)
gdsmc_add_cli_test(cli_sonine_alpha_text 2 "^gdsmc sonine: --alpha: '0\\.2x' is not a number"
                   sonine --alpha 0.2x)
gdsmc_add_cli_test(cli_sonine_d_range 2
                   "^gdsmc sonine: --d: '1' is out of range \\(allowed 2 <= d <= 100\\)"
                   sonine --alpha 0.2 --d 1)
gdsmc_add_cli_test(cli_sonine_missing_alpha 2 "^gdsmc sonine: missing --alpha" sonine --d 3)
gdsmc_add_cli_test(cli_sonine_needs_value 2 "^gdsmc sonine: option '--alpha' needs a value"
                   sonine --alpha)
gdsmc_add_cli_test(cli_sonine_unknown_option 2 "^gdsmc sonine: unknown option '--beta'"
                   sonine --alpha 0.2 --beta 1)
gdsmc_add_cli_test(cli_bench_small 0 "\\| hs-relax \\| 1000 \\|"
                   bench --max-n 1000 --seconds 0.05)
gdsmc_add_cli_test(cli_bench_bad_n 2 "--max-n '10': allowed 1000 <= N" bench --max-n 10)
# found by the fuzzer: a huge output count used to be accepted (and scanned)
gdsmc_add_cli_test(cli_outputs_too_many 2
                   "scene.outputs: '20000000' is out of range \\(allowed 2 <= outputs <= 10000000\\)"
                   run ${S}/grw-ex3.ini --set scene.outputs=20000000)
