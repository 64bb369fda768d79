# Fails when docs/gallery.md differs from `gallery --markdown` (run: cmake -DPROGRAM=.. -DPAGE=.. -P ..).
execute_process(COMMAND ${PROGRAM} --markdown OUTPUT_VARIABLE page RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --markdown failed (${rc})")
endif()
file(READ ${PAGE} committed)
if(NOT page STREQUAL committed)
  message(FATAL_ERROR "${PAGE} is stale: regenerate it with `${PROGRAM} --markdown > ${PAGE}`")
endif()
