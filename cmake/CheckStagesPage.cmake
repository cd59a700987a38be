# Fails when docs/stages.md differs from `plumbago stages --markdown`.
# cmake -DPLUMBAGO=<the plumbago program> -DPAGE=<docs/stages.md> -P CheckStagesPage.cmake
execute_process(COMMAND ${PLUMBAGO} stages --markdown OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "`plumbago stages --markdown` failed (${rc})")
endif()
file(READ ${PAGE} page)
if(NOT page STREQUAL generated)
  message(FATAL_ERROR "${PAGE} is out of date: run `build/plumbago stages --markdown > docs/stages.md`")
endif()
