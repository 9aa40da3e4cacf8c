#pragma once
// Writing an output file (superelement file, DMIG deck, OP4 matrices): refuse to overwrite unless
// asked, write to a temporary file and rename it into place so that a failure never leaves half a file.
#include <filesystem>
#include <fstream>
#include <string>

#include "seflex/common/error.hpp"

namespace seflex::io::detail {

inline void write_file_atomically(const std::filesystem::path& path, const std::string& bytes, bool overwrite) {
  if (!overwrite && std::filesystem::exists(path))
    throw InputError(SourceRef{path.string(), 0},
                     "exists already; refusing to overwrite it (use --force to replace it)");
  std::filesystem::path tmp = path;
  tmp += ".tmp-seflex";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw InputError(SourceRef{path.string(), 0}, "cannot be written (check the folder exists and is writable)");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw InputError(SourceRef{path.string(), 0}, "write failed (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(SourceRef{path.string(), 0}, "cannot be replaced: " + ec.message());
  }
}

}  // namespace seflex::io::detail
