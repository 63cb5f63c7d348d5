// Prints the Mini Cheetah's joint-space mass matrix at the zero configuration (trunk at the origin,
// identity orientation, all joints at 0) from the code rbdc_generate() wrote at build time.
#include <iostream>

#include "mini_cheetah/full.hpp"

int main() {
  namespace robot = rbdc_gen::mini_cheetah::full;
  robot::ConfigVector<double> q = robot::ConfigVector<double>::Zero();
  q[3] = 1;  // quaternion w
  robot::MassMatrix<double> M;
  robot::mass_matrix(q, M);
  std::cout << "Mini Cheetah mass matrix M(q0), " << robot::nv << " x " << robot::nv << ":\n"
            << M << "\n";
  return 0;
}
