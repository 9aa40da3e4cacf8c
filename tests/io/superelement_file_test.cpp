// Superelement file (docs/superelement-format.md): save then load is bit-exact; truncated, corrupted,
// foreign and newer-version files are refused with a message naming the file and the problem;
// the Python reference reader (scripts/read_superelement.py) reads the same numbers.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "seflex/common/error.hpp"
#include "seflex/io/sha256.hpp"
#include "seflex/io/superelement_file.hpp"
#include "test_support.hpp"

using namespace seflex;

namespace {

// A consistent superelement with random (symmetric) matrices: N interface nodes, m modes.
se::Superelement random_superelement(int N, int m, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  se::Superelement s;
  s.name = "test body";
  s.source_file = "model.bdf";
  s.source_hash = std::string(64, 'a');
  s.created = "2026-11-21T00:00:00Z";
  s.frame_node_id = 42;
  s.p_OBo = {0.1, -0.2, 1.0 / 3.0};
  for (int j = 0; j < N; ++j) {
    se::InterfaceNode in;
    in.id = 1 + j;
    in.p_BoN_B = {g(rng), g(rng), g(rng)};
    s.interfaces.push_back(in);
  }
  s.num_modes = m;
  s.mode_frequencies_hz = Eigen::VectorXd::LinSpaced(m, 10.0, 100.0);
  const int n = 6 * N + m;
  Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(n, n, [&]() { return g(rng); });
  s.K = A * A.transpose();
  Eigen::MatrixXd B = Eigen::MatrixXd::NullaryExpr(n, n, [&]() { return g(rng); });
  s.M = B * B.transpose() + Eigen::MatrixXd::Identity(n, n);
  s.Phi_f = Eigen::MatrixXd::NullaryExpr(6, n, [&]() { return g(rng); });
  s.mass = M_PI;
  s.p_BoCm_B = {1e-300, -7.25, 3e10};
  s.I_Cm_B = Eigen::Matrix3d::Identity() * 0.1;
  const int nfe = 5;
  for (int i = 0; i < nfe; ++i) s.fe_node_ids.push_back(100 + i);
  s.p_BoI_B = Eigen::Matrix3Xd::NullaryExpr(3, nfe, [&]() { return g(rng); });
  s.recovery = Eigen::MatrixXd::NullaryExpr(6 * nfe, n, [&]() { return g(rng); });
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 6 * nfe; ++i) t.emplace_back(i, i, 1.0 + i);
  t.emplace_back(0, 4, 0.25);
  t.emplace_back(4, 0, 0.25);
  s.M_fe.resize(6 * nfe, 6 * nfe);
  s.M_fe.setFromTriplets(t.begin(), t.end());
  s.cells.push_back({se::MeshCell::Type::Quad, {0, 1, 2, 3}, 7});
  s.cells.push_back({se::MeshCell::Type::Line, {3, 4, -1, -1}, 8});
  s.truncation.effective_mass_fraction = {0.9, 0.8, 0.7, 0.6, 0.5, 0.4};
  s.truncation.first_neglected_hz = 123.456;
  s.truncation.max_kept_hz = 100.0;
  return s;
}

bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace

TEST(Sha256, KnownVectors) {
  // FIPS 180-2 appendix B (NIST CSRC "SHA256.pdf"): "abc" (B.1), the 448-bit message (B.2) and one
  // million 'a' (B.3), plus the empty string.
  auto hex = [](const std::string& m) {
    io::Sha256 h;
    h.update(m);
    return h.hex_digest();
  };
  EXPECT_EQ(hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  EXPECT_EQ(io::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // The million 'a' fed in uneven pieces (across the 64-byte block boundaries): the same digest.
  io::Sha256 h;
  const std::string a(1000000, 'a');
  for (std::size_t at = 0, piece = 1; at < a.size(); at += piece, piece = piece * 3 % 1021 + 1)
    h.update(a.data() + at, std::min(piece, a.size() - at));
  EXPECT_EQ(h.hex_digest(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, VerifiesTheChecksumsOfFilesWrittenBefore) {
  // The superelement files of tests/data were written by seflex's own SHA-256 code (before nettle);
  // each ends in the SHA-256 of the bytes before its 40-byte trailer. nettle must give those digests.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::data_dir() / "fuzz-regressions" / "superelement")) {
    if (entry.path().extension() != ".se") continue;
    const std::string bytes = test::read_file(entry.path());
    ASSERT_GT(bytes.size(), 40u) << entry.path();
    ASSERT_EQ(bytes.substr(bytes.size() - 40, 8), "SEFLXEND") << entry.path();
    io::Sha256 h;
    h.update(bytes.data(), bytes.size() - 40);
    const auto d = h.digest();
    EXPECT_EQ(std::string(d.begin(), d.end()), bytes.substr(bytes.size() - 32)) << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 5);
}

TEST(SuperelementFile, SaveThenLoadIsBitExact) {
  test::TempDir tmp;
  const auto s = random_superelement(3, 4, 1);
  io::save_superelement(s, tmp / "body.se");
  const auto r = io::load_superelement(tmp / "body.se");
  EXPECT_EQ(r.name, s.name);
  EXPECT_EQ(r.source_hash, s.source_hash);
  EXPECT_EQ(r.frame_node_id, 42);
  ASSERT_EQ(r.interfaces.size(), 3u);
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(r.interfaces[j].id, s.interfaces[j].id);
    EXPECT_TRUE(same_bits(r.interfaces[j].p_BoN_B, s.interfaces[j].p_BoN_B));
  }
  EXPECT_TRUE(same_bits(r.p_OBo, s.p_OBo));
  EXPECT_TRUE(same_bits(r.K, s.K));
  EXPECT_TRUE(same_bits(r.M, s.M));
  EXPECT_TRUE(same_bits(r.Phi_f, s.Phi_f));
  EXPECT_TRUE(same_bits(r.recovery, s.recovery));
  EXPECT_TRUE(same_bits(r.p_BoI_B, s.p_BoI_B));
  EXPECT_TRUE(same_bits(r.mode_frequencies_hz, s.mode_frequencies_hz));
  EXPECT_TRUE(same_bits(r.p_BoCm_B, s.p_BoCm_B));
  EXPECT_TRUE(same_bits(r.I_Cm_B, s.I_Cm_B));
  EXPECT_EQ(r.mass, s.mass);
  EXPECT_TRUE(same_bits(Eigen::MatrixXd(r.M_fe), Eigen::MatrixXd(s.M_fe)));
  ASSERT_EQ(r.cells.size(), 2u);
  EXPECT_EQ(r.cells[0].nodes, s.cells[0].nodes);
  EXPECT_EQ(r.cells[1].type, se::MeshCell::Type::Line);
  EXPECT_EQ(r.truncation.first_neglected_hz, 123.456);
  // And the bytes of a second save are identical.
  EXPECT_EQ(io::serialize_superelement(r), io::serialize_superelement(s));
}

TEST(SuperelementFile, RefusesToOverwrite) {
  test::TempDir tmp;
  const auto s = random_superelement(2, 0, 2);
  io::save_superelement(s, tmp / "body.se");
  const std::string msg = message_of([&] { io::save_superelement(s, tmp / "body.se"); });
  EXPECT_NE(msg.find("body.se"), std::string::npos) << msg;
  EXPECT_NE(msg.find("refusing to overwrite"), std::string::npos) << msg;
  EXPECT_NO_THROW(io::save_superelement(s, tmp / "body.se", {.overwrite = true}));
}

TEST(SuperelementFile, TruncatedFileIsRefusedAtEveryLength) {
  const std::string bytes = io::serialize_superelement(random_superelement(2, 1, 3));
  // Every truncation must be refused with a clear message (never a crash or a silent partial load).
  for (std::size_t len = 0; len < bytes.size(); len += 1 + len / 7) {
    const std::string msg = message_of([&] { io::parse_superelement(bytes.substr(0, len), "cut.se"); });
    EXPECT_EQ(msg.rfind("cut.se: ", 0), 0u) << "length " << len << ": " << msg;
    EXPECT_TRUE(msg.find("truncated") != std::string::npos || msg.find("not a seflex superelement") != std::string::npos ||
                msg.find("corrupted") != std::string::npos)
        << "length " << len << ": " << msg;
  }
}

TEST(SuperelementFile, CorruptedByteIsDetected) {
  const std::string bytes = io::serialize_superelement(random_superelement(2, 1, 4));
  std::mt19937 rng(5);
  for (int k = 0; k < 200; ++k) {
    std::string bad = bytes;
    const std::size_t pos = 8 + rng() % (bytes.size() - 8);
    bad[pos] = static_cast<char>(bad[pos] ^ (1 + rng() % 255));
    const std::string msg = message_of([&] { io::parse_superelement(bad, "bad.se"); });
    EXPECT_EQ(msg.rfind("bad.se: ", 0), 0u) << msg;
  }
  std::string bad = bytes;
  bad[bytes.size() / 2] ^= 0x10;
  EXPECT_NE(message_of([&] { io::parse_superelement(bad, "bad.se"); }).find("checksum mismatch"), std::string::npos);
}

TEST(SuperelementFile, ForeignAndNewerFilesAreRefused) {
  EXPECT_NE(message_of([] { io::parse_superelement("GRID    1       0       0.      0.      0.\n", "deck.bdf"); })
                .find("not a seflex superelement file"),
            std::string::npos);
  std::string bytes = io::serialize_superelement(random_superelement(1, 0, 6));
  bytes[8] = 2;  // format major 2
  const std::string msg = message_of([&] { io::parse_superelement(bytes, "new.se"); });
  EXPECT_NE(msg.find("format 2." + std::to_string(io::kSuperelementFormatMinor) + " is not supported"), std::string::npos) << msg;
}

TEST(SuperelementFile, InconsistentSuperelementIsNotSaved) {
  auto s = random_superelement(2, 0, 7);
  s.K(0, 1) += 1.0;  // not symmetric
  EXPECT_THROW(io::serialize_superelement(s), InvariantError);
  s = random_superelement(2, 0, 7);
  s.M(3, 3) = std::nan("");
  EXPECT_THROW(io::serialize_superelement(s), InvariantError);
}

TEST(SuperelementFile, PythonReferenceReaderReadsTheSameNumbers) {
  // numpy and scipy are dependencies of the build (scripts/install-deps.sh): their absence is a
  // broken environment to report, not a reason to skip the only independent reader of the format.
  ASSERT_EQ(std::system("/usr/bin/python3 -c 'import numpy, scipy' >/dev/null 2>&1"), 0)
      << "/usr/bin/python3 cannot import numpy and scipy (scripts/install-deps.sh installs them)";
  test::TempDir tmp;
  const auto s = random_superelement(2, 2, 8);
  io::save_superelement(s, tmp / "body.se");
  const std::string script = (test::source_dir() / "scripts" / "read_superelement.py").string();
  const std::string cmd = "/usr/bin/python3 '" + script + "' '" + (tmp / "body.se").string() + "' > '" +
                          (tmp / "out.txt").string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string out = test::read_file(tmp / "out.txt");
  char expect[128];
  std::snprintf(expect, sizeof expect, "K[0,0] %.17g", s.K(0, 0));
  EXPECT_NE(out.find("2 interface nodes, 2 modes, n = 14"), std::string::npos) << out;
  // repr() of a Python float is the shortest round-trip string; compare numerically instead of textually.
  const auto pos = out.find("K[0,0] ");
  ASSERT_NE(pos, std::string::npos);
  EXPECT_EQ(std::stod(out.substr(pos + 7)), s.K(0, 0)) << expect;
  // The mass (str() of a Python float: shortest round trip, exact) and trace(M) (numpy's own sum of the
  // 14 positive diagonal terms, in an order of its choosing: to a few ulps).
  const auto at_mass = out.find("mass ");
  ASSERT_NE(at_mass, std::string::npos) << out;
  EXPECT_EQ(std::stod(out.substr(at_mass + 5)), s.mass) << out;
  const auto at_trace = out.find("trace(M) ");
  ASSERT_NE(at_trace, std::string::npos) << out;
  EXPECT_NEAR(std::stod(out.substr(at_trace + 9)), s.M.trace(), 1e-15 * s.M.trace()) << out;
  EXPECT_NE(out.find("mesh part: 5 FE nodes"), std::string::npos) << out;
}
