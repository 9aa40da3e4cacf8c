#pragma once
// The superelement file (.se): a versioned, self-describing, checksummed container for a
// se::Superelement. Format specification: docs/superelement-format.md (a reference reader in Python
// is scripts/read_superelement.py).
//
// Layout: magic "SEFLEXSE", format version, a JSON header (metadata + a table of datasets), the
// datasets as raw little-endian column-major arrays, and a trailer with the SHA-256 of all bytes
// before it. Save then load is bit-exact.
#include <filesystem>
#include <string>

#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

inline constexpr int kSuperelementFormatMajor = 1;
inline constexpr int kSuperelementFormatMinor = 1;

struct SaveOptions {
  bool overwrite = false;  ///< refuse to replace an existing file unless set
};

/// Write `se` to `path` (atomically: a temporary file renamed into place).
/// Throws InputError if the file exists and !overwrite, or cannot be written; InvariantError if the
/// superelement is inconsistent (se::check_consistency) or holds non-finite numbers.
void save_superelement(const se::Superelement& se, const std::filesystem::path& path, const SaveOptions& options = {});

/// Read a superelement file. Checks magic, format version, header, sizes, the SHA-256 trailer
/// (truncation and corruption), finiteness and symmetry; throws InputError naming the file and
/// what is wrong.
se::Superelement load_superelement(const std::filesystem::path& path);

/// Same, from bytes already in memory (`name` is used in messages).
se::Superelement parse_superelement(const std::string& bytes, const std::string& name);

/// Serialise to bytes (what save_superelement writes).
std::string serialize_superelement(const se::Superelement& se);

}  // namespace seflex::io
