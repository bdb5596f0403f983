# bench_optimal_peer times OCCT's FairCurve_Batten beside fair::Optimal_curve_2 when OCCT is
# installed (a benchmark dependency only; see test/optimal_fit/optional.cmake for the packages).
find_package(OpenCASCADE QUIET)
if(OpenCASCADE_FOUND AND TARGET TKGeomAlgo)
  target_compile_definitions(${name} PRIVATE FAIR_HAVE_OCCT=1)
  target_include_directories(${name} SYSTEM PRIVATE ${OpenCASCADE_INCLUDE_DIR})
  target_link_libraries(${name} PRIVATE TKGeomAlgo TKG2d TKMath TKernel)
endif()
