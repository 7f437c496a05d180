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
    "render_size_pixels|$.render.size: 16384x16384: too large: 268435456 pixels")
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

# The limits table (docs/limits.md): each job outside it is refused before the scene is loaded,
# with the limit in the message. Before, `render --size 16384x16384` rendered for 60 s in
# 2.5 GB and failed at the image writer, and `panorama` had no cap at all.
set(MINIMAL ${CMAKE_SOURCE_DIR}/tests/data/projects/minimal.json)
tessera_add_test(NAME cli.limits.render_pixels
                 COMMAND tessera render ${MINIMAL} --size 16384x16384 -o ${OUT}/limits-big.png
                 EXPECT_RC 2 EXPECT_STDERR "a 16384x16384 image: too large: 268435456 pixels" "134217728"
                 LABELS cli ENV TESSERA_GL=osmesa TIMEOUT 30)
tessera_add_test(NAME cli.limits.panorama_pixels
                 COMMAND tessera panorama ${MINIMAL} --size 40000x20000 -o ${OUT}/limits-pano.jpg
                 EXPECT_RC 2 EXPECT_STDERR "--size 40000x20000: too large: a panorama of 800000000 pixels"
                 LABELS cli ENV TESSERA_GL=osmesa TIMEOUT 30)
tessera_add_test(NAME cli.limits.video_frames
                 COMMAND tessera video ${MINIMAL} --seconds 3600 --fps 240 -o ${OUT}/limits-v.mp4
                 EXPECT_RC 2 EXPECT_STDERR "too long: 864000 frames" "the limit is 90000"
                 LABELS cli ENV TESSERA_GL=osmesa TIMEOUT 30)
tessera_add_test(NAME cli.limits.reference_samples
                 COMMAND tessera reference ${MINIMAL} --size 64x48 --samples 100000
                         -o ${OUT}/limits-ref.exr
                 EXPECT_RC 2 EXPECT_STDERR "too many samples: 100000 a pixel" "the limit is 65536"
                 LABELS cli TIMEOUT 30)
tessera_add_test(NAME cli.limits.memory
                 COMMAND tessera render ${MINIMAL} --size 4096x4096 -o ${OUT}/limits-mem.png
                 EXPECT_RC 2 EXPECT_STDERR "too large: needs about 640 MB of memory, more than the 300 MB"
                 LABELS cli ENV TESSERA_GL=osmesa TESSERA_MEMORY_LIMIT_MB=300 TIMEOUT 30)
