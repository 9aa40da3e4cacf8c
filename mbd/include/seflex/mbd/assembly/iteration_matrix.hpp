#pragma once
// The coefficients of the Newton iteration matrix (assembly.hpp: AssemblyOptions::iteration,
// combine_matrices; Data::S_flex).
#include <Eigen/Core>
#include <vector>

namespace seflex::mbd {

/// The Newton iteration matrix cK K T + cC C + cM M that combine_matrices will form (T: the Free
/// nodes' rotation tangent operators in the order of Model::rotation_dof_starts, or none).
struct IterationMatrix {
  double cK = 1.0, cC = 0.0, cM = 0.0;
  const std::vector<Eigen::Matrix3d>* rotation_jacobians = nullptr;
};

}  // namespace seflex::mbd
