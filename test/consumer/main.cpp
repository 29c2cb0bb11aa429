// Computes something with the installed library and checks it exactly.
#include <cvms/rational.hpp>
#include <cvms/vec.hpp>

#include <cstdio>

int main() {
  cvms::Vec3 a{cvms::parse_rational("0.1"), 0, 0};
  cvms::Vec3 b{cvms::parse_rational("0.2"), 0, 0};
  if ((a + b).x != cvms::parse_rational("0.3")) {
    std::puts("consumer: 0.1 + 0.2 != 0.3");
    return 1;
  }
  std::puts("consumer: ok");
  return 0;
}
