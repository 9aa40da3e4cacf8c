// seflex info BODY.se and seflex reduce --no-mesh from the command line: the description of a
// superelement reduced in the test (provenance, interfaces, modes, mass properties against the
// deck's CONM2 cards, invariants, mesh part); a dynamics-only file; refusals of damaged files and
// of options that apply to decks; seflex run --no-animation reads the dynamics part only.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "scene_fixture.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/sha256.hpp"
#include "seflex/io/superelement_file.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

using test::q;
std::filesystem::path yoke() { return test::source_dir() / "meshes" / "yoke.bdf"; }

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(InfoSuperelementCli, DescribesAReducedYoke) {
  test::TempDir tmp;
  const auto se_path = tmp / "yoke.se";
  const auto red = test::run_seflex("reduce " + q(yoke()) + " --interface 1,3,4 --modes 4 -o " + q(se_path));
  ASSERT_EQ(red.exit_code, 0) << red.err;
  const auto r = test::run_seflex("info " + q(se_path));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string& o = r.out;
  const se::Superelement s = io::load_superelement(se_path);

  EXPECT_TRUE(has(o, "superelement " + se_path.string() + "\n")) << o;
  EXPECT_TRUE(has(o, "  name                         yoke\n")) << o;
  EXPECT_TRUE(has(o, "  format                       1.4, ")) << o;
  EXPECT_TRUE(has(o, "  source                       " + yoke().string() + "\n")) << o;
  EXPECT_TRUE(has(o, "  source SHA-256               " + io::sha256_file_hex(yoke()) + "\n")) << o;
  EXPECT_TRUE(has(o, "  units                        SI\n")) << o;
  EXPECT_TRUE(has(o, "frame node 18 at ")) << o;
  EXPECT_TRUE(has(o, "interfaces: 3 nodes, 18 dofs")) << o;
  for (const auto& n : s.interfaces) {
    char row[96];
    std::snprintf(row, sizeof row, "  %8d %14.6E %14.6E %14.6E\n", n.id, n.p_BoN_B.x(), n.p_BoN_B.y(), n.p_BoN_B.z());
    EXPECT_TRUE(has(o, row)) << row << o;
  }
  EXPECT_TRUE(has(o, "reduced size n = 22 (6 x 3 interface dofs + 4 fixed-interface modes)")) << o;
  // The frequencies reduce printed, to the digit.
  for (int k = 0; k < 4; ++k) {
    const std::string f = fmt("%16.6f Hz", s.mode_frequencies_hz(k));
    EXPECT_TRUE(has(o, "  mode " + fmt("%4.0f", k + 1) + " " + f)) << f << o;
    EXPECT_TRUE(has(red.out, fmt("%14.6f Hz", s.mode_frequencies_hz(k)))) << red.out;
  }
  // Mass properties against the deck: 14 CONM2 of 0.9 kg (meshes/README.md), centre of mass = their
  // mean position (no offsets), from the frame node.
  EXPECT_TRUE(has(o, "  mass                           1.260000E+01\n")) << o;
  const fem::Model m = io::read_model(yoke());
  ASSERT_EQ(m.conm2.size(), 14u);
  Eigen::Vector3d cg = Eigen::Vector3d::Zero();
  for (const auto& c : m.conm2) {
    EXPECT_EQ(c.x, Eigen::Vector3d::Zero());
    cg += m.grids[m.grid_index.at(c.grid)].x_basic / 14.0;
  }
  cg -= m.grids[m.grid_index.at(18)].x_basic;
  const auto at = o.find("  centre of mass from frame ");
  ASSERT_NE(at, std::string::npos) << o;
  std::istringstream com(o.substr(at + 28));
  Eigen::Vector3d printed;
  com >> printed.x() >> printed.y() >> printed.z();
  EXPECT_LE((printed - cg).norm(), 1e-6 * cg.norm()) << printed.transpose() << " vs " << cg.transpose();  // 7 digits printed
  const io::SuperelementFileInfo info = io::inspect_superelement(se_path);
  if (info.has_invariants())
    EXPECT_TRUE(has(o, "inertia invariants           present, ")) << o;
  else
    EXPECT_TRUE(has(o, "inertia invariants           absent")) << o;
  // reduce computes the geometric-stiffness invariants by default: 12 inertia cases, one per interface dof.
  ASSERT_TRUE(info.dynamics.stiffening.present());
  EXPECT_TRUE(has(o, "stiffening invariants        present: 12 inertia load cases, " +
                         std::to_string(6 * info.dynamics.num_interfaces()) + " constraint modes; ")) << o;
  EXPECT_TRUE(has(o, "mesh part                    present: " + std::to_string(m.grids.size()) + " FE nodes, 19 cells, "
                     "recovery yes, FE mass yes;")) << o;
  EXPECT_TRUE(has(o, "modal effective mass fraction")) << o;
  EXPECT_TRUE(has(o, fmt("  first neglected mode       %14.6f Hz", s.truncation.first_neglected_hz))) << o;
  EXPECT_TRUE(has(o, "source warnings")) << o;
  // Not the Nastran reader's answer.
  EXPECT_FALSE(has(o + r.err, "binary")) << o << r.err;
}

TEST(InfoSuperelementCli, NoMeshWritesTheDynamicsOnly) {
  test::TempDir tmp;
  const auto full = tmp / "full.se", dyn = tmp / "dyn.se";
  ASSERT_EQ(test::run_seflex("reduce " + q(yoke()) + " --interface 1,3,4 --modes 4 -o " + q(full)).exit_code, 0);
  const auto red = test::run_seflex("reduce " + q(yoke()) + " --interface 1,3,4 --modes 4 --no-mesh -o " + q(dyn));
  ASSERT_EQ(red.exit_code, 0) << red.err;
  EXPECT_TRUE(has(red.out, "mesh part: left out (--no-mesh;")) << red.out;
  EXPECT_LT(std::filesystem::file_size(dyn), std::filesystem::file_size(full));
  const se::Superelement a = io::load_superelement(full), b = io::load_superelement(dyn);
  EXPECT_TRUE(b.fe_node_ids.empty());
  EXPECT_EQ(b.p_BoI_B.cols(), 0);
  EXPECT_EQ(b.recovery.size(), 0);
  EXPECT_EQ(b.M_fe.size(), 0);
  EXPECT_TRUE(b.cells.empty());
  EXPECT_EQ(b.invariants.present(), a.invariants.present());  // computed before the mesh is dropped
  // Same reduction: the same dynamics.
  EXPECT_LE((a.K - b.K).cwiseAbs().maxCoeff(), 1e-12 * a.K.cwiseAbs().maxCoeff());
  EXPECT_LE((a.M - b.M).cwiseAbs().maxCoeff(), 1e-12 * a.M.cwiseAbs().maxCoeff());
  EXPECT_LE((a.Phi_f - b.Phi_f).cwiseAbs().maxCoeff(), 1e-12);
  const auto r = test::run_seflex("info " + q(dyn));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "mesh part                    absent (reduced with --no-mesh")) << r.out;
}

TEST(InfoSuperelementCli, RefusesDamagedFilesAndDeckOptions) {
  test::TempDir tmp;
  const auto se_path = tmp / "yoke.se";
  ASSERT_EQ(test::run_seflex("reduce " + q(yoke()) + " --interface 1,5 --no-mesh -o " + q(se_path)).exit_code, 0);
  const auto opt = test::run_seflex("info " + q(se_path) + " --grdpnt 2");
  EXPECT_EQ(opt.exit_code, 2);
  EXPECT_TRUE(has(opt.err, "is a superelement file; --grdpnt, --properties, --set and --symbol apply to a model")) << opt.err;
  std::string bytes = test::read_file(se_path);
  bytes[bytes.size() / 2] ^= 0x01;
  const auto bad = tmp.write("bad.se", bytes);
  const auto r = test::run_seflex("info " + q(bad));
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_TRUE(has(r.err, bad.string() + ": corrupted superelement file: SHA-256 checksum mismatch")) << r.err;
  const auto cut = tmp.write("cut.se", bytes.substr(0, 100));
  const auto c = test::run_seflex("info " + q(cut));
  EXPECT_EQ(c.exit_code, 3);
  EXPECT_TRUE(has(c.err, "cut.se: truncated")) << c.err;
}

// seflex run reports the superelement memory it holds: without animation the mesh part is not read.
TEST(InfoSuperelementCli, RunWithoutAnimationReadsTheDynamicsOnly) {
  test::TempDir dir;
  // No fixed-interface modes: the integrator's error weights of modal coordinates use the mode
  // shapes' peak FE translation when the mesh is loaded (mbd/src/bodies/aic_element.cpp), so with modes
  // the two runs would differ by their step sequence, not by their dynamics.
  test::write_link(dir, "link.se");
  const auto scene = dir.write("scene.yaml", R"(title: link
bodies:
  - {name: link, superelement: link.se}
hinges:
  - {name: H1, parent: ground, child: link.1, axis: [0, 0, 1]}
loads:
  gravity: [0, -9.81, 0]
integrator:
  t_end: 0.01
  step: 1.0e-3
output:
  interval: 0.01
  animation: {interval: 0.01}
)");
  const se::Superelement all = io::load_superelement(dir / "link.se");
  const se::Superelement dyn = io::load_superelement(dir / "link.se", {io::SuperelementParts::Dynamics});
  const auto kb = [](const se::Superelement& s) {
    return fmt("%.1f kB", static_cast<double>(io::superelement_memory_bytes(s)) / 1024.0);
  };
  const auto r = test::run_seflex("run " + q(scene) + " -o " + q(dir / "out1") + " --no-animation");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "superelements in memory: " + kb(dyn) + " (dynamics only, mesh parts not read)")) << r.out;
  const auto a = test::run_seflex("run " + q(scene) + " -o " + q(dir / "out2"));
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_TRUE(has(a.out, "superelements in memory: " + kb(all) + " (with mesh parts)")) << a.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "out2" / "animation.pvd"));
  // Same dynamics, same history.
  EXPECT_EQ(test::read_file(dir / "out1" / "history.csv"), test::read_file(dir / "out2" / "history.csv"));
}

}  // namespace
}  // namespace seflex
