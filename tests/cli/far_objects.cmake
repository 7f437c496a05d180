# Far objects, depth range and black renders (docs/rendering.md, "Depth range"; docs/cli.md,
# `render` and `check`). Included from tests/cli/CMakeLists.txt (DATA, OUT, check_image_file).

# An object moved to z = 2 505 000 mm (mm typed as m) or ten times farther: the render is the
# room without it, to within a few display steps (the depth range follows the room).
foreach(far IN ITEMS far-object far-object-25km)
  tessera_add_test(NAME cli.render.${far}
                   COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/render_pair.sh $<TARGET_FILE:tessera>
                           $<TARGET_FILE:check_image_file> 128x96 ${DATA}/${far}.json
                           ${OUT}/${far}.png ${DATA}/minimal.json ${OUT}/${far}-base.png
                           --max-diff 8 --mean-diff 0.5
                   EXPECT_OUTPUT "check_image_file: PASS" LABELS cli)
endforeach()

# `check` names the far object, its distance and its side.
tessera_add_test(NAME cli.check.far_object COMMAND tessera check ${DATA}/far-object.json
                 EXPECT_RC 1
                 EXPECT_OUTPUT "error +outside-room .*slipped is 2502300 mm outside the room's box \\(above the ceiling"
                 LABELS cli)
tessera_add_test(NAME cli.check.near_objects_pass COMMAND tessera check ${DATA}/minimal.json
                 EXPECT_RC 0 EXPECT_OUTPUT "0 findings, 0 errors" LABELS cli)

# A plan 10 km high (the reader's limit): the walls by the eye stay in front of the near plane.
tessera_add_test(NAME cli.render.tall_room
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/render_vs_reference.sh $<TARGET_FILE:tessera>
                         $<TARGET_FILE:check_image_file> ${DATA}/tall-room.json 128x96 front
                         ${OUT}/tall-room.png ${OUT}/tall-room-ref.exr
                         --black-excess 0.01 --max-diff 255 --mean-diff 12
                 EXPECT_OUTPUT "check_image_file: PASS" LABELS cli)

# Cameras on a room corner (at eye height and on the floor) and on a wall: no pixel left black
# where the tracer's direct light shows the room (beyond 1 %: the sphere's unlit underside).
foreach(camera IN ITEMS corner floor-corner on-wall)
  tessera_add_test(NAME cli.render.camera_${camera}
                   COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/render_vs_reference.sh
                           $<TARGET_FILE:tessera> $<TARGET_FILE:check_image_file>
                           ${DATA}/corner-camera.json 128x96 ${camera}
                           ${OUT}/camera-${camera}.png ${OUT}/camera-${camera}-ref.exr
                           --black-excess 0.01 --max-diff 255 --mean-diff 12
                   EXPECT_OUTPUT "check_image_file: PASS" LABELS cli)
endforeach()

# A camera outside the room looking away from it: the image is written, and render says so.
tessera_add_test(NAME cli.render.no_room
                 COMMAND tessera render ${DATA}/corner-camera.json --camera outside --size 64x48
                         -o ${OUT}/camera-outside.png
                 EXPECT_RC 1
                 EXPECT_STDERR "camera outside shows no room in 100 % of" LABELS cli)
