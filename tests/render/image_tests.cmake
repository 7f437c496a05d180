# Image I/O and golden-image comparison tests (no GL). include()d from tests/render/CMakeLists.txt;
# needs the tessera_testcommon target from tests/common (golden.h, check.h).
add_executable(test_image_io ${CMAKE_CURRENT_LIST_DIR}/test_image_io.c)
target_link_libraries(test_image_io PRIVATE tessera_testcommon tessera_render m)
target_compile_definitions(test_image_io
                           PRIVATE TEST_OUT_DIR="${CMAKE_CURRENT_BINARY_DIR}/test_image_io.out")
add_test(NAME render.test_image_io COMMAND test_image_io)

add_executable(test_golden_compare ${CMAKE_CURRENT_LIST_DIR}/test_golden_compare.c)
target_link_libraries(test_golden_compare PRIVATE tessera_testcommon tessera_render m)
target_compile_definitions(
  test_golden_compare PRIVATE TEST_OUT_DIR="${CMAKE_CURRENT_BINARY_DIR}/test_golden_compare.out")
add_test(NAME render.test_golden_compare COMMAND test_golden_compare)

set_tests_properties(render.test_image_io render.test_golden_compare PROPERTIES LABELS unit)

# The OpenEXR header check: the fuzzer's gigabyte-claiming headers refused in under a second.
add_executable(test_image_exr_header ${CMAKE_CURRENT_LIST_DIR}/test_image_exr_header.c)
target_link_libraries(test_image_exr_header PRIVATE tessera_testcommon tessera_render m)
target_compile_definitions(
  test_image_exr_header
  PRIVATE TEST_CORPUS_DIR="${CMAKE_SOURCE_DIR}/tests/fuzz/corpus/image"
          TEST_OUT_DIR="${CMAKE_CURRENT_BINARY_DIR}")
add_test(NAME render.test_image_exr_header COMMAND test_image_exr_header)
set_tests_properties(render.test_image_exr_header PROPERTIES LABELS unit TIMEOUT 60)
