# cli.lean_links: fails if the lean `tessera` loads a library of the renderer, the window, image
# files, models or print: ldd lists what the loader maps (the NEEDED entries and theirs).
#   cmake -DPROGRAM=build/ui/tessera -P tests/cli/check_lean_links.cmake
# The C++ runtime is not on the list: the sanitizer runtimes bring it in the ASan build.
execute_process(COMMAND ldd ${PROGRAM} OUTPUT_VARIABLE libs ERROR_VARIABLE err
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ldd ${PROGRAM} failed (${rc}): ${err}")
endif()
set(heavy "OpenImageIO|libGL|libEGL|OSMesa|glfw|gtk|gdk|cairo|pango|embree|OpenMesh|imgui"
          "|xlsxwriter|tbb|libX11|wayland")
string(JOIN "" heavy ${heavy})
string(REGEX MATCHALL "[^\n]*(${heavy})[^\n]*" found "${libs}")
if(found)
  string(REPLACE ";" "\n" found "${found}")
  message(FATAL_ERROR "the lean tessera loads heavy libraries:\n${found}")
endif()
message(STATUS "the lean tessera loads:\n${libs}")
