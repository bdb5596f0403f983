# bench_linear_algebra times Eigen's sparse solvers beside the library's hand-written ones when
# Eigen 3 is installed (a benchmark dependency only: the library itself does not use Eigen; see
# doc/linear_algebra.md). Without Eigen it times the hand-written solvers alone.
find_package(Eigen3 3.3 QUIET NO_MODULE)
if(TARGET Eigen3::Eigen)
  target_compile_definitions(${name} PRIVATE FAIR_HAVE_EIGEN=1)
  target_link_libraries(${name} PRIVATE Eigen3::Eigen)
endif()
