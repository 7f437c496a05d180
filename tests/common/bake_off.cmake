# The CLI bakes indirect light by default (docs/rendering.md, "Baked indirect light"). Tests
# written against the project's plain ambient keep it: included at the end of a tests folder's
# CMakeLists.txt, this gives every test of that folder that names neither TESSERA_BAKE nor
# XDG_CACHE_HOME in its environment (a test about the bake, or a golden of the CLI's default
# picture, which caches its bake in the build tree) TESSERA_BAKE=off.
get_property(bake_off_tests DIRECTORY PROPERTY TESTS)
foreach(t IN LISTS bake_off_tests)
  get_test_property(${t} ENVIRONMENT env)
  if(NOT env MATCHES "TESSERA_BAKE|XDG_CACHE_HOME")
    set_property(TEST ${t} APPEND PROPERTY ENVIRONMENT "TESSERA_BAKE=off")
  endif()
endforeach()
