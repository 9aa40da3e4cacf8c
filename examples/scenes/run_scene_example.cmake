# CTest driver of a scene example: copies the scene and its deck to OUT, reduces the deck with
# `seflex reduce` (the command in the scene's header), runs `seflex run`, and checks the results.
# Variables: SEFLEX (the seflex executable), SRC (examples/scenes), NAME (scene stem), OUT.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(COPY ${SRC}/${NAME}.yaml ${SRC}/link.bdf DESTINATION ${OUT})
execute_process(COMMAND ${SEFLEX} reduce link.bdf --interface 1,5 --frame 3 --modes 3 -o link.se
                WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "seflex reduce failed (${rc})")
endif()
execute_process(COMMAND ${SEFLEX} run ${NAME}.yaml -o results WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "seflex run ${NAME}.yaml failed (${rc})")
endif()
foreach(f history.csv events.csv poses.csv summary.json summary.txt animation.pvd)
  if(NOT EXISTS ${OUT}/results/${f})
    message(FATAL_ERROR "seflex run did not write ${f}")
  endif()
endforeach()
file(READ ${OUT}/results/summary.json summary)
if(NOT summary MATCHES "\"status\": \"ok\"")
  message(FATAL_ERROR "run status is not ok: ${summary}")
endif()
