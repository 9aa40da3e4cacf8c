#pragma once
// The superelement file (.se): a versioned, self-describing, checksummed container for a
// se::Superelement. Format specification: docs/superelement-format.md (a reference reader in Python
// is scripts/read_superelement.py).
//
// Layout: magic "SEFLEXSE", format version, a JSON header (metadata + a table of datasets), the
// datasets as raw little-endian column-major arrays, and a trailer with the SHA-256 of all bytes
// before it. Save then load is bit-exact.
//
// A file has two parts (format 1.2): the dynamics (reduced matrices, frame-node rows, inertia
// invariants; all a simulation needs) and the optional mesh (FE node ids and positions, recovery
// matrix, FE mass, cells; for animation, recovery and for computing invariants). A reader can skip
// the mesh part (SuperelementParts::Dynamics): the checksum still covers every byte, streamed.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "seflex/superelement/stress_modes.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

inline constexpr int kSuperelementFormatMajor = 1;
inline constexpr int kSuperelementFormatMinor = 4;


struct SaveOptions {
  bool overwrite = false;  ///< refuse to replace an existing file unless set
  const se::StressModes* stress = nullptr;  ///< stress modes to store with the body (format 1.4; null: none)
};

/// Write `se` to `path` (atomically: a temporary file renamed into place).
/// Throws InputError if the file exists and !overwrite, or cannot be written; InvariantError if the
/// superelement is inconsistent (se::check_consistency) or holds non-finite numbers.
void save_superelement(const se::Superelement& se, const std::filesystem::path& path, const SaveOptions& options = {});

/// Which datasets a reader loads.
enum class SuperelementParts {
  All,       ///< everything the file holds
  Dynamics,  ///< K, M, Phi_f, invariants and the header; the mesh datasets (fe_node_ids, fe_positions,
             ///< recovery, M_fe.*, cells.*) are checked in the table but not read (fe_node_ids empty)
};

struct LoadOptions {
  SuperelementParts parts = SuperelementParts::All;
  se::StressModes* stress = nullptr;  ///< receives the file's stress modes (empty when it has none); null: not read
};

/// Read a superelement file. Checks magic, format version, header, sizes, the SHA-256 trailer
/// (truncation and corruption, streamed over the whole file), finiteness and symmetry; throws
/// InputError naming the file and what is wrong. Memory: the datasets loaded, not the file.
se::Superelement load_superelement(const std::filesystem::path& path, const LoadOptions& options = {});

/// Same, from bytes already in memory (`name` is used in messages).
se::Superelement parse_superelement(const std::string& bytes, const std::string& name, const LoadOptions& options = {});

/// One entry of a file's dataset table.
struct DatasetEntry {
  std::string name, dtype;
  std::vector<std::int64_t> shape;
  std::uint64_t offset = 0, bytes = 0;
  bool mesh = false;  ///< part of the mesh (skipped by SuperelementParts::Dynamics)
};

/// What a superelement file holds: the dynamics part as loaded (SuperelementParts::Dynamics), the
/// format version and the dataset table with the header's mesh sizes. For `seflex info` and for
/// deciding which parts a run loads. Same checks and errors as load_superelement.
struct SuperelementFileInfo {
  se::Superelement dynamics;           ///< fe_node_ids, recovery, M_fe, cells empty
  int format_major = 0, format_minor = 0;
  std::uint64_t file_bytes = 0;
  std::int64_t num_fe_nodes = 0, num_cells = 0;  ///< of the mesh part (0 when absent)
  std::vector<DatasetEntry> datasets;
  se::StressModes stress;              ///< the stress modes (format 1.4; empty when absent)
  bool has_invariants() const { return dynamics.invariants.present(); }
  bool has_mesh() const;               ///< fe_positions with at least one node, recovery or M_fe
  bool has(const std::string& dataset) const;
  std::uint64_t bytes_of(bool mesh) const;     ///< total bytes of the mesh (or dynamics) datasets
  std::uint64_t invariant_bytes() const;       ///< total bytes of the inv.* datasets
};
SuperelementFileInfo inspect_superelement(const std::filesystem::path& path);

/// Bytes of numbers a loaded superelement holds in memory (matrices, invariants, mesh arrays).
std::uint64_t superelement_memory_bytes(const se::Superelement& se);

/// The superelement without its mesh part (fe_node_ids, p_BoI_B, recovery, M_fe, cells), as
/// `seflex reduce --no-mesh` writes it.
void drop_mesh(se::Superelement& se);

/// Serialise to bytes (what save_superelement writes).
std::string serialize_superelement(const se::Superelement& se, const se::StressModes* stress = nullptr);

/// The superelement with only its first `modes` fixed-interface modes (exact truncation of the
/// Craig-Bampton basis: K, M, Phi_f, recovery and the inertia invariants lose the trailing columns).
se::Superelement keep_internal_modes(const se::Superelement& s, int modes);

}  // namespace seflex::io
