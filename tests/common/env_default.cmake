# tessera_env_default(REGEX ASSIGNMENT): every test of the calling folder (added so far) whose
# ENVIRONMENT matches nothing of REGEX gets ASSIGNMENT ("NAME=VALUE") added to it: a default a
# test that is about the setting overrides by naming it.
function(tessera_env_default regex assignment)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(t IN LISTS tests)
    get_test_property(${t} ENVIRONMENT env)
    if(NOT env MATCHES "${regex}")
      set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT "${assignment}")
    endif()
  endforeach()
endfunction()
