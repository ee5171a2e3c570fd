# Runs cmp_benchmark on spot with one repetition and checks that it succeeds
# and writes its Markdown and CSV tables, including spot's figures (the net
# length per sqrt(area) that the `trace` stage reports).
# Usage: cmake -DBENCHMARK=<exe> -DDATA_DIR=<shared data> -DOUTPUT=<file.md> -P RunSmokeTest.cmake
cmake_policy(SET CMP0007 NEW) # table cells are list items; keep empty ones so columns line up
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

# The figures table: find the net_length_per_sqrt_area column by name (other
# stages may add figures before it) and check spot's cell there is a number.
string(FIND "${_table}" "## Figures per model" _at)
if(_at EQUAL -1)
  message(FATAL_ERROR "${OUTPUT} has no 'Figures per model' table:\n${_table}")
endif()
string(SUBSTRING "${_table}" ${_at} -1 _figures)
string(REGEX MATCH "\n\\| model \\|[^\n]*" _header "${_figures}")
string(REGEX MATCH "\n\\| spot \\|[^\n]*" _row "${_figures}")
string(REPLACE "|" ";" _header "${_header}")
string(REPLACE "|" ";" _row "${_row}")
list(FIND _header " net_length_per_sqrt_area " _column)
if(_column EQUAL -1 OR NOT _row)
  message(FATAL_ERROR "the figures table has no net_length_per_sqrt_area column or no row for spot:\n${_figures}")
endif()
list(GET _row ${_column} _value)
if(NOT _value MATCHES "^ [0-9]+(\\.[0-9]+)? $")
  message(FATAL_ERROR "spot's net_length_per_sqrt_area is '${_value}', not a number:\n${_figures}")
endif()

file(READ "${_csv}" _csvText)
if(NOT _csvText MATCHES "^[^\n]*,process_peak_mb,[^\n]*net_length_per_sqrt_area")
  message(FATAL_ERROR "${_csv} has no net_length_per_sqrt_area column:\n${_csvText}")
endif()
message(STATUS "cmp_benchmark wrote a row for spot:\n${_table}")
