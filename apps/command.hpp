#pragma once
// Subcommand registry of the `seflex` command. Each cmd_<name>.cpp defines one command:
//
//   static int run_info(seflex::app::Args& args);
//   SEFLEX_COMMAND(info, "DECK", "counts, unsupported cards and mass properties of a model", run_info);
//
// Only apps/ prints and chooses exit codes; library errors arrive as exceptions and are turned into
// a one-line message on stderr and a non-zero exit status by main().
#include <functional>
#include <stdexcept>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace seflex::app {

/// Exit codes of the seflex command.
enum Exit : int { kOk = 0, kFailure = 1, kUsage = 2, kInputError = 3, kNotConverged = 4 };

/// Error in the command line itself (unknown option, missing value): exit code kUsage.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Minimal option parser: positional arguments and --name [value] options, in any order.
class Args {
 public:
  Args(std::string command, std::vector<std::string> argv);
  const std::string& command() const { return command_; }
  /// Next positional argument; throws UsageError naming `what` if absent.
  std::string positional(const std::string& what);
  std::optional<std::string> optional_positional();
  /// --name VALUE (also --name=VALUE); a name starting with '-' ("-o") is matched as given.
  /// nullopt if absent. Query options before positional arguments.
  std::optional<std::string> value(const std::string& name);
  std::string value_or(const std::string& name, const std::string& fallback);
  double number(const std::string& name, double fallback);
  int integer(const std::string& name, int fallback);
  bool flag(const std::string& name);
  /// Throws UsageError if anything was not consumed.
  void finish();

 private:
  std::string command_;
  std::vector<std::string> argv_;
  std::vector<bool> used_;
};

/// The text of option --`option` as a finite number > 0; otherwise UsageError
/// "option --OPTION expects EXPECTED, got 'TEXT'".
double positive_number(const std::string& option, const std::string& text, const std::string& expected);

struct Command {
  std::string name, usage, summary;
  std::function<int(Args&)> run;
};

std::map<std::string, Command>& registry();

struct Registrar {
  Registrar(const char* name, const char* usage, const char* summary, std::function<int(Args&)> run) {
    registry()[name] = Command{name, usage, summary, std::move(run)};
  }
};

}  // namespace seflex::app

#define SEFLEX_COMMAND(name, usage, summary, fn) \
  static ::seflex::app::Registrar seflex_registrar_##name(#name, usage, summary, fn)
