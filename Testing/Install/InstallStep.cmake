# A step of the install tests (Testing/Install/CMakeLists.txt) that needs a
# fresh folder:
#
#   cmake -DSTEP=install -DBUILD_DIR=B -DPREFIX=P -P InstallStep.cmake
#     `cmake --install B --prefix P` into an emptied P;
#   cmake -DSTEP=configure -DSOURCE_DIR=S -DBINARY_DIR=D -DPREFIX=P -DGENERATOR=G -DBUILD_TYPE=T
#         -DCC=C_COMPILER -DCXX=CXX_COMPILER -P InstallStep.cmake
#     configures S as a project of its own in an emptied D with only P on
#     CMAKE_PREFIX_PATH, and fails unless find_package(CMP) found P's package.

function(_cmp_run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${result}): ${command}")
  endif()
endfunction()

if(STEP STREQUAL "install")
  file(REMOVE_RECURSE "${PREFIX}")
  _cmp_run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}")
elseif(STEP STREQUAL "configure")
  file(REMOVE_RECURSE "${BINARY_DIR}")
  _cmp_run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${BINARY_DIR}" -G "${GENERATOR}"
    "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}" "-DCMAKE_PREFIX_PATH=${PREFIX}" "-DCMAKE_C_COMPILER=${CC}" "-DCMAKE_CXX_COMPILER=${CXX}")
  file(STRINGS "${BINARY_DIR}/CMakeCache.txt" cmp_dir REGEX "^CMP_DIR:")
  string(FIND "${cmp_dir}" "=${PREFIX}/" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "find_package(CMP) did not find the install in ${PREFIX}: ${cmp_dir}")
  endif()
  message(STATUS "${cmp_dir}")
else()
  message(FATAL_ERROR "unknown STEP '${STEP}'")
endif()
