#pragma once
// Factories of the backends of linalg/ (private to the library; one source file each).
#include <memory>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::linalg {

std::unique_ptr<SparseFactorization> make_cholmod_factorization();
std::unique_ptr<SparseFactorization> make_ldlt_factorization();

}  // namespace seflex::linalg
