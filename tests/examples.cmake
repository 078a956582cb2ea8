# The solver-protocol helpers (examples/, docs/solver-protocol.md): their
# numbers against the engine's definitions.
find_program(DEBIAN_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)   # python3-numpy
set(EX_PY ${PROJECT_SOURCE_DIR}/examples/python)

# The helpers' observables and steady quantities of one velocity array
# against sim_observe and sim_steady_sample: the C header (cmocka), then the
# Python module on the values the C test wrote.
gdsmc_add_test(test_examples_protocol SOURCES test_examples_protocol.c LIBS gdsmc_sim
               LABELS unit)
set_tests_properties(test_examples_protocol PROPERTIES FIXTURES_SETUP examples_engine_values)
add_test(NAME examples_python_protocol
         COMMAND ${DEBIAN_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/check_examples_protocol.py
                 examples-protocol-engine.txt ${EX_PY})
set_tests_properties(examples_python_protocol PROPERTIES TIMEOUT 60 LABELS unit
                     FIXTURES_REQUIRED examples_engine_values)
