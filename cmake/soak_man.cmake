# cmake -DSOAK=<soak> -DOUT=<soak.1> -P soak_man.cmake: the manual page, from
# `soak --man`, written only when it succeeded.
execute_process(COMMAND ${SOAK} --man OUTPUT_FILE ${OUT}.tmp RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(REMOVE ${OUT}.tmp)
  message(FATAL_ERROR "${SOAK} --man failed (${rc})")
endif()
file(RENAME ${OUT}.tmp ${OUT})
