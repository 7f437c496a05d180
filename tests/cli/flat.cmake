# Flats: several rooms in one project file (docs/project-format.md "Flats"), the generator
# `tessera generate-flat`, and what check, quantities and render do with a flat. Included from
# tests/cli/CMakeLists.txt (DATA, OUT, tessera_cli_error). The tests share one catalog file, in
# turn (RESOURCE_LOCK), and the flats the generator tests write. No light bake: the renders
# compare two builds of one room, which a bake would only slow down.
set(FLAT_ENV "TESSERA_CATALOG=${OUT}/flat-catalog.sqlite;TESSERA_GL=osmesa;TESSERA_BAKE=off")

tessera_add_test(NAME cli.flat.generate
                 COMMAND tessera generate-flat --rooms 8 --seed 7 -o ${OUT}/flat8.json
                 EXPECT_OUTPUT "flat8.json: 8 rooms, [0-9]+ fixtures, [0-9]+ tilings" LABELS cli
                 TIMEOUT 60 PROPERTIES FIXTURES_SETUP flat8)
tessera_add_test(NAME cli.flat.generate_small
                 COMMAND tessera generate-flat --rooms 3 --seed 7 -o ${OUT}/flat3.json
                 EXPECT_OUTPUT "flat3.json: 3 rooms" LABELS cli TIMEOUT 60
                 PROPERTIES FIXTURES_SETUP flat3)

# The generated flat passes check: every room checked, no error.
tessera_add_test(NAME cli.flat.check COMMAND tessera check ${OUT}/flat8.json
                 EXPECT_RC 0
                 EXPECT_OUTPUT "Room \"Bathroom\": [0-9]+ fixtures" "Room \"Guest WC\": "
                               "flat8.json: [0-9]+ fixtures checked in 8 rooms; [0-9]+ findings, 0 errors"
                 LABELS cli TIMEOUT 300 ENV ${FLAT_ENV}
                 PROPERTIES FIXTURES_REQUIRED flat8 RESOURCE_LOCK flat_catalog)

# The flat's quantities are the sum of its rooms'.
tessera_add_test(NAME cli.flat.quantities_sum
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/flat_quantities_sum.py
                         $<TARGET_FILE:tessera> ${OUT}/flat3.json 3
                 EXPECT_OUTPUT "flat_quantities_sum: PASS: 3 rooms" LABELS cli TIMEOUT 300
                 ENV ${FLAT_ENV} PROPERTIES FIXTURES_REQUIRED flat3 RESOURCE_LOCK flat_catalog)

# The flat's --json: each room as the room alone prints it, the total the sum of the rooms
# quantified alone (tiles, trims, consumables, labour, money), and the quotation every room's
# lines in turn; on the generated flat and on a flat with trims and a shower zone
# (tests/data/tiles/flat_trims.json: reveals_room.json and consumables_wall.json as two rooms).
tessera_add_test(NAME cli.flat.quantities_json
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/flat_quantities_json.py
                         $<TARGET_FILE:tessera> ${OUT}/flat3.json ${OUT}/flat3-rooms
                 EXPECT_OUTPUT "flat_quantities_json: PASS: 3 rooms" LABELS cli TIMEOUT 300
                 ENV ${FLAT_ENV} PROPERTIES FIXTURES_REQUIRED flat3 RESOURCE_LOCK flat_catalog)
tessera_add_test(NAME cli.flat.quantities_json_trims
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/flat_quantities_json.py
                         $<TARGET_FILE:tessera> ${CMAKE_SOURCE_DIR}/tests/data/tiles/flat_trims.json ${OUT}/flat-trims-rooms
                 EXPECT_OUTPUT "flat_quantities_json: PASS: 2 rooms" LABELS cli TIMEOUT 300
                 ENV ${FLAT_ENV} PROPERTIES RESOURCE_LOCK flat_catalog)
# The flat's quotation as a spreadsheet, read back against the JSON's "quotation"
# (xlsx_check.py); the text and CSV forms carry each room's consumables and the flat's total.
add_test(NAME cli.flat.quantities_xlsx
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/xlsx_check.py ${OUT}/flat-quote.xlsx --
                 $<TARGET_FILE:tessera> quantities ${CMAKE_SOURCE_DIR}/tests/data/tiles/flat_trims.json
                 --company ${CMAKE_SOURCE_DIR}/assets/company/company.json)
set_tests_properties(cli.flat.quantities_xlsx PROPERTIES LABELS cli TIMEOUT 300
                     ENVIRONMENT "${FLAT_ENV};XDG_CONFIG_HOME=${OUT}/no-config"
                     RESOURCE_LOCK flat_catalog)
tessera_add_test(NAME cli.flat.quantities_text
                 COMMAND tessera quantities ${CMAKE_SOURCE_DIR}/tests/data/tiles/flat_trims.json
                 EXPECT_OUTPUT "== room: Bathroom ==.*Trim profiles.*KT-L10 [^\n]* 4 +4.00 m +2 +5.00 m.*adhesive [0-9.]+ kg.*== room: Shower ==.*waterproofing 4.41 m2.*== flat: Trim and shower flat \\(2 rooms\\) ==.*KT-L10 [^\n]* 4 +4.00 m +2 +5.00 m.*waterproofing 4.41 m2.*Quotation Q-2026-0042.*LAB-TILE-WALL"
                 LABELS cli TIMEOUT 300 ENV ${FLAT_ENV} PROPERTIES RESOURCE_LOCK flat_catalog)
tessera_add_test(NAME cli.flat.quantities_csv
                 COMMAND tessera quantities ${CMAKE_SOURCE_DIR}/tests/data/tiles/flat_trims.json --csv
                 EXPECT_OUTPUT "room,\"Bathroom\".*trims,Kantec,KT-L10,CP,[^\n]*,4,4.000,2.5,2,5.000,18.90,7.56,EUR.*consumables,adhesive,.*flat,\"Trim and shower flat \\(2 rooms\\)\".*consumables,waterproofing,4.4100,m2.*quote,number,Q-2026-0042.*bom,[^\n]*,labour,"
                 LABELS cli TIMEOUT 300 ENV ${FLAT_ENV} PROPERTIES RESOURCE_LOCK flat_catalog)
# tessera print on the flat: each room's part list and quotation bills its consumables and
# labour (the Shower room its waterproofing) and the trims by the metre; --xlsx writes the
# flat's one quotation, read back against `quantities FLAT --json`'s "quotation".
tessera_add_test(NAME cli.flat.print_quotation
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/flat_print_quotation.sh
                         $<TARGET_FILE:tessera> ${CMAKE_SOURCE_DIR}/tests/data/tiles/flat_trims.json
                         ${OUT}/flat-print "Bathroom:FW-C2-25" "Bathroom:LAB-TILE-WALL"
                         "Bathroom:4.00 m needed: 2 x 2.5 m = 5.00 m billed" "Shower:FW-C2-25"
                         "Shower:FW-DS-M2" "Shower:LAB-TILE-WALL"
                 EXPECT_OUTPUT "flat_print_quotation: PASS: 6 texts" LABELS cli TIMEOUT 300
                 ENV ${FLAT_ENV} PROPERTIES RESOURCE_LOCK flat_catalog)
add_test(NAME cli.flat.print_quotation_xlsx
         COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/xlsx_check.py ${OUT}/flat-print-quote.xlsx --
                 $<TARGET_FILE:tessera> print ${CMAKE_SOURCE_DIR}/tests/data/tiles/flat_trims.json
                 -o ${OUT}/flat-print-quote.pdf --renders none --date 2026-12-04
                 --company ${CMAKE_SOURCE_DIR}/assets/company/company.json)
set_tests_properties(cli.flat.print_quotation_xlsx PROPERTIES LABELS cli TIMEOUT 300
                     ENVIRONMENT "${FLAT_ENV};XDG_CONFIG_HOME=${OUT}/no-config"
                     RESOURCE_LOCK flat_catalog)

# A room's camera renders that room, and only it is built: the kitchen's view of the 3-room flat
# is the same picture as the kitchen's own single-room file (flat_room.py writes it).
tessera_add_test(NAME cli.flat.render_room
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/flat_render_room.sh $<TARGET_FILE:tessera>
                         $<TARGET_FILE:check_image_file> ${OUT}/flat3.json Kitchen kitchen-view
                         ${OUT}/flat3-kitchen
                 EXPECT_OUTPUT "room 2 of 3, \"Kitchen\" \\(the others culled\\)"
                               "check_image_file: PASS"
                 LABELS cli TIMEOUT 300 ENV ${FLAT_ENV}
                 PROPERTIES FIXTURES_REQUIRED flat3 RESOURCE_LOCK flat_catalog)

# A bad rooms array: the file and the JSON path.
tessera_cli_error(flat_rooms_object "flat-rooms-object.json|$.rooms: expected an array of rooms, got object" check ${DATA}/flat-rooms-object.json)
tessera_cli_error(flat_no_rooms "flat-no-rooms.json|$.rooms: a flat has 1 to 256 rooms, got 0" check ${DATA}/flat-no-rooms.json)
tessera_cli_error(flat_bad_room "flat-bad-room.json|$.rooms[1].plan.corners[2][1]|expected a finite number, got string" quantities ${DATA}/flat-bad-room.json)
tessera_cli_error(flat_bad_room_render "flat-bad-room.json|$.rooms[1].plan.corners[2][1]" render ${DATA}/flat-bad-room.json -o ${OUT}/x.png)
tessera_cli_error(flat_room_not_object "flat-room-not-object.json|$.rooms[1]: expected an object (a room), got number" check ${DATA}/flat-room-not-object.json)
tessera_cli_error(flat_duplicate_name "flat-duplicate-name.json|$.rooms[1].name: \"Bath\" is also the name of room 1" check ${DATA}/flat-duplicate-name.json)
tessera_cli_error(flat_plan_at_top "flat-plan-at-top.json|$.plan: a flat keeps \"plan\" in each room" check ${DATA}/flat-plan-at-top.json)
tessera_cli_error(flat_single_room_command "flat-two-rooms.json|$.rooms: a flat of several rooms" export-glb ${DATA}/flat-two-rooms.json -o ${OUT}/flat.glb)
tessera_cli_error(flat_unknown_camera "no room has a camera \"nope\"" render ${DATA}/flat-two-rooms.json -o ${OUT}/x.png --camera nope)

# The two-room file: both rooms pass check, --room picks the second for render.
tessera_add_test(NAME cli.flat.check_two_rooms COMMAND tessera check ${DATA}/flat-two-rooms.json
                 EXPECT_OUTPUT "Room \"Bath\": 0 fixtures" "Room \"Hall\": 0 fixtures"
                               "0 fixtures checked in 2 rooms; 0 findings, 0 errors"
                 LABELS cli ENV ${FLAT_ENV} PROPERTIES RESOURCE_LOCK flat_catalog)
tessera_add_test(NAME cli.flat.render_room_option
                 COMMAND tessera render ${DATA}/flat-two-rooms.json --room 2 --size 64x48
                         -o ${OUT}/flat-two-rooms-hall.png
                 EXPECT_STDERR "room 2 of 2, \"Hall\" (the others culled)" LABELS cli
                 ENV ${FLAT_ENV})

# The documented example (docs/project-format.md "Flats") reads and passes check.
tessera_add_test(NAME cli.flat.doc_example
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/flat_doc_example.sh $<TARGET_FILE:tessera>
                         ${CMAKE_SOURCE_DIR}/docs/project-format.md ${OUT}/flat-doc-example.json
                 EXPECT_OUTPUT "0 fixtures checked in 2 rooms; 0 findings, 0 errors" LABELS cli
                 ENV ${FLAT_ENV} PROPERTIES RESOURCE_LOCK flat_catalog)
