# cli.lean_alone: the lean `tessera` copied alone into DIR runs the catalog commands itself and
# names tessera-full for anything else, exit code 1.
#   cmake -DPROGRAM=build/ui/tessera -DDIR=/tmp/x -P tests/cli/lean_alone.cmake
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
file(COPY ${PROGRAM} DESTINATION ${DIR})
set(T ${DIR}/tessera)

function(expect what rc_want out_regex err_regex)
  execute_process(COMMAND ${T} ${ARGN} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc STREQUAL rc_want OR NOT out MATCHES "${out_regex}" OR NOT err MATCHES "${err_regex}")
    message(FATAL_ERROR "${what}: tessera ${ARGN}: exit ${rc} (want ${rc_want})\n"
                        "stdout (want /${out_regex}/):\n${out}\nstderr (want /${err_regex}/):\n${err}")
  endif()
endfunction()

expect("version" 0 "^tessera [0-9]" "^$" --version)
expect("catalog search" 0 "washbasin" "" catalog search Waschtisch --db ${DIR}/catalog.sqlite)
expect("help of a full command" 0 "usage: tessera render PROJECT" "^$" help render)
expect("a full command" 1 "^$" "render needs the full program .*/tessera-full: No such file"
       render project.json -o x.png)
expect("the window" 1 "^$" "the planner window needs the full program .*/tessera-full" )
