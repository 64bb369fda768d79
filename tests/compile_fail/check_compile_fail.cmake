# cmake -DCXX=<compiler> -DINCLUDE=<lib/include> -DSOURCE=<file.cpp> -DMESSAGE=<regex> -P check_compile_fail.cmake
# Passes when SOURCE fails to compile with an error matching MESSAGE, and compiles with -DT2_CONTROL.
execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT failed)
  message(FATAL_ERROR "${SOURCE} compiled, but it must not")
endif()
if(NOT "${out}${err}" MATCHES "${MESSAGE}")
  message(FATAL_ERROR "${SOURCE} failed to compile, but not with '${MESSAGE}':\n${err}")
endif()
execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only -DT2_CONTROL -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE failed ERROR_VARIABLE err)
if(failed)
  message(FATAL_ERROR "the control build of ${SOURCE} (-DT2_CONTROL) must compile:\n${err}")
endif()
message(STATUS "${SOURCE}: rejected with '${MESSAGE}', control compiles")
