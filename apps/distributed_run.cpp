// The front end of distributed runs (distributed_run.hpp).
#include "distributed_run.hpp"

#include <cstdio>
#include <iostream>
#include <new>

#include "command.hpp"
#include "seflex/common/error.hpp"

namespace seflex::app {

bool distributed_backend_requested(const std::string& value) {
  if (value == "serial") return false;
  if (value != "slepc") throw UsageError("option --backend expects serial or slepc, got '" + value + "'");
#ifdef SEFLEX_HAVE_MPI
  return true;
#else
  throw UsageError("--backend slepc: this seflex was built without the distributed backend (SEFLEX_MPI=OFF: PETSc, "
                   "SLEPc or MPI were not found when it was configured; scripts/install-deps.sh installs them)");
#endif
}

#ifdef SEFLEX_HAVE_MPI
namespace {

/// Thrown by checkpoint() when another rank failed: carries that rank's failure.
struct RemoteFailure {
  parallel::Failure failure;
};

}  // namespace

void checkpoint(const parallel::Session& session) {
  if (auto f = session.agree(std::nullopt)) throw RemoteFailure{*f};
}

int run_distributed(const std::string& command, const std::function<int(parallel::Session&)>& body) {
  std::unique_ptr<parallel::Session> session;
  try {
    session = parallel_backend().open_session();
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kFailure;
  }
  parallel::Session& s = *session;
  // Only rank 0 talks: the other ranks compute the same tables, which would repeat it P times.
  // (stderr too: card-usage warnings; the failure message is printed by rank 0 below.)
  if (s.rank() != 0) {
    if (std::freopen("/dev/null", "w", stdout) == nullptr) std::fclose(stdout);
    if (std::freopen("/dev/null", "w", stderr) == nullptr) std::fclose(stderr);
  }
  std::optional<parallel::Failure> local, agreed;
  int code = kOk;
  auto fail = [&](int exit_code, const std::string& message) { local = parallel::Failure{exit_code, message, s.rank()}; };
  try {
    code = body(s);
  } catch (const RemoteFailure& r) {
    agreed = r.failure;
  } catch (const parallel::PeerFailure&) {
    // another rank failed inside a collective call: its message arrives through agree() below
  } catch (const UsageError& e) {
    fail(kUsage, std::string("seflex ") + command + ": " + e.what());
  } catch (const InputError& e) {
    fail(kInputError, e.what());
  } catch (const ConvergenceError& e) {
    fail(kNotConverged, e.what());
  } catch (const std::bad_alloc&) {
    fail(kFailure, "out of memory");
  } catch (const std::exception& e) {
    fail(kFailure, e.what());
  }
  std::fflush(stdout);
  if (!agreed) {
    try {
      agreed = s.agree(local);
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      return kFailure;
    }
  }
  if (!agreed) return code;
  if (s.rank() == 0) {
    std::cerr << "error: " << agreed->message;
    if (s.size() > 1) std::cerr << " (rank " << agreed->rank << " of " << s.size() << ")";
    std::cerr << "\n";
  }
  return agreed->exit_code;
}
#endif

}  // namespace seflex::app
