# The catalog database tests (catalog.db_*), include()d from tests/catalog/CMakeLists.txt.
# Plain C executables linking tessera_catalog (and SQLite, to look behind the API), and CLI
# tests that run the tessera binary on catalogs in this build folder.
set(CAT_DB_SOURCE "${CMAKE_SOURCE_DIR}/assets/catalog")

foreach(name test_db_schema test_db_import test_db_mounting test_db_hostile test_db_search test_db_shipped test_db_faults
             test_db_roundtrip test_db_search_words test_db_pattern)
  add_executable(${name} ${CMAKE_CURRENT_LIST_DIR}/${name}.c)
  target_link_libraries(${name} PRIVATE tessera_catalog)
  target_include_directories(${name} PRIVATE ${CMAKE_SOURCE_DIR}/tests/common)
  target_compile_definitions(${name} PRIVATE TESSERA_CATALOG_SOURCE="${CAT_DB_SOURCE}")
  string(REPLACE "test_db_" "db_" test_name ${name})
  add_test(NAME catalog.${test_name} COMMAND ${name})
  set_tests_properties(catalog.${test_name} PROPERTIES LABELS unit)
endforeach()
set_tests_properties(catalog.db_mounting PROPERTIES LABELS "catalog;unit" TIMEOUT 60)
set_tests_properties(catalog.db_pattern PROPERTIES LABELS "catalog;unit" TIMEOUT 60)

# Colour words against finishes; German compound words (one executable, one test each).
add_executable(test_db_search_finishes ${CMAKE_CURRENT_LIST_DIR}/test_db_search_finishes.c)
target_link_libraries(test_db_search_finishes PRIVATE tessera_catalog)
target_include_directories(test_db_search_finishes PRIVATE ${CMAKE_SOURCE_DIR}/tests/common
                                                           ${CMAKE_CURRENT_LIST_DIR})
target_compile_definitions(test_db_search_finishes PRIVATE TESSERA_CATALOG_SOURCE="${CAT_DB_SOURCE}")
add_test(NAME catalog.db_search_finishes COMMAND test_db_search_finishes finishes)
add_test(NAME catalog.db_search_compounds COMMAND test_db_search_finishes compounds)
set_tests_properties(catalog.db_search_finishes catalog.db_search_compounds
                     PROPERTIES LABELS "catalog;unit" TIMEOUT 60)

# The readers' open: read-only when current, brought up to date otherwise.
add_executable(test_db_open_read ${CMAKE_CURRENT_LIST_DIR}/test_db_open_read.c)
target_link_libraries(test_db_open_read PRIVATE tessera_catalog_db)
target_include_directories(test_db_open_read PRIVATE ${CMAKE_SOURCE_DIR}/tests/common)
target_compile_definitions(test_db_open_read PRIVATE TESSERA_CATALOG_SOURCE="${CAT_DB_SOURCE}")
add_test(NAME catalog.db_open_read COMMAND test_db_open_read)
set_tests_properties(catalog.db_open_read PROPERTIES LABELS "catalog;unit" TIMEOUT 60)

# A search in this process while `tessera catalog import` runs in another; racing builds.
add_executable(test_db_concurrent ${CMAKE_CURRENT_LIST_DIR}/test_db_concurrent.c)
target_link_libraries(test_db_concurrent PRIVATE tessera_catalog)
target_include_directories(test_db_concurrent PRIVATE ${CMAKE_SOURCE_DIR}/tests/common)
target_compile_definitions(test_db_concurrent PRIVATE TESSERA_CATALOG_SOURCE="${CAT_DB_SOURCE}")
add_test(NAME catalog.db_concurrent COMMAND test_db_concurrent $<TARGET_FILE:tessera>)
set_tests_properties(catalog.db_concurrent PROPERTIES LABELS "catalog;unit" TIMEOUT 120)

# The command line, each test on a catalog file of its own (built on first use).
set(CAT_DB_CLI ${CMAKE_CURRENT_BINARY_DIR}/db-cli)
file(MAKE_DIRECTORY ${CAT_DB_CLI})
file(WRITE ${CAT_DB_CLI}/bad-rows.csv
     "manufacturer,article,gtin,category,name,width_mm,depth_mm,height_mm,list_price\n"
     "Cli,C-1,4006381333931,basins,Good basin,600,550,175,259.00\n"
     "Cli,C-2,4006381333932,basins,Bad GTIN,600,550,175,259.00\n"
     "Cli,C-3,,sinks,Bad category,600,550,175,259.00\n")
file(WRITE ${CAT_DB_CLI}/bad-mounting.csv
     "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price,mounting_height_mm,mounting_to,companions\n"
     "Cli,M-1,basins,Basin,600,550,175,259.00,-850,rim,\n"
     "Cli,M-2,vanity_units,Vanity,600,460,520,599.00,680,top,M-1;NO-SUCH\n")
file(WRITE ${CAT_DB_CLI}/bad-pattern.csv
     "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price,variant_code,variant_name,pattern,grain\n"
     "Cli,P-1,vanity_units,Vanity,600,460,520,599.00,OK,Oak,marble,\n"
     "Cli,P-2,vanity_units,Vanity,600,460,520,599.00,OK,Oak,wood,diagonal\n")
# tessera_add_test (tests/common/tessera_test.cmake) checks the exit code with the output and
# fails on any sanitizer report.
tessera_add_test(NAME catalog.db_cli_search
                 COMMAND tessera catalog search thermostatic bath --category taps_mixers
                         --max-width 400 --limit 5 --db ${CAT_DB_CLI}/search.sqlite
                 EXPECT_OUTPUT "thermostatic bath mixer, exposed +taps_mixers +300 x 195 x 110"
                 LABELS unit)
# German words through folding and synonyms; every word required, the one that matches nothing
# named.
tessera_add_test(NAME catalog.db_cli_search_german
                 COMMAND tessera catalog search "Weiß" --db ${CAT_DB_CLI}/search-de.sqlite
                 EXPECT_OUTPUT "Weiss field tile 100 x 100" "Calacatta Bianco field tile"
                 LABELS unit)
tessera_add_test(NAME catalog.db_cli_search_unmatched
                 COMMAND tessera catalog search tile purple --db ${CAT_DB_CLI}/search-de.sqlite
                 EXPECT_STDERR "0 products" "no match for 'purple'" LABELS unit)
tessera_add_test(NAME catalog.db_cli_show
                 COMMAND tessera catalog show NK-51244.00 --manufacturer nordkeram
                         --db ${CAT_DB_CLI}/show.sqlite
                 EXPECT_OUTPUT "Fjord back-to-wall WC, rimless.*GTIN +7351234[0-9]+.*variants \\(3\\)"
                 LABELS unit)
tessera_add_test(NAME catalog.db_cli_import_bad
                 COMMAND tessera catalog import ${CAT_DB_CLI}/bad-rows.csv
                         --db ${CAT_DB_CLI}/import.sqlite
                 EXPECT_RC 1 2
                 EXPECT_STDERR "bad-rows.csv:3: column gtin: check digit"
                               "bad-rows.csv:4: column category"
                               "2 problems in 3 rows; nothing was imported"
                 LABELS unit)
tessera_add_test(NAME catalog.db_cli_export_import
                 COMMAND sh -c "\"$0\" catalog export -o \"$1/export.csv\" --db \"$1/rt.sqlite\" && \"$0\" catalog import \"$1/export.csv\" --db \"$1/rt.sqlite\""
                         $<TARGET_FILE:tessera> ${CAT_DB_CLI}
                 EXPECT_OUTPUT "rows, 0 products added, [1-9][0-9]* updated" LABELS unit)
tessera_add_test(NAME catalog.db_cli_bad_option
                 COMMAND tessera catalog search tap --colour red
                 EXPECT_RC 1 2 EXPECT_STDERR "unknown option \"--colour\"" LABELS unit)
tessera_add_test(NAME catalog.db_cli_not_found
                 COMMAND tessera catalog show NO-SUCH-1 --db ${CAT_DB_CLI}/show.sqlite
                 EXPECT_RC 1 2 EXPECT_STDERR "no product with article number or GTIN \"NO-SUCH-1\""
                 LABELS unit)
# Nonsense mounting data is refused with the file, the line and the column
# (docs/catalog.md "Mounting heights and companions").
tessera_add_test(NAME catalog.db_cli_import_bad_mounting
                 COMMAND tessera catalog import ${CAT_DB_CLI}/bad-mounting.csv
                         --db ${CAT_DB_CLI}/bad-mounting.sqlite
                 EXPECT_RC 2
                 EXPECT_STDERR "bad-mounting.csv:2: column mounting_height_mm: must be between 0 and 4000"
                               "bad-mounting.csv:3: column companions: companion 2, Cli NO-SUCH, is neither"
                 LABELS "catalog;unit" TIMEOUT 60)
# An unknown pattern word and a grain that is no direction, named with file, line and value
# (docs/catalog.md "The import format").
tessera_add_test(NAME catalog.db_cli_import_bad_pattern
                 COMMAND tessera catalog import ${CAT_DB_CLI}/bad-pattern.csv
                         --db ${CAT_DB_CLI}/bad-pattern.sqlite
                 EXPECT_RC 2
                 EXPECT_STDERR "bad-pattern.csv:2: column pattern: unknown pattern \"marble\" (known: none, wood)"
                               "bad-pattern.csv:3: column grain: must be horizontal, vertical or an angle of 0 to 180 degrees, got \"diagonal\""
                 LABELS "catalog;unit" TIMEOUT 60)
