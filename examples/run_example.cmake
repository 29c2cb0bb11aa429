# Runs one example for ctest: cmake -DPROGRAM=... -DARGS=a|b -DEXPECT_EXIT=0
# -DEXPECT_REGEX=... -P run_example.cmake. Fails unless the program exits
# with EXPECT_EXIT and its stdout followed by its stderr matches EXPECT_REGEX.
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND "${PROGRAM}" ${args}
  RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
message("${all}")
if(NOT exit_code STREQUAL EXPECT_EXIT)
  message(FATAL_ERROR "exit code ${exit_code}, expected ${EXPECT_EXIT}")
endif()
if(NOT all MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match:\n${EXPECT_REGEX}")
endif()
