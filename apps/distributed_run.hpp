#pragma once
// The front end of `--backend slepc` runs (SEFLEX_MPI builds): every rank runs the same command body;
// only rank 0 writes to stdout and files; an error on any rank stops every rank with one message
// (docs/distributed.md).
//
//   return run_distributed([&](seflex::parallel::Session& s) { ...; checkpoint(s); ...; return kOk; });
//
// - The body's exceptions map to exit codes as in main.cpp (UsageError 2, InputError 3,
//   ConvergenceError 4, others 1). A failing rank reports at once; the others learn it at their next
//   checkpoint() (collective: place them where every rank passes, e.g. after reading the deck) or at
//   the end of the body. Every rank then returns the failing rank's exit code; rank 0 prints its
//   message to stderr.
#include <functional>
#include <string>

#ifdef SEFLEX_HAVE_MPI
#include "seflex/parallel/backend.hpp"
#include "seflex/parallel/session.hpp"

namespace seflex::app {

/// The distributed backend, its plugin loaded at the first call (apps/parallel_backend.cpp); throws
/// std::runtime_error naming the file when the plugin is missing, does not load or is from another build.
const parallel::Backend& parallel_backend();

int run_distributed(const std::string& command, const std::function<int(parallel::Session&)>& body);

/// Collective: throws (to run_distributed) if some rank failed since the last checkpoint.
void checkpoint(const parallel::Session& session);

/// True on rank 0 (the rank that writes files).
inline bool writes_files(const parallel::Session* session) { return session == nullptr || session->rank() == 0; }

}  // namespace seflex::app
#else
namespace seflex::parallel {
class Session;
}
namespace seflex::app {
inline void checkpoint(const parallel::Session&) {}
inline bool writes_files(const parallel::Session*) { return true; }
}  // namespace seflex::app
#endif

namespace seflex::app {
/// Usage text of the --backend option.
inline constexpr const char* kBackendUsage = "[--backend serial|slepc]";
/// Parses --backend (serial, the default, or slepc); throws UsageError for anything else, and for
/// slepc in a build without the distributed backend.
bool distributed_backend_requested(const std::string& value);
}  // namespace seflex::app
