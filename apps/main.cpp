// The seflex command: dispatches to the registered subcommands (cmd_*.cpp) and turns exceptions into
// a one-line diagnosis and an exit status.
#include <cmath>
#include <cctype>
#include <cstdio>
#include <exception>
#include <iostream>
#include <stdexcept>

#include "command.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/version.hpp"
#include "seflex/linalg/blas_threads.hpp"

namespace seflex::app {

std::map<std::string, Command>& registry() {
  static std::map<std::string, Command> commands;
  return commands;
}

Args::Args(std::string command, std::vector<std::string> argv)
    : command_(std::move(command)), argv_(std::move(argv)), used_(argv_.size(), false) {}

std::optional<std::string> Args::optional_positional() {
  for (std::size_t i = 0; i < argv_.size(); ++i) {
    if (used_[i]) continue;
    const std::string& a = argv_[i];
    if (a.size() > 1 && a[0] == '-' && !(a.size() > 1 && (std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.'))) {
      // an option: skip it and its value (values are consumed when the option is queried)
      continue;
    }
    used_[i] = true;
    return a;
  }
  return std::nullopt;
}

std::string Args::positional(const std::string& what) {
  auto p = optional_positional();
  if (!p) throw UsageError("missing " + what);
  return *p;
}

std::optional<std::string> Args::value(const std::string& name) {
  const std::string key = name.rfind('-', 0) == 0 ? name : "--" + name;  // "-o" is a short option as given
  for (std::size_t i = 0; i < argv_.size(); ++i) {
    if (used_[i]) continue;
    if (argv_[i] == key) {
      if (i + 1 >= argv_.size()) throw UsageError("option " + key + " needs a value");
      used_[i] = used_[i + 1] = true;
      return argv_[i + 1];
    }
    if (argv_[i].rfind(key + "=", 0) == 0) {
      used_[i] = true;
      return argv_[i].substr(key.size() + 1);
    }
  }
  return std::nullopt;
}

std::string Args::value_or(const std::string& name, const std::string& fallback) {
  auto v = value(name);
  return v ? *v : fallback;
}

double Args::number(const std::string& name, double fallback) {
  auto v = value(name);
  if (!v) return fallback;
  try {
    std::size_t pos = 0;
    double x = std::stod(*v, &pos);
    if (pos != v->size()) throw std::invalid_argument("trailing");
    return x;
  } catch (const std::exception&) {
    throw UsageError("option --" + name + " expects a number, got '" + *v + "'");
  }
}

double positive_number(const std::string& option, const std::string& text, const std::string& expected) {
  std::size_t pos = 0;
  double x = 0;
  try {
    x = std::stod(text, &pos);
  } catch (const std::exception&) {
    pos = 0;
  }
  if (pos == 0 || pos != text.size() || !std::isfinite(x) || !(x > 0))
    throw UsageError("option --" + option + " expects " + expected + ", got '" + text + "'");
  return x;
}

int Args::integer(const std::string& name, int fallback) {
  auto v = value(name);
  if (!v) return fallback;
  try {
    std::size_t pos = 0;
    int x = std::stoi(*v, &pos);
    if (pos != v->size()) throw std::invalid_argument("trailing");
    return x;
  } catch (const std::exception&) {
    throw UsageError("option --" + name + " expects an integer, got '" + *v + "'");
  }
}

bool Args::flag(const std::string& name) {
  const std::string key = "--" + name;
  for (std::size_t i = 0; i < argv_.size(); ++i)
    if (!used_[i] && argv_[i] == key) {
      used_[i] = true;
      return true;
    }
  return false;
}

void Args::finish() {
  for (std::size_t i = 0; i < argv_.size(); ++i)
    if (!used_[i]) throw UsageError("unexpected argument '" + argv_[i] + "'");
}

}  // namespace seflex::app

namespace {
void print_help() {
  std::cout << "seflex " << seflex::kVersion
            << " - Craig-Bampton superelements in flexible multibody dynamics\n\n"
               "usage: seflex <command> [arguments]\n\ncommands:\n";
  for (const auto& [name, c] : seflex::app::registry())
    std::cout << "  " << name << " " << c.usage << "\n      " << c.summary << "\n";
  std::cout << "\nseflex <command> --help prints the usage of one command.\n";
}
}  // namespace

int main(int argc, char** argv) {
  using namespace seflex::app;
  // OpenBLAS's workers, started when the library was loaded, would spin 0.13 s of CPU waiting for
  // work; the reduction's first multithreaded call starts them again (blas_threads.hpp).
  seflex::linalg::release_idle_blas_threads();
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" || std::string(argv[1]) == "help") {
    print_help();
    return argc < 2 ? kUsage : kOk;
  }
  if (std::string(argv[1]) == "--version") {
    std::cout << "seflex " << seflex::kVersion << "\n";
    return kOk;
  }
  const std::string name = argv[1];
  auto it = registry().find(name);
  if (it == registry().end()) {
    std::cerr << "seflex: unknown command '" << name << "' (seflex --help lists the commands)\n";
    return kUsage;
  }
  std::vector<std::string> rest(argv + 2, argv + argc);
  for (const auto& a : rest)
    if (a == "--help" || a == "-h") {
      std::cout << "usage: seflex " << name << " " << it->second.usage << "\n  " << it->second.summary << "\n";
      return kOk;
    }
  try {
    Args args(name, rest);
    return it->second.run(args);
  } catch (const UsageError& e) {
    std::cerr << "seflex " << name << ": " << e.what() << "\nusage: seflex " << name << " " << it->second.usage << "\n";
    return kUsage;
  } catch (const seflex::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kInputError;
  } catch (const seflex::ConvergenceError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kNotConverged;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return kFailure;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kFailure;
  }
}
