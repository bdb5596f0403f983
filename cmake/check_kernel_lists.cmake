# cmake -DINCLUDE=<include dir> -DTEST_DIR=<test dir> -DSOURCES=<a|b|...> -P check_kernel_lists.cmake
#
# The ctest test `kernel_lists` (test/CMakeLists.txt). The executables of FAIR_TESTS_WITHOUT_PREDICATES
# run their typed suites without EPICK, because EPICK and SC_double differ only in the predicates
# that compute (a determinant: Orientation_2, Collinear_2, ...). This fails when one of their
# SOURCES calls such a predicate itself or includes a library header that does, so that EPICK
# comes back to the list before it is needed rather than after a missed bug.

cmake_minimum_required(VERSION 3.18) # list(POP_FRONT), if(IN_LIST) in script mode

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

# The project headers a source reaches through #include lines: "x" relative to the including
# file, then TEST_DIR and INCLUDE; <x> in TEST_DIR and INCLUDE (the -I of the tests); anything
# else (CGAL, the standard library, OCCT) is not followed.
function(include_closure src result)
  set(queue ${src})
  set(seen)
  while(queue)
    list(POP_FRONT queue file)
    get_filename_component(here ${file} DIRECTORY)
    file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS lines)
      if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*([<\"])([^>\"]+)[>\"]")
        continue()
      endif()
      set(name ${CMAKE_MATCH_2})
      set(dirs ${TEST_DIR} ${INCLUDE})
      if(CMAKE_MATCH_1 STREQUAL "\"")
        list(PREPEND dirs ${here})
      endif()
      foreach(dir IN LISTS dirs)
        if(EXISTS ${dir}/${name} AND NOT IS_DIRECTORY ${dir}/${name})
          get_filename_component(found ${dir}/${name} ABSOLUTE)
          if(NOT found IN_LIST seen)
            list(APPEND seen ${found})
            list(APPEND queue ${found})
          endif()
          break()
        endif()
      endforeach()
    endforeach()
  endwhile()
  set(${result} "${seen}" PARENT_SCOPE)
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
  # The include closure over the project's own headers (the only ones that can be in `calling`):
  # a scan of the #include lines, conditionals ignored, so the closure is a superset of what
  # the compiler reads and a failure can be spurious but a reach is never missed. (It replaced
  # `${CXX} -MM`, which preprocessed CGAL once per source: 33 s of the release tests.)
  include_closure(${src} deps)
  if(NOT deps MATCHES "/fair/")
    list(APPEND failures "${src}: the include scan found no fair header: check include_closure in this script")
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
