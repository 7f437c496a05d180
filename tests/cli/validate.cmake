# One validation for every command (docs/project-format.md, "Limits"): each hostile project in
# tests/data/projects/hostile/ is refused alike by check, render, quantities, print and
# export-glb, at reading, with the file and the JSON path in the message. Before, each passed
# `check` and failed in one command only (or in none). Included from tests/cli/CMakeLists.txt.
set(HOSTILE ${CMAKE_SOURCE_DIR}/tests/data/projects/hostile)
# NAME|text the message must hold
set(hostile_cases
    "lights_17|$.lights[16]: 17 lights"
    "lights_15_and_window|$.plan.openings[0]: 15 lights in $.lights and 2 from the windows' daylight"
    "tiling_rotation|$.tilings[0].rotation: must be in [-360, 360], got 1e+308"
    "tiling_origin|$.tilings[0].origin[0]: must be in [-1e+07, 1e+07]"
    "tiling_wall_01|$.tilings[1].surface: unknown surface \"wall:01\": a wall number has no leading zeros"
    "opening_zero_width|$.plan.openings[0].width: must be >= 1"
    "niche_zero_depth|$.plan.niches[0].depth: must be >= 1"
    "object_scale|$.objects[0].scale[0]: must be in [-1000, 1000]"
    "utf8_object_name|$.objects[0].name: not valid UTF-8 text"
    "utf8_material_name|$.materials: the name of member 3 is not valid UTF-8 text"
    "render_size_pixels|$.render.size: 16384x16384: 268435456 pixels")
foreach(case IN LISTS hostile_cases)
  string(FIND "${case}" "|" bar)
  string(SUBSTRING "${case}" 0 ${bar} name)
  math(EXPR from "${bar} + 1")
  string(SUBSTRING "${case}" ${from} -1 message)
  foreach(command IN ITEMS check render quantities print export-glb)
    set(args "")
    if(command STREQUAL "render")
      set(args --size 32x24 -o ${OUT}/hostile-${name}.png)
    elseif(command STREQUAL "print")
      set(args -o ${OUT}/hostile-${name}.pdf --renders none)
    elseif(command STREQUAL "export-glb")
      set(args -o ${OUT}/hostile-${name}.glb)
    endif()
    tessera_add_test(NAME cli.validate.${name}.${command}
                     COMMAND tessera ${command} ${HOSTILE}/${name}.json ${args}
                     EXPECT_RC 2 EXPECT_STDERR "hostile/${name}.json: ${message}"
                     LABELS cli ENV TESSERA_GL=osmesa TIMEOUT 60)
  endforeach()
endforeach()
