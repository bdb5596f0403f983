# OCCT's FairCurve_Batten as a peer of fair::Optimal_curve_2 (issue 11 §5): a test dependency
# only, never of the library. Debian: libocct-modeling-algorithms-dev libocct-modeling-data-dev
# libocct-foundation-dev libtbb-dev (OCCT's CMake config needs TBB). Without them the peer test
# is simply not built.
find_package(OpenCASCADE QUIET)
if(OpenCASCADE_FOUND AND TARGET TKGeomAlgo)
  target_sources(test_${part} PRIVATE ${folder}/occt_batten.cpp)
  target_include_directories(test_${part} SYSTEM PRIVATE ${OpenCASCADE_INCLUDE_DIR})
  target_link_libraries(test_${part} PRIVATE TKGeomAlgo TKG2d TKMath TKernel)
  message(STATUS "fair: test_${part} compares with OCCT ${OpenCASCADE_VERSION} (FairCurve_Batten)")
else()
  message(STATUS "fair: OCCT not found, test_${part} without the FairCurve_Batten peer")
endif()
