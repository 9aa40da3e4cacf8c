// Superelement file writer and reader (docs/superelement-format.md).
#include "seflex/io/superelement_file.hpp"

#include <yaml-cpp/yaml.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "atomic_write.hpp"
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
// Reading
/// "a list", "an object", ... for messages about a header value of the wrong kind.
std::string node_kind(const YAML::Node& n) {
  if (n.IsScalar()) return "the value '" + n.Scalar() + "'";
  if (n.IsSequence()) return "an array";
  if (n.IsMap()) return "an object";
  return "null";
}

class Reader {
 public:
  Reader(const std::string& bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& what) const { throw InputError(SourceRef{name_, 0}, what); }

  se::Superelement read() {
    if (bytes_.size() < kPreamble + kTrailer || std::memcmp(bytes_.data(), kMagic, 8) != 0) {
      if (bytes_.size() >= 8 && std::memcmp(bytes_.data(), kMagic, 8) == 0)
        fail("truncated superelement file: only " + std::to_string(bytes_.size()) + " bytes");
      fail("not a seflex superelement file (expected the magic bytes 'SEFLEXSE' at the start)");
    }
    std::uint32_t major, minor;
    std::uint64_t header_len;
    std::memcpy(&major, bytes_.data() + 8, 4);
    std::memcpy(&minor, bytes_.data() + 12, 4);
    std::memcpy(&header_len, bytes_.data() + 16, 8);
    if (static_cast<int>(major) != kSuperelementFormatMajor)
      fail("superelement file format " + std::to_string(major) + "." + std::to_string(minor) +
           " is not supported; this seflex reads format " + std::to_string(kSuperelementFormatMajor) + ".x");
    if (header_len > bytes_.size() - kPreamble - kTrailer)
      fail("truncated superelement file: the header promises " + std::to_string(header_len) + " bytes but the file has " +
           std::to_string(bytes_.size()) + " bytes in all");
    // Trailer: the declared total length and the checksum.
    const std::size_t body_len = bytes_.size() - kTrailer;
    if (std::memcmp(bytes_.data() + body_len, kTrailerMagic, 8) != 0)
      fail("truncated or corrupted superelement file: the end-of-file marker 'SEFLXEND' is missing");
    Sha256 h;
    h.update(bytes_.data(), body_len);
    const auto digest = h.digest();
    if (std::memcmp(digest.data(), bytes_.data() + body_len + 8, 32) != 0)
      fail("corrupted superelement file: SHA-256 checksum mismatch (the file was modified or damaged)");

    YAML::Node header;
    try {
      header = YAML::Load(std::string(bytes_.data() + kPreamble, header_len));
    } catch (const YAML::Exception& e) {
      fail(std::string("unreadable JSON header: ") + e.what());
    }
    if (!header.IsMap()) fail("the header is not a JSON object");
    data_begin_ = kPreamble + header_len;
    data_end_ = body_len;
    return build(header);
  }

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

  // Locate a dataset; checks dtype, shape and that its bytes lie inside the data region.
  const char* dataset(const YAML::Node& table, const std::string& name, const std::string& dtype,
                      std::vector<std::int64_t> shape, bool required = true) const {
    const YAML::Node d = table[name];
    if (!d) {
      if (required) fail("dataset '" + name + "' is missing");
      return nullptr;
    }
    if (!d.IsMap()) fail("dataset '" + name + "': its table entry must be an object");
    if (get<std::string>(d, "dtype") != dtype) fail("dataset '" + name + "' must have dtype " + dtype);
    const auto got = get<std::vector<std::int64_t>>(d, "shape");
    if (got != shape) {
      auto text = [](const std::vector<std::int64_t>& v) {
        std::string t;
        for (auto x : v) {
          if (!t.empty()) t += 'x';
          t += std::to_string(x);
        }
        return t;
      };
      fail("dataset '" + name + "' has shape " + text(got) + ", expected " + text(shape));
    }
    const auto offset = get<std::uint64_t>(d, "offset");
    const auto nbytes = get<std::uint64_t>(d, "bytes");
    std::uint64_t count = 1;
    for (auto s : shape) count *= static_cast<std::uint64_t>(s);
    const std::uint64_t width = dtype == "float64" || dtype == "int64" ? 8 : 4;
    if (nbytes != count * width) fail("dataset '" + name + "': byte count does not match its shape");
    if (offset < data_begin_ || offset > data_end_ || nbytes > data_end_ - offset)
      fail("dataset '" + name + "' lies outside the file's data section (truncated file?)");
    return bytes_.data() + offset;
  }

  Eigen::MatrixXd matrix(const YAML::Node& table, const std::string& name, Eigen::Index rows, Eigen::Index cols) const {
    Eigen::MatrixXd A(rows, cols);
    const char* p = dataset(table, name, "float64", {rows, cols});
    if (A.size() > 0) std::memcpy(A.data(), p, sizeof(double) * static_cast<std::size_t>(A.size()));
    return A;
  }

  template <class T>
  std::vector<T> array(const YAML::Node& table, const std::string& name, const char* dtype, std::int64_t n) const {
    std::vector<T> v(static_cast<std::size_t>(n));
    const char* p = dataset(table, name, dtype, {n});
    if (n > 0) std::memcpy(v.data(), p, sizeof(T) * v.size());
    return v;
  }

  se::Superelement build(const YAML::Node& h) const {
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
    const Eigen::Index n = s.size();
    s.K = matrix(table, "K", n, n);
    s.M = matrix(table, "M", n, n);
    s.Phi_f = matrix(table, "Phi_f", 6, n);
    const std::int64_t nfe = get<std::int64_t>(h, "num_fe_nodes");
    if (nfe < 0 || static_cast<std::uint64_t>(nfe) > bytes_.size()) fail("header: 'num_fe_nodes' out of range");
    s.fe_node_ids = array<std::int32_t>(table, "fe_node_ids", "int32", nfe);
    s.p_BoI_B = matrix(table, "fe_positions", 3, nfe);
    if (table["recovery"]) s.recovery = matrix(table, "recovery", 6 * nfe, n);
    if (table["M_fe.values"]) {
      const auto shape = get<std::vector<std::int64_t>>(table["M_fe.values"], "shape");
      if (shape.size() != 1 || shape[0] < 0 || static_cast<std::uint64_t>(shape[0]) > bytes_.size())
        fail("dataset 'M_fe.values' must be a vector of a plausible length");
      const std::int64_t nnz = shape[0];
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
    const std::int64_t ncells = get<std::int64_t>(h, "num_cells");
    if (ncells < 0 || static_cast<std::uint64_t>(ncells) > bytes_.size()) fail("header: 'num_cells' out of range");
    if (ncells > 0) {
      const auto types = array<std::int32_t>(table, "cells.type", "int32", ncells);
      const auto eids = array<std::int32_t>(table, "cells.element_id", "int32", ncells);
      std::vector<std::int32_t> nodes(static_cast<std::size_t>(4 * ncells));
      std::memcpy(nodes.data(), dataset(table, "cells.nodes", "int32", {4, ncells}), nodes.size() * 4);
      s.cells.resize(static_cast<std::size_t>(ncells));
      for (std::int64_t c = 0; c < ncells; ++c) {
        auto& cell = s.cells[static_cast<std::size_t>(c)];
        if (types[c] != 2 && types[c] != 3 && types[c] != 4) fail("dataset 'cells.type' has an unknown cell type");
        cell.type = static_cast<se::MeshCell::Type>(types[c]);
        cell.element_id = eids[c];
        for (int k = 0; k < 4; ++k) cell.nodes[k] = nodes[static_cast<std::size_t>(4 * c + k)];
      }
    }
    const auto problems = se::check_consistency(s);
    if (!problems.empty()) {
      std::string msg = "inconsistent superelement:";
      for (const auto& p : problems) msg += " " + p + ";";
      msg.pop_back();
      fail(msg);
    }
    return s;
  }

  const std::string& bytes_;
  std::string name_;
  std::uint64_t data_begin_ = 0, data_end_ = 0;
};

}  // namespace

std::string serialize_superelement(const se::Superelement& s) {
  const auto problems = se::check_consistency(s);
  if (!problems.empty()) {
    std::string msg = "cannot save an inconsistent superelement:";
    for (const auto& p : problems) msg += " " + p + ";";
    throw InvariantError(msg);
  }
  const auto nfe = static_cast<std::int64_t>(s.fe_node_ids.size());

  std::vector<Dataset> data;
  data.push_back(matrix_dataset("K", s.K));
  data.push_back(matrix_dataset("M", s.M));
  data.push_back(matrix_dataset("Phi_f", s.Phi_f));
  std::vector<std::int32_t> ids(s.fe_node_ids.begin(), s.fe_node_ids.end());
  data.push_back(make_dataset("fe_node_ids", "int32", ids.data(), {nfe}));
  data.push_back(make_dataset("fe_positions", "float64", s.p_BoI_B.data(), {3, nfe}));
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
  detail::write_file_atomically(path, serialize_superelement(s), options.overwrite);
}

se::Superelement parse_superelement(const std::string& bytes, const std::string& name) {
  return Reader(bytes, name).read();
}

se::Superelement load_superelement(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceRef{path.string(), 0}, "cannot open superelement file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_superelement(ss.str(), path.string());
}

}  // namespace seflex::io
