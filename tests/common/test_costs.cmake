# Each test's cost for ctest's scheduling. ctest -j starts the costliest tests of a dependency
# level first, from Testing/Temporary/CTestCostData.txt, which a fresh clone (CI) does not have;
# without it every test costs 0 and runs in the order it is declared, so a long test declared
# late runs alone at the end while the other core idles. Included at the end of each tests
# folder's CMakeLists.txt (a test's properties can be set only where it is added); the Xvfb
# sessions give theirs in tests/ui/CMakeLists.txt.
#
# Seconds of one run on the shared 2-core machine (a load of 10 to 17, so all of them long by
# the same factor; only their order matters): `ctest --test-dir build -j2`, and the sanitizer
# build's ctest of .ci/test, then build*/Testing/Temporary/CTestCostData.txt. "-": not measured
# there, the normal build's figure stands. Tests under 5 s in both are left at 0.
#                                        build  build-asan
set(tessera_test_costs
    ref.test_self_trace_primitives             103    43
    render.test_reflections.osmesa              55    44
    cli.read_only_folder                        54    70
    render.test_reflections.egl                 46     -
    cli.render.contrast_print                   42    45
    golden.demo-door.egl                        42     -
    ref.test_room_probe                         41    26
    ref.light.mirror_gpu                        40   176
    cli.disk_full.render-png                    39    11
    cli.render.room_probe_off                   39    45
    cli.render.print_adaptive                   38    33
    cli.stats.room_probe_off                    38    27
    cli.disk_full.render-jpg                    37    11
    cli.bake.first                              36   179
    ref.test_planar_mirror                      32    26
    ref.test_self_reflections                   28    20
    cli.stats.room_probe_on                     25    17
    cli.render.adaptive_off                     24    22
    ref.test_sh9_ambient                        24    16
    ref.light.gpu_soft                          23   120
    cli.extremes                                22    28
    ref.light.smoke_mirror_gpu                  22    35
    ref.test_ref_bake                           20    29
    catalog.db_faults                           19    87
    cli.render.planar_off                       19    22
    render.test_adaptive_ss.egl                 18     -
    render.test_adaptive_ss.osmesa              18     9
    cli.help.every_command                      17    13
    ref.light.traced_1                          16    93
    ref.light.traced_unclaimed                  16   120
    cli.bake.render_cached                      15    54
    cli.render.print_room_probe                 15    18
    cli.sweep.bounces                           15    22
    cli.sweep.smoke                             15    23
    cli.bake.moved                              14    23
    cli.demo                                    14    48
    cli.flat.render_room                        14    30
    cli.render.print_no_room_probe              14    19
    ref.light.mirror_traced_0                   14   106
    ref.light.traced_0                          14    84
    cli.disk_full.panorama                      13    13
    cli.disk_full.share                         13    22
    cli.print.set                               13    10
    cli.render.final_no_room_probe              13    16
    cli.render.print_planar                     13    15
    ref.light.mirror_traced_1                   13    96
    cli.disk_full.render-exr                    12    13
    cli.disk_full.render-tif                    12    11
    cli.render.glaze_off                        12    17
    cli.stats.interactive                       12     8
    catalog.thumbs_cli                          11    20
    cli.edit.replay_and_check                   11    10
    golden.demo-door.osmesa                     11    98
    ui.tile_actions                             11    13
    cli.disk_full.bench-csv                     10    10
    cli.disk_full.export-glb                    10     7
    cli.disk_full.print-pdf                     10     9
    cli.disk_full.print-svg                     10     9
    render.test_shadows.osmesa                  10    15
    cli.render.self_reflections_off              9    19
    ref.test_depth_correction                    9    10
    render.test_shadows.egl                      9     -
    cli.flat.print_quotation_xlsx                8    15
    cli.flat.quantities_json_trims               8    14
    cli.print.quotation_xlsx                     8     2
    cli.render.adaptive_on                       8     5
    ref.test_ref_furnace                         8    17
    render.test_frame_work.egl                   8     -
    render.test_frame_work.osmesa                8     5
    render.test_probe_group_gloss.egl            8     -
    render.test_probe_group_gloss.osmesa         8    12
    cli.render.quality_print                     7     8
    cli.render.self_reflections                  7    17
    cli.symlink_save                             7    11
    project_kill_save                            7    34
    ref.test_exact_lamps                         7     9
    ref.test_ref_cornell                         7     8
    ref.test_ref_vs_gpu                          7     9
    catalog.db_concurrent                        6    41
    cli.designed_bathroom.quantities             6    11
    cli.disk_full.video                          6     5
    cli.error.out_of_range                       6     3
    cli.error.stats_unwritable                   6     7
    cli.flat.print_quotation                     6    10
    cli.render.exact_lamps_off                   6     8
    cli.render.far-object                        6    10
    fuzz.image                                   6     4
    golden.demo-basin.egl                        6     -
    bake_worker                                  5     8
    cli.error.unknown_option                     5     4
    cli.export_glb.project                       5     7
    cli.quantities.xlsx                          5     1
    cli.render.exr                               5    10
    cli.render.jpg                               5     9
    golden.demo-basin.osmesa                     5     7
    render.test_gpu_vs_ref.osmesa                5     5
    catalog.db_hostile                           0    23
    catalog.db_import                            0     8
    catalog.db_open_read                         0     5
    catalog.db_roundtrip                         0     6
    catalog.db_search                            0     5
    catalog.db_shipped                           0     8
    catalog.test_model_absurd                    0     6
    catalog.test_model_files                     0     7
    catalog.test_model_lod                       0    17
    catalog.test_model_shipped                   0     8
    catalog.test_model_write                     0     6
    cli.bake.cached                              0     7
    cli.bench.animate                            0     8
    cli.designed_bathroom.basin_alone            0    10
    cli.designed_bathroom.group_move             0    11
    cli.edit.companions                          0     5
    cli.edit.drop_swing                          0     8
    cli.flat.quantities_csv                      0     5
    cli.flat.quantities_json                     0    16
    cli.flat.quantities_text                     0     5
    cli.flat.quantities_xlsx                     0     6
    cli.print_outputs                            0     7
    cli.render.camera_corner                     0    10
    cli.render.camera_floor-corner               0     7
    cli.render.camera_on-wall                    0     6
    cli.render.exact_lamps                       0     6
    cli.render.far-object-25km                   0    12
    cli.render.planar_on                         0     6
    cli.render.png                               0    11
    cli.render.probe_resolution                  0     8
    cli.render.self_reflection_rays              0    11
    cli.render.tall_room                         0     9
    cli.render.tif                               0     9
    cli.surfaces                                 0     9
    cli.surfaces_csv                             0     8
    cli.validate.render_size_pixels.render       0     5
    cli.validate.utf8_material_name.export-glb     0     5
    commands_undo_redo                           0     5
    print_layout                                 0    13
    print_set                                    0    12
    project_glb                                  0     6
    project_save_read                            0    16
    quantities_consumables                       0     9
    ref.cli.demo_bounces                         0     9
    ref.cli.demo_direct                          0     6
    ref.cli.reference                            0     6
    ref.light.gpu_print                          0   120
    ref.light.mirror_gpu_plain                   0     7
    ref.light.smoke_gpu_print                    0    15
    ref.light.smoke_traced.mirror-glass-room     0     6
    ref.light.smoke_traced.soft-shadow-room-unclaimed     0     5
    ref.test_ref_glossy                          0    11
    render.test_cube_data                        0     6
    render.test_glaze.osmesa                     0     8
    render.test_golden_compare                   0     6
    render.test_grout.osmesa                     0     9
    render.test_image_io                         0    13
    render.test_rect_light.osmesa                0    10
    render.test_render_api.osmesa                0     6
    render.test_tone_gpu.osmesa                  0     6
    render.test_wood_grain.osmesa                0     9
    room_setout                                  0     9
    scene_move                                   0     7
    window_daylight                              0     6
)
list(LENGTH tessera_test_costs cost_fields)
set(cost_at 0)
while(cost_at LESS cost_fields)
  math(EXPR cost_normal_at "${cost_at} + 1")
  math(EXPR cost_sanitize_at "${cost_at} + 2")
  list(GET tessera_test_costs ${cost_at} cost_test)
  list(GET tessera_test_costs ${cost_normal_at} cost)
  list(GET tessera_test_costs ${cost_sanitize_at} cost_sanitize)
  if(TEST ${cost_test})
    if(TESSERA_SANITIZE AND NOT cost_sanitize STREQUAL "-")
      set(cost ${cost_sanitize})
    endif()
    set_tests_properties(${cost_test} PROPERTIES COST ${cost})
  endif()
  math(EXPR cost_at "${cost_at} + 3")
endwhile()
