# The lean `tessera` (ui/CMakeLists.txt; docs/cli.md, "Two executables"): it links the command
# line, the catalog database and SQLite only, and runs tessera-full beside it for every other
# command. include()d from tests/cli/CMakeLists.txt.

# No renderer, window, image, model or print library among what the loader maps for it.
add_test(NAME cli.lean_links
         COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:tessera>
                 -P ${CMAKE_CURRENT_LIST_DIR}/check_lean_links.cmake)
set_tests_properties(cli.lean_links PROPERTIES LABELS cli TIMEOUT 30)

# A command it does not link runs in tessera-full with the same arguments: the usage (and every
# error) comes from there.
tessera_add_test(NAME cli.lean_runs_full COMMAND tessera render --help
                 EXPECT_RC 0 EXPECT_OUTPUT "usage: tessera render PROJECT" "--all-views"
                 LABELS cli TIMEOUT 30)

# Copied alone into a folder (no tessera-full beside it): the catalog commands, help and
# --version still run; any other command, and the window, say what is missing.
add_test(NAME cli.lean_alone
         COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:tessera>
                 -DDIR=${CMAKE_CURRENT_BINARY_DIR}/lean-alone
                 -P ${CMAKE_CURRENT_LIST_DIR}/lean_alone.cmake)
set_tests_properties(cli.lean_alone PROPERTIES LABELS cli TIMEOUT 60)
