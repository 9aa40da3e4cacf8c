// Factory and names of the sparse factorisation backends.
#include "seflex/linalg/sparse_factorization.hpp"

#include "backends.hpp"

namespace seflex::linalg {

std::string_view to_string(FactorizationBackend backend) {
  switch (backend) {
    case FactorizationBackend::Cholmod: return "cholmod";
    case FactorizationBackend::EigenLdlt: return "ldlt";
    case FactorizationBackend::Mumps: return "mumps";
  }
  return "?";
}

std::optional<FactorizationBackend> parse_factorization_backend(std::string_view name) {
  if (name == "cholmod") return FactorizationBackend::Cholmod;
  if (name == "ldlt") return FactorizationBackend::EigenLdlt;
  return std::nullopt;
}

std::unique_ptr<SparseFactorization> make_factorization(FactorizationBackend backend) {
  switch (backend) {
    case FactorizationBackend::Cholmod: return make_cholmod_factorization();
    case FactorizationBackend::EigenLdlt: return make_ldlt_factorization();
    case FactorizationBackend::Mumps: break;  // parallel/'s, through a FactorizationMaker
  }
  SEFLEX_DEMAND(false, "make_factorization: backend " + std::string(to_string(backend)) + " is not built into linalg/");
  return nullptr;
}

}  // namespace seflex::linalg
