# Runs cmp_benchmark on spot with one repetition and checks that it succeeds
# and writes its Markdown and CSV tables.
# Usage: cmake -DBENCHMARK=<exe> -DDATA_DIR=<shared data> -DOUTPUT=<file.md> -P RunSmokeTest.cmake
if(NOT DATA_DIR OR NOT IS_DIRECTORY "${DATA_DIR}")
  message("SKIPPED: no shared data folder (CMP_SHARED_DATA_DIR='${DATA_DIR}')")
  return()
endif()

get_filename_component(_dir "${OUTPUT}" DIRECTORY)
get_filename_component(_stem "${OUTPUT}" NAME_WLE)
set(_csv "${_dir}/${_stem}.csv")
file(REMOVE "${OUTPUT}" "${_csv}")

execute_process(
  COMMAND "${BENCHMARK}" --data "${DATA_DIR}" --only spot --repeat 1 --output "${OUTPUT}"
  RESULT_VARIABLE _result
  OUTPUT_VARIABLE _out
  ERROR_VARIABLE _err)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "cmp_benchmark exited with '${_result}'\n${_out}\n${_err}")
endif()

foreach(_file IN ITEMS "${OUTPUT}" "${_csv}")
  if(NOT EXISTS "${_file}")
    message(FATAL_ERROR "cmp_benchmark did not write ${_file}\n${_out}\n${_err}")
  endif()
endforeach()
file(READ "${OUTPUT}" _table)
if(NOT _table MATCHES "\\| spot \\| [0-9]+ \\| [0-9]+ \\|")
  message(FATAL_ERROR "${OUTPUT} has no row for spot:\n${_table}")
endif()
message(STATUS "cmp_benchmark wrote a row for spot:\n${_table}")
