# Installs fair from FAIR_BINARY_DIR into SCRATCH/prefix, then builds and runs the consumer.
file(REMOVE_RECURSE ${SCRATCH})
macro(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endmacro()
# Only the library (component Development): the consumer needs neither the program nor a full build.
run(${CMAKE_COMMAND} --install ${FAIR_BINARY_DIR} --prefix ${SCRATCH}/prefix --component Development)
# The licence every file refers to is installed with the headers.
file(GLOB_RECURSE licence ${SCRATCH}/prefix/share/doc/fair/LICENSE_1_0.txt)
if(NOT licence)
  message(FATAL_ERROR "LICENSE_1_0.txt not installed under ${SCRATCH}/prefix/share/doc/fair")
endif()
run(${CMAKE_COMMAND} -S ${FAIR_SOURCE_DIR}/test/consumer -B ${SCRATCH}/build
    -DCMAKE_PREFIX_PATH=${SCRATCH}/prefix -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${SCRATCH}/build)
run(${SCRATCH}/build/consumer)
message(STATUS "consumer output: ${out}")

# The occt component (fair::occt), where this build installed it (OpenCASCADE was found): a
# second consumer that asks for it with find_package(fair REQUIRED COMPONENTS occt).
file(GLOB_RECURSE occt_targets ${SCRATCH}/prefix/fairOcctTargets.cmake)
if(occt_targets)
  run(${CMAKE_COMMAND} -S ${FAIR_SOURCE_DIR}/test/consumer/occt -B ${SCRATCH}/build-occt
      -DCMAKE_PREFIX_PATH=${SCRATCH}/prefix -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${SCRATCH}/build-occt)
  run(${SCRATCH}/build-occt/consumer_occt)
  message(STATUS "occt consumer output: ${out}")
else()
  message(STATUS "fair::occt not installed (no OpenCASCADE at build time): no occt consumer")
endif()
