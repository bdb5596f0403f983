# Installs fair from FAIR_BINARY_DIR into SCRATCH/prefix, then builds and runs a consumer of the
# installed package (test/CMakeLists.txt registers one ctest test per MODE, each with its own
# SCRATCH):
#   MODE core (default)  test/consumer: find_package(fair REQUIRED COMPONENTS io), every installed
#                        public header in one translation unit, a κ-curve and an exact conic;
#   MODE occt            test/consumer/occt: find_package(fair REQUIRED COMPONENTS occt) and a
#                        round trip through OCCT's Geom2d_BSplineCurve; then the same configure
#                        with OpenCASCADE made unavailable (CMAKE_DISABLE_FIND_PACKAGE_OpenCASCADE)
#                        and with an OpenCASCADE_DIR whose config reports it not found: both must
#                        fail, naming the occt component and OpenCASCADE;
#   MODE arrangements    test/consumer/arrangements: examples/arrangement_intersections.cpp built
#                        against the installed package (CGAL's Bezier arrangement traits, CORE).
if(NOT MODE)
  set(MODE core)
endif()
file(REMOVE_RECURSE ${SCRATCH})
macro(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endmacro()
# Only the library (component Development): the consumer needs neither the program nor a full build.
run(${CMAKE_COMMAND} --install ${FAIR_BINARY_DIR} --prefix ${SCRATCH}/prefix --component Development)

if(MODE STREQUAL "core")
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

elseif(MODE STREQUAL "occt")
  # This test is registered only where the build found OpenCASCADE: the component must be installed.
  file(GLOB_RECURSE occt_targets ${SCRATCH}/prefix/fairOcctTargets.cmake)  # (recursive: under lib*/cmake/fair)
  if(NOT occt_targets)
    message(FATAL_ERROR "fairOcctTargets.cmake not installed under ${SCRATCH}/prefix, although the build has fair::occt")
  endif()
  run(${CMAKE_COMMAND} -S ${FAIR_SOURCE_DIR}/test/consumer/occt -B ${SCRATCH}/build-occt
      -DCMAKE_PREFIX_PATH=${SCRATCH}/prefix -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${SCRATCH}/build-occt)
  run(${SCRATCH}/build-occt/consumer_occt)
  message(STATUS "occt consumer output: ${out}")

  # Without OpenCASCADE the component is not found, and the configure step says why (the reason
  # fairConfig.cmake gives). Last, a package installed without the component says so.
  file(WRITE ${SCRATCH}/broken-occt/OpenCASCADEConfig.cmake
       "# a broken OpenCASCADE installation: its config reports it not found\nset(OpenCASCADE_FOUND FALSE)\n")
  foreach(how "-DCMAKE_DISABLE_FIND_PACKAGE_OpenCASCADE=ON" "-DOpenCASCADE_DIR=${SCRATCH}/broken-occt" "no fairOcctTargets.cmake")
    set(expected "needs OpenCASCADE with TKG2d, TKMath")
    set(option ${how})
    if(how STREQUAL "no fairOcctTargets.cmake")
      file(REMOVE ${occt_targets})
      set(expected "is not installed: this fair was built without OpenCASCADE")
      set(option)
    endif()
    string(MAKE_C_IDENTIFIER "${how}" tag)
    execute_process(COMMAND ${CMAKE_COMMAND} -S ${FAIR_SOURCE_DIR}/test/consumer/occt -B ${SCRATCH}/no-occt-${tag}
                            -DCMAKE_PREFIX_PATH=${SCRATCH}/prefix ${option}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 0)
      message(FATAL_ERROR "find_package(fair REQUIRED COMPONENTS occt) succeeded without OpenCASCADE (${how})")
    endif()
    string(REGEX REPLACE "[ \n]+" " " said "${err}")
    if(NOT said MATCHES "Reason given by package: fair: the component occt \\(fair::occt\\) ${expected}")
      message(FATAL_ERROR "without OpenCASCADE (${how}) the configure failed without saying \"${expected}\":\n${err}")
    endif()
    string(REGEX MATCH "fair: the component occt[^.]*" said "${said}")
    message(STATUS "without OpenCASCADE (${how}): ${said}")
  endforeach()

elseif(MODE STREQUAL "arrangements")
  run(${CMAKE_COMMAND} -S ${FAIR_SOURCE_DIR}/test/consumer/arrangements -B ${SCRATCH}/build-arrangements
      -DCMAKE_PREFIX_PATH=${SCRATCH}/prefix -DCMAKE_BUILD_TYPE=Release -DFAIR_EXAMPLES_DIR=${FAIR_SOURCE_DIR}/examples)
  run(${CMAKE_COMMAND} --build ${SCRATCH}/build-arrangements)
  run(${SCRATCH}/build-arrangements/consumer_arrangements)
  message(STATUS "arrangements consumer output: ${out}")

else()
  message(FATAL_ERROR "run_consumer_test.cmake: unknown MODE ${MODE}")
endif()
