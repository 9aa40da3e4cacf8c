#pragma once
// Plain CSV result tables: a header line, then one line per row. Numbers are written in the
// shortest form that reads back to the same double (std::to_chars), so integers print as integers.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace seflex::io {

/// Write `rows` (one line each, columns.size() values per row) under the header `columns`.
/// Throws InputError (naming the file) if it exists and !overwrite, or cannot be written.
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& columns,
               const Eigen::Ref<const Eigen::MatrixXd>& rows, bool overwrite = false);

/// Throws InputError (naming the file) if `path` exists and !overwrite: for commands that check
/// their outputs before they compute.
void check_writable(const std::filesystem::path& path, bool overwrite);

}  // namespace seflex::io
