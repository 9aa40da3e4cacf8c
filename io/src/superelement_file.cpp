// Superelement file writer and reader (docs/superelement-format.md).
#include "seflex/io/superelement_file.hpp"

#include <yaml-cpp/yaml.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <span>
#include <sstream>
#include <vector>

#include "atomic_write.hpp"
#include "invariant_datasets.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/version.hpp"
#include "seflex/io/sha256.hpp"

static_assert(std::endian::native == std::endian::little, "the superelement file format is little-endian");

namespace seflex::io {
namespace {

constexpr char kMagic[8] = {'S', 'E', 'F', 'L', 'E', 'X', 'S', 'E'};
constexpr char kTrailerMagic[8] = {'S', 'E', 'F', 'L', 'X', 'E', 'N', 'D'};
constexpr std::size_t kPreamble = 24;  // magic(8) + major(4) + minor(4) + header length(8)
constexpr std::size_t kTrailer = 40;   // trailer magic(8) + sha256(32)

// ---------------------------------------------------------------------------------------------
// JSON output helpers (the header is strict JSON so any language can read it).
std::string json_number(double x) {
  SEFLEX_DEMAND(std::isfinite(x), "non-finite number in a superelement header");
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

template <class Vec>
std::string json_array(const Vec& v) {
  std::string s = "[";
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(v.size()); ++i) s += (i ? ", " : "") + json_number(v[i]);
  return s + "]";
}

std::string json_matrix3(const Eigen::Matrix3d& A) {  // row-major 9 numbers
  Eigen::Matrix<double, 9, 1> v;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) v[3 * r + c] = A(r, c);
  return json_array(v);
}

// A dataset: raw bytes of a column-major array.
struct Dataset {
  std::string name, dtype;
  std::vector<std::int64_t> shape;
  std::string bytes;
};

template <class Scalar>
Dataset make_dataset(const std::string& name, const char* dtype, const Scalar* data, std::vector<std::int64_t> shape) {
  std::int64_t count = 1;
  for (auto s : shape) count *= s;
  Dataset d{name, dtype, std::move(shape), {}};
  d.bytes.assign(reinterpret_cast<const char*>(data), static_cast<std::size_t>(count) * sizeof(Scalar));
  return d;
}

Dataset matrix_dataset(const std::string& name, const Eigen::MatrixXd& A) {
  return make_dataset(name, "float64", A.data(), {A.rows(), A.cols()});
}

// ---------------------------------------------------------------------------------------------
// Reading: random access to the bytes of a string or of a file (a file is never read whole).
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual std::uint64_t size() const = 0;
  /// Copy n bytes at offset to dst (the range lies inside size()).
  virtual void read(std::uint64_t offset, std::size_t n, void* dst) const = 0;
  /// Hash the first n bytes.
  virtual void hash(std::uint64_t n, Sha256& h) const = 0;
};

class StringSource final : public ByteSource {
 public:
  explicit StringSource(const std::string& bytes) : bytes_(bytes) {}
  std::uint64_t size() const override { return bytes_.size(); }
  void read(std::uint64_t offset, std::size_t n, void* dst) const override {
    if (n > 0) std::memcpy(dst, bytes_.data() + offset, n);
  }
  void hash(std::uint64_t n, Sha256& h) const override { h.update(bytes_.data(), n); }

 private:
  const std::string& bytes_;
};

class FileSource final : public ByteSource {
 public:
  explicit FileSource(const std::filesystem::path& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw InputError(SourceRef{path.string(), 0}, "cannot open superelement file");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw InputError(SourceRef{path.string(), 0}, "is not a regular file; expected a superelement file (.se)");
    in_.seekg(0, std::ios::end);
    const auto end = in_.tellg();
    if (end < 0) throw InputError(SourceRef{path.string(), 0}, "cannot read superelement file");
    size_ = static_cast<std::uint64_t>(end);
  }
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::size_t n, void* dst) const override {
    if (n == 0) return;
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(offset));
    in_.read(static_cast<char*>(dst), static_cast<std::streamsize>(n));
    if (!in_) throw InputError(SourceRef{path_.string(), 0}, "read error in the superelement file");
  }
  void hash(std::uint64_t n, Sha256& h) const override {
    // 64 kB, not zeroed: a block that stays in the cache between the read and the hash (a fresh 1 MB
    // vector cost more in page faults and zeroing than the hash itself, docs/benchmarks.md).
    constexpr std::size_t kBlock = std::size_t{1} << 16;
    const std::unique_ptr<char[]> storage(new char[kBlock]);
    const std::span<char> buf(storage.get(), kBlock);
    in_.clear();
    in_.seekg(0);
    while (n > 0) {
      const std::size_t k = static_cast<std::size_t>(std::min<std::uint64_t>(n, buf.size()));
      in_.read(buf.data(), static_cast<std::streamsize>(k));
      if (!in_) throw InputError(SourceRef{path_.string(), 0}, "read error in the superelement file");
      h.update(buf.data(), k);
      n -= k;
    }
  }

 private:
  std::filesystem::path path_;
  mutable std::ifstream in_;
  std::uint64_t size_ = 0;
};

bool is_mesh_dataset(const std::string& name) {
  return name == "fe_node_ids" || name == "fe_positions" || name == "recovery" || name.rfind("M_fe.", 0) == 0 ||
         name.rfind("cells.", 0) == 0;
}

std::string shape_text(const std::vector<std::int64_t>& v) {
  std::string t;
  for (auto x : v) {
    if (!t.empty()) t += 'x';
    t += std::to_string(x);
  }
  return t;
}

/// "a list", "an object", ... for messages about a header value of the wrong kind.
std::string node_kind(const YAML::Node& n) {
  if (n.IsScalar()) return "the value '" + n.Scalar() + "'";
  if (n.IsSequence()) return "an array";
  if (n.IsMap()) return "an object";
  return "null";
}

class Reader {
 public:
  Reader(const ByteSource& src, std::string name, SuperelementParts parts)
      : src_(src), name_(std::move(name)), parts_(parts) {}

  [[noreturn]] void fail(const std::string& what) const { throw InputError(SourceRef{name_, 0}, what); }

  se::Superelement read() {
    const std::uint64_t size = src_.size();
    char pre[kPreamble] = {};
    src_.read(0, static_cast<std::size_t>(std::min<std::uint64_t>(size, kPreamble)), pre);
    if (size < kPreamble + kTrailer || std::memcmp(pre, kMagic, 8) != 0) {
      if (size >= 8 && std::memcmp(pre, kMagic, 8) == 0)
        fail("truncated superelement file: only " + std::to_string(size) + " bytes");
      fail("not a seflex superelement file (expected the magic bytes 'SEFLEXSE' at the start)");
    }
    std::uint32_t major, minor;
    std::uint64_t header_len;
    std::memcpy(&major, pre + 8, 4);
    std::memcpy(&minor, pre + 12, 4);
    std::memcpy(&header_len, pre + 16, 8);
    major_ = static_cast<int>(major);
    minor_ = static_cast<int>(minor);
    if (static_cast<int>(major) != kSuperelementFormatMajor)
      fail("superelement file format " + std::to_string(major) + "." + std::to_string(minor) +
           " is not supported; this seflex reads format " + std::to_string(kSuperelementFormatMajor) + ".x");
    if (header_len > size - kPreamble - kTrailer)
      fail("truncated superelement file: the header promises " + std::to_string(header_len) + " bytes but the file has " +
           std::to_string(size) + " bytes in all");
    // Trailer: the end marker and the checksum of every byte before it (streamed).
    const std::uint64_t body_len = size - kTrailer;
    char trailer[kTrailer];
    src_.read(body_len, kTrailer, trailer);
    if (std::memcmp(trailer, kTrailerMagic, 8) != 0)
      fail("truncated or corrupted superelement file: the end-of-file marker 'SEFLXEND' is missing");
    Sha256 h;
    src_.hash(body_len, h);
    const auto digest = h.digest();
    if (std::memcmp(digest.data(), trailer + 8, 32) != 0)
      fail("corrupted superelement file: SHA-256 checksum mismatch (the file was modified or damaged)");

    std::string header_text(static_cast<std::size_t>(header_len), '\0');
    src_.read(kPreamble, header_text.size(), header_text.data());
    YAML::Node header;
    try {
      header = YAML::Load(header_text);
    } catch (const YAML::Exception& e) {
      fail(std::string("unreadable JSON header: ") + e.what());
    }
    if (!header.IsMap()) fail("the header is not a JSON object");
    data_begin_ = kPreamble + header_len;
    data_end_ = body_len;
    return build(header);
  }

  int major() const { return major_; }
  int minor() const { return minor_; }
  const se::StressModes& stress() const { return stress_; }  ///< format 1.4 (empty when absent)
  std::int64_t num_fe_nodes() const { return nfe_; }
  std::int64_t num_cells() const { return ncells_; }
  const std::vector<DatasetEntry>& table() const { return entries_; }

 private:
  template <class T>
  T get(const YAML::Node& node, const std::string& key) const {
    // yaml-cpp throws its own exception (not an InputError) for a key looked up in a scalar or a list
    if (!node.IsMap()) fail("header: expected an object with the key '" + key + "', got " + node_kind(node));
    const YAML::Node v = node[key];
    if (!v) fail("header: missing key '" + key + "'");
    try {
      return v.as<T>();
    } catch (const YAML::Exception&) {
      fail("header: key '" + key + "' has the wrong type");
    }
  }

  Eigen::VectorXd vector(const YAML::Node& node, const std::string& key, Eigen::Index expected) const {
    const YAML::Node v = node[key];
    if (!v || !v.IsSequence()) fail("header: key '" + key + "' must be an array");
    if (expected >= 0 && static_cast<Eigen::Index>(v.size()) != expected)
      fail("header: '" + key + "' has " + std::to_string(v.size()) + " entries, expected " + std::to_string(expected));
    Eigen::VectorXd x(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      try {
        x[i] = v[i].as<double>();
      } catch (const YAML::Exception&) {
        fail("header: '" + key + "' entry " + std::to_string(i) + " is not a number");
      }
    }
    return x;
  }

  Eigen::Matrix3d matrix3(const YAML::Node& node, const std::string& key) const {
    const Eigen::VectorXd v = vector(node, key, 9);
    Eigen::Matrix3d A;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) A(r, c) = v[3 * r + c];
    return A;
  }

  // Locate a dataset; checks dtype, shape and that its bytes lie inside the data region. Returns
  // its offset, or 0 when it is absent and not required.
  std::uint64_t dataset(const YAML::Node& table, const std::string& name, const std::string& dtype,
                        std::vector<std::int64_t> shape, bool required = true) const {
    const YAML::Node d = table[name];
    if (!d) {
      if (required) fail("dataset '" + name + "' is missing");
      return 0;
    }
    if (!d.IsMap()) fail("dataset '" + name + "': its table entry must be an object");
    if (get<std::string>(d, "dtype") != dtype) fail("dataset '" + name + "' must have dtype " + dtype);
    const auto got = get<std::vector<std::int64_t>>(d, "shape");
    if (got != shape) fail("dataset '" + name + "' has shape " + shape_text(got) + ", expected " + shape_text(shape));
    const auto offset = get<std::uint64_t>(d, "offset");
    const auto nbytes = get<std::uint64_t>(d, "bytes");
    std::uint64_t count = 1;
    for (auto s : shape) count *= static_cast<std::uint64_t>(s);
    const std::uint64_t width = dtype == "float64" || dtype == "int64" ? 8 : 4;
    if (nbytes != count * width) fail("dataset '" + name + "': byte count does not match its shape");
    if (offset < data_begin_ || offset > data_end_ || nbytes > data_end_ - offset)
      fail("dataset '" + name + "' lies outside the file's data section (truncated file?)");
    return offset;
  }

  bool skip_mesh() const { return parts_ == SuperelementParts::Dynamics; }

  template <class Derived>
  void fill(const YAML::Node& table, const std::string& name, Eigen::PlainObjectBase<Derived>& A, Eigen::Index rows,
            Eigen::Index cols) const {
    const std::uint64_t offset = dataset(table, name, "float64", {rows, cols});
    A.resize(rows, cols);
    src_.read(offset, sizeof(double) * static_cast<std::size_t>(A.size()), A.data());
    if (A.size() > 0 && !A.allFinite()) fail("dataset '" + name + "' has non-finite entries");
  }

  Eigen::MatrixXd matrix(const YAML::Node& table, const std::string& name, Eigen::Index rows, Eigen::Index cols) const {
    Eigen::MatrixXd A;
    fill(table, name, A, rows, cols);
    return A;
  }

  template <class T>
  std::vector<T> array(const YAML::Node& table, const std::string& name, const char* dtype, std::int64_t n) const {
    std::vector<T> v(static_cast<std::size_t>(n));
    const std::uint64_t offset = dataset(table, name, dtype, {n});
    src_.read(offset, sizeof(T) * v.size(), v.data());
    return v;
  }

  /// Datasets stored complete or not at all (the inertia invariants, format 1.2; the geometric-stiffness
  /// invariants, 1.3): each(obj, f) calls f(name, matrix, rows, cols) for every dataset of obj.
  /// Fills `out` and returns true when the file has them.
  template <class T, class Each>
  bool read_all_or_none(const YAML::Node& table, T& out, Each&& each, const char* what) const {
    std::string first_present, first_missing;
    T probe;
    each(probe, [&](const std::string& name, auto&, Eigen::Index, Eigen::Index) {
      if (table[name] && first_present.empty()) first_present = name;
      if (!table[name] && first_missing.empty()) first_missing = name;
    });
    if (first_present.empty()) return false;
    if (!first_missing.empty())
      fail("dataset '" + first_missing + "' is missing; the file has '" + first_present + "', and the " + what +
           " are stored complete or not at all");
    each(out, [&](const std::string& name, auto& A, Eigen::Index r, Eigen::Index c) { fill(table, name, A, r, c); });
    return true;
  }

  void read_invariants(const YAML::Node& table, se::Superelement& s) const {
    const bool present = read_all_or_none(table, s.invariants, [&](auto& inv, auto&& f) {
      detail::for_each_invariant_dataset(inv, s.size(), s.num_modes, f);
    }, "inertia invariants");
    if (!present) return;
    s.invariants.n = s.size();
    if (s.size() == 0) fail("the inertia invariants are stored for a body of size 0");
  }

  void read_stiffening(const YAML::Node& table, se::Superelement& s) const {
    if (read_all_or_none(table, s.stiffening, [&](auto& st, auto&& f) {
          detail::for_each_stiffening_dataset(st, s.size(), s.num_interfaces(), f);
        }, "geometric-stiffness invariants"))
      s.stiffening.n = s.size();
  }

  // Format 1.4: the stress modes, all four datasets or none (kept beside the superelement: stress()).
  void read_stress_modes(const YAML::Node& table, Eigen::Index n) {
    const char* names[4] = {"stress.element_id", "stress.kind", "stress.row", "stress.modes"};
    int present = 0;
    for (const char* name : names) present += table[name] ? 1 : 0;
    if (present == 0) return;
    if (present < 4)
      for (const char* name : names)
        if (!table[name])
          fail("dataset '" + std::string(name) +
               "' is missing; the file has other stress.* datasets, and the stress modes are stored complete or not at all");
    const auto shape = [&](const char* name) { return get<std::vector<std::int64_t>>(table[name], "shape"); };
    const std::vector<std::int64_t> ne = shape("stress.element_id"), sm = shape("stress.modes");
    if (ne.size() != 1 || sm.size() != 2 || ne[0] <= 0 || sm[0] < ne[0] || static_cast<std::uint64_t>(sm[0]) > src_.size())
      fail("datasets 'stress.*': inconsistent shapes");
    stress_.element_ids = array<std::int32_t>(table, "stress.element_id", "int32", ne[0]);
    stress_.kinds = array<std::int32_t>(table, "stress.kind", "int32", ne[0]);
    stress_.rows = array<std::int32_t>(table, "stress.row", "int32", ne[0]);
    stress_.S = matrix(table, "stress.modes", sm[0], n);
    const auto problems = se::check_consistency(stress_, n);
    if (!problems.empty()) fail("datasets 'stress.*': " + problems.front());
  }
  void list_table(const YAML::Node& table) {
    for (const auto& kv : table) {
      DatasetEntry e;
      if (!kv.first.IsScalar()) fail("datasets: every key must be a dataset name, got " + node_kind(kv.first));
      e.name = kv.first.Scalar();
      const YAML::Node d = kv.second;
      if (!d.IsMap()) fail("dataset '" + e.name + "': its table entry must be an object");
      e.dtype = get<std::string>(d, "dtype");
      e.shape = get<std::vector<std::int64_t>>(d, "shape");
      e.offset = get<std::uint64_t>(d, "offset");
      e.bytes = get<std::uint64_t>(d, "bytes");
      e.mesh = is_mesh_dataset(e.name);
      entries_.push_back(std::move(e));
    }
  }

  se::Superelement build(const YAML::Node& h) {
    se::Superelement s;
    if (get<std::string>(h, "format") != "seflex-superelement") fail("header: 'format' is not seflex-superelement");
    s.name = get<std::string>(h, "name");
    s.units = get<std::string>(h, "units");
    s.seflex_version = get<std::string>(h, "seflex_version");
    s.source_file = get<std::string>(h, "source_file");
    s.source_hash = get<std::string>(h, "source_hash");
    s.created = get<std::string>(h, "created");
    if (const YAML::Node w = h["source_warnings"]; w) {  // format 1.1
      if (!w.IsSequence()) fail("header: 'source_warnings' must be an array of strings");
      for (const auto& line : w) {
        if (!line.IsScalar()) fail("header: 'source_warnings' must be an array of strings, got " + node_kind(line));
        s.source_warnings.push_back(line.Scalar());
      }
    }
    const YAML::Node frame = h["frame_node"];
    if (!frame || !frame.IsMap()) fail("header: missing object 'frame_node'");
    s.frame_node_id = get<int>(frame, "id");
    s.p_OBo = vector(frame, "position", 3);
    const YAML::Node ifs = h["interfaces"];
    if (!ifs || !ifs.IsSequence() || ifs.size() == 0) fail("header: 'interfaces' must be a non-empty array");
    for (const auto& node : ifs) {
      se::InterfaceNode in;
      in.id = get<int>(node, "id");
      in.p_BoN_B = vector(node, "position", 3);
      in.R_BN = matrix3(node, "triad");
      s.interfaces.push_back(in);
    }
    s.num_modes = get<int>(h, "num_modes");
    if (s.num_modes < 0 || s.num_modes > 1000000) fail("header: 'num_modes' out of range");
    s.mode_frequencies_hz = vector(h, "mode_frequencies_hz", s.num_modes);
    const YAML::Node mp = h["mass_properties"];
    if (!mp || !mp.IsMap()) fail("header: missing object 'mass_properties'");
    s.mass = get<double>(mp, "mass");
    s.p_BoCm_B = vector(mp, "center_of_mass", 3);
    s.I_Cm_B = matrix3(mp, "inertia_about_center_of_mass");
    if (const YAML::Node tr = h["truncation"]; tr && tr.IsMap()) {
      const Eigen::VectorXd f = vector(tr, "effective_mass_fraction", 6);
      for (int i = 0; i < 6; ++i) s.truncation.effective_mass_fraction[i] = f[i];
      s.truncation.first_neglected_hz = get<double>(tr, "first_neglected_hz");
      s.truncation.max_kept_hz = get<double>(tr, "max_kept_hz");
    }

    const YAML::Node table = h["datasets"];
    if (!table || !table.IsMap()) fail("header: missing object 'datasets'");
    list_table(table);
    const Eigen::Index n = s.size();
    s.K = matrix(table, "K", n, n);
    s.M = matrix(table, "M", n, n);
    s.Phi_f = matrix(table, "Phi_f", 6, n);
    read_invariants(table, s);
    read_stiffening(table, s);
    read_stress_modes(table, s.size());

    const std::int64_t nfe = get<std::int64_t>(h, "num_fe_nodes");
    if (nfe < 0 || static_cast<std::uint64_t>(nfe) > src_.size()) fail("header: 'num_fe_nodes' out of range");
    nfe_ = nfe;
    const std::int64_t ncells = get<std::int64_t>(h, "num_cells");
    if (ncells < 0 || static_cast<std::uint64_t>(ncells) > src_.size()) fail("header: 'num_cells' out of range");
    ncells_ = ncells;
    // Format 1.2: the mesh part is optional (`seflex reduce --no-mesh`): no fe_node_ids, no fe_positions.
    const bool mesh_ids = nfe > 0 || table["fe_node_ids"];
    if (skip_mesh()) {
      if (mesh_ids) {
        dataset(table, "fe_node_ids", "int32", {nfe});
        dataset(table, "fe_positions", "float64", {3, nfe});
      }
      dataset(table, "recovery", "float64", {6 * nfe, n}, false);
      s.p_BoI_B.resize(3, 0);
    } else {
      if (mesh_ids) {
        s.fe_node_ids = array<std::int32_t>(table, "fe_node_ids", "int32", nfe);
        fill(table, "fe_positions", s.p_BoI_B, 3, nfe);
      }
      if (table["recovery"]) s.recovery = matrix(table, "recovery", 6 * nfe, n);
    }
    if (table["M_fe.values"]) read_fe_mass(table, nfe, s);
    if (ncells > 0) read_cells(table, ncells, s);
    const auto problems = se::check_consistency(s);
    if (!problems.empty()) {
      std::string msg = "inconsistent superelement:";
      for (const auto& p : problems) msg += " " + p + ";";
      msg.pop_back();
      fail(msg);
    }
    return s;
  }

  void read_fe_mass(const YAML::Node& table, std::int64_t nfe, se::Superelement& s) const {
    const YAML::Node v = table["M_fe.values"];
    if (!v.IsMap()) fail("dataset 'M_fe.values': its table entry must be an object");
    const auto shape = get<std::vector<std::int64_t>>(v, "shape");
    if (shape.size() != 1 || shape[0] < 0 || static_cast<std::uint64_t>(shape[0]) > src_.size())
      fail("dataset 'M_fe.values' must be a vector of a plausible length");
    const std::int64_t nnz = shape[0];
    if (skip_mesh()) {
      dataset(table, "M_fe.colptr", "int64", {6 * nfe + 1});
      dataset(table, "M_fe.rowind", "int64", {nnz});
      dataset(table, "M_fe.values", "float64", {nnz});
      return;
    }
    const auto colptr = array<std::int64_t>(table, "M_fe.colptr", "int64", 6 * nfe + 1);
    const auto rowind = array<std::int64_t>(table, "M_fe.rowind", "int64", nnz);
    const auto values = array<double>(table, "M_fe.values", "float64", nnz);
    if (colptr.front() != 0 || colptr.back() != nnz) fail("dataset 'M_fe.colptr' is inconsistent with M_fe.values");
    std::vector<Eigen::Triplet<double>> trips;
    trips.reserve(static_cast<std::size_t>(nnz));
    for (std::int64_t c = 0; c < 6 * nfe; ++c) {
      if (colptr[c + 1] < colptr[c] || colptr[c + 1] > nnz)  // checked before rowind[k] is read
        fail("dataset 'M_fe.colptr' is not non-decreasing from 0 to the length of M_fe.values");
      for (std::int64_t k = colptr[c]; k < colptr[c + 1]; ++k) {
        if (rowind[k] < 0 || rowind[k] >= 6 * nfe) fail("dataset 'M_fe.rowind' has a row index out of range");
        trips.emplace_back(static_cast<int>(rowind[k]), static_cast<int>(c), values[k]);
      }
    }
    s.M_fe.resize(6 * nfe, 6 * nfe);
    s.M_fe.setFromTriplets(trips.begin(), trips.end());
    if (!s.M_fe.isCompressed()) s.M_fe.makeCompressed();
  }

  void read_cells(const YAML::Node& table, std::int64_t ncells, se::Superelement& s) const {
    if (skip_mesh()) {
      dataset(table, "cells.type", "int32", {ncells});
      dataset(table, "cells.element_id", "int32", {ncells});
      dataset(table, "cells.nodes", "int32", {4, ncells});
      return;
    }
    const auto types = array<std::int32_t>(table, "cells.type", "int32", ncells);
    const auto eids = array<std::int32_t>(table, "cells.element_id", "int32", ncells);
    std::vector<std::int32_t> nodes(static_cast<std::size_t>(4 * ncells));
    src_.read(dataset(table, "cells.nodes", "int32", {4, ncells}), nodes.size() * 4, nodes.data());
    s.cells.resize(static_cast<std::size_t>(ncells));
    for (std::int64_t c = 0; c < ncells; ++c) {
      auto& cell = s.cells[static_cast<std::size_t>(c)];
      if (types[c] != 2 && types[c] != 3 && types[c] != 4) fail("dataset 'cells.type' has an unknown cell type");
      cell.type = static_cast<se::MeshCell::Type>(types[c]);
      cell.element_id = eids[c];
      for (int k = 0; k < 4; ++k) cell.nodes[k] = nodes[static_cast<std::size_t>(4 * c + k)];
    }
  }

  const ByteSource& src_;
  std::string name_;
  SuperelementParts parts_;
  std::uint64_t data_begin_ = 0, data_end_ = 0;
  int major_ = 0, minor_ = 0;
  se::StressModes stress_;
  std::int64_t nfe_ = 0, ncells_ = 0;
  std::vector<DatasetEntry> entries_;
};

}  // namespace

std::string serialize_superelement(const se::Superelement& s, const se::StressModes* stress) {
  const auto problems = se::check_consistency(s);
  if (!problems.empty()) {
    std::string msg = "cannot save an inconsistent superelement:";
    for (const auto& p : problems) msg += " " + p + ";";
    throw InvariantError(msg);
  }
  const auto nfe = static_cast<std::int64_t>(s.fe_node_ids.size());

  // The dynamics part first (a reader that skips the mesh reads one contiguous block), then the mesh.
  std::vector<Dataset> data;
  data.push_back(matrix_dataset("K", s.K));
  data.push_back(matrix_dataset("M", s.M));
  data.push_back(matrix_dataset("Phi_f", s.Phi_f));
  if (s.invariants.present()) {
    if (s.invariants.n != s.size())
      throw InvariantError("cannot save superelement '" + s.name + "': its inertia invariants are for n = " +
                           std::to_string(s.invariants.n) + ", the body has n = " + std::to_string(s.size()));
    detail::for_each_invariant_dataset(s.invariants, s.size(), s.num_modes,
                                       [&](const std::string& name, const auto& A, Eigen::Index r, Eigen::Index c) {
                                         if (A.rows() != r || A.cols() != c)
                                           throw InvariantError("cannot save superelement '" + s.name + "': invariant " +
                                                                name + " is " + std::to_string(A.rows()) + "x" +
                                                                std::to_string(A.cols()) + ", expected " +
                                                                std::to_string(r) + "x" + std::to_string(c));
                                         if (A.size() > 0 && !A.allFinite())
                                           throw InvariantError("cannot save superelement '" + s.name + "': invariant " +
                                                                name + " has non-finite entries");
                                         data.push_back(make_dataset(name, "float64", A.data(), {r, c}));
                                       });
  }
  if (s.stiffening.present()) {
    if (s.stiffening.n != s.size() || s.stiffening.interface.size() != static_cast<std::size_t>(6 * s.num_interfaces()))
      throw InvariantError("cannot save superelement '" + s.name + "': its geometric-stiffness invariants are for n = " +
                           std::to_string(s.stiffening.n) + " with " + std::to_string(s.stiffening.interface.size()) +
                           " interface dofs, the body has n = " + std::to_string(s.size()) + " and " +
                           std::to_string(6 * s.num_interfaces()));
    detail::for_each_stiffening_dataset(s.stiffening, s.size(), s.num_interfaces(),
                                        [&](const std::string& name, const auto& A, Eigen::Index r, Eigen::Index c) {
                                          if (A.rows() != r || A.cols() != c || !A.allFinite())
                                            throw InvariantError("cannot save superelement '" + s.name + "': " + name +
                                                                 " is not a finite " + std::to_string(r) + "x" +
                                                                 std::to_string(c) + " matrix");
                                          data.push_back(make_dataset(name, "float64", A.data(), {r, c}));
                                        });
  }
  if (stress && stress->present()) {  // format 1.4
    const auto problems = se::check_consistency(*stress, s.size());
    if (!problems.empty()) throw InvariantError("cannot save superelement '" + s.name + "': " + problems.front());
    const auto E = static_cast<std::int64_t>(stress->element_ids.size());
    data.push_back(make_dataset("stress.element_id", "int32", stress->element_ids.data(), {E}));
    data.push_back(make_dataset("stress.kind", "int32", stress->kinds.data(), {E}));
    data.push_back(make_dataset("stress.row", "int32", stress->rows.data(), {E}));
    data.push_back(matrix_dataset("stress.modes", stress->S));
  }
  if (nfe > 0) {  // format 1.2: no mesh part, no fe_node_ids/fe_positions
    std::vector<std::int32_t> ids(s.fe_node_ids.begin(), s.fe_node_ids.end());
    data.push_back(make_dataset("fe_node_ids", "int32", ids.data(), {nfe}));
    data.push_back(make_dataset("fe_positions", "float64", s.p_BoI_B.data(), {3, nfe}));
  }
  if (s.recovery.size() > 0) data.push_back(matrix_dataset("recovery", s.recovery));
  if (s.M_fe.nonZeros() > 0) {
    Eigen::SparseMatrix<double> A = s.M_fe;
    A.makeCompressed();
    std::vector<std::int64_t> colptr(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    std::vector<std::int64_t> rowind(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    data.push_back(make_dataset("M_fe.colptr", "int64", colptr.data(), {static_cast<std::int64_t>(colptr.size())}));
    data.push_back(make_dataset("M_fe.rowind", "int64", rowind.data(), {static_cast<std::int64_t>(rowind.size())}));
    data.push_back(make_dataset("M_fe.values", "float64", A.valuePtr(), {static_cast<std::int64_t>(A.nonZeros())}));
  }
  const auto ncells = static_cast<std::int64_t>(s.cells.size());
  if (ncells > 0) {
    std::vector<std::int32_t> types, eids, nodes;
    for (const auto& c : s.cells) {
      types.push_back(static_cast<std::int32_t>(c.type));
      eids.push_back(c.element_id);
      for (int k = 0; k < 4; ++k) nodes.push_back(c.nodes[k]);
    }
    data.push_back(make_dataset("cells.type", "int32", types.data(), {ncells}));
    data.push_back(make_dataset("cells.element_id", "int32", eids.data(), {ncells}));
    data.push_back(make_dataset("cells.nodes", "int32", nodes.data(), {4, ncells}));
  }

  // The header holds the dataset offsets, which depend on the header length: iterate until stable.
  auto header_text = [&](std::uint64_t data_start) {
    std::ostringstream o;
    o << "{\n  \"format\": \"seflex-superelement\",\n"
      << "  \"format_version\": \"" << kSuperelementFormatMajor << "." << kSuperelementFormatMinor << "\",\n"
      << "  \"seflex_version\": " << json_string(s.seflex_version.empty() ? kVersion : s.seflex_version) << ",\n"
      << "  \"name\": " << json_string(s.name) << ",\n"
      << "  \"units\": " << json_string(s.units) << ",\n"
      << "  \"source_file\": " << json_string(s.source_file) << ",\n"
      << "  \"source_hash\": " << json_string(s.source_hash) << ",\n"
      << "  \"created\": " << json_string(s.created) << ",\n"
      << "  \"source_warnings\": [";
    for (std::size_t k = 0; k < s.source_warnings.size(); ++k) o << (k ? ", " : "") << json_string(s.source_warnings[k]);
    o << "],\n"
      << "  \"coordinates\": \"q = [u_1, theta_1, ..., u_N, theta_N, eta_1, ..., eta_m]; body frame B: origin at the "
         "frame node, axes parallel to the source model's basic axes\",\n"
      << "  \"frame_node\": {\"id\": " << s.frame_node_id << ", \"position\": " << json_array(s.p_OBo) << "},\n"
      << "  \"interfaces\": [";
    for (std::size_t j = 0; j < s.interfaces.size(); ++j) {
      const auto& in = s.interfaces[j];
      o << (j ? ",\n    " : "\n    ") << "{\"id\": " << in.id << ", \"position\": " << json_array(in.p_BoN_B)
        << ", \"triad\": " << json_matrix3(in.R_BN) << "}";
    }
    o << "\n  ],\n"
      << "  \"num_modes\": " << s.num_modes << ",\n"
      << "  \"mode_frequencies_hz\": " << json_array(s.mode_frequencies_hz) << ",\n"
      << "  \"mass_properties\": {\"mass\": " << json_number(s.mass) << ", \"center_of_mass\": " << json_array(s.p_BoCm_B)
      << ", \"inertia_about_center_of_mass\": " << json_matrix3(s.I_Cm_B) << "},\n"
      << "  \"truncation\": {\"effective_mass_fraction\": "
      << json_array(Eigen::Map<const Eigen::Matrix<double, 6, 1>>(s.truncation.effective_mass_fraction.data()))
      << ", \"first_neglected_hz\": " << json_number(s.truncation.first_neglected_hz)
      << ", \"max_kept_hz\": " << json_number(s.truncation.max_kept_hz) << "},\n"
      << "  \"num_fe_nodes\": " << nfe << ",\n"
      << "  \"num_cells\": " << ncells << ",\n"
      << "  \"datasets\": {";
    std::uint64_t offset = data_start;
    for (std::size_t k = 0; k < data.size(); ++k) {
      const auto& d = data[k];
      o << (k ? ",\n    " : "\n    ") << json_string(d.name) << ": {\"dtype\": \"" << d.dtype << "\", \"order\": \"F\", \"shape\": [";
      for (std::size_t i = 0; i < d.shape.size(); ++i) o << (i ? ", " : "") << d.shape[i];
      o << "], \"offset\": " << offset << ", \"bytes\": " << d.bytes.size() << "}";
      offset += (d.bytes.size() + 7) / 8 * 8;
    }
    o << "\n  }\n}\n";
    return o.str();
  };
  std::string header;
  std::uint64_t data_start = 0;
  for (int pass = 0; pass < 8; ++pass) {
    header = header_text(data_start);
    const std::uint64_t next = (kPreamble + header.size() + 7) / 8 * 8;
    if (next == data_start) break;
    data_start = next;
  }
  header.resize(data_start - kPreamble, ' ');  // pad the JSON with trailing blanks to the 8-byte boundary

  std::string out;
  out.append(kMagic, 8);
  const std::uint32_t major = kSuperelementFormatMajor, minor = kSuperelementFormatMinor;
  const std::uint64_t hlen = header.size();
  out.append(reinterpret_cast<const char*>(&major), 4);
  out.append(reinterpret_cast<const char*>(&minor), 4);
  out.append(reinterpret_cast<const char*>(&hlen), 8);
  out += header;
  for (const auto& d : data) {
    out += d.bytes;
    out.append((8 - d.bytes.size() % 8) % 8, '\0');
  }
  Sha256 h;
  h.update(out);
  const auto digest = h.digest();
  out.append(kTrailerMagic, 8);
  out.append(reinterpret_cast<const char*>(digest.data()), 32);
  return out;
}

void save_superelement(const se::Superelement& s, const std::filesystem::path& path, const SaveOptions& options) {
  if (!options.overwrite && std::filesystem::exists(path))  // before serialising a large body
    throw InputError(SourceRef{path.string(), 0}, "exists already; refusing to overwrite it (use --force to replace it)");
  detail::write_file_atomically(path, serialize_superelement(s, options.stress), options.overwrite);
}

se::Superelement parse_superelement(const std::string& bytes, const std::string& name, const LoadOptions& options) {
  const StringSource src(bytes);
  Reader r(src, name, options.parts);
  se::Superelement s = r.read();
  if (options.stress) *options.stress = r.stress();
  return s;
}

se::Superelement load_superelement(const std::filesystem::path& path, const LoadOptions& options) {
  const FileSource src(path);
  Reader r(src, path.string(), options.parts);
  se::Superelement s = r.read();
  if (options.stress) *options.stress = r.stress();
  return s;
}

SuperelementFileInfo inspect_superelement(const std::filesystem::path& path) {
  const FileSource src(path);
  Reader r(src, path.string(), SuperelementParts::Dynamics);
  SuperelementFileInfo info;
  info.dynamics = r.read();
  info.format_major = r.major();
  info.format_minor = r.minor();
  info.file_bytes = src.size();
  info.num_fe_nodes = r.num_fe_nodes();
  info.num_cells = r.num_cells();
  info.datasets = r.table();
  info.stress = r.stress();
  return info;
}

bool SuperelementFileInfo::has(const std::string& dataset) const {
  for (const auto& d : datasets)
    if (d.name == dataset) return true;
  return false;
}

bool SuperelementFileInfo::has_mesh() const { return num_fe_nodes > 0 || has("recovery") || has("M_fe.values"); }

std::uint64_t SuperelementFileInfo::bytes_of(bool mesh) const {
  std::uint64_t total = 0;
  for (const auto& d : datasets)
    if (d.mesh == mesh) total += d.bytes;
  return total;
}

std::uint64_t SuperelementFileInfo::invariant_bytes() const {
  std::uint64_t total = 0;
  for (const auto& d : datasets)
    if (d.name.rfind("inv.", 0) == 0) total += d.bytes;
  return total;
}

std::uint64_t superelement_memory_bytes(const se::Superelement& s) {
  std::uint64_t total = 8 * static_cast<std::uint64_t>(s.K.size() + s.M.size() + s.Phi_f.size() + s.recovery.size() +
                                                       s.p_BoI_B.size() + s.mode_frequencies_hz.size());
  total += 4 * s.fe_node_ids.size() + sizeof(se::MeshCell) * s.cells.size();
  total += 12 * static_cast<std::uint64_t>(s.M_fe.nonZeros()) + 4 * static_cast<std::uint64_t>(s.M_fe.outerSize() + 1);
  detail::for_each_invariant_dataset(s.invariants, s.size(), s.num_modes, [&](const std::string&, const auto& A, Eigen::Index, Eigen::Index) {
    total += 8 * static_cast<std::uint64_t>(A.size());
  });
  for (const auto& G : s.stiffening.inertia) total += 8 * static_cast<std::uint64_t>(G.size());
  for (const auto& G : s.stiffening.interface) total += 8 * static_cast<std::uint64_t>(G.size());
  return total;
}

void drop_mesh(se::Superelement& s) {
  s.fe_node_ids = {};
  s.p_BoI_B.resize(3, 0);
  s.recovery = Eigen::MatrixXd();
  s.M_fe = Eigen::SparseMatrix<double>();
  s.cells = {};
}

}  // namespace seflex::io
