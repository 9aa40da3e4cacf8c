#pragma once
// Errors of seflex, in three tiers (docs/architecture.md):
//  1. InputError: something a user wrote is wrong. Always checked; the message names the file, line,
//     card or key, the field, and what was expected, e.g.
//     "panel.bdf:57: CQUAD4 1203, field 3 (PID): references PSHELL 7, which is not defined".
//  2. InvariantError (SEFLEX_DEMAND): a promise of the code itself is broken (a bug or a numerical
//     breakdown such as a singular matrix). Always checked.
//  3. SEFLEX_DEBUG_ASSERT: expensive consistency checks, compiled only into Debug builds.
// Library code throws; only apps/ prints and chooses the exit status.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace seflex {

/// Where something came from in a user's file; line is 1-based, 0 means "whole file / unknown".
struct SourceRef {
  std::string file;
  int line = 0;
  std::string str() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};

/// Base of all seflex errors.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A user-input problem (file, card, field, scene key). what() is the full, user-facing message.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(message) {}
  InputError(const SourceRef& where, const std::string& message)
      : Error(where.str().empty() ? message : where.str() + ": " + message), where_(where) {}
  const SourceRef& where() const { return where_; }

 private:
  SourceRef where_;
};

/// A broken internal promise or a numerical breakdown (singular matrix, no convergence).
class InvariantError : public Error {
 public:
  using Error::Error;
};

/// A computation that stopped without converging (Newton, eigensolver); carries a diagnosis.
class ConvergenceError : public Error {
 public:
  using Error::Error;
};

namespace detail {
[[noreturn]] inline void demand_failed(const char* cond, const char* file, int line, const std::string& msg) {
  throw InvariantError(std::string(file) + ":" + std::to_string(line) + ": invariant (" + cond + ") failed" +
                       (msg.empty() ? std::string() : ": " + msg));
}
}  // namespace detail
}  // namespace seflex

/// Always-on invariant check. Write conditions so that NaN fails them (e.g. `x < tol`, not `!(x >= tol)`).
#define SEFLEX_DEMAND(cond, msg)                                                        \
  do {                                                                                  \
    if (!(cond)) ::seflex::detail::demand_failed(#cond, __FILE__, __LINE__, (msg));     \
  } while (0)

#ifdef SEFLEX_DEBUG_CHECKS
#define SEFLEX_DEBUG_ASSERT(cond, msg) SEFLEX_DEMAND(cond, msg)
#else
#define SEFLEX_DEBUG_ASSERT(cond, msg) \
  do {                                 \
  } while (0)
#endif
