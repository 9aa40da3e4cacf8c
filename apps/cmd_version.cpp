// seflex version: print the version of seflex and of the libraries it was built with.
#include <Eigen/Core>
#include <iostream>

#include "command.hpp"
#include "seflex/common/version.hpp"

namespace {
int run_version(seflex::app::Args& args) {
  args.finish();
  std::cout << "seflex " << seflex::kVersion << "\n"
            << "Eigen " << EIGEN_WORLD_VERSION << "." << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << "\n";
  return seflex::app::kOk;
}
}  // namespace

SEFLEX_COMMAND(version, "", "print the version of seflex", run_version);
