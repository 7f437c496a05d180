# CPU reference of the reflection formulas: cube maps, reflection, correction, blur, blend,
# SH9, sphere maps, refraction (no GL). include()d from tests/render/CMakeLists.txt.
foreach(name test_cube_data test_reflect_ref test_sh9)
  add_executable(${name} ${CMAKE_CURRENT_LIST_DIR}/${name}.c)
  target_link_libraries(${name} PRIVATE tessera_render m)
  add_test(NAME render.${name} COMMAND ${name})
  set_tests_properties(render.${name} PROPERTIES LABELS unit)
endforeach()
