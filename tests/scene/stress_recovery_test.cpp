// Stress recovery in a run (docs/stresses.md) against `seflex static` on the body's own deck: the link of
// examples/scenes (4 CBARs, interfaces 1 and 5, frame 3) reduced with --stresses, welded to ground at
// grid 1 and loaded at grid 5, solved quasi-statically (mbd::solve_static, the slow-loading limit) with the
// run's observer; its interface displacements written as a static subcase (SPC1 + SPCD) of link.bdf and
// solved by `seflex static --element-results`: the element results must agree to 1e-6 (the fixed-
// interface modes carry no load when nothing loads the interior).
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "scene_fixture.hpp"
#include "static_run.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_results.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/io/interface_subcase.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "seflex/mbd/data.hpp"
#include "seflex/mbd/solvers/statics.hpp"
#include "seflex/mbd/state.hpp"
#include "seflex/scene/advise.hpp"
#include "seflex/scene/run_output.hpp"
#include "seflex/scene/scene.hpp"

namespace seflex::test {
namespace {

/// element id -> component name -> value, of `seflex static --element-results` (one subcase).
std::map<int, std::map<std::string, double>> element_csv(const std::filesystem::path& p) {
  std::map<int, std::map<std::string, double>> out;
  std::istringstream in(read_file(p));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "subcase,element,card,component,value");
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string sub, id, card, comp, value;
    std::getline(f, sub, ',');
    std::getline(f, id, ',');
    std::getline(f, card, ',');
    std::getline(f, comp, ',');
    std::getline(f, value, ',');
    out[std::stoi(id)][comp] = std::stod(value);
  }
  return out;
}

/// The link of examples/scenes (link.bdf) copied to `dir` and reduced there to link.se (interfaces 1 and 5,
/// frame 3, `modes` fixed-interface modes) with `--stresses ELSET`; returns the deck's text and the command's output.
std::pair<std::string, RunResult> reduce_link(const TempDir& dir, const std::string& elset, int modes = 3) {
  const std::string deck = read_file(source_dir() / "examples/scenes/link.bdf");
  { std::ofstream(dir.path() / "link.bdf") << deck; }
  return {deck, run_seflex("reduce link.bdf --interface 1,5 --frame 3 --modes " + std::to_string(modes) + " --stresses " + elset + " -o link.se", dir.path())};
}

/// The link (grid 1 welded) under a tip load P along basic y applied at t = 0, full FE: average-acceleration
/// Newmark on the deck's K and M (the 24 dofs of grids 2-5, u = v = 0 at t = 0) with step h over [0, T]:
/// the peak root moment of element 1 and its m2_a at t_sub.
struct FullTransient {
  double peak = 0, at_sub = 0;
};
FullTransient full_transient(const std::filesystem::path& deck, double P, double T, double h, double t_sub) {
  const fem::Model m = io::read_nastran(deck);
  const fem::GlobalMatrices g = fem::assemble(m, fem::assembly_options(m));
  const Eigen::MatrixXd K = Eigen::MatrixXd(g.K).bottomRightCorner(24, 24), M = Eigen::MatrixXd(g.M).bottomRightCorner(24, 24);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(24);
  f(18 + 1) = P;  // grid 5, T2
  const fem::ElementResultMap map = fem::make_element_result_map(m, {1});
  const Eigen::MatrixXd A = K + (4.0 / (h * h)) * M;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(24), v = u, a = u, ug = Eigen::VectorXd::Zero(30);
  for (int i = 0; i < 24; ++i)
    if (M(i, i) > 0) a(i) = f(i) / M(i, i);  // M a0 = f - K u0 (lumped M; massless dofs do not enter M a)
  FullTransient out;
  const long n_sub = std::lround(t_sub / h);
  for (long n = 0; n * h < T; ++n) {
    const Eigen::VectorXd un = lu.solve(f + M * ((4.0 / (h * h)) * u + (4.0 / h) * v + a));
    const Eigen::VectorXd vn = (2.0 / h) * (un - u) - v;
    a = (4.0 / (h * h)) * (un - u) - (4.0 / h) * v - a;
    u = un;
    v = vn;
    ug.tail(24) = u;
    const Eigen::VectorXd r = map.apply(ug);
    out.peak = std::max(out.peak, fem::element_result_peak(fem::ResultKind::Bar, r.data()).value);
    if (n + 1 == n_sub) out.at_sub = r[1];
  }
  return out;
}

/// The sudden-tip-load scene on link.se (2 N along basic y at grid 5 from t = 0, 0.1 s) with `body_extra`
/// added to the body's entry (e.g. ", internal_modes: 2") and `output_extra` to its output block.
std::string tip_load_scene(const std::string& body_extra, const std::string& output_extra) {
  return "title: link under a sudden tip load\nbodies:\n  - {name: link, superelement: link.se" + body_extra +
         "}\nground: [link.1]\nloads:\n  nodal:\n    - {node: link.5, force: [0.0, 2.0, 0.0]}\nintegrator:\n  rho_inf: 1.0\n"
         "  t_end: 0.1\n  step: 1.0e-5\n  max_step: 1.0e-4\n  tolerance: {position: 1.0e-9, angle: 1.0e-9}\noutput:\n"
         "  interval: 1.0e-4\n" + output_extra;
}

TEST(StressRecovery, QuasiStaticRunMatchesSeflexStaticOnTheDeck) {
  TempDir dir;
  const auto [deck, red] = reduce_link(dir, "all");
  ASSERT_EQ(red.exit_code, 0) << red.out << red.err;
  EXPECT_NE(red.out.find("stress modes: 4 elements"), std::string::npos) << red.out;
  const auto info = run_seflex("info link.se", dir.path());
  EXPECT_NE(info.out.find("stress modes                 present: 4 elements (4 bar)"), std::string::npos) << info.out;

  { std::ofstream(dir.path() / "scene.yaml") << R"(title: link bent at its tip
bodies:
  - {name: link, superelement: link.se}
ground: [link.1]
loads:
  nodal:
    - {node: link.5, force: [0.0, 2.0e-3, 1.0e-3], moment: [1.0e-4, 0.0, 0.0]}
integrator:
  t_end: 1.0
output:
  interface_loads: true
)"; }
  const scene::Scene sc = scene::build_scene(scene::read_scene(dir.path() / "scene.yaml"));
  ASSERT_TRUE(sc.stress.at(0) && sc.stress[0]->present());
  const mbd::Sample last = solve_static_with_output(sc, dir.path() / "results");
  const se::Superelement& body = *sc.superelements[0];
  const se::StressModes& modes = *sc.stress[0];
  const Eigen::VectorXd& xi = last.flexible[0].xi;
  const Eigen::VectorXd run = modes.S * xi;

  // The instant as a static subcase of the deck, solved by seflex static.
  io::write_interface_subcase(dir.path() / "subcase.bdf", body, xi, 9001, "the quasi-static end state");
  std::string bulk = deck.substr(0, deck.rfind("ENDDATA"));
  {
    std::ofstream f(dir.path() / "static.bdf");
    f << "SOL 101\nCEND\nSUBCASE 1\n  SPC = 9001\n  LOAD = 9001\n" << bulk << read_file(dir.path() / "subcase.bdf") << "ENDDATA\n";
  }
  const auto st = run_seflex("static static.bdf --element-results elements.csv", dir.path());
  ASSERT_EQ(st.exit_code, 0) << st.out << st.err;
  const auto ref = element_csv(dir.path() / "elements.csv");
  ASSERT_EQ(ref.size(), 4u);
  double err = 0, scale = 0;
  for (std::size_t e = 0; e < modes.element_ids.size(); ++e) {
    const auto kind = static_cast<fem::ResultKind>(modes.kinds[e]);
    const auto& names = fem::element_result_components(kind);
    const auto& r = ref.at(modes.element_ids[e]);
    for (std::size_t c = 0; c < names.size(); ++c) {
      scale = std::max(scale, std::abs(r.at(names[c])));
      err = std::max(err, std::abs(run[modes.rows[e] + static_cast<Eigen::Index>(c)] - r.at(names[c])));
    }
  }
  std::printf("quasi-static run against seflex static: largest difference %.3e of the largest result %.3e (%.2e)\n", err,
              scale, err / scale);
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(err, 1e-6 * scale);

  // The envelope's root element: the largest end moment of the cantilever, |F_y| L = 2e-3 N m at grid 1
  // (|F_z| L = 1e-3 about the other axis); measured within the geometric nonlinearity of the tip load.
  const Csv env = read_csv(dir.path() / "results/stress_envelope.csv");
  ASSERT_EQ(env.rows.size(), 4u);
  EXPECT_EQ(env.rows[0][1], 1.0);
  EXPECT_NEAR(env.rows[0][4], 2.0e-3, 1e-6 * 2.0e-3);
  // Interface loads: at the tip the body takes the applied load (statics), in the basic axes (FX..MZ), to
  // 4.2e-8 of |F| (measured); root and tip loads balance.
  const Csv loads = read_csv(dir.path() / "results/interface_loads.csv");
  ASSERT_GE(loads.rows.size(), 2u);
  const auto& tip = loads.rows.back();
  const auto& root = loads.rows[loads.rows.size() - 2];
  ASSERT_EQ(tip[2], 5.0);
  ASSERT_EQ(root[2], 1.0);
  std::printf("tip interface load (basic): %.9e %.9e %.9e  %.9e %.9e %.9e\n", tip[9], tip[10], tip[11], tip[12], tip[13], tip[14]);
  const double F[6] = {0.0, 2.0e-3, 1.0e-3, 1.0e-4, 0.0, 0.0};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(tip[9 + k], F[k], 1e-6 * 2e-3) << "component " << k;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(tip[9 + k] + root[9 + k], 0.0, 1e-9 * 2e-3) << "force balance " << k;
  // Quasi-statically the full load (the body's assembled share, fx..mz) reduces to its elastic share
  // K_bb q_b (el_fx..el_mz), both in the body frame, except along the link: there K_bb q_b reads the
  // second-order shortening of the bent link (EA/L = 7e6 N/m: 6e-11 m) as an axial force of -4.0e-4 N, a
  // fifth of the load, which the assembled elastic force (with the floating frame's transfer Tx^T and
  // the stiffening's foreshortening term) does not have.
  double d = 0, d_axial = 0;
  for (const auto* row : {&tip, &root}) {
    d_axial = std::max(d_axial, std::abs((*row)[3] - (*row)[15]));
    for (int k = 1; k < 6; ++k) d = std::max(d, std::abs((*row)[3 + k] - (*row)[15 + k]));
  }
  std::printf("quasi-static: full load against K_bb q_b: largest difference %.3e across the link, %.3e along it\n", d, d_axial);
  EXPECT_LT(d, 1e-4 * 2e-3);
  EXPECT_NEAR(d_axial, 4.0e-4, 0.1e-4);
}


// A suddenly applied tip load on the cantilevered link (grid 1 welded, 2 N along basic y at grid 5: the
// strong plane, first bending mode about 16 Hz): the peak root moment of the run's recovery (stress
// modes x elastic coordinates, 3 fixed-interface modes) against a full-FE transient (average-acceleration
// Newmark on the deck's K and M, 24 free dofs, step 1e-5 s: doubling it changes the peak by 1.5e-4),
// over the first 0.1 s (one and a half periods; the peak is the first overshoot, about twice the
// static P L).
TEST(StressRecovery, SuddenTipLoadPeakRootMomentMatchesFullTransient) {
  TempDir dir;
  const auto [deck, red] = reduce_link(dir, "1");
  ASSERT_EQ(red.exit_code, 0) << red.out << red.err;
  const double P = 2.0, T = 0.1;

  const double t_sub = 0.03;
  const FullTransient ft = full_transient(dir.path() / "link.bdf", P, T, 1e-5, t_sub);
  const double full = ft.peak, at_sub = ft.at_sub;
  std::printf("full-FE Newmark peak root moment %.9g N m (h = 1e-5 s), %.9g (h = 2e-5 s); static P L = %.3g\n", full,
              full_transient(dir.path() / "link.bdf", P, T, 2e-5, t_sub).peak, P * 1.0);

  { std::ofstream(dir.path() / "scene.yaml") << tip_load_scene("", "  static_subcases: [0.03]\n"); }
  const auto run = run_seflex("run scene.yaml -o results", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const Csv env = read_csv(dir.path() / "results/stress_envelope.csv");
  ASSERT_EQ(env.rows.size(), 1u);
  const double recovered = env.rows[0][4];
  std::printf("run recovery peak root moment %.9g N m at t = %.4g s: %.3e relative to the full transient\n", recovered,
              env.rows[0][5], recovered / full - 1.0);
  EXPECT_NEAR(recovered, full, 0.02 * full);  // the issue's target; measured -8.5e-4 (3 modes)
  const std::string summary = read_file(dir.path() / "results/summary.txt");
  EXPECT_NE(summary.find("largest element results of link"), std::string::npos) << summary;

  // The instant t = 0.03 s as a static subcase of the deck (interface displacements as SPCD, the inertia
  // loads -M a of the interior grids as FORCE/MOMENT), solved by seflex static. The kept modes' dynamic
  // share is carried by the inertia loads; what the static solution adds to the run's S xi is the static
  // response of the truncated modes to those loads (the mode-acceleration correction), so it lands closer
  // to the full transient than the run's recovery does.
  const std::filesystem::path sub = dir.path() / "results/static_subcases/link_0.bdf";
  ASSERT_TRUE(std::filesystem::exists(sub));
  const std::string sub_text = read_file(sub);
  EXPECT_NE(sub_text.find("FORCE*"), std::string::npos) << sub_text;
  {
    std::ofstream f(dir.path() / "static.bdf");
    f << "SOL 101\nCEND\nSUBCASE 1\n  SPC = 9001\n  LOAD = 9001\n" << deck.substr(0, deck.rfind("ENDDATA")) << sub_text
      << "ENDDATA\n";
  }
  const auto st = run_seflex("static static.bdf --element-results elements.csv", dir.path());
  ASSERT_EQ(st.exit_code, 0) << st.out << st.err;
  const double m2a_static = element_csv(dir.path() / "elements.csv").at(1).at("m2_a");  // load along basic y = element z
  se::StressModes modes;
  const se::Superelement body = io::load_superelement(dir.path() / "link.se", io::LoadOptions{io::SuperelementParts::Dynamics, &modes});
  const Csv poses = read_csv(dir.path() / "results/poses.csv");
  std::size_t i = 0;
  while (i < poses.rows.size() && poses.rows[i][0] < t_sub - 1e-12) ++i;
  ASSERT_LT(i, poses.rows.size());
  Eigen::VectorXd xi(body.size());
  for (Eigen::Index k = 0; k < xi.size(); ++k) xi[k] = poses.rows[i][14 + static_cast<std::size_t>(k)];
  const Eigen::Index nb = 6 * body.num_interfaces();
  const double run_m2a = (modes.S * xi)[1], constraint_m2a = (modes.S.leftCols(nb) * xi.head(nb))[1];
  std::printf("t = %.4g s: root m2_a: full transient %.6g, run %.6g (%.2e), static subcase %.6g (%.2e); constraint-mode share %.6g\n",
              poses.rows[i][0], at_sub, run_m2a, run_m2a / at_sub - 1, m2a_static, m2a_static / at_sub - 1, constraint_m2a);
  // Measured: the subcase gives -4.40205 against the run's -4.41619 (3.2e-3 of it: the truncated modes'
  // static share; the central differences of the inertia loads change it by 4e-5 when the output interval
  // is halved), where the interface displacements alone miss 7.2 %. Both are 1.1-1.4 % off the full
  // transient at this instant (the kept modes' phase), within the 2 % the peak is held to.
  EXPECT_GT(std::abs(constraint_m2a - run_m2a), 0.05 * std::abs(run_m2a));
  EXPECT_NEAR(m2a_static, run_m2a, 5e-3 * std::abs(run_m2a));
  EXPECT_NEAR(m2a_static, at_sub, 0.02 * std::abs(at_sub));
}


// The issue's dynamic target with the modes the advisor recommends (not hand-picked): the link reduced
// with 5 fixed-interface modes (with 6 the run at rho_inf 1 stops at t = 2.2 ms: next test),
// `seflex advise` on the sudden-tip-load scene with a 2 % stress tolerance
// (the variants' peak element results against its finest, all 5 modes, full inertia) and 1 or 2 modes as
// "a few" (`--modes 1,2,3,4`); the recommended variant run on its own, its peak root moment against the
// full-FE Newmark transient within 2 %.
TEST(StressRecovery, SuddenTipLoadWithTheAdvisedModesMatchesFullTransient) {
  TempDir dir;
  const auto red = reduce_link(dir, "1", 5).second;
  ASSERT_EQ(red.exit_code, 0) << red.out << red.err;
  { std::ofstream(dir.path() / "scene.yaml") << tip_load_scene("", ""); }
  scene::AdviseOptions o;
  o.tolerance = 1.0 * M_PI / 180.0;  // no hinges: the stress tolerance decides
  o.t_end = 0.1;
  o.stress_tolerance = 0.02;
  o.few_modes = {1, 2, 3, 4};
  const scene::AdviseReport rep = scene::advise(scene::read_scene(dir.path() / "scene.yaml"), o);
  ASSERT_GE(rep.recommended, 0);
  const scene::AdviseRow& best = rep.rows[static_cast<std::size_t>(rep.recommended)];
  for (const auto& row : rep.rows)
    std::printf("%-50s stress error %.3e%s\n", row.name.c_str(), row.max_stress_error, &row == &best ? "  <- recommended" : "");
  // The recommendation's settings: formulation, inertia model and mode count (variants are named
  // "flexible / INERTIA / N modes" or "FFRF-LM / flexible / all modes").
  const bool ffrf = best.name.rfind("FFRF-LM / ", 0) == 0;
  ASSERT_TRUE(ffrf || best.name.rfind("flexible / ", 0) == 0) << best.name;
  ASSERT_EQ(best.name.find("stiffening"), std::string::npos) << best.name;
  const bool full_inertia = best.name.find("full inertia") != std::string::npos;
  const std::size_t slash = best.name.rfind("/ ");
  const std::string modes = best.name.substr(slash + 2);
  std::string body = full_inertia ? ", inertia: full" : "";
  if (modes != "all modes") body += ", internal_modes: " + std::to_string(std::stoi(modes));
  { std::ofstream(dir.path() / "advised.yaml") << tip_load_scene(body, ""); }
  const auto run = run_seflex(std::string("run advised.yaml -o results") + (ffrf ? " --formulation ffrf-lm" : ""), dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const double recovered = read_csv(dir.path() / "results/stress_envelope.csv").rows.at(0)[4];
  const double full = full_transient(dir.path() / "link.bdf", 2.0, 0.1, 1e-5, 0.03).peak;
  std::printf("advised (%s): peak root moment %.9g N m, full transient %.9g: %.3e\n", best.name.c_str(), recovered, full,
              recovered / full - 1.0);
  EXPECT_NEAR(recovered, full, 0.02 * full);  // the issue's target; measured -4.1e-3 (FFRF-LM, all 5 modes recommended)
}


// With 6 fixed-interface modes the link has a direction without mass in the plane of the load: the three
// in-plane bending modes span every interior translation across it, so grid 5's rotation about z with the
// interior held still is a shape of the basis, and the deck lumps translational mass only (the bars) and no
// rotary inertia there. The reduced model welded at grid 1 (12 dofs, its DMIG in `seflex modes`) has a mode
// at 1.7e7 Hz beside the next at 1382 Hz. Its acceleration is not set by any mass: generalized-alpha
// at rho_inf = 1 keeps a period-two-step oscillation of it undamped, the geometric stiffening reads it
// through the frame's acceleration, and it grows until the steps collapse (docs/stability.md, "Directions
// without mass"). The run must stop with that diagnosis, naming the dof; rho_inf 0.9 damps it and the run
// matches the full-FE transient like the 3- and 5-mode runs above.
TEST(StressRecovery, SixModesDirectionWithoutMassAtRhoInfOneIsDiagnosed) {
  TempDir dir;
  const auto red = reduce_link(dir, "1", 6).second;
  ASSERT_EQ(red.exit_code, 0) << red.out << red.err;
  // The reduced model's frequencies, welded at grid 1.
  ASSERT_EQ(run_seflex("export link.se --dmig link_dmig.bdf", dir.path()).exit_code, 0);
  std::string dmig = read_file(dir.path() / "link_dmig.bdf");
  dmig.replace(dmig.find("METHOD = 1\n"), 11, "METHOD = 1\nSPC = 1\n");
  dmig.replace(dmig.find("BEGIN BULK\n"), 11, "BEGIN BULK\nSPC1,1,123456,1\n");
  { std::ofstream(dir.path() / "welded.bdf") << dmig; }
  const auto modes = run_seflex("modes welded.bdf --count 12 --eigensolver dense --csv modes.csv", dir.path());
  ASSERT_EQ(modes.exit_code, 0) << modes.out << modes.err;
  const Csv f = read_csv(dir.path() / "modes.csv");
  ASSERT_GE(f.rows.size(), 2u);
  const double highest = f.rows.back()[2], next = f.rows[f.rows.size() - 2][2];
  std::printf("6 modes, welded at grid 1: highest frequency %.4g Hz, the next %.4g Hz\n", highest, next);
  EXPECT_GT(highest, 1e6);  // measured 1.69e7 Hz: a mass at round-off level
  EXPECT_LT(next, 2e3);     // measured 1382 Hz

  { std::ofstream(dir.path() / "rho1.yaml") << tip_load_scene("", ""); }
  const auto rho1 = run_seflex("run rho1.yaml -o rho1", dir.path());
  std::printf("rho_inf 1: %s\n", rho1.err.c_str());
  EXPECT_EQ(rho1.exit_code, 4) << rho1.out << rho1.err;
  EXPECT_NE(rho1.err.find("stopped at t = 0.00"), std::string::npos) << rho1.err;  // within 10 ms (measured 2.2 ms)
  EXPECT_NE(rho1.err.find("was led by node 'link.5' rz, whose acceleration changed sign at every step"), std::string::npos) << rho1.err;
  EXPECT_NE(rho1.err.find("\"Directions without mass\""), std::string::npos) << rho1.err;

  std::string text = tip_load_scene("", "");
  text.replace(text.find("rho_inf: 1.0"), 12, "rho_inf: 0.9");
  { std::ofstream(dir.path() / "rho09.yaml") << text; }
  const auto run = run_seflex("run rho09.yaml -o results", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const double recovered = read_csv(dir.path() / "results/stress_envelope.csv").rows.at(0)[4];
  const double full = full_transient(dir.path() / "link.bdf", 2.0, 0.1, 1e-5, 0.03).peak;
  std::printf("6 modes, rho_inf 0.9: peak root moment %.9g N m, full transient %.9g: %.3e\n", recovered, full, recovered / full - 1.0);
  EXPECT_NEAR(recovered, full, 0.02 * full);  // the issue's target; measured +1.1e-3
}

// Format 1.4: the stress modes of a reduction round-trip bit-exactly through the file, fewer internal
// modes keep their leading columns, and a body reduced without them writes no stress.* dataset.
TEST(StressRecovery, StressModesRoundTripThroughTheFile) {
  TempDir dir;
  const fem::Model m = io::read_nastran(source_dir() / "examples/scenes/link.bdf");
  reduction::SuperelementOptions o;
  o.interface_ids = {1, 5};
  o.frame_node = 3;
  o.modes.modes = 3;
  o.name = "link";
  o.stress_elements = std::vector<int>{2, 4};
  se::StressModes st;
  const se::Superelement s = reduction::reduce_to_superelement(m, o, nullptr, &st);
  ASSERT_EQ(st.element_ids, (std::vector<std::int32_t>{2, 4}));
  ASSERT_EQ(st.S.rows(), 16);
  ASSERT_EQ(st.S.cols(), s.size());
  io::save_superelement(s, dir.path() / "link.se", io::SaveOptions{false, &st});
  se::StressModes r;
  io::load_superelement(dir.path() / "link.se", io::LoadOptions{io::SuperelementParts::Dynamics, &r});
  EXPECT_EQ(r.element_ids, st.element_ids);
  EXPECT_EQ(r.kinds, st.kinds);
  EXPECT_EQ(r.rows, st.rows);
  ASSERT_EQ(r.S.size(), st.S.size());
  EXPECT_EQ(std::memcmp(r.S.data(), st.S.data(), sizeof(double) * static_cast<std::size_t>(st.S.size())), 0);
  EXPECT_TRUE(r.first_columns(13).S == st.S.leftCols(13));
  EXPECT_EQ(io::serialize_superelement(s).find("stress."), std::string::npos);
  EXPECT_NE(io::serialize_superelement(s, &st).find("\"stress.modes\""), std::string::npos);
  // Unknown element ids are reported, not fatal.
  o.stress_elements = std::vector<int>{1, 77};
  reduction::SuperelementInfo info;
  se::StressModes u;
  reduction::reduce_to_superelement(m, o, &info, &u);
  EXPECT_EQ(u.element_ids.size(), 1u);
  ASSERT_EQ(info.stress_missing.size(), 1u);
  EXPECT_EQ(info.stress_missing[0].first, "unknown element id 77");
}


// The advisor's stress tolerance: a variant without stress modes (all bodies rigid) misses every peak
// (error exactly 1); a tolerance no variant but the finest meets recommends the finest; a tolerance of
// 300 % constrains nothing (the recommendation of the angle tolerance alone). Over 0.3 s of the flexible
// double pendulum of examples/scenes.
TEST(StressRecovery, AdvisorStressTolerance) {
  TempDir dir;
  const auto red = reduce_link(dir, "all").second;
  ASSERT_EQ(red.exit_code, 0) << red.out << red.err;
  // The flexible double pendulum of examples/scenes (the upper link keeps 2 of the file's 3 modes).
  { std::ofstream(dir.path() / "scene.yaml") << read_file(source_dir() / "examples/scenes/double_pendulum.yaml"); }
  const scene::SceneDescription d = scene::read_scene(dir.path() / "scene.yaml");
  scene::AdviseOptions o;
  o.tolerance = 5.0 * M_PI / 180.0;
  o.t_end = 0.3;
  const scene::AdviseReport angles_only = scene::advise(d, o);
  o.stress_tolerance = 3.0;
  const scene::AdviseReport loose = scene::advise(d, o);
  EXPECT_EQ(loose.rows[static_cast<std::size_t>(loose.recommended)].name,
            angles_only.rows[static_cast<std::size_t>(angles_only.recommended)].name);
  bool rigid_seen = false;
  for (const auto& row : loose.rows)
    if (row.name == "rigid") {
      rigid_seen = true;
      EXPECT_TRUE(row.ran);
      EXPECT_EQ(row.max_stress_error, 1.0);  // no stress modes: every peak missed
    }
  EXPECT_TRUE(rigid_seen);
  o.stress_tolerance = 1e-12;
  const scene::AdviseReport tight = scene::advise(d, o);
  const auto& best = tight.rows[static_cast<std::size_t>(tight.recommended)];
  EXPECT_LE(best.max_stress_error, 1e-12) << best.name;
  for (const auto& row : tight.rows)
    std::printf("%-50s stress error %.3e%s\n", row.name.c_str(), row.max_stress_error,
                &row == &best ? "  <- recommended" : "");
}

}  // namespace
}  // namespace seflex::test
