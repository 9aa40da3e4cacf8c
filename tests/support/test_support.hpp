#pragma once
// Helpers shared by the tests: paths, temporary folders, and running the seflex command.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace seflex::test {

inline std::filesystem::path source_dir() { return SEFLEX_SOURCE_DIR; }
inline std::filesystem::path data_dir() { return SEFLEX_TEST_DATA; }
inline std::filesystem::path validation_dir() { return data_dir() / "validation"; }
inline std::filesystem::path seflex_bin() { return SEFLEX_BIN; }

/// A fresh temporary folder, removed when the object goes out of scope.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("seflex-test-" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  /// Write `text` to a file in this folder and return its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Largest |a_k - b_k| of two series of the same length; +infinity when the lengths differ.
inline double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

/// Rows of a numeric CSV file (the header line dropped), e.g. the --csv output of seflex.
inline std::vector<std::vector<double>> csv_rows(const std::filesystem::path& p) {
  std::istringstream in(read_file(p));
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    rows.push_back(v);
  }
  return rows;
}

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

/// Run the shell command `command` (quoted as needed) in `cwd`; captures stdout and stderr.
inline RunResult run_command(const std::string& command, const std::filesystem::path& cwd = {}) {
  TempDir tmp;
  const auto out = tmp / "stdout.txt", err = tmp / "stderr.txt";
  std::ostringstream cmd;
  if (!cwd.empty()) cmd << "cd '" << cwd.string() << "' && ";
  cmd << "{ " << command << "; } >'" << out.string() << "' 2>'" << err.string() << "'";
  const int status = std::system(cmd.str().c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

/// Run `seflex <args>` (args already shell-quoted as needed); captures stdout and stderr.
inline RunResult run_seflex(const std::string& args, const std::filesystem::path& cwd = {}) {
  return run_command("'" + seflex_bin().string() + "' " + args, cwd);
}

}  // namespace seflex::test
