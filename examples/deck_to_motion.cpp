// seflex example: deck_to_motion — from a Nastran deck to the motion of a flexible pendulum, on the
// library API (no scene file, no command).
//
// It solves: the 1 m aluminium link of examples/scenes/link.bdf (4 CBARs, grids 1..5) hung from a
// revolute hinge at grid 1, about z, under gravity (0, -9.81, 0) m/s^2, set swinging with a small
// amplitude (0.01 rad). The steps are those of `seflex reduce` and `seflex run`:
//   1. io::read_model           read the deck
//   2. reduction::reduce_to_superelement
//                               Craig-Bampton: interfaces 1 and 5, frame node 3, 3 fixed-interface
//                               modes; io::record_source adds the provenance `seflex reduce` writes
//                               (--save FILE.se writes the file: the same bytes as
//                               `seflex reduce DECK --interface 1,5 --frame 3 --modes 3 --name link`
//                               writes, but for the time stamp `created`)
//   3. mbd::ModelBuilder        a ground hinge, the link as an AIC flexible body (full inertia)
//   4. mbd::simulate            generalized-alpha, local error 1e-7, the hinge angle every 5 ms
// and it prints the swing period measured from the upward zero crossings of the swing angle (of the
// chord from the hinge to the tip, grid 5).
//
// Reference (independent of the multibody solver): the small-amplitude period of a compound pendulum,
// T0 = 2 pi sqrt(I_O / (m g d)), from the deck's rigid-body mass properties (the FE mass matrix: m,
// the centre of mass at distance d from the hinge, I_O = I_zz about the centre of mass + m d^2). By
// hand: the bars lump rho A L / 4 = 0.0675 kg per element to their end grids (0.03375 kg at grids
// 1 and 5, 0.0675 kg at 2..4), so m = 0.27 kg, d = 0.5 m, I_O = 0.0675 (0.25^2 + 0.5^2 + 0.75^2) +
// 0.03375 * 1^2 = 0.0928125 kg m^2 and T0 = 1.66336 s (a uniform rod, I_O = m L^2 / 3, would give
// 1.6386 s). At 0.01 rad the amplitude lengthens it by theta^2 / 16 = 6e-6; the link's lowest
// fixed-interface mode (26 Hz) is forty times faster than the swing and hardly bends it. Measured:
// 1.663414 s against 1.663343 s, 4.3e-5 relative, over 3 swings and over 10 alike. The example fails
// (exit status 1) when the period is off T0 by more than 1e-4 relative.
//
// Run it (built with -DSEFLEX_BUILD_EXAMPLES=ON, the default; a CTest with --small):
//   build/examples/example_deck_to_motion [--small] [--save link.se] [DECK.bdf]
// --small: 3 swings instead of 10. DECK: another link with grids 1, 3, 5 (default: the example's).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "seflex/io/model_reader.hpp"
#include "seflex/io/provenance.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/mbd/model.hpp"
#include "seflex/mbd/output.hpp"
#include "seflex/mbd/solvers/simulate.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

namespace {

using namespace seflex;

/// Records the swing angle at every output sample: the angle of the chord from the pivot to the
/// tip node (the lower end) from the downward vertical -y, about z.
struct SwingAngle final : mbd::Observer {
  explicit SwingAngle(mbd::NodeIndex tip_node) : tip(tip_node) {}
  mbd::NodeIndex tip;
  std::vector<double> t, phi;
  void on_sample(const mbd::Model&, const mbd::Sample& s) override {
    const Eigen::Vector3d& p_W = s.nodes.at(static_cast<std::size_t>(tip.value)).p;
    t.push_back(s.t);
    phi.push_back(std::atan2(p_W.x(), -p_W.y()));
  }
};

/// Mean period from the upward zero crossings (linear interpolation between samples).
double period_from_crossings(const SwingAngle& h, int* crossings) {
  std::vector<double> up;
  for (std::size_t k = 1; k < h.t.size(); ++k)
    if (h.phi[k - 1] < 0.0 && h.phi[k] >= 0.0)
      up.push_back(h.t[k - 1] + (h.t[k] - h.t[k - 1]) * (-h.phi[k - 1]) / (h.phi[k] - h.phi[k - 1]));
  *crossings = static_cast<int>(up.size());
  return up.size() < 2 ? NAN : (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

}  // namespace

int main(int argc, char** argv) {
  bool small = false;
  std::string deck = SEFLEX_EXAMPLES_DIR "/scenes/link.bdf", save;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--small") == 0) small = true;
    else if (std::strcmp(argv[i], "--save") == 0 && i + 1 < argc) save = argv[++i];
    else if (argv[i][0] != '-') deck = argv[i];
    else {
      std::fprintf(stderr, "usage: %s [--small] [--save FILE.se] [DECK.bdf]\n", argv[0]);
      return 2;
    }
  }
  try {
    // 1-2. Deck -> Craig-Bampton superelement.
    const fem::Model fe = io::read_model(deck);
    reduction::SuperelementOptions ro;
    ro.interface_ids = {1, 5};
    ro.frame_node = 3;
    ro.modes.modes = 3;
    ro.modes.backend = linalg::EigenBackend::Spectra;  // `seflex reduce`'s default --eigensolver
    ro.name = "link";
    se::Superelement link = reduction::reduce_to_superelement(fe, ro);
    io::record_source(link, fe, deck);
    if (!save.empty()) io::save_superelement(link, save, io::SaveOptions{true});

    // 3. The pendulum: the link turned by -90 deg about z so that it hangs along -y from the hinge.
    const Eigen::Matrix3d R_WB = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d p_WO = Eigen::Vector3d::Zero();  // the deck's origin (grid 1) at the hinge
    const Eigen::Vector3d g_W(0.0, -9.81, 0.0);
    const double amplitude = 0.01;  // rad
    mbd::ModelBuilder mb;
    const auto sei = mb.add_superelement(link);
    const auto ground = mb.add_ground("pivot", mbd::Pose{});
    const double d = (link.p_OBo + link.p_BoCm_B).norm();  // hinge (grid 1, the deck's origin) to centre of mass
    const double I_O = link.I_Cm_B(2, 2) + link.mass * d * d;
    const double T0 = 2.0 * M_PI * std::sqrt(I_O / (link.mass * g_W.norm() * d));
    // It starts at the bottom, turning as a rigid body at the rate of that amplitude: the hinge and the
    // tip node (v = w x p) alike, the modes at rest.
    const double w0 = amplitude * 2.0 * M_PI / T0;
    mbd::HingeOptions ho;
    ho.phidot0 = w0;
    const auto hinge = mb.add_hinge("pivot", ground, Eigen::Vector3d::UnitZ(), R_WB, ho);
    const Eigen::Vector3d p_W5 = p_WO + R_WB * (link.p_OBo + link.interfaces[1].p_BoN_B);
    const auto tip = mb.add_node("tip", mbd::Pose{R_WB, p_W5});
    mb.set_initial_velocity(tip, (w0 * Eigen::Vector3d::UnitZ()).cross(p_W5 - p_WO), w0 * Eigen::Vector3d::UnitZ());
    mbd::FlexibleBodyOptions fo;
    fo.inertia = mbd::InertiaModel::Full;
    mb.add_flexible_body("link", sei, {mb.hinge_child(hinge), tip}, mbd::Pose{R_WB, p_WO + R_WB * link.p_OBo}, fo);
    mb.set_gravity(g_W);
    const mbd::Model model = mb.build();

    // 4. Simulate.
    mbd::IntegratorSettings is;
    is.t_end = (small ? 3.2 : 10.2) * T0;
    is.output_interval = 0.005;
    is.tol_position = is.tol_angle = 1e-7;
    is.rho_inf = 0.9;
    SwingAngle angle(tip);
    const mbd::SimulationRun run =
        mbd::simulate(model, is, mbd::IntegratorMethod::GeneralizedAlpha, mbd::Formulation::Aic, &angle);
    int crossings = 0;
    const double T = period_from_crossings(angle, &crossings);
    const double rel = (T - T0) / T0;

    std::printf("deck %s: %zu grids; superelement '%s': %d interfaces, %d modes (first %.3f Hz), mass %.6g kg\n",
                deck.c_str(), fe.grids.size(), link.name.c_str(), link.num_interfaces(), link.num_modes,
                link.mode_frequencies_hz(0), link.mass);
    std::printf("model: %d dofs; simulated %.3f s in %ld steps\n", model.num_dofs, is.t_end, run.run.steps);
    std::printf("period from %d upward zero crossings: %.6f s\n", crossings, T);
    std::printf("compound pendulum (I_O = %.7g kg m^2, d = %.6g m): %.6f s; relative difference %.2e\n", I_O, d, T0, rel);
    const double tolerance = 1e-4;
    if (!(std::abs(rel) <= tolerance)) {
      std::fprintf(stderr, "deck_to_motion: the period is off the compound pendulum's by %.2e (more than %.0e)\n", rel,
                   tolerance);
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "deck_to_motion: %s\n", e.what());
    return 1;
  }
}
