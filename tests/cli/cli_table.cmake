# The table-driven command line (app/src/cli/cli_table.h, docs/cli.md): the tables hold
# together, every command has its help, errors name the option and what it takes, and
# --stats FILE.json reports which stages ran.
add_executable(test_cli_table test_cli_table.c)
target_link_libraries(test_cli_table PRIVATE tessera_app)
target_include_directories(test_cli_table PRIVATE ${CMAKE_SOURCE_DIR}/app/src)
add_test(NAME cli.table COMMAND test_cli_table)
set_tests_properties(cli.table PROPERTIES LABELS "cli;unit")

add_test(NAME cli.help.every_command
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/help_all.sh $<TARGET_FILE:tessera>)
set_tests_properties(cli.help.every_command PROPERTIES LABELS "cli")
tessera_cli_error(help_unknown_command "frobnicate|tessera --help" help frobnicate)
tessera_cli_error(unknown_option "--frobnicate|unknown option|usage: tessera render"
                  render ${DATA}/minimal.json -o ${OUT}/x.png --frobnicate)
tessera_cli_error(missing_value "--size|needs a value|WIDTHxHEIGHT"
                  render ${DATA}/minimal.json -o ${OUT}/x.png --size)
tessera_cli_error(out_of_range "\"9\"|--supersample|1 to 4"
                  render ${DATA}/minimal.json -o ${OUT}/x.png --supersample 9)
tessera_cli_error(unknown_catalog_command "frobnicate|tessera catalog --help" catalog frobnicate)
tessera_cli_error(stats_unwritable "/no/such/folder/s.json|cannot write"
                  render ${DATA}/minimal.json -o ${OUT}/stats-x.png --stats /no/such/folder/s.json)

# --stats: the settings a render resolved to and what its stages did.
set(STATS_DEMO ${CMAKE_SOURCE_DIR}/assets/projects/demo-bathroom.json)
add_test(NAME cli.stats.room_probe_off
         COMMAND ${STATS_CHECK} ${OUT}/room-off.json settings.quality=print settings.room_probe=off
                 frame.room_probe=0 --
                 $<TARGET_FILE:tessera> render ${STATS_DEMO} --quality print --room-probe off --glaze off
                 --supersample 1 --size 160x90 -o ${OUT}/stats-room-off.png --stats ${OUT}/room-off.json)
add_test(NAME cli.stats.room_probe_on
         COMMAND ${STATS_CHECK} ${OUT}/room-on.json settings.quality=print settings.room_probe=on
                 frame.room_probe=1 settings.self_reflections=on frame.self_traced_probes=>0 --
                 $<TARGET_FILE:tessera> render ${STATS_DEMO} --quality print --room-probe on
                 --supersample 1 --size 160x90 -o ${OUT}/stats-room-on.png --stats ${OUT}/room-on.json)
add_test(NAME cli.stats.interactive
         COMMAND ${STATS_CHECK} ${OUT}/interactive.json settings.quality=interactive
                 settings.planar_mirrors=off frame.planar_mirrors=0 settings.exact_lamps=on
                 frame.emitters=>0 settings.self_reflections=off frame.self_traced_probes=0
                 frame.adaptive=0 --
                 $<TARGET_FILE:tessera> render ${STATS_DEMO} --quality interactive --camera basin
                 --size 160x90 -o ${OUT}/stats-interactive.png --stats ${OUT}/interactive.json)
set_tests_properties(cli.stats.room_probe_off cli.stats.room_probe_on cli.stats.interactive
                     PROPERTIES LABELS "cli")
