# cmake -DCXX=<compiler> -DINCLUDE=<include dir> -DTEST_DIR=<test dir> -DSOURCES=<a|b|...> -P check_kernel_lists.cmake
#
# The ctest test `kernel_lists` (test/CMakeLists.txt). The executables of FAIR_TESTS_WITHOUT_PREDICATES
# run their typed suites without EPICK, because EPICK and SC_double differ only in the predicates
# that compute (a determinant: Orientation_2, Collinear_2, ...). This fails when one of their
# SOURCES calls such a predicate itself or includes a library header that does, so that EPICK
# comes back to the list before it is needed rather than after a missed bug.

# A call of a kernel predicate: CGAL's free functions, the functor objects of a kernel
# (k.orientation_2_object(), also matches the constructions: cautious), the functor types.
set(call "CGAL::(orientation|collinear|left_turn|right_turn|angle|side_of_[a-z_]+|bounded_side_2|compare_distance[a-z_]*|compare_slope|do_intersect|are_[a-z_]+)[ ]*\\(")
set(object "_2_object[ ]*\\(")
set(type "(Orientation|Collinear|Left_turn|Angle|Side_of_[a-z_]+|Compare_distance|Compare_slope|Do_intersect|Collinear_are_[a-z_]+)_2[^A-Za-z_]")
set(pattern "(${call}|${object}|${type})")

function(calls_predicate file result)
  file(STRINGS ${file} lines REGEX "${pattern}")
  list(FILTER lines EXCLUDE REGEX "^[ ]*//")
  set(${result} "${lines}" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE headers ${INCLUDE}/fair/*.h)
set(calling)
foreach(h IN LISTS headers)
  calls_predicate(${h} lines)
  if(lines)
    list(APPEND calling ${h})
  endif()
endforeach()
if(NOT calling)
  # internal/kappa/pieces.h calls Orientation_2 today: no match at all means the pattern is stale.
  message(FATAL_ERROR "no header of ${INCLUDE}/fair calls a kernel predicate: check the pattern of this script")
endif()
string(REPLACE "${INCLUDE}/" "" names "${calling}")
message(STATUS "headers that call a kernel predicate: ${names}")

string(REPLACE "|" ";" SOURCES "${SOURCES}")
set(failures)
foreach(src IN LISTS SOURCES)
  calls_predicate(${src} lines)
  if(lines)
    list(APPEND failures "${src} calls a kernel predicate: ${lines}")
  endif()
  # The include closure, from the compiler (-MG: a missing optional header, e.g. OCCT's, is no error).
  execute_process(COMMAND ${CXX} -std=c++17 -MM -MG -I${TEST_DIR} -I${INCLUDE} ${src}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE deps ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    list(APPEND failures "${src}: ${CXX} -MM failed: ${err}")
  endif()
  foreach(h IN LISTS calling)
    string(FIND "${deps}" "${h}" at)
    if(NOT at EQUAL -1)
      list(APPEND failures "${src} includes ${h}, which calls a kernel predicate")
    endif()
  endforeach()
endforeach()
if(failures)
  string(REPLACE ";" "\n" failures "${failures}")
  message(FATAL_ERROR "${failures}\nEPICK and SC_double differ there: remove the executable from "
                      "FAIR_TESTS_WITHOUT_PREDICATES in test/CMakeLists.txt.")
endif()
list(LENGTH SOURCES n)
message(STATUS "kernel_lists: ${n} sources reach no kernel predicate")
