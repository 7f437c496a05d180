# tessera_add_test: a ctest test that checks the exit code and the output together (ctest's
# PASS_REGULAR_EXPRESSION alone passes on any exit code once its regex matches). The command runs
# under run_test.cmake, which names every broken expectation.
#
#   tessera_add_test(NAME name COMMAND program [args...]
#                    [EXPECT_RC code...]       the exit codes allowed (default 0); a signal fails
#                    [EXPECT_OUTPUT regex...]  each must match somewhere in stdout+stderr
#                    [EXPECT_STDERR text...]   each must occur, literally, in stderr
#                    [LABELS label...] [ENV VAR=value...] [TIMEOUT seconds]
#                    [PROPERTIES name value...])   any other test property
#
# A sanitizer report in the output fails every such test. program may be a target's name. A
# command that must fail cleanly (a clear message, exit code 1 or 2, never a crash) is
#   tessera_add_test(NAME ... COMMAND ... EXPECT_RC 1 2 EXPECT_STDERR "piece" "piece")
set(TESSERA_RUN_TEST ${CMAKE_CURRENT_LIST_DIR}/run_test.cmake)

function(tessera_add_test)
  cmake_parse_arguments(PARSE_ARGV 0 T "" "NAME;TIMEOUT"
                        "COMMAND;EXPECT_RC;EXPECT_OUTPUT;EXPECT_STDERR;LABELS;ENV;PROPERTIES")
  if(NOT T_NAME OR NOT T_COMMAND)
    message(FATAL_ERROR "tessera_add_test: NAME and COMMAND are required")
  endif()
  if(T_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "tessera_add_test(${T_NAME}): unexpected ${T_UNPARSED_ARGUMENTS}")
  endif()
  set(args "")
  foreach(rc IN LISTS T_EXPECT_RC)
    list(APPEND args RC ${rc})
  endforeach()
  # A ';' in a regex, text or argument stays in it (escaped, or the list would split there).
  foreach(re IN LISTS T_EXPECT_OUTPUT)
    string(REPLACE ";" "\\;" re "${re}")
    list(APPEND args OUTPUT "${re}")
  endforeach()
  foreach(text IN LISTS T_EXPECT_STDERR)
    string(REPLACE ";" "\\;" text "${text}")
    list(APPEND args STDERR "${text}")
  endforeach()
  list(APPEND args RUN)
  set(first TRUE)
  foreach(arg IN LISTS T_COMMAND)
    if(first AND TARGET "${arg}")
      set(arg $<TARGET_FILE:${arg}>)
    endif()
    set(first FALSE)
    string(REPLACE ";" "\\;" arg "${arg}")
    list(APPEND args "${arg}")
  endforeach()
  # CMake lists also join the elements between an unbalanced '[' and ']': refuse rather than
  # pass a different test.
  list(LENGTH T_EXPECT_RC n_rc)
  list(LENGTH T_EXPECT_OUTPUT n_out)
  list(LENGTH T_EXPECT_STDERR n_err)
  list(LENGTH T_COMMAND n_cmd)
  list(LENGTH args n_args)
  math(EXPR n_want "2 * (${n_rc} + ${n_out} + ${n_err}) + 1 + ${n_cmd}")
  if(NOT n_args EQUAL n_want)
    message(FATAL_ERROR "tessera_add_test(${T_NAME}): an argument with an unbalanced [ or ] "
                        "cannot be passed whole")
  endif()
  add_test(NAME ${T_NAME} COMMAND ${CMAKE_COMMAND} -P ${TESSERA_RUN_TEST} -- ${args})
  if(T_LABELS)
    set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}")
  endif()
  if(T_ENV)
    set_tests_properties(${T_NAME} PROPERTIES ENVIRONMENT "${T_ENV}")
  endif()
  if(T_TIMEOUT)
    set_tests_properties(${T_NAME} PROPERTIES TIMEOUT ${T_TIMEOUT})
  endif()
  if(T_PROPERTIES)
    set_tests_properties(${T_NAME} PROPERTIES ${T_PROPERTIES})
  endif()
endfunction()
