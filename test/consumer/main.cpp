// A tiny consumer of the installed package: find_package(fair) + fair::fair.
#include <fair/Errors.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <iostream>

int main() {
  typedef CGAL::Exact_predicates_exact_constructions_kernel K;
  K::Point_2 p(0, 0), q(1, 0), r(0, 1);
  try {
    fair::internal::require(CGAL::orientation(p, q, r) == CGAL::LEFT_TURN, "unexpected orientation");
  } catch (const fair::Error& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  std::cout << "fair consumer ok\n";
  return 0;
}
