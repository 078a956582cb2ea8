# Command-line tests: bad input exits 2 with a message naming file, line and
# key, before any work (STYLE: Tests).  Paths are relative to the source tree.
set(S verify/cases/scenes)
set(B tests/scenes)
gdsmc_add_cli_test(cli_help 0 "usage: gdsmc COMMAND" --help)
gdsmc_add_cli_test(cli_run_help 0 "NAME_ci = 3.2 sqrt" run --help)
gdsmc_add_cli_test(cli_verify_list 0
                   "suites: quick .*\n  grw-ex3 +grw +paper A Ex 3, Table 1: .*\\[quick\\]\n"
                   verify --list)
gdsmc_add_cli_test(cli_reference_list 0
                   "name,kind,what\nT_exact,series,.*\nT_le,series,.*\na2_C10,value,\"paper C Eq. \\(10\\)"
                   reference --list)
gdsmc_add_cli_test(cli_splitting_needs_timestep 2
                   "--set scene.splitting: only used with scheme = timestep"
                   run ${S}/grw-ex5.ini --set scene.splitting=strang)
# the first row is t = 0 with T near the scene's 1 (n = 16, N = 10: ci 0.14);
# the last is t_end
gdsmc_add_cli_test(cli_timestep_small 0
                   "\nt,T,T_ci,T_raw,[^\n]*\n0,(0\\.[6-9]|1\\.[0-3])[0-9]*,.*\n0\\.5,[^\n]*\n$"
                   run ${S}/grw-ex5.ini --set scene.scheme=timestep --set scene.dt=0.01
                   --set scene.splitting=strang --set particles.n=16
                   --set particles.ensembles=10 --set scene.t_end=0.5 --set scene.outputs=6
                   --quiet)
# --case takes a list; an unknown name in it exits 2, naming it
gdsmc_add_cli_test(cli_verify_case_list_unknown 2 "unknown case 'nope'"
                   verify --case grw-ex3,nope)
# A simulation two cases of one run need runs once: vro-grw-ex3's conditional
# rows are grw-ex3's (verdicts on stdout, then progress on stderr)
gdsmc_add_cli_test(cli_verify_repeat_runs_once 0
                   "\nverify: [1-9][0-9]* passed, 0 failed.*vro-grw-ex3 n=64 conditional: taken from its checkpoint \\(the same simulation ran earlier in this run\\)"
                   verify --suite quick --case grw-ex3,vro-grw-ex3
                   --out ${CMAKE_CURRENT_BINARY_DIR}/repeat-runs-once)
set_tests_properties(cli_verify_repeat_runs_once PROPERTIES LABELS verification)
# The CI gate itself: a wrong solver (restitution 0.45 for 0.5) exits 1 with
# failed checks counted; the right one exits 0 with none.
gdsmc_add_cli_test(cli_verify_gate_wrong_solver 1
                   "\nFAIL  grw-ex3 n=64 T_raw vs exact finite-n expectation: .*\nverify: [0-9]+ passed, [1-9][0-9]* failed, [0-9]+ skipped\n"
                   verify --suite quick --case grw-ex3 --solver-set collisions.restitution=0.45
                   --out ${CMAKE_CURRENT_BINARY_DIR}/gate-wrong)
gdsmc_add_cli_test(cli_verify_gate_right_solver 0
                   "\nverify: [1-9][0-9]* passed, 0 failed, [0-9]+ skipped\n"
                   verify --suite quick --case grw-ex3 --out ${CMAKE_CURRENT_BINARY_DIR}/gate-right)
set_tests_properties(cli_verify_gate_wrong_solver cli_verify_gate_right_solver
                     PROPERTIES LABELS verification)
# Paper D: a heat-flux force of the wrong sign, or half the force (the
# factor 1/2 of D Eq. 4.1 applied twice), fails msg-kappa at quick sizes.
gdsmc_add_cli_test(cli_verify_msg_wrong_sign 1
                   "\nFAIL  msg-kappa alpha=1.0 eps\\*=0.025 kappa' within 5% of first Sonine: -"
                   verify --suite quick --case msg-kappa --solver-set heat-flux.strength=-0.025
                   --out ${CMAKE_CURRENT_BINARY_DIR}/msg-wrong-sign)
gdsmc_add_cli_test(cli_verify_msg_half_force 1
                   "\nFAIL  msg-kappa alpha=1.0 eps\\*=0.025 kappa' within 5% of first Sonine: 0\\.[3-6]"
                   verify --suite quick --case msg-kappa --solver-set heat-flux.strength=0.0125
                   --out ${CMAKE_CURRENT_BINARY_DIR}/msg-half-force)
set_tests_properties(cli_verify_msg_wrong_sign cli_verify_msg_half_force
                     PROPERTIES LABELS verification)
# Paper E: a shear of the wrong sign fails as-steady at quick sizes.
# (every row 16 tau0 long: the a tau0 = 0.1 rows sheared at a tau0 = -4 for 300 tau0
# would take 30 s)
gdsmc_add_cli_test(cli_verify_as_wrong_sign 1
                   "\nFAIL  as-steady alpha=0\\.70 ihs a_tau0=4 -Pxy/nT within 10% of BGK"
                   verify --suite quick --case as-steady --solver-set shear.rate=-4
                   --set scene.t_end=16 --set scene.outputs=81 --set steady.from=12
                   --out ${CMAKE_CURRENT_BINARY_DIR}/as-wrong-sign)
set_tests_properties(cli_verify_as_wrong_sign PROPERTIES LABELS verification)
# EHS colliding at the IHS rate (beta = 1 instead of (1 + alpha)/2 = 0.85): its
# (Pxx - Pyy)/nT is 13% below BGK's (8 ensembles, so the half-width is 8%)
gdsmc_add_cli_test(cli_verify_as_wrong_beta 1
                   "\nFAIL  as-steady alpha=0\\.70 ehs a_tau0=4 \\(Pxx - Pyy\\)/nT within 5% of BGK"
                   verify --suite quick --case as-steady --set particles.ensembles=8
                   --solver-set collisions.beta=1 --out ${CMAKE_CURRENT_BINARY_DIR}/as-wrong-beta)
set_tests_properties(cli_verify_as_wrong_beta PROPERTIES LABELS verification)
# ... and turns E Fig. 17's marginals over: g_x^(+) sheared the wrong way is
# farther from BGK's than the local equilibrium is (1.9 times, against 0.11)
gdsmc_add_cli_test(cli_verify_as_distribution_wrong_sign 1
                   "\nFAIL  as-distribution alpha=0\\.50 ihs a_tau0=4 g_x\\+ nearer BGK than equilibrium \\([1-9]"
                   verify --suite quick --case as-distribution --solver-set shear.rate=-4
                   --out ${CMAKE_CURRENT_BINARY_DIR}/as-distribution-wrong-sign)
set_tests_properties(cli_verify_as_distribution_wrong_sign PROPERTIES LABELS verification)
# The slab's Lees-Edwards wrap with the wrong sign (a particle leaving through
# the top re-enters with v_x + aL): shear.rate enters the slab's dynamics only
# there, so --solver-set shear.rate=-4 is that wrap; the shear stress turns
# over and the steady -Pxy/nT (E: 0.33) fails
gdsmc_add_cli_test(cli_verify_as_slab_wrong_wrap 1
                   "\nFAIL  as-slab ihs \\(3\\.5\\) -Pxy/nT = -0\\.3"
                   verify --suite quick --case as-slab --solver-set shear.rate=-4
                   --out ${CMAKE_CURRENT_BINARY_DIR}/as-slab-wrong-wrap)
set_tests_properties(cli_verify_as_slab_wrong_wrap PROPERTIES LABELS verification)
gdsmc_add_cli_test(cli_verify_unknown_case 2 "unknown case 'grw-ex9'" verify --case grw-ex9)
# at t = 0: T_exact = 1, E T_n = 1 - 1/n = 63/64, E T_raw = 1
gdsmc_add_cli_test(cli_reference_ex3 0 "\nt,T_exact,T_finite_n,T_raw_finite_n\n0,1,0\\.984375,1\n0\\.1,1\\.12042752"
                   reference ${S}/grw-ex3.ini)
# 81 rows from t = 0 (T near 1: n = 8, N = 20, ci 0.21) to t = 8
gdsmc_add_cli_test(cli_run_small 0
                   "\nt,T,T_ci,T_raw,T_raw_ci,ux,ux_ci[^\n]*\n0,(0\\.[6-9]|1\\.[0-3])[0-9]*,.*\n8,[^\n]*\n$"
                   run ${S}/grw-ex3.ini --set particles.n=8 --set particles.ensembles=20
                   --quiet)
# The solver protocol's result file (verify/protocol/result.h): the header lines, every
# observable with its sample variance, one row per output time (t = 0, 4, 8),
# full precision, and nothing on standard output.
gdsmc_add_cli_test(cli_run_result 0
                   "^# gdsmc-result 1\n# solver = gdsmc [0-9.]+ \\(built-in engine\\)\n# n = 8\n# ensembles = 20\n# cpu_seconds = [0-9.e+-]+\n# events = [1-9][0-9]*\n# violations = 0\nt,T,T_var,T_raw,T_raw_var,ux,ux_var,[^\n]*,a2,a2_var,a3,a3_var\n0,[01]\\.[0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][^\n]*\n4,[^\n]*\n8,[^\n]*\n$"
                   run ${S}/grw-ex3.ini --set particles.n=8 --set particles.ensembles=20
                   --set scene.outputs=3 --set scene.observation=sampled --result /dev/stdout
                   --quiet)

# Byte-identical output for 1 and 2 threads (hard spheres with heating: the
# majorant, fictitious collisions and Brownian catch-ups all take part).
add_test(NAME cli_threads_identical
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc>
                 -DSCENE=${PROJECT_SOURCE_DIR}/${S}/grw-ex5.ini
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/threads -P ${CMAKE_CURRENT_SOURCE_DIR}/run_threads.cmake)
set_tests_properties(cli_threads_identical PROPERTIES TIMEOUT 120 LABELS unit)

# Every report file starts with its provenance, the committed reports/paper
# included (tests/run_provenance.cmake).
add_test(NAME cli_reports_provenance
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DVERSION=${PROJECT_VERSION}
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/provenance
                 -DPAPER=${PROJECT_SOURCE_DIR}/reports/paper
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/run_provenance.cmake)
set_tests_properties(cli_reports_provenance PROPERTIES TIMEOUT 300 LABELS regression)

# The built-in engine through the solver protocol gives the built-in run's
# verdicts and tables (tests/run_solver_conformance.cmake).
find_program(PYTHON3 python3)
add_test(NAME cli_solver_conformance
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DPYTHON=${PYTHON3}
                 -DCOMPARE=${PROJECT_SOURCE_DIR}/tools/compare-reports
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/conformance
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/run_solver_conformance.cmake)
set_tests_properties(cli_solver_conformance PROPERTIES TIMEOUT 300 LABELS regression
                     WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})

# gdsmc sonine (docs/theory.md §13): paper C's Sonine values as CSV name,value.  Bad
# input: the message and nothing else (anchored: standard output comes first).
gdsmc_add_cli_test(cli_sonine_help 0 "usage: gdsmc sonine --alpha A" sonine --help)
gdsmc_add_cli_test(cli_sonine_mu4_0 0 "name,value.*mu4_0,10\\.9248886721"
                   sonine --alpha 0.2)
gdsmc_add_cli_test(cli_sonine_tails 0 "A_white_noise,1\\.98767.*A_gaussian,4\\.41153"
                   sonine --alpha 0.4)
# paper D at alpha = 0.5 (docs/theory.md §14.1: 1.31870, 1.90108) and the exact elastic value
gdsmc_add_cli_test(cli_sonine_kappa 0
                   "kappa_over_kappa0,1\\.90108.*kappa_prime_over_kappa0,1\\.31870.*kappa_elastic_exact,1\\.025218"
                   sonine --alpha 0.5)
# --steady: paper D's steady averages as name,mean,ci (T stays T0 = 1/2 exactly)
gdsmc_add_cli_test(cli_run_steady 0
                   "name,mean,ci\nT,0\\.5,[^\n]*\n.*\nkappa_prime,[01]\\.[0-9]+,.*\nb1_x_outer,.*\ng1_0,.*\nbeta1_49,"
                   run ${S}/msg.ini --set particles.n=2000 --set particles.ensembles=2
                   --set scene.t_end=3 --set scene.outputs=7 --set steady.from=1
                   --set heat-flux.strength=0.2 --quiet --steady /dev/stdout)
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
gdsmc_add_cli_test(cli_bench_small 0 "\\| hs-relax \\| 1000 \\|.*\\| as-slab \\| 10000 \\|"
                   bench --max-n 1000 --seconds 0.05)
gdsmc_add_cli_test(cli_bench_bad_n 2 "--max-n '10': allowed 1000 <= N" bench --max-n 10)
# found by the fuzzer: a huge output count used to be accepted (and scanned)
gdsmc_add_cli_test(cli_outputs_too_many 2
                   "scene.outputs: '20000000' is out of range \\(allowed 2 <= outputs <= 10000000\\)"
                   run ${S}/grw-ex3.ini --set scene.outputs=20000000)

# Nothing lost (issue 5): interrupted twice (deterministically, after one
# finished simulation each time) and resumed, a case's tables come out as an
# uninterrupted run's, timings aside.
add_test(NAME cli_verify_resume
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DCASE=grw-ex4 -DRC=0
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/resume -P ${CMAKE_CURRENT_SOURCE_DIR}/run_resume.cmake)
set_tests_properties(cli_verify_resume PROPERTIES TIMEOUT 300 LABELS regression)
foreach(sig INT TERM)
  add_test(NAME cli_verify_sig${sig}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DSIG=${sig}
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/signal-${sig}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/run_signal.cmake)
  set_tests_properties(cli_verify_sig${sig} PROPERTIES TIMEOUT 60 LABELS unit)
endforeach()

# Sizes that cannot fit are refused before anything is allocated, with the
# estimate in the message (n x bytes per particle per thread).
gdsmc_add_cli_test(cli_memory_refused_statistics 2
                   "N = 1000000 ensembles and 10000000 outputs need about [0-9.e+]+ GB at once"
                   run ${S}/grw-ex3.ini --set particles.n=100 --set particles.ensembles=1000000
                   --set scene.outputs=10000000)

# ---- Every error path a user can reach, with its exact message (issue 5) ----
# gdsmc_add_cli_exact(NAME CODE MESSAGE ARGS...): the whole output, standard
# output and standard error together, must be MESSAGE and its newline: the
# message is escaped into an anchored regular expression here, so it is
# written as gdsmc prints it.  Scene-level messages (parser, engine,
# references) are tested exactly in tests/test_scene.c; these check the same
# paths end to end (prefix, file, exit code 2, nothing on standard output).
function(gdsmc_add_cli_exact name code message)
  string(REGEX REPLACE "([][\\.*+?^$()|])" "\\\\\\1" re "${message}")
  gdsmc_add_cli_test(${name} ${code} "^${re}[^!-~]*$" ${ARGN})
endfunction()

# The command line itself (verify/cli/cli.c)
gdsmc_add_cli_test(cli_x_no_command 2
                   "^usage: gdsmc COMMAND \\[OPTIONS\\].*exit status: 0 success, 1 a verification check failed, 2 bad input or error\\.[^!-~]*$"
                   "")
gdsmc_add_cli_exact(cli_x_unknown_command 2
                    "gdsmc: unknown command 'frobnicate' (allowed run, reference, verify, sonine, bench, check-result; see gdsmc --help)"
                    frobnicate)
gdsmc_add_cli_exact(cli_x_run_unknown_option 2
                    "gdsmc run: unknown option '--fast' (see gdsmc run --help)"
                    run ${S}/grw-ex3.ini --fast)
gdsmc_add_cli_exact(cli_x_run_solver_set 2
                    "gdsmc run: unknown option '--solver-set' (see gdsmc run --help)"
                    run ${S}/grw-ex3.ini --solver-set collisions.restitution=0.45)
gdsmc_add_cli_exact(cli_x_run_unexpected_argument 2
                    "gdsmc run: unexpected argument 'extra.ini' (see gdsmc run --help)"
                    run ${S}/grw-ex3.ini extra.ini)
gdsmc_add_cli_exact(cli_x_run_missing_scene 2
                    "gdsmc run: missing SCENE file (see gdsmc run --help)" run --quiet)
gdsmc_add_cli_exact(cli_x_run_set_needs_value 2
                    "gdsmc run: option '--set' needs a value (see gdsmc run --help)"
                    run ${S}/grw-ex3.ini --set)
gdsmc_add_cli_exact(cli_x_run_out_needs_value 2
                    "gdsmc run: option '--out' needs a value (see gdsmc run --help)"
                    run ${S}/grw-ex3.ini --out)
# at most 64 --set options: 64 run, 65 are refused
set(sets62)
foreach(i RANGE 1 62)
  list(APPEND sets62 --set scene.seed=${i})
endforeach()
gdsmc_add_cli_test(cli_x_run_64_sets 0 "^# gdsmc [^ ]+ run verify/cases/scenes/grw-ex3\\.ini: seed 62, n = 8, N = 2,"
                   run ${S}/grw-ex3.ini ${sets62} --set particles.n=8 --set particles.ensembles=2
                   --quiet)
gdsmc_add_cli_exact(cli_x_run_65_sets 2
                    "gdsmc run: more than 64 --set options (see gdsmc run --help)"
                    run ${S}/grw-ex3.ini ${sets62} --set particles.n=8 --set particles.ensembles=2
                    --set scene.outputs=3)
# scene files (verify/protocol/scene_ini.c)
gdsmc_add_cli_exact(cli_x_run_missing_file 2
                    "gdsmc run: no/such.ini: cannot open: No such file or directory"
                    run no/such.ini)
gdsmc_add_cli_exact(cli_x_run_directory 2 "gdsmc run: tests: cannot read: Is a directory"
                    run tests)
gdsmc_add_cli_exact(cli_x_run_restitution 2
                    "gdsmc run: tests/scenes/restitution-1.7.ini:6: collisions.restitution: '1.7' is out of range (allowed 0 < restitution <= 1)"
                    run ${B}/restitution-1.7.ini)
gdsmc_add_cli_exact(cli_x_run_unknown_key 2
                    "gdsmc run: tests/scenes/unknown-key.ini:5: collisions.speed: unknown key (allowed kernel, exponent, constant, rate, restitution, model, beta, rule)"
                    run ${B}/unknown-key.ini)
gdsmc_add_cli_exact(cli_x_run_negative_temperature 2
                    "gdsmc run: --set particles.temperature=-2: particles.temperature: '-2' is out of range (allowed temperature > 0)"
                    run ${S}/grw-ex3.ini --set particles.temperature=-2)
gdsmc_add_cli_exact(cli_x_run_n_zero 2
                    "gdsmc run: --set particles.n=0: particles.n: '0' is out of range (allowed 2 <= n <= 1000000000)"
                    run ${S}/grw-ex3.ini --set particles.n=0)
# n = 1e13 (issue 5): refused by the key's range before anything is estimated
gdsmc_add_cli_exact(cli_x_run_n_1e13 2
                    "gdsmc run: --set particles.n=10000000000000: particles.n: '10000000000000' is out of range (allowed 2 <= n <= 1000000000)"
                    run ${S}/grw-ex3.ini --set particles.n=10000000000000)
gdsmc_add_cli_exact(cli_x_run_n_1e13_text 2
                    "gdsmc run: --set particles.n=1e13: particles.n: '1e13' is not a whole number (allowed 2 <= n <= 1000000000)"
                    run ${S}/grw-ex3.ini --set particles.n=1e13)
gdsmc_add_cli_exact(cli_x_run_bad_override 2
                    "gdsmc run: --set particles.n: expected section.key=value (no '=')"
                    run ${S}/grw-ex3.ini --set particles.n)
# valid scenes the engine refuses (sim/engine.c, sim/effect_*.c)
gdsmc_add_cli_exact(cli_x_run_shear 2
                    "gdsmc run: tests/scenes/shear.ini:10: shear.boundary: lees-edwards needs scheme = timestep (the jump scheme keeps no positions)"
                    run ${B}/shear.ini)
gdsmc_add_cli_exact(cli_x_run_steady_without 2
                    "gdsmc run: --steady s.csv: verify/cases/scenes/grw-ex3.ini has no [steady] section (steady averages need one: from, bins, c_max, pairs)"
                    run ${S}/grw-ex3.ini --steady s.csv)
gdsmc_add_cli_exact(cli_x_run_heat_flux 2
                    "gdsmc run: verify/cases/scenes/grw-ex3.ini:10: scene.scheme: the heat-flux force couples the particles (through the mean and the temperature) and needs scheme = timestep"
                    run ${S}/grw-ex3.ini --set heat-flux.strength=0.025
                    --set scene.observation=sampled)
gdsmc_add_cli_exact(cli_x_run_ehs 2
                    "gdsmc run: verify/cases/scenes/grw-ex3.ini: --set collisions.model: ehs (its drag depends on the temperature) needs scheme = timestep, or [shear] alone beside it"
                    run ${S}/grw-ex3.ini --set collisions.model=ehs)
gdsmc_add_cli_exact(cli_x_run_heat_flux_heating 2
                    "gdsmc run: verify/cases/scenes/ms-gaussian.ini:50: heating.type: heat-flux carries its own thermostat (paper D Eq. 4.2); remove [heating]"
                    run ${S}/ms-gaussian.ini --set heat-flux.strength=0.025)
gdsmc_add_cli_exact(cli_x_run_non_gaussian_jump 2
                    "gdsmc run: verify/cases/scenes/grw-ex5.ini: --set heating.type: non-gaussian heating needs scene.scheme = timestep (the jump scheme supports white-noise and gaussian)"
                    run ${S}/grw-ex5.ini --set heating.type=non-gaussian)
gdsmc_add_cli_exact(cli_x_run_too_many_steps 2
                    "gdsmc run: verify/cases/scenes/grw-ex5.ini: --set scene.dt: 1e-300 gives 5e+298 steps between output times (allowed at most 1e12)"
                    run ${S}/grw-ex5.ini --set scene.scheme=timestep --set scene.dt=1e-300)
gdsmc_add_cli_exact(cli_x_run_background_timestep 2
                    "gdsmc run: verify/cases/scenes/brs-ex4.ini: background: the background is not implemented in the time-step scheme (supported: jump)"
                    run ${S}/brs-ex4.ini --set scene.scheme=timestep --set scene.dt=0.1)
gdsmc_add_cli_exact(cli_x_run_two_species 2
                    "gdsmc run: verify/cases/scenes/brs-ex1.ini: --set particles.mass2: the engine simulates one species: mass2 = 2 must equal mass1 = 1"
                    run ${S}/brs-ex1.ini --set particles.mass2=2)
# sizes that cannot fit (sim/ensemble.c): the whole message, the machine's numbers aside
gdsmc_add_cli_test(cli_x_run_memory_refused 2
                   "^gdsmc run: verify/cases/scenes/grw-ex3\\.ini: --set particles\\.n: n = 1000000000 particles per ensemble on [0-9]+ threads, N = 2 ensembles and 81 outputs need about [0-9.]+ GB at once, more than the [0-9.]+ GB of memory this machine has[^!-~]*$"
                   run ${S}/grw-ex3.ini --set particles.n=1000000000 --set particles.ensembles=2
                   --quiet)
# an unwritable --out is refused before the work (here hours of it: found only
# afterwards, the test would time out)
gdsmc_add_cli_exact(cli_x_run_out_unwritable 2
                    "gdsmc run: /nonexistent/gdsmc/x.csv: cannot write: No such file or directory"
                    run ${S}/grw-ex3.ini --set particles.n=4096 --set scene.t_end=1e6 --quiet
                    --out /nonexistent/gdsmc/x.csv)
# gdsmc reference (verify/driver/scene_refs.c)
gdsmc_add_cli_exact(cli_x_reference_missing_scene 2
                    "gdsmc reference: missing SCENE file (see gdsmc reference --help)" reference)
gdsmc_add_cli_exact(cli_x_reference_unknown_option 2
                    "gdsmc reference: unknown option '--quick' (see gdsmc reference --help)"
                    reference ${S}/grw-ex3.ini --quick)
gdsmc_add_cli_exact(cli_x_reference_no_collisions 2
                    "gdsmc reference: tests/scenes/no-collisions.ini: collisions: no reference applies: paper A references need [collisions]"
                    reference ${B}/no-collisions.ini)
gdsmc_add_cli_exact(cli_x_reference_gaussian 2
                    "gdsmc reference: verify/cases/scenes/grw-ex3.ini: --set heating.type: paper A references need white-noise heating"
                    reference ${S}/grw-ex3.ini --set heating.type=gaussian
                    --set scene.observation=sampled)
gdsmc_add_cli_exact(cli_x_reference_drift 2
                    "gdsmc reference: verify/cases/scenes/grw-ex3.ini: --set particles.velocity: paper A references need an initial Maxwellian at rest (allowed 0 0 0)"
                    reference ${S}/grw-ex3.ini "--set" "particles.velocity=0 1 0")
gdsmc_add_cli_exact(cli_x_reference_mass 2
                    "gdsmc reference: verify/cases/scenes/grw-ex3.ini: --set particles.mass: paper A references are for unit mass (got 2)"
                    reference ${S}/grw-ex3.ini --set particles.mass=2)
gdsmc_add_cli_exact(cli_x_reference_vhs 2
                    "gdsmc reference: verify/cases/scenes/grw-ex3.ini: --set collisions.exponent: no reference for VHS lambda = 0.5 (only 0 and 1)"
                    reference ${S}/grw-ex3.ini --set collisions.kernel=vhs --set collisions.exponent=0.5)
# paper E: the BGK model's T and stresses; late times reach its steady state
# (alpha = 0.9, a tau0 = 4: T_s/T0 = 150.3, T_s = 75.15)
gdsmc_add_cli_test(cli_reference_bgk 0
                   "\nt,T_bgk,Pxx_bgk,Pyy_bgk,Pzz_bgk,Pxy_bgk,s0_bgk\n0,0\\.5,0\\.5,0\\.5,0\\.5,0,0\n.*\n40,75\\.15[0-9]*,"
                   reference ${S}/as.ini --set scene.t_end=40 --set scene.outputs=11
                   --set steady.from=0)
gdsmc_add_cli_exact(cli_x_reference_shear 2
                    "gdsmc reference: verify/cases/scenes/grw-ex3.ini:28: collisions.kernel: the BGK reference of paper E needs hard spheres"
                    reference ${S}/grw-ex3.ini --set shear.rate=1 --set scene.observation=sampled)
gdsmc_add_cli_exact(cli_x_reference_background_heating 2
                    "gdsmc reference: verify/cases/scenes/brs-ex1.ini: background: no reference for a background combined with heating, shear or a heat-flux force"
                    reference ${S}/brs-ex1.ini --set heating.strength=1)
gdsmc_add_cli_exact(cli_x_reference_kernels 2
                    "gdsmc reference: verify/cases/scenes/brs-ex1.ini: --set collisions.kernel: paper B references need the same kernel for binary and background collisions (background.kernel is maxwell)"
                    reference ${S}/brs-ex1.ini --set collisions.kernel=hard-spheres)
# a closure CVODE cannot integrate: which reference, the flag, SUNDIALS' reason
gdsmc_add_cli_test(cli_x_reference_cvode_failure 2
                   "^gdsmc reference: verify/cases/scenes/grw-ex5\\.ini: T_maxwell_closure: CVODE failed at t = 0: CV_[A-Z_]+ \\(CVODE in CVode: .*$"
                   reference ${S}/grw-ex5.ini --set scene.t_end=1e300)
gdsmc_add_cli_exact(cli_x_reference_out_unwritable 2
                    "gdsmc reference: /nonexistent/gdsmc/r.csv: cannot write: No such file or directory"
                    reference ${S}/grw-ex3.ini --out /nonexistent/gdsmc/r.csv)
# gdsmc sonine
gdsmc_add_cli_exact(cli_x_sonine_unexpected_argument 2
                    "gdsmc sonine: unexpected argument '0.2' (see gdsmc sonine --help)"
                    sonine 0.2)
gdsmc_add_cli_exact(cli_x_sonine_alpha_overflow 2
                    "gdsmc sonine: --alpha: '1e999' is not a number (see gdsmc sonine --help)"
                    sonine --alpha 1e999)
gdsmc_add_cli_exact(cli_x_sonine_d_text 2
                    "gdsmc sonine: --d: 'three' is not a number (see gdsmc sonine --help)"
                    sonine --alpha 0.2 --d three)
gdsmc_add_cli_exact(cli_x_sonine_d_above 2
                    "gdsmc sonine: --d: '101' is out of range (allowed 2 <= d <= 100)"
                    sonine --alpha 0.2 --d 101)
gdsmc_add_cli_exact(cli_x_sonine_out_needs_value 2
                    "gdsmc sonine: option '--out' needs a value (see gdsmc sonine --help)"
                    sonine --alpha 0.2 --out)
gdsmc_add_cli_exact(cli_x_sonine_out_unwritable 2
                    "gdsmc sonine: /nonexistent/gdsmc/s.csv: cannot write: No such file or directory"
                    sonine --alpha 0.2 --out /nonexistent/gdsmc/s.csv)
# gdsmc bench
gdsmc_add_cli_exact(cli_x_bench_unknown_argument 2
                    "gdsmc bench: unknown option '--quick' (see gdsmc bench --help)"
                    bench --quick)
gdsmc_add_cli_exact(cli_x_bench_needs_value 2
                    "gdsmc bench: option '--seconds' needs a value (see gdsmc bench --help)"
                    bench --seconds)
gdsmc_add_cli_exact(cli_x_bench_max_n_text 2
                    "gdsmc bench: --max-n '1e4x': allowed 1000 <= N <= 1e9 (see gdsmc bench --help)"
                    bench --max-n 1e4x)
gdsmc_add_cli_exact(cli_x_bench_max_n_above 2
                    "gdsmc bench: --max-n '2e9': allowed 1000 <= N <= 1e9 (see gdsmc bench --help)"
                    bench --max-n 2e9)
gdsmc_add_cli_exact(cli_x_bench_seconds_zero 2
                    "gdsmc bench: --seconds '0': allowed 0 < S <= 3600 (see gdsmc bench --help)"
                    bench --seconds 0)
gdsmc_add_cli_exact(cli_x_bench_seconds_text 2
                    "gdsmc bench: --seconds 'nan': allowed 0 < S <= 3600 (see gdsmc bench --help)"
                    bench --seconds nan)
gdsmc_add_cli_exact(cli_x_bench_seconds_above 2
                    "gdsmc bench: --seconds '3601': allowed 0 < S <= 3600 (see gdsmc bench --help)"
                    bench --seconds 3601)
# refused before the measurements (an hour of them with --seconds 3600)
gdsmc_add_cli_exact(cli_x_bench_out_unwritable 2
                    "gdsmc bench: /nonexistent/gdsmc/b.csv: cannot write: No such file or directory"
                    bench --max-n 1000 --seconds 3600 --out /nonexistent/gdsmc/b.csv)
gdsmc_add_cli_exact(cli_x_bench_md_unwritable 2
                    "gdsmc bench: /nonexistent/gdsmc/b.md: cannot write: No such file or directory"
                    bench --max-n 1000 --seconds 3600 --md /nonexistent/gdsmc/b.md)
# gdsmc verify (verify/cli/cli.c, verify/driver/cases.c)
gdsmc_add_cli_test(cli_x_verify_solver_set_out_of_range 2
                   "[^!-~]gdsmc verify: --solver-set collisions\\.restitution=1\\.7: collisions\\.restitution: '1\\.7' is out of range \\(allowed 0 < restitution <= 1\\)[^!-~]*$"
                   verify --case grw-ex3 --suite quick --out build/tests/solver-set
                   --solver-set collisions.restitution=1.7)
gdsmc_add_cli_test(cli_x_verify_unknown_suite 2
                   "^gdsmc verify: unknown suite 'fast' \\(allowed quick, paper, grw, brs[a-z, -]*\\) \\(see gdsmc verify --help\\)[^!-~]*$"
                   verify --suite fast)
gdsmc_add_cli_exact(cli_x_verify_unknown_case 2
                    "gdsmc verify: unknown case 'grw-ex9' (gdsmc verify --list shows them) (see gdsmc verify --help)"
                    verify --case grw-ex9)
gdsmc_add_cli_exact(cli_x_verify_unknown_option 2
                    "gdsmc verify: unknown option '--scene' (see gdsmc verify --help)"
                    verify --scene ${S})
gdsmc_add_cli_exact(cli_x_verify_unexpected_argument 2
                    "gdsmc verify: unexpected argument 'grw-ex3' (see gdsmc verify --help)"
                    verify grw-ex3)
gdsmc_add_cli_exact(cli_x_verify_case_needs_value 2
                    "gdsmc verify: option '--case' needs a value (see gdsmc verify --help)"
                    verify --case)
set(solver_sets65)
foreach(i RANGE 0 64)
  list(APPEND solver_sets65 --solver-set scene.seed=${i})
endforeach()
gdsmc_add_cli_exact(cli_x_verify_65_solver_sets 2
                    "gdsmc verify: more than 64 --solver-set options (see gdsmc verify --help)"
                    verify --case grw-ex3 ${solver_sets65})
gdsmc_add_cli_exact(cli_x_verify_bad_set 2
                    "gdsmc verify: --set collisions.restitution=1.7: collisions.restitution: '1.7' is out of range (allowed 0 < restitution <= 1)"
                    verify --case grw-ex3 --suite quick --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/verify-bad-set
                    --set collisions.restitution=1.7)
gdsmc_add_cli_exact(cli_x_verify_scenes_missing 2
                    "gdsmc verify: /nonexistent/gdsmc/grw-ex3.ini: cannot open: No such file or directory"
                    verify --case grw-ex3 --suite quick --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/verify-no-scenes
                    --scenes /nonexistent/gdsmc)
gdsmc_add_cli_exact(cli_x_verify_out_under_file 2
                    "gdsmc verify: tests/scenes/unknown-key.ini/reports: cannot create the report directory: Not a directory"
                    verify --case grw-ex3 --suite quick --quiet --out ${B}/unknown-key.ini/reports)
# an existing file is not a report directory (refused before the first simulation)
gdsmc_add_cli_exact(cli_x_verify_out_is_file 2
                    "gdsmc verify: tests/scenes/unknown-key.ini: cannot create the report directory: Not a directory"
                    verify --case grw-ex3 --suite quick --quiet --out ${B}/unknown-key.ini)
# a case's own requirements on its scene (tests/scenes/cases/), before any simulation
gdsmc_add_cli_exact(cli_x_verify_split_needs_steady 2
                    "gdsmc verify: tests/scenes/cases/split-ex5.ini: the splitting case needs [steady] and scheme = timestep (needs [steady])"
                    verify --case split-ex5 --suite quick --quiet --scenes ${B}/cases
                    --out ${CMAKE_CURRENT_BINARY_DIR}/verify-cases)
gdsmc_add_cli_exact(cli_x_verify_ms_needs_steady 2
                    "gdsmc verify: tests/scenes/cases/ms-white-noise.ini: paper C's cases need [steady] and scheme = timestep (needs scene.scheme=timestep)"
                    verify --case ms-a2-white-noise --suite quick --quiet --scenes ${B}/cases
                    --out ${CMAKE_CURRENT_BINARY_DIR}/verify-cases)
# --set collisions.kernel=hard-spheres leaves paper A's cases without their
# exact references: refused before simulating (they reported FAIL, Emax = inf)
gdsmc_add_cli_exact(cli_x_verify_grw_needs_maxwell 2
                    "gdsmc verify: verify/cases/scenes/grw-ex3.ini: the scene has no T_exact T_finite_n T_raw_finite_n references (paper A's exact solution needs collisions.kernel = maxwell)"
                    verify --case grw-ex3 --suite quick --quiet --scenes ${S}
                    --set collisions.kernel=hard-spheres --out build/tests/grw-needs-maxwell)
gdsmc_add_cli_exact(cli_x_verify_vro_needs_maxwell 2
                    "gdsmc verify: verify/cases/scenes/grw-ex3.ini: the scene has no T_finite_n T_raw_finite_n references (paper A's exact solution needs collisions.kernel = maxwell)"
                    verify --case vro-grw-ex3 --suite quick --quiet --scenes ${S}
                    --set collisions.kernel=hard-spheres --out build/tests/grw-needs-maxwell)
gdsmc_add_cli_exact(cli_x_verify_brs_needs_hard_spheres 2
                    "gdsmc verify: tests/scenes/cases/brs-ex4.ini: the scene has no T_le T_grad uy_le uy_grad references (paper B's closures need collisions.kernel = hard-spheres and background.kernel = hard-spheres)"
                    verify --case brs-ex4 --suite quick --quiet --scenes ${B}/cases
                    --out ${CMAKE_CURRENT_BINARY_DIR}/verify-cases)

# No partial output: a failing command leaves no FILE, no FILE.tmp, and an
# existing FILE as it was (tests/run_no_output.cmake).
# gdsmc_add_no_output_test(NAME CODE REGEX OUT [PRE text] [OUT_IS_DIR 1]
#                          [SIGNAL SIG AFTER S] [STDOUT_FILE path] ARGS ...)
function(gdsmc_add_no_output_test name code regex out)
  cmake_parse_arguments(T "" "PRE;OUT_IS_DIR;SIGNAL;AFTER;STDOUT_FILE" "ARGS" ${ARGN})
  set(extra)
  foreach(opt PRE OUT_IS_DIR SIGNAL AFTER STDOUT_FILE)
    if(DEFINED T_${opt})
      list(APPEND extra "-D${opt}=${T_${opt}}")
    endif()
  endforeach()
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DCODE=${code}
                   "-DREGEX=${regex}" "-DARGS=${T_ARGS}" "-DOUT=${out}"
                   -DWORKDIR=${PROJECT_SOURCE_DIR} ${extra}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/run_no_output.cmake)
  set_tests_properties(${name} PROPERTIES TIMEOUT 60 LABELS unit ENVIRONMENT OMP_NUM_THREADS=1)
endfunction()
set(NO ${CMAKE_CURRENT_BINARY_DIR}/no-output)
gdsmc_add_no_output_test(cli_no_output_bad_scene 2
    "^gdsmc run: tests/scenes/restitution-1\\.7\\.ini:6: collisions\\.restitution: '1\\.7' is out of range \\(allowed 0 < restitution <= 1\\)[^!-~]*$"
    ${NO}/bad-scene.csv ARGS run ${B}/restitution-1.7.ini --out ${NO}/bad-scene.csv)
gdsmc_add_no_output_test(cli_no_output_bad_scene_keeps_file 2
    "^gdsmc run: tests/scenes/restitution-1\\.7\\.ini:6: collisions\\.restitution: "
    ${NO}/keep.csv PRE "an earlier run's output" ARGS run ${B}/restitution-1.7.ini --out ${NO}/keep.csv)
gdsmc_add_no_output_test(cli_no_output_engine_refused 2
    "^gdsmc run: tests/scenes/shear\\.ini:10: shear\\.boundary: lees-edwards needs scheme = timestep \\(the jump scheme keeps no positions\\)[^!-~]*$"
    ${NO}/shear.csv ARGS run ${B}/shear.ini --out ${NO}/shear.csv)
gdsmc_add_no_output_test(cli_no_output_memory_refused 2
    "^gdsmc run: verify/cases/scenes/grw-ex3\\.ini: --set particles\\.n: n = 100 particles per ensemble on 1 threads, N = 1000000 ensembles and 10000000 outputs need about [0-9.e+]+ GB at once, more than the [0-9.]+ GB of memory this machine has[^!-~]*$"
    ${NO}/memory.csv ARGS run ${S}/grw-ex3.ini --set particles.n=100
    --set particles.ensembles=1000000 --set scene.outputs=10000000 --quiet --out ${NO}/memory.csv)
gdsmc_add_no_output_test(cli_no_output_reference_refused 2
    "^gdsmc reference: tests/scenes/no-collisions\\.ini: collisions: no reference applies: paper A references need \\[collisions\\][^!-~]*$"
    ${NO}/reference.csv ARGS reference ${B}/no-collisions.ini --out ${NO}/reference.csv)
gdsmc_add_no_output_test(cli_no_output_sonine_refused 2
    "^gdsmc sonine: --alpha: '1\\.5' is out of range \\(allowed 0 <= alpha <= 1\\)[^!-~]*$"
    ${NO}/sonine.csv ARGS sonine --alpha 1.5 --out ${NO}/sonine.csv)
# stopped by SIGINT (exit 130): nothing written, an existing file untouched
gdsmc_add_no_output_test(cli_no_output_run_stopped 130
    "^gdsmc run: verify/cases/scenes/grw-ex3\\.ini: stopped on request after [0-9]+ of 10000 ensembles; nothing written[^!-~]*$"
    ${NO}/stopped.csv SIGNAL INT AFTER 2
    ARGS run ${S}/grw-ex3.ini --set particles.n=4096 --quiet --out ${NO}/stopped.csv)
gdsmc_add_no_output_test(cli_no_output_run_stopped_keeps_file 130
    "^gdsmc run: verify/cases/scenes/grw-ex3\\.ini: stopped on request after [0-9]+ of 10000 ensembles; nothing written[^!-~]*$"
    ${NO}/stopped-keep.csv PRE "an earlier run's output" SIGNAL TERM AFTER 2
    ARGS run ${S}/grw-ex3.ini --set particles.n=4096 --quiet --out ${NO}/stopped-keep.csv)
# FILE is a directory (the final rename would fail): refused before the work,
# and no FILE.tmp stays behind
gdsmc_add_no_output_test(cli_no_output_out_is_directory 2
    "^gdsmc run: [^ ]*/no-output/dir\\.csv: cannot write: Is a directory[^!-~]*$"
    ${NO}/dir.csv OUT_IS_DIR 1
    ARGS run ${S}/grw-ex3.ini --set particles.n=8 --set particles.ensembles=2 --quiet
    --out ${NO}/dir.csv)
# standard output that cannot be written: exit 2 with a message, not silently
gdsmc_add_no_output_test(cli_no_output_stdout_full 2
    "^gdsmc run: standard output: cannot write: No space left on device[^!-~]*$"
    ${NO}/stdout-full.csv STDOUT_FILE /dev/full
    ARGS run ${S}/grw-ex3.ini --set particles.n=8 --set particles.ensembles=2 --quiet)
gdsmc_add_no_output_test(cli_no_output_sonine_stdout_full 2
    "^gdsmc sonine: standard output: cannot write: No space left on device[^!-~]*$"
    ${NO}/sonine-full.csv STDOUT_FILE /dev/full ARGS sonine --alpha 0.2)

# --out naming a device or pipe writes in place: renaming a FILE.tmp over it
# would replace the device node (as root) with a plain file.
gdsmc_add_cli_test(cli_out_device 0 "^# gdsmc [^\n]*sonine[^\n]*\nname,value\nbeta_1,"
                   sonine --alpha 0.3 --out /dev/stdout)
# a FIFO is written in place too, and is never opened before the results are
# ready (opening and closing it early would end its reader's input)
add_test(NAME cli_out_fifo
         COMMAND sh -c "rm -f fifo.csv got.csv && mkfifo fifo.csv && { cat fifo.csv > got.csv & } && \"$0\" run \"$1\" --set particles.n=8 --set particles.ensembles=2 --quiet --out fifo.csv && wait && grep -c '^[0-9]' got.csv | grep -qx 81"
                 $<TARGET_FILE:gdsmc> ${PROJECT_SOURCE_DIR}/${S}/grw-ex3.ini
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(cli_out_fifo PROPERTIES TIMEOUT 60 LABELS unit)

# A bad external solver (issue 14): exit 2, a message naming the command or
# the result's file and line, nothing on standard output and no table.
set(SB ${CMAKE_CURRENT_BINARY_DIR}/solver-bad)
gdsmc_add_no_output_test(cli_solver_not_found 2
    "^gdsmc verify: grw-ex4 n=64: the solver cannot be started: 'nosuch-solver': No such file or directory \\(--solver 'nosuch-solver {scene} {out}'\\)\n$"
    ${SB}-not_found/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-not_found
    --solver "nosuch-solver {scene} {out}")
gdsmc_add_no_output_test(cli_solver_exit_status 2
    "^gdsmc verify: grw-ex4 n=64: the solver exited with status 4 \\(--solver 'sh -c \"echo boom >&2 && exit 4\" {scene} {out}'\\); the last lines of its output \\([^\n]*/\\.solver/[0-9a-f]+\\.err\\):\n    boom\n$"
    ${SB}-exit_status/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-exit_status
    --solver "sh -c \"echo boom >&2 && exit 4\" {scene} {out}")
# Exit status 3 is a refusal only with its reason on standard error.
gdsmc_add_no_output_test(cli_solver_refusal_without_reason 2
    "^gdsmc verify: grw-ex4 n=64: the solver exited with status 3, a refusal, but gave no reason as the last line of its standard error [^\n]*/\\.solver/[0-9a-f]+\\.err \\(--solver 'sh -c \"echo out && exit 3\" {scene} {out}'\\)\n$"
    ${SB}-refusal_without_reason/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet
    --out ${SB}-refusal_without_reason --solver "sh -c \"echo out && exit 3\" {scene} {out}")
gdsmc_add_no_output_test(cli_solver_timeout 2
    "^gdsmc verify: grw-ex4 n=64: the solver took more than 0.5 s \\(--solver-timeout\\) and was killed \\(--solver 'sh -c \"sleep 30\" {scene} {out}'\\)\n$"
    ${SB}-timeout/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-timeout
    --solver "sh -c \"sleep 30\" {scene} {out}" --solver-timeout 0.5)
gdsmc_add_no_output_test(cli_solver_no_result 2
    "^gdsmc verify: grw-ex4 n=64: the solver exited with status 0 but wrote no result [^\n]*/\\.solver/[0-9a-f]+\\.result \\(--solver 'true {scene} {out}'\\)\n$"
    ${SB}-no_result/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-no_result
    --solver "true {scene} {out}")
gdsmc_add_no_output_test(cli_solver_bad_result 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:1: the first line must be '# gdsmc-result 1' \\(the protocol version\\), got '\\[scene\\]'\n$"
    ${SB}-bad_result/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-bad_result
    --solver "cp {scene} {out}")
gdsmc_add_cli_exact(cli_x_verify_solver_timeout_bad 2
                    "gdsmc verify: --solver-timeout 'soon': allowed 0 < S <= 1e6 seconds (see gdsmc verify --help)"
                    verify --case grw-ex4 --solver "true {scene} {out}" --solver-timeout soon)
gdsmc_add_cli_exact(cli_x_verify_solver_quote 2
                    "gdsmc verify: --solver 'sh -c 'echo': an unterminated single quote (see gdsmc verify --help)"
                    verify --case grw-ex4 --solver "sh -c 'echo")
gdsmc_add_cli_exact(cli_x_verify_solver_no_out 2
                    "gdsmc verify: --solver 'true {scene}': no {out}: the command must name where the result goes ({out}) (see gdsmc verify --help)"
                    verify --case grw-ex4 --solver "true {scene}")
gdsmc_add_cli_exact(cli_x_verify_solver_no_scene 2
                    "gdsmc verify: --solver 'true {out}': no {scene}: the command must name where the scene file is ({scene}) (see gdsmc verify --help)"
                    verify --case grw-ex4 --solver "true {out}")
gdsmc_add_cli_exact(cli_x_verify_solver_unterminated 2
                    "gdsmc verify: --solver 'true {scene} {out': an unterminated placeholder '{out' (write {out}) (see gdsmc verify --help)"
                    verify --case grw-ex4 --solver "true {scene} {out")

# A refusal is an answer (docs/solver-protocol.md): the whole quick suite
# through a solver that refuses every scene runs to the end, every check that
# needs the solver a SKIP with the reason, the JUnit report written (exit 0:
# nothing failed) ...
add_test(NAME cli_solver_refuses_everything
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DCODE=0 -DPYTHON=${PYTHON3}
                 -DCHECK=${CMAKE_CURRENT_SOURCE_DIR}/check_junit.py
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/solver-refuses-all
                 -DREPORTS=${CMAKE_CURRENT_BINARY_DIR}/solver-refuses-all-reports
                 "-DSUMMARY=verify: [0-9]+ passed, 0 failed, [1-9][0-9]* skipped, [1-9][0-9]* rows refused by the solver"
                 "-DARGS=--suite;quick;--out;${CMAKE_CURRENT_BINARY_DIR}/solver-refuses-all-reports;--solver;sh -c \"echo 'nothing here is implemented' >&2 && exit 3\" {scene} {out}"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/run_junit.cmake)
set_tests_properties(cli_solver_refuses_everything PROPERTIES TIMEOUT 300 LABELS regression
                     WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
# ... and one that refuses white noise: ms-table1's white-noise rows are SKIP
# with its reason (the last line of its standard error), its Gaussian rows
# are judged, and grw-ex3 (white noise) does not stop ms-a2-gaussian.
gdsmc_add_cli_test(cli_solver_refuses_some 0
    "SKIP  grw-ex3 n=64 [^\n]*: solver refused: white-noise heating is not implemented\n.*PASS  ms-a2-gaussian .*SKIP  ms-table1 alpha=0\\.4 white [^\n]*: solver refused: white-noise heating is not implemented\n.*PASS  ms-table1 alpha=0\\.4 gaussian .*\nverify: 11 passed, 0 failed, 15 skipped, 4 rows refused by the solver\n"
    verify --suite quick --case ms-table1,grw-ex3,ms-a2-gaussian
    --out ${CMAKE_CURRENT_BINARY_DIR}/solver-refuses-some
    --solver "sh tests/solvers/refuse_white_noise.sh $<TARGET_FILE:gdsmc> {scene} {out}")
set_tests_properties(cli_solver_refuses_some PROPERTIES TIMEOUT 600 LABELS regression)

# --dry-run: each row's scene as the solver would get it, and what the checks
# read; nothing simulated, no report; not with what needs a simulation.
gdsmc_add_cli_test(cli_verify_dry_run 0
    "== grw-ex3 \\(quick sizes\\): 3 rows, the scenes in [^\n]*/dry-run/grw-ex3/\n   row 1: grw-ex3 n=64 -> [^\n]*/dry-run/grw-ex3/row-01\\.ini\n.*\n       value         T                      reported: an observable, at every output time\n       against       T_finite_n             a reference\n   the checks read directly: T_raw T \\("
    verify --dry-run --suite quick --case grw-ex3 --out ${CMAKE_CURRENT_BINARY_DIR}/dry-run)
set_tests_properties(cli_verify_dry_run PROPERTIES LABELS unit TIMEOUT 60)
gdsmc_add_cli_exact(cli_x_verify_dry_run_resume 2
                    "gdsmc verify: --dry-run simulates nothing: not with --seeds, --power, --must-fail, --resume or --junit (see gdsmc verify --help)"
                    verify --dry-run --case grw-ex3 --resume)

# A solver whose majorant is raised after each step declares the violations
# its algorithm lets through; the violations check holds it to that bound.
gdsmc_add_cli_test(cli_solver_violations_within 0
    "PASS  ms-a2-gaussian alpha=0\\.20 majorant violations: 30 \\(allowed at most 40, declared by the solver's '# violations_allowed'\\)\n"
    verify --suite quick --case ms-a2-gaussian --out ${CMAKE_CURRENT_BINARY_DIR}/solver-violations-40
    --solver "sh tests/solvers/violations.sh $<TARGET_FILE:gdsmc> {scene} {out} 40")
gdsmc_add_cli_test(cli_solver_violations_beyond 1
    "FAIL  ms-a2-gaussian alpha=0\\.20 majorant violations: 30 \\(allowed at most 10, declared by the solver's '# violations_allowed'\\)\n"
    verify --suite quick --case ms-a2-gaussian --out ${CMAKE_CURRENT_BINARY_DIR}/solver-violations-10
    --solver "sh tests/solvers/violations.sh $<TARGET_FILE:gdsmc> {scene} {out} 10")

# --suite protocol: the adapter mechanics in seconds; the engine passes, an
# adapter that writes standard deviations for the sample variances fails.
gdsmc_add_cli_test(cli_verify_protocol 0 "\nverify: 12 passed, 0 failed, 0 skipped\n"
                   verify --suite protocol --out ${CMAKE_CURRENT_BINARY_DIR}/protocol)
gdsmc_add_cli_test(cli_verify_protocol_std_not_var 1
    "FAIL  protocol series T_raw variance at t = 0 vs the initial Maxwellian's: [^\n]*\n.*\nverify: [0-9]+ passed, [1-9][0-9]* failed"
    verify --suite protocol --out ${CMAKE_CURRENT_BINARY_DIR}/protocol-std
    --solver "sh tests/solvers/std_not_var.sh $<TARGET_FILE:gdsmc> {scene} {out}")

# gdsmc check-result SCENE RESULT: a valid result (the engine's own) is
# described, a malformed one refused with its file and line, exit 2.
add_test(NAME cli_check_result_valid
         COMMAND sh -c "\"$0\" run \"$1\" --set particles.n=8 --set particles.ensembles=4 --result check-result.txt --quiet && \"$0\" check-result \"$1\" check-result.txt --set particles.n=8 --set particles.ensembles=4"
                 $<TARGET_FILE:gdsmc> ${PROJECT_SOURCE_DIR}/${S}/grw-ex3.ini
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(cli_check_result_valid PROPERTIES LABELS unit TIMEOUT 60
    PASS_REGULAR_EXPRESSION "^check-result\\.txt: a valid version 1 result for [^\n]*grw-ex3\\.ini: 81 output times, 4 ensembles of 8 particles, 11 of 16 observables, 0 of 0 steady quantities, events, violations\nnot reported \\(checks on them are SKIPs\\): qx qy qz a2 a3\n$")
gdsmc_add_cli_test(cli_check_result_malformed 2
    "^gdsmc check-result: [^\n]*grw-ex3\\.ini:1: the first line must be '# gdsmc-result 1' \\(the protocol version\\), got '; Paper A, Example 3[^\n]*'\n$"
    check-result ${S}/grw-ex3.ini ${S}/grw-ex3.ini)
# '# substituted =' names algorithm keys only (docs/scenes.md)
add_test(NAME cli_check_result_substituted
         COMMAND sh -c "\"$0\" run \"$1\" --set particles.n=8 --set particles.ensembles=4 --result substituted.txt --quiet && sed -i '2a # substituted = scene.scheme, collisions.rule' substituted.txt && \"$0\" check-result \"$1\" substituted.txt --set particles.n=8 --set particles.ensembles=4 && sed -i 's/^# substituted = .*/# substituted = collisions.restitution/' substituted.txt && \"$0\" check-result \"$1\" substituted.txt --set particles.n=8 --set particles.ensembles=4"
                 $<TARGET_FILE:gdsmc> ${PROJECT_SOURCE_DIR}/${S}/grw-ex3.ini
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(cli_check_result_substituted PROPERTIES LABELS unit TIMEOUT 60 WILL_FAIL 0
    PASS_REGULAR_EXPRESSION "violations; substituted scene\\.scheme, collisions\\.rule\n.*gdsmc check-result: substituted\\.txt:3: substituted = 'collisions\\.restitution': collisions\\.restitution is a physics key: a solver must honour it or refuse the scene \\(docs/scenes\\.md\\)\n")
gdsmc_add_cli_exact(cli_x_check_result_no_result 2
                    "gdsmc check-result: missing RESULT file (see gdsmc check-result --help)"
                    check-result ${S}/grw-ex3.ini)

# An independent solver in another language (examples/python, NumPy): paper
# A's Examples 3 and 4 at quick sizes pass through the solver protocol, and
# the same program with a deliberate error (the heating halved) fails the
# gate.  Debian's python3, where python3-numpy installs (make deps).
find_program(DEBIAN_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
set(EXAMPLE "${DEBIAN_PYTHON3} examples/python/heated_maxwell.py {scene} {out}")
foreach(ex grw-ex3 grw-ex4)
  add_test(NAME example_python_${ex}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DCODE=0
                   "-DREGEX=\nverify: [0-9]+ passed, 0 failed"
                   "-DARGS=verify;--suite;quick;--case;${ex};--out;${CMAKE_CURRENT_BINARY_DIR}/example-${ex};--solver;${EXAMPLE}"
                   -DWORKDIR=${PROJECT_SOURCE_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/run_cli.cmake)
  set_tests_properties(example_python_${ex} PROPERTIES TIMEOUT 600 LABELS verification)
endforeach()
add_test(NAME example_python_halved_heating
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DCODE=1
                 "-DREGEX=\nverify: [0-9]+ passed, [1-9][0-9]* failed"
                 "-DARGS=verify;--suite;quick;--case;grw-ex4;--out;${CMAKE_CURRENT_BINARY_DIR}/example-halved;--solver;${EXAMPLE} --halve-heating"
                 -DWORKDIR=${PROJECT_SOURCE_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/run_cli.cmake)
set_tests_properties(example_python_halved_heating PROPERTIES TIMEOUT 600 LABELS verification)

# --junit: the report parses and its counts are the verdicts' (a wrong solver:
# failures and a skip).
add_test(NAME cli_verify_junit
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DCODE=1 -DPYTHON=${PYTHON3}
                 -DCHECK=${CMAKE_CURRENT_SOURCE_DIR}/check_junit.py
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/junit
                 "-DARGS=--suite;quick;--case;grw-ex3;--out;${CMAKE_CURRENT_BINARY_DIR}/junit-reports;--solver-set;collisions.restitution=0.45"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/run_junit.cmake)
set_tests_properties(cli_verify_junit PROPERTIES TIMEOUT 300 LABELS regression
                     WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
# ... and of a run with known differences (brs-ex1's Table 1 Conf: DIFFERS,
# JUnit <skipped> "DIFFERS: ", exit 0), whose verdicts files and index hold the
# same verdicts (docs/verdicts.md).
add_test(NAME cli_verify_junit_differs
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:gdsmc> -DCODE=0 -DPYTHON=${PYTHON3}
                 -DCHECK=${CMAKE_CURRENT_SOURCE_DIR}/check_junit.py
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/junit-differs
                 -DREPORTS=${CMAKE_CURRENT_BINARY_DIR}/junit-differs-reports
                 "-DARGS=--suite;quick;--case;grw-ex3,brs-ex1;--out;${CMAKE_CURRENT_BINARY_DIR}/junit-differs-reports"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/run_junit.cmake)
set_tests_properties(cli_verify_junit_differs PROPERTIES TIMEOUT 300 LABELS regression
                     WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})

# The gate measured (docs/verdicts.md).  Every case catches each error its
# description declares (must_fail), at quick sizes, under the scenes' seeds.
gdsmc_add_cli_test(cli_verify_must_fail 0 "\nmust-fail: 0 declared errors not caught\n"
                   verify --suite quick --must-fail --out ${CMAKE_CURRENT_BINARY_DIR}/must-fail)
set_tests_properties(cli_verify_must_fail PROPERTIES LABELS verification TIMEOUT 1200)
# --perturb, --seeds: bad input exits 2 before any work, naming what is wrong
gdsmc_add_cli_test(cli_verify_perturb_unknown_key 2
                   "--perturb heating.nope: unknown key \\(allowed type, strength, keep_temperature\\)"
                   verify --suite quick --case grw-ex3 --perturb heating.nope=1.1)
gdsmc_add_cli_test(cli_verify_perturb_factor 2
                   "--perturb heating.strength: factor '0' is not a positive number"
                   verify --suite quick --case grw-ex3 --perturb heating.strength=0)
gdsmc_add_cli_test(cli_verify_perturb_not_a_number_key 2
                   "--perturb heating.type: not a number key"
                   verify --suite quick --case grw-ex3 --perturb heating.type=1.1)
gdsmc_add_cli_test(cli_verify_perturb_absent_section 2
                   "--perturb shear.rate=1.1: shear.rate: the scene [^\n]*grw-ex3.ini has no \\[shear\\] section"
                   verify --suite quick --case grw-ex3 --perturb shear.rate=1.1
                   --out ${CMAKE_CURRENT_BINARY_DIR}/perturb-absent)
gdsmc_add_cli_test(cli_verify_perturb_refused_value 2
                   "--perturb: a perturbed value is refused: [^\n]*collisions.restitution"
                   verify --suite quick --case grw-ex3 --perturb collisions.restitution=3
                   --out ${CMAKE_CURRENT_BINARY_DIR}/perturb-refused)
gdsmc_add_cli_test(cli_verify_seeds_too_few 2 "--seeds '1': allowed an integer 2 <= K <= 1000"
                   verify --suite quick --seeds 1)
# --seeds and --power run and say where their tables are (brs-ex1: a second a run)
gdsmc_add_cli_test(cli_verify_seeds 0
                   "seeds: 2 of 2 runs passed whole; 0 checks failed in more than one run \\([^)]*/seeds.md\\)\n.*seeds: run 2 of 2: [0-9]+ passed, 0 failed"
                   verify --suite quick --case brs-ex1 --seeds 2
                   --out ${CMAKE_CURRENT_BINARY_DIR}/seeds)
gdsmc_add_cli_test(cli_verify_power 0
                   "power: [^\n]*/power.md\n.*power: brs-ex1 collisions.constant=1.05: caught under 3 of 3 seeds\n"
                   verify --suite quick --case brs-ex1 --power --out ${CMAKE_CURRENT_BINARY_DIR}/power)
set_tests_properties(cli_verify_seeds cli_verify_power PROPERTIES LABELS verification
                     TIMEOUT 600)
# a 5% too strong heating fails grw-ex3 (its must_fail)
gdsmc_add_cli_test(cli_verify_perturb_caught 1
                   "\nFAIL  grw-ex3 n=64 T_raw vs exact finite-n expectation: .*\nverify: [0-9]+ passed, [1-9][0-9]* failed"
                   verify --suite quick --case grw-ex3 --perturb heating.strength=1.05
                   --out ${CMAKE_CURRENT_BINARY_DIR}/perturb-caught)
set_tests_properties(cli_verify_perturb_caught PROPERTIES LABELS verification)

# What a solver does not report is a SKIP saying so, never a PASS; a check
# that models the built-in engine's own streams is a SKIP for any other.
gdsmc_add_cli_test(cli_solver_not_reported 0
    "PASS  grw-ex4 n=64 T_raw vs exact finite-n expectation[^\n]*\nSKIP  grw-ex4 n=64 T vs exact finite-n expectation: T not reported by the solver\n.*verify: [0-9]+ passed, 0 failed, [0-9]+ skipped"
    verify --suite quick --case grw-ex4 --out ${CMAKE_CURRENT_BINARY_DIR}/solver-partial
    --solver "sh tests/solvers/partial.sh $<TARGET_FILE:gdsmc> {scene} {out}")
gdsmc_add_cli_test(cli_solver_builtin_only 0
    "SKIP  vro-grw-ex3 n=64 sampled vs conditional T_raw: built-in engine only: the conditional variant is this engine's observation from running sums\n"
    verify --suite quick --case vro-grw-ex3 --out ${CMAKE_CURRENT_BINARY_DIR}/solver-vro
    --solver "$<TARGET_FILE:gdsmc> run {scene} --result {out} --quiet")
# The engine's own result of a [steady] scene without steady.pairs leaves the
# unmeasured mu2 and mu4 out (it wrote 'nan', which the reader refuses).
gdsmc_add_cli_test(cli_solver_steady_without_pairs 0
    "\nverify: [1-9][0-9]* passed, 0 failed, [0-9]+ skipped\n"
    verify --suite quick --case split-gaussian --out ${CMAKE_CURRENT_BINARY_DIR}/solver-split
    --solver "$<TARGET_FILE:gdsmc> run {scene} --result {out} --quiet")
set_tests_properties(cli_solver_not_reported cli_solver_builtin_only
                     cli_solver_steady_without_pairs
                     PROPERTIES LABELS regression TIMEOUT 180)

# Each kind of malformed result (tests/solvers/corrupt.sh edits the built-in
# engine's): exit 2, the result file and line in the exact message, nothing on
# standard output and no table.
gdsmc_add_no_output_test(cli_solver_result_version 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:1: protocol version '2', this gdsmc reads version 1\n$"
    ${SB}-result_version/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_version
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '1s/.*/# gdsmc-result 2/'")
gdsmc_add_no_output_test(cli_solver_result_n 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:3: n = 65 does not match the scene's particles.n = 64\n$"
    ${SB}-result_n/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_n
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '3s/.*/# n = 65/'")
gdsmc_add_no_output_test(cli_solver_result_ensembles 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:4: ensembles = 1999 does not match the scene's particles.ensembles = 2000\n$"
    ${SB}-result_ensembles/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_ensembles
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '4s/.*/# ensembles = 1999/'")
gdsmc_add_no_output_test(cli_solver_result_no_t 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:8: column 1 is 'time', expected t\n$"
    ${SB}-result_no_t/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_no_t
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '8s/^t,/time,/'")
gdsmc_add_no_output_test(cli_solver_result_no_var 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:8: column 2: T must be followed by T_var\n$"
    ${SB}-result_no_var/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_no_var
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '8s/T,T_var/T,T_sd/'")
gdsmc_add_no_output_test(cli_solver_result_nan 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:9: column 2 \\(T\\): 'nan' is not finite\n$"
    ${SB}-result_nan/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_nan
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '9s/^0,[^,]*/0,nan/'")
gdsmc_add_no_output_test(cli_solver_result_negative_var 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:10: column 3 \\(T_var\\): -1 is a negative variance\n$"
    ${SB}-result_negative_var/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_negative_var
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '10s/^\\([^,]*,[^,]*\\),[^,]*/\\1,-1/'")
gdsmc_add_no_output_test(cli_solver_result_time 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:11: t = 0.25, but the scene's output time 2 is 0.20000000000000001 \\(allowed relative difference 1e-9\\)\n$"
    ${SB}-result_time/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_time
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '11s/^[^,]*/0.25/'")
gdsmc_add_no_output_test(cli_solver_result_fields 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:12: 22 fields, the header has 23\n$"
    ${SB}-result_fields/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_fields
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '12s/,[^,]*$//'")
gdsmc_add_no_output_test(cli_solver_result_short 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:88: the file ends after 80 rows, the scene has 81 output times\n$"
    ${SB}-result_short/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_short
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '89d'")
gdsmc_add_no_output_test(cli_solver_result_long 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:90: more rows than the scene's 81 output times, or text after them: '8.1,1,0'\n$"
    ${SB}-result_long/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_long
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '$a 8.1,1,0'")
gdsmc_add_no_output_test(cli_solver_result_trailing 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result:90: unexpected line after the rows: '# trailing' \\(allowed: the steady section, '# steady'\\)\n$"
    ${SB}-result_trailing/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_trailing
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} '$a # trailing'")
gdsmc_add_no_output_test(cli_solver_result_empty 2
    "^gdsmc verify: [^\n]*/\\.solver/[0-9a-f]+\\.result: empty result \\(the solver wrote nothing\\)\n$"
    ${SB}-result_empty/grw-ex4.csv ARGS verify --suite quick --case grw-ex4 --quiet --out ${SB}-result_empty
    --solver "sh tests/solvers/corrupt.sh $<TARGET_FILE:gdsmc> {scene} {out} 'empty'")

# A solver that reports nothing but t: every check of these cases needs its
# data, so every one is a SKIP (row rules, the hard suite's own rules, a
# hook's fits and counts, case checks), none a PASS or a FAIL.
foreach(c grw-ex5 hard-tiny cost-brs-ex2)
  gdsmc_add_cli_test(cli_solver_nothing_${c} 0 "\nverify: 0 passed, 0 failed, [1-9][0-9]* skipped\n"
      verify --suite quick --case ${c} --out ${CMAKE_CURRENT_BINARY_DIR}/solver-nothing-${c}
      --solver "sh tests/solvers/nothing.sh $<TARGET_FILE:gdsmc> {scene} {out}")
  set_tests_properties(cli_solver_nothing_${c} PROPERTIES LABELS regression TIMEOUT 300)
endforeach()
