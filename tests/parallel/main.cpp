// main() of the distributed-backend tests: run under `mpirun -n P` (tests/CMakeLists.txt). Every rank
// runs every test (the backends are collective); rank 0 prints the results; the exit status is
// non-zero on every rank if a test failed on any.
#include <gtest/gtest.h>

#include "seflex/parallel/session.hpp"

namespace seflex::parallel {
namespace {
Session* the_session = nullptr;
}
Session& test_session() { return *the_session; }
}  // namespace seflex::parallel

int main(int argc, char** argv) {
  seflex::parallel::Session session;
  seflex::parallel::the_session = &session;
  ::testing::InitGoogleTest(&argc, argv);
  if (session.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int local = RUN_ALL_TESTS();
  std::optional<seflex::parallel::Failure> mine;
  if (local != 0) mine = seflex::parallel::Failure{1, "a test failed", session.rank()};
  return session.agree(mine) ? 1 : 0;
}
