// Superelement file format 1.2 and 1.3 (docs/superelement-format.md): the inertia invariants (and the 1.3
// geometric-stiffness invariants) round-trip
// bit-exactly; a reader can load the dynamics without the mesh (and still verifies the checksum
// over every byte); invariants with a wrong shape or an incomplete set are refused with a message
// naming the dataset; 1.1 files are still read; fewer internal modes truncate the invariants
// exactly; a scene whose full-inertia body has neither invariants nor mesh is refused with a
// message that says what to do.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "beam_superelement.hpp"
#include "seflex/common/error.hpp"
#include "seflex/scene/scene.hpp"
#include "seflex/io/sha256.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/reduction/inertia_invariants.hpp"
#include "test_support.hpp"

using namespace seflex;

namespace {

template <class A>
void randomize(A& a, Eigen::Index r, Eigen::Index c, std::mt19937& rng) {
  std::normal_distribution<double> g;
  a.resize(r, c);
  for (Eigen::Index k = 0; k < a.size(); ++k) a.data()[k] = g(rng) * std::pow(10.0, static_cast<int>(rng() % 40) - 20);
}

// Every field of se::InertiaInvariants (superelement/inertia_invariants.hpp) with random numbers
// spanning 40 decades (bit-exactness is then a real test of the number path).
se::InertiaInvariants random_invariants(Eigen::Index n, Eigen::Index m, unsigned seed) {
  std::mt19937 rng(seed);
  se::InertiaInvariants v;
  v.n = static_cast<int>(n);
  randomize(v.Mpp, n, n, rng);
  randomize(v.PmE0, n, 6, rng);
  randomize(v.E0mE0, 6, 6, rng);
  randomize(v.HP, 3 * n, n, rng);
  randomize(v.HE0, 18, n, rng);
  randomize(v.HE1, 9 * n, n, rng);
  randomize(v.PmLX, n, 6, rng);
  randomize(v.E0mLX, 6, 6, rng);
  for (auto& a : v.PmLP) randomize(a, n, n, rng);
  for (auto& a : v.E0mLP) randomize(a, 6, n, rng);
  randomize(v.HLX, 18, n, rng);
  for (auto& a : v.HLP) randomize(a, 3 * n, n, rng);
  for (auto& a : v.PmGP) randomize(a, n, n, rng);
  for (auto& a : v.E0mGP) randomize(a, 6, n, rng);
  for (auto& a : v.HGP) randomize(a, 3 * n, n, rng);
  randomize(v.PgOO, n, 9, rng);
  randomize(v.EgOO, 3, 9, rng);
  for (auto& a : v.PgOV) randomize(a, n, n, rng);
  for (auto& a : v.EgOV) randomize(a, 3, n, rng);
  randomize(v.mode_max_translation, m, 1, rng);
  return v;
}

// A 1 m beam along x (tests/mbd's Craig-Bampton builder): interfaces at both ends, `modes` modes,
// with recovery, FE node positions and FE mass.
se::Superelement beam(int modes) {
  test::BeamSection sec;
  sec.E = 7e10;
  sec.G = sec.E / 2.6;
  sec.A = 1e-4;
  sec.Iy = sec.Iz = 2e-9;
  sec.J = 4e-9;
  test::FrameFE fe = test::straight_beam(1.0, 4, sec);
  se::Superelement s = test::craig_bampton(fe, {0, 4}, 2, modes, "link");
  s.source_file = "link.bdf";
  s.source_hash = std::string(64, 'b');
  s.created = "2026-11-26T00:00:00Z";
  return s;
}

template <class A, class B>
bool same_bits(const A& a, const B& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// Every field of two invariant sets side by side (the array members as name.k): f(name, a, b).
template <class F>
void for_each_field(const se::InertiaInvariants& a, const se::InertiaInvariants& b, F&& f) {
  auto one = [&](const char* name, const auto& x, const auto& y) { f(std::string(name), Eigen::MatrixXd(x), Eigen::MatrixXd(y)); };
  auto arr = [&](const char* name, const auto& x, const auto& y) {
    for (std::size_t k = 0; k < x.size(); ++k) f(std::string(name) + "." + std::to_string(k), Eigen::MatrixXd(x[k]), Eigen::MatrixXd(y[k]));
  };
  one("Mpp", a.Mpp, b.Mpp);
  one("PmE0", a.PmE0, b.PmE0);
  one("E0mE0", a.E0mE0, b.E0mE0);
  one("HP", a.HP, b.HP);
  one("HE0", a.HE0, b.HE0);
  one("HE1", a.HE1, b.HE1);
  one("PmLX", a.PmLX, b.PmLX);
  one("E0mLX", a.E0mLX, b.E0mLX);
  arr("PmLP", a.PmLP, b.PmLP);
  arr("E0mLP", a.E0mLP, b.E0mLP);
  one("HLX", a.HLX, b.HLX);
  arr("HLP", a.HLP, b.HLP);
  arr("PmGP", a.PmGP, b.PmGP);
  arr("E0mGP", a.E0mGP, b.E0mGP);
  arr("HGP", a.HGP, b.HGP);
  one("PgOO", a.PgOO, b.PgOO);
  one("EgOO", a.EgOO, b.EgOO);
  arr("PgOV", a.PgOV, b.PgOV);
  arr("EgOV", a.EgOV, b.EgOV);
  one("mode_max_translation", a.mode_max_translation, b.mode_max_translation);
}

// Compare two invariant sets field by field, bit for bit; returns the first field that differs.
std::string first_difference(const se::InertiaInvariants& a, const se::InertiaInvariants& b) {
  if (a.n != b.n) return "n";
  std::string first;
  for_each_field(a, b, [&](const std::string& name, const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
    if (first.empty() && !same_bits(x, y)) first = name;
  });
  return first;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// Replace `from` by `to` (same length) in a file's JSON header and re-seal the checksum: a file a
// buggy or foreign writer could have produced.
std::string edit_header(std::string bytes, const std::string& from, const std::string& to) {
  EXPECT_EQ(from.size(), to.size());
  std::uint64_t hlen = 0;
  std::memcpy(&hlen, bytes.data() + 16, 8);
  const auto pos = bytes.find(from, 24);
  EXPECT_NE(pos, std::string::npos) << from;
  EXPECT_LT(pos, 24 + hlen) << from;
  bytes.replace(pos, from.size(), to);
  io::Sha256 h;
  h.update(bytes.data(), bytes.size() - 40);
  const auto d = h.digest();
  std::memcpy(bytes.data() + bytes.size() - 32, d.data(), 32);
  return bytes;
}

}  // namespace

TEST(SuperelementParts, InvariantsRoundTripBitExactly) {
  test::TempDir tmp;
  se::Superelement s = beam(3);
  s.invariants = random_invariants(s.size(), s.num_modes, 11);
  io::save_superelement(s, tmp / "body.se");
  const std::string bytes = test::read_file(tmp / "body.se");
  EXPECT_EQ(bytes.substr(8, 8), std::string("\x01\0\0\0\x04\0\0\0", 8));  // format 1.4 (the invariants came with 1.2/1.3)
  EXPECT_NE(bytes.find("\"format_version\": \"1.4\""), std::string::npos);
  EXPECT_NE(bytes.find("\"inv.PmLP.5\""), std::string::npos);
  EXPECT_NE(bytes.find("\"inv.EgOV.2\""), std::string::npos);
  const se::Superelement r = io::load_superelement(tmp / "body.se");
  EXPECT_EQ(first_difference(r.invariants, s.invariants), "");
  EXPECT_TRUE(same_bits(r.recovery, s.recovery));
  EXPECT_EQ(io::serialize_superelement(r), bytes);  // a second save gives the same bytes

  // Without the mesh part (seflex reduce --no-mesh).
  se::Superelement d = s;
  io::drop_mesh(d);
  const std::string dyn = io::serialize_superelement(d);
  EXPECT_LT(dyn.size(), bytes.size());
  for (const char* name : {"\"fe_node_ids\"", "\"fe_positions\"", "\"recovery\"", "\"M_fe.values\""})
    EXPECT_EQ(dyn.find(name), std::string::npos) << name;
  const se::Superelement rd = io::parse_superelement(dyn, "dyn.se");
  EXPECT_EQ(first_difference(rd.invariants, s.invariants), "");
  EXPECT_TRUE(rd.fe_node_ids.empty());
  EXPECT_EQ(rd.p_BoI_B.cols(), 0);
  EXPECT_EQ(rd.recovery.size(), 0);
  EXPECT_TRUE(same_bits(rd.K, s.K));
}

TEST(SuperelementParts, DynamicsLoadSkipsTheMeshButChecksEveryByte) {
  test::TempDir tmp;
  se::Superelement s = beam(2);
  s.invariants = random_invariants(s.size(), s.num_modes, 12);
  io::save_superelement(s, tmp / "body.se");
  const se::Superelement d = io::load_superelement(tmp / "body.se", {io::SuperelementParts::Dynamics});
  EXPECT_TRUE(d.fe_node_ids.empty());
  EXPECT_EQ(d.recovery.size(), 0);
  EXPECT_EQ(d.M_fe.size(), 0);
  EXPECT_TRUE(d.cells.empty());
  EXPECT_TRUE(same_bits(d.K, s.K));
  EXPECT_TRUE(same_bits(d.M, s.M));
  EXPECT_TRUE(same_bits(d.Phi_f, s.Phi_f));
  EXPECT_EQ(first_difference(d.invariants, s.invariants), "");
  EXPECT_EQ(d.mass, s.mass);
  EXPECT_LT(io::superelement_memory_bytes(d), io::superelement_memory_bytes(s));

  // A flipped byte in the recovery matrix (not read) is still caught by the checksum.
  std::string bytes = test::read_file(tmp / "body.se");
  const auto table = bytes.find("\"recovery\": {");
  ASSERT_NE(table, std::string::npos);
  const auto off = std::stoull(bytes.substr(bytes.find("\"offset\": ", table) + 10));
  bytes[off + 17] ^= 0x40;
  const auto bad = tmp.write("bad.se", bytes);
  const std::string msg = message_of([&] { io::load_superelement(bad, {io::SuperelementParts::Dynamics}); });
  EXPECT_NE(msg.find("bad.se: corrupted superelement file: SHA-256 checksum mismatch"), std::string::npos) << msg;

  // inspect_superelement: what `seflex info` prints.
  const io::SuperelementFileInfo info = io::inspect_superelement(tmp / "body.se");
  EXPECT_EQ(info.format_major, 1);
  EXPECT_EQ(info.format_minor, 4);
  EXPECT_TRUE(info.has_invariants());
  EXPECT_TRUE(info.has_mesh());
  EXPECT_EQ(info.num_fe_nodes, 5);
  const auto n = static_cast<std::uint64_t>(s.size());
  // n^2 (Mpp) + 6n (PmE0) + 36 + 3n^2 (HP) + 18n + 9n^2 + 6n + 36 + 6 n^2 + 36n + 18n + 18n^2 + 3n^2 + 18n + 9n^2
  // + 9n + 27 + 3n^2 + 9n: 52 n^2 + 120 n + 99 numbers, and the m mode amplitudes
  EXPECT_EQ(info.invariant_bytes(), 8 * (52 * n * n + 120 * n + 99 + static_cast<std::uint64_t>(s.num_modes)));
  // Mesh part: ids (int32), positions, recovery, M_fe (colptr 31, rowind and values nnz), 4 line cells.
  const auto nnz = static_cast<std::uint64_t>(s.M_fe.nonZeros());
  EXPECT_EQ(info.bytes_of(true), 4 * 5 + 8 * 15 + 8 * 30 * n + 8 * 31 + 16 * nnz + 4 * (4 + 4 + 16));
  EXPECT_EQ(info.bytes_of(false), 8 * (2 * n * n + 6 * n) + info.invariant_bytes());
}

TEST(SuperelementParts, BadInvariantDatasetsAreRefusedByName) {
  se::Superelement s = beam(0);  // n = 12
  s.invariants = random_invariants(s.size(), s.num_modes, 13);
  const std::string bytes = io::serialize_superelement(s);
  // A wrong shape (the byte count then also differs: the shape is checked first).
  const std::string msg1 = message_of(
      [&] { io::parse_superelement(edit_header(bytes, "\"inv.HE1\": {\"dtype\": \"float64\", \"order\": \"F\", \"shape\": [108, 12]",
                                               "\"inv.HE1\": {\"dtype\": \"float64\", \"order\": \"F\", \"shape\": [107, 12]"),
                                   "x.se"); });
  EXPECT_NE(msg1.find("x.se: dataset 'inv.HE1' has shape 107x12, expected 108x12"), std::string::npos) << msg1;
  // An incomplete set.
  const std::string msg2 = message_of([&] { io::parse_superelement(edit_header(bytes, "\"inv.HGP.1\"", "\"inv.HGQ.1\""), "y.se"); });
  EXPECT_NE(msg2.find("y.se: dataset 'inv.HGP.1' is missing; the file has 'inv.Mpp', and the inertia invariants are stored "
                      "complete or not at all"),
            std::string::npos)
      << msg2;
  // A writer never stores a wrong shape.
  se::Superelement w = s;
  w.invariants.PgOV[1].resize(3, 3);
  const std::string msg3 = message_of([&] { io::serialize_superelement(w); });
  EXPECT_NE(msg3.find("invariant inv.PgOV.1 is 3x3, expected 12x12"), std::string::npos) << msg3;
  w = s;
  w.invariants.HLX(2, 3) = std::nan("");
  EXPECT_NE(message_of([&] { io::serialize_superelement(w); }).find("invariant inv.HLX has non-finite entries"),
            std::string::npos);
}

TEST(SuperelementParts, MissingFileOrFolderIsNamed) {
  test::TempDir tmp;
  const std::string missing = message_of([&] { io::load_superelement(tmp / "none.se"); });
  EXPECT_NE(missing.find("none.se: cannot open superelement file"), std::string::npos) << missing;
  const std::string folder = message_of([&] { io::load_superelement(tmp.path()); });
  EXPECT_NE(folder.find(tmp.path().string() + ": is not a regular file; expected a superelement file (.se)"),
            std::string::npos)
      << folder;
}

TEST(SuperelementParts, Format11FileIsStillRead) {
  // A 1.1 file: the same bytes as today's (1.4) without invariants or stress modes, with minor version 1.
  const se::Superelement s = beam(2);
  std::string bytes = edit_header(io::serialize_superelement(s), "\"format_version\": \"1.4\"", "\"format_version\": \"1.1\"");
  bytes[12] = 1;
  io::Sha256 h;
  h.update(bytes.data(), bytes.size() - 40);
  const auto d = h.digest();
  std::memcpy(bytes.data() + bytes.size() - 32, d.data(), 32);
  const se::Superelement r = io::parse_superelement(bytes, "old.se");
  EXPECT_FALSE(r.invariants.present());
  EXPECT_TRUE(same_bits(r.recovery, s.recovery));
  EXPECT_EQ(r.fe_node_ids, s.fe_node_ids);
  EXPECT_TRUE(same_bits(Eigen::MatrixXd(r.M_fe), Eigen::MatrixXd(s.M_fe)));
}

// H_k(P) of inertia_invariants.hpp by its definition, stored (3n) x n with row r + 3c, column k:
// sum over FE nodes i of P_t,i[:, k] x (M P)_t,i[:, c].
Eigen::MatrixXd reference_HP(const se::Superelement& s) {
  const Eigen::Index n = s.size(), nfe = s.p_BoI_B.cols();
  const Eigen::MatrixXd MP = s.M_fe * s.recovery;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3 * n, n);
  for (Eigen::Index i = 0; i < nfe; ++i)
    for (Eigen::Index k = 0; k < n; ++k)
      for (Eigen::Index c = 0; c < n; ++c)
        H.block<3, 1>(3 * c, k) += Eigen::Vector3d(s.recovery.block<3, 1>(6 * i, k))
                                       .cross(Eigen::Vector3d(MP.block<3, 1>(6 * i, c)));
  return H;
}

// keep_internal_modes keeps the top-left corner of each invariant: checked on P^T M P and H_k(P)
// computed here from their definitions (the other fields share the layout rule).
TEST(SuperelementParts, FewerModesKeepTheInvariantsOfTheKeptColumns) {
  se::Superelement s = beam(4);
  s.invariants = random_invariants(s.size(), s.num_modes, 14);
  s.invariants.Mpp = s.recovery.transpose() * (s.M_fe * s.recovery);
  s.invariants.HP = reference_HP(s);
  const se::Superelement t = io::keep_internal_modes(s, 1);
  ASSERT_EQ(t.size(), 13);
  ASSERT_EQ(t.invariants.n, 13);
  const Eigen::MatrixXd Mpp = t.recovery.transpose() * (t.M_fe * t.recovery), HP = reference_HP(t);
  EXPECT_LE((t.invariants.Mpp - Mpp).cwiseAbs().maxCoeff(), 1e-14 * Mpp.cwiseAbs().maxCoeff());
  ASSERT_EQ(t.invariants.HP.rows(), HP.rows());
  ASSERT_EQ(t.invariants.HP.cols(), HP.cols());
  EXPECT_LE((t.invariants.HP - HP).cwiseAbs().maxCoeff(), 1e-14 * HP.cwiseAbs().maxCoeff());
  EXPECT_GT(HP.cwiseAbs().maxCoeff(), 0.0);
  // Every field has its shape for n = 13 (else the writer refuses it) and the fixed ones are kept.
  EXPECT_NO_THROW(io::serialize_superelement(t));
  EXPECT_TRUE(same_bits(t.invariants.EgOO, s.invariants.EgOO));
  EXPECT_TRUE(same_bits(t.invariants.HE1, Eigen::MatrixXd(s.invariants.HE1.topLeftCorner(9 * 13, 13))));
  EXPECT_TRUE(same_bits(t.invariants.E0mLP[4], Eigen::MatrixXd(s.invariants.E0mLP[4].leftCols(13))));
}

// keep_internal_modes truncates the invariants exactly: equal to the invariants computed from the
// truncated recovery matrix (reduction::compute_inertia_invariants always returns them for a body with
// its mesh part: their absence is a failure, not a reason to skip).
TEST(SuperelementParts, FewerModesTruncateTheInvariantsExactly) {
  se::Superelement s = beam(4);
  s.invariants = reduction::compute_inertia_invariants(s);
  ASSERT_TRUE(s.invariants.present()) << "reduction::compute_inertia_invariants returned no invariants";
  ASSERT_EQ(s.invariants.n, s.size());
  se::Superelement t = io::keep_internal_modes(s, 2);
  ASSERT_EQ(t.invariants.n, t.size());
  se::Superelement ref = t;
  ref.invariants = reduction::compute_inertia_invariants(ref);
  ASSERT_EQ(ref.invariants.n, t.size());
  // Same sums over the same nodes, in the same order: equal to round-off, every field (relative to
  // the field's largest entry; a field that is zero must stay zero).
  const double tol = 1e-13;
  int fields = 0;
  for_each_field(t.invariants, ref.invariants, [&](const std::string& name, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    ++fields;
    ASSERT_EQ(a.rows(), b.rows()) << name;
    ASSERT_EQ(a.cols(), b.cols()) << name;
    if (b.size() == 0) return;
    EXPECT_LE((a - b).cwiseAbs().maxCoeff(), tol * b.cwiseAbs().maxCoeff()) << name;
  });
  EXPECT_EQ(fields, 45);  // 12 single fields and 33 array members (6 + 6 + 6 + 3 + 3 + 3 + 3 + 3)
}

namespace {
const char* kScene = R"(title: one beam
bodies:
  - {name: link, superelement: link.se, inertia: INERTIA}
hinges:
  - {name: H1, parent: ground, child: link.1, axis: [0, 0, 1]}
integrator:
  t_end: 0.01
  step: 1.0e-3
output:
  interval: 0.01
)";

std::string scene_text(const std::string& inertia) {
  std::string t = kScene;
  t.replace(t.find("INERTIA"), 7, inertia);
  return t;
}
}  // namespace

TEST(SuperelementParts, FullInertiaWithoutInvariantsOrMeshIsRefused) {
  test::TempDir tmp;
  se::Superelement s = beam(1);
  io::drop_mesh(s);
  io::save_superelement(s, tmp / "link.se");
  const auto scene = tmp.write("scene.yaml", scene_text("full"));
  const std::string msg = message_of([&] { scene::build_scene(scene::read_scene(scene), {.keep_mesh = false}); });
  for (const char* part : {"scene.yaml:3: bodies[0]: inertia: full needs the inertia invariants of superelement ",
                           "link.se or its mesh part (recovery matrix and FE mass), and the file has neither",
                           "reduced with --no-mesh", "re-run `seflex reduce` with this seflex",
                           "or use inertia: simplified for this body"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << "\n" << msg;
  // The simplified inertia needs neither.
  const auto simple = tmp.write("simple.yaml", scene_text("simplified"));
  EXPECT_NO_THROW(scene::build_scene(scene::read_scene(simple), {.keep_mesh = false}));
}

// A run without animation reads the dynamics part only; a full-inertia body of an old file (no
// invariants) gets them from the mesh part, which is then dropped when they could be computed.
TEST(SuperelementParts, SceneLoadsTheDynamicsOnlyWhenTheMeshIsNotNeeded) {
  test::TempDir tmp;
  const se::Superelement s = beam(2);  // with mesh, no invariants
  io::save_superelement(s, tmp / "link.se");
  const auto simple = tmp.write("simple.yaml", scene_text("simplified"));
  const scene::Scene a = scene::build_scene(scene::read_scene(simple), {.keep_mesh = false});
  EXPECT_TRUE(a.superelements[0]->fe_node_ids.empty());
  EXPECT_EQ(a.superelements[0]->recovery.size(), 0);
  const scene::Scene b = scene::build_scene(scene::read_scene(simple));
  EXPECT_EQ(b.superelements[0]->fe_node_ids, s.fe_node_ids);

  const auto full = tmp.write("full.yaml", scene_text("full"));
  const scene::Scene c = scene::build_scene(scene::read_scene(full), {.keep_mesh = false});
  const se::InertiaInvariants expected = reduction::compute_inertia_invariants(s);
  ASSERT_TRUE(expected.present());  // else first_difference of two empty sets would be "" too
  ASSERT_TRUE(c.superelements[0]->invariants.present());
  EXPECT_EQ(first_difference(c.superelements[0]->invariants, expected), "");
  // Invariants computed: the mesh part is not kept.
  EXPECT_TRUE(c.superelements[0]->fe_node_ids.empty());
  EXPECT_EQ(c.superelements[0]->recovery.size(), 0);
}

// Format 1.3: the geometric-stiffness invariants (docs/geometric-stiffening.md) round-trip bit-exactly,
// fewer internal modes keep each matrix's top-left corner, and a scene that asks for
// geometric_stiffening: on from a file without them is refused with a message saying what to do.
namespace {
se::StiffeningInvariants random_stiffening(Eigen::Index n, int N, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> nd;
  auto sym = [&] {
    Eigen::MatrixXd A(n, n);
    for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = nd(rng);
    return Eigen::MatrixXd(A + A.transpose());
  };
  se::StiffeningInvariants st;
  st.n = static_cast<int>(n);
  for (auto& G : st.inertia) G = sym();
  for (int j = 0; j < 6 * N; ++j) st.interface.push_back(sym());
  return st;
}
}  // namespace

TEST(SuperelementParts, StiffeningInvariantsRoundTripAndTruncate) {
  test::TempDir tmp;
  se::Superelement s = beam(3);
  s.stiffening = random_stiffening(s.size(), s.num_interfaces(), 21);
  io::save_superelement(s, tmp / "body.se");
  const std::string bytes = test::read_file(tmp / "body.se");
  EXPECT_NE(bytes.find("\"stiff.inertia.11\""), std::string::npos);
  EXPECT_NE(bytes.find("\"stiff.interface." + std::to_string(6 * s.num_interfaces() - 1) + "\""), std::string::npos);
  const se::Superelement r = io::load_superelement(tmp / "body.se", {io::SuperelementParts::Dynamics});
  ASSERT_TRUE(r.stiffening.present());
  ASSERT_EQ(r.stiffening.interface.size(), s.stiffening.interface.size());
  for (std::size_t c = 0; c < 12; ++c) EXPECT_TRUE(same_bits(r.stiffening.inertia[c], s.stiffening.inertia[c])) << c;
  for (std::size_t j = 0; j < s.stiffening.interface.size(); ++j)
    EXPECT_TRUE(same_bits(r.stiffening.interface[j], s.stiffening.interface[j])) << j;
  const se::Superelement t = io::keep_internal_modes(s, 1);
  const Eigen::Index n = t.size();
  ASSERT_EQ(t.stiffening.n, n);
  EXPECT_TRUE(same_bits(t.stiffening.inertia[7], Eigen::MatrixXd(s.stiffening.inertia[7].topLeftCorner(n, n))));
  EXPECT_TRUE(same_bits(t.stiffening.interface[3], Eigen::MatrixXd(s.stiffening.interface[3].topLeftCorner(n, n))));
  EXPECT_NO_THROW(io::serialize_superelement(t));
  // A file without them reads as before (not present).
  se::Superelement plain = beam(3);
  EXPECT_FALSE(io::parse_superelement(io::serialize_superelement(plain), "plain.se").stiffening.present());
}

TEST(SuperelementParts, StiffeningAskedFromAFileWithoutItIsRefused) {
  test::TempDir tmp;
  se::Superelement s = beam(1);
  io::save_superelement(s, tmp / "link.se");
  std::string text = scene_text("simplified");
  text.replace(text.find("inertia: simplified}"), 20, "inertia: simplified, geometric_stiffening: on}");
  const auto scene = tmp.write("scene.yaml", text);
  const std::string msg = message_of([&] { scene::build_scene(scene::read_scene(scene), {.keep_mesh = false}); });
  for (const char* part : {"scene.yaml:3: bodies[0]: geometric_stiffening: on, but ", "link.se carries no geometric-stiffness invariants",
                           "re-run `seflex reduce` without --no-stiffening", "or set geometric_stiffening: off"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << "\n" << msg;
  // Unset, the body runs without stiffening; with the invariants in the file it runs with them.
  EXPECT_NO_THROW(scene::build_scene(scene::read_scene(tmp.write("plain.yaml", scene_text("simplified"))), {.keep_mesh = false}));
  s.stiffening = random_stiffening(s.size(), s.num_interfaces(), 3);
  io::save_superelement(s, tmp / "link.se", io::SaveOptions{true});
  EXPECT_NO_THROW(scene::build_scene(scene::read_scene(scene), {.keep_mesh = false}));
}
