// CSV result tables (results_csv.hpp).
#include "seflex/io/results_csv.hpp"

#include <charconv>
#include <fstream>

#include "seflex/common/error.hpp"

namespace seflex::io {

void check_writable(const std::filesystem::path& path, bool overwrite) {
  if (!overwrite && std::filesystem::exists(path))
    throw InputError(SourceRef{path.string(), 0}, "exists already; refusing to overwrite it (use --force)");
}

void write_csv(const std::filesystem::path& path, const std::vector<std::string>& columns,
               const Eigen::Ref<const Eigen::MatrixXd>& rows, bool overwrite) {
  SEFLEX_DEMAND(static_cast<Eigen::Index>(columns.size()) == rows.cols(), "write_csv: one header per column");
  check_writable(path, overwrite);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(SourceRef{path.string(), 0}, "cannot be opened for writing");
  for (std::size_t j = 0; j < columns.size(); ++j) out << (j ? "," : "") << columns[j];
  out << '\n';
  char buf[64];
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    for (Eigen::Index j = 0; j < rows.cols(); ++j) {
      const auto r = std::to_chars(buf, buf + sizeof buf, rows(i, j));
      if (j) out << ',';
      out.write(buf, r.ptr - buf);
    }
    out << '\n';
  }
  out.flush();
  if (!out) throw InputError(SourceRef{path.string(), 0}, "cannot be written (disk full?)");
}

}  // namespace seflex::io
