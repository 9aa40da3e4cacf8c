// seflex advise SCENE --tol ANGLE_DEG [--node NAME --tol-position M]: the cheapest model of a scene
// whose hinge angles (and node positions) stay within a tolerance of the finest one over a short
// horizon, with the evidence (scene/advise.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "seflex/scene/advise.hpp"
#include "seflex/scene/scene.hpp"

namespace {

using seflex::app::UsageError;
namespace scene = seflex::scene;

std::vector<int> mode_list(const std::string& v) {
  std::vector<int> out;
  std::istringstream in(v);
  for (std::string f; std::getline(in, f, ',');) {
    std::size_t pos = 0;
    int k = -1;
    try {
      k = std::stoi(f, &pos);
    } catch (const std::exception&) {
      pos = 0;
    }
    if (pos == 0 || pos != f.size() || k < 1) throw UsageError("option --modes expects mode counts >= 1 separated by commas (e.g. 2,4), got '" + v + "'");
    out.push_back(k);
  }
  return out;
}

int run_advise(seflex::app::Args& args) {
  const auto tol = args.value("tol");
  const auto t_end = args.value("t-end");
  std::vector<std::string> alternatives, nodes;
  while (const auto a = args.value("alternative")) alternatives.push_back(*a);
  while (const auto n = args.value("node")) nodes.push_back(*n);
  const auto tol_position = args.value("tol-position");
  const auto tol_stress = args.value("tol-stress");
  const auto modes = args.value("modes");
  const auto csv = args.value("csv");
  const std::string scene_path = args.positional("SCENE");
  args.finish();
  if (!tol) throw UsageError("missing --tol ANGLE_DEG (the largest acceptable hinge-angle error, degrees)");
  scene::AdviseOptions o;
  o.tolerance = seflex::app::positive_number("tol", *tol, "a number > 0") * std::numbers::pi / 180.0;
  if (t_end) o.t_end = seflex::app::positive_number("t-end", *t_end, "a number > 0");
  if (modes) o.few_modes = mode_list(*modes);
  if (!nodes.empty() && !tol_position)
    throw UsageError("option --node needs --tol-position METRES (the largest acceptable position error of the node)");
  if (tol_position && nodes.empty()) throw UsageError("option --tol-position needs at least one --node NAME (e.g. the tip, body.grid)");
  for (const auto& n : nodes)
    if (n.empty()) throw UsageError("option --node expects a node name (body.grid, e.g. beam.11), got ''");
  o.nodes = nodes;
  if (tol_position) o.position_tolerance = seflex::app::positive_number("tol-position", *tol_position, "a length > 0 (metres)");
  if (tol_stress) o.stress_tolerance = seflex::app::positive_number("tol-stress", *tol_stress, "a percentage > 0") / 100.0;
  const scene::SceneDescription d = scene::read_scene(scene_path);
  for (const auto& a : alternatives) o.alternatives.push_back(scene::read_scene(a));

  std::printf("seflex advise %s --tol %s", scene_path.c_str(), tol->c_str());
  for (const auto& n : nodes) std::printf(" --node %s", n.c_str());
  if (tol_position) std::printf(" --tol-position %s", tol_position->c_str());
  if (tol_stress) std::printf(" --tol-stress %s", tol_stress->c_str());
  for (const auto& a : alternatives) std::printf(" --alternative %s", a.c_str());
  std::printf("\n");
  std::fflush(stdout);
  const scene::AdviseReport r = scene::advise(d, o);
  const double deg = 180.0 / std::numbers::pi;
  if (r.horizon_at_lock)
    std::printf("horizon: %.4g s (first lock of the finest model: %s)\n", r.horizon, r.horizon_lock.c_str());
  else
    std::printf("horizon: %.4g s\n", r.horizon);
  const bool pos = !r.nodes.empty();
  std::size_t width = 48;
  for (const auto& row : r.rows) width = std::max(width, row.name.size());
  const int w = static_cast<int>(width);
  const bool str = r.stress_tolerance > 0.0;
  std::printf("\n%-*s %8s %10s %7s %14s%s%s  %s\n", w, "variant", "unknowns", "CPU [s]", "steps", "max err [deg]", pos ? "   max pos [m]" : "",
              str ? " stress err [%]" : "", "within");
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const scene::AdviseRow& row = r.rows[i];
    char err[32], perr[32] = "", serr[32] = "";
    if (str) {
      if (row.reference) std::snprintf(serr, sizeof serr, " %14s", "(reference)");
      else if (!row.ran) std::snprintf(serr, sizeof serr, " %14s", "failed");
      else std::snprintf(serr, sizeof serr, " %14.3g", 100.0 * row.max_stress_error);
    }
    if (row.reference) std::snprintf(err, sizeof err, "(reference)");
    else if (!row.ran) std::snprintf(err, sizeof err, "failed");
    else std::snprintf(err, sizeof err, "%.3g", row.max_error * deg);
    if (pos) {
      if (row.reference) std::snprintf(perr, sizeof perr, " %13s", "(reference)");
      else if (!row.ran) std::snprintf(perr, sizeof perr, " %13s", "failed");
      else std::snprintf(perr, sizeof perr, " %13.3g", row.max_position_error);
    }
    std::string unknowns = std::to_string(row.dofs);
    if (row.multipliers > 0) unknowns += '+' + std::to_string(row.multipliers);
    std::printf("%-*s %8s %10.3f %7ld %14s%s%s  %s%s\n", w, row.name.c_str(), unknowns.c_str(), row.cpu_seconds, row.steps, err, perr, serr,
                row.within ? "yes" : "no", static_cast<int>(i) == r.recommended ? "  <- recommended" : "");
  }
  std::printf("(unknowns: dofs of the AIC variants; coordinates + Lagrange multipliers of FFRF-LM and rigid-LM)\n");
  for (const auto& row : r.rows)
    if (!row.ran && !row.reference) std::printf("  %s: %s\n", row.name.c_str(), row.failure.c_str());
  const scene::AdviseRow& best = r.rows.at(static_cast<std::size_t>(r.recommended));
  std::printf("\nrecommended: %s (%.3g s CPU, %.2fx the finest model's %.3g s; max hinge-angle error %.3g deg <= %s deg",
              best.name.c_str(), best.cpu_seconds, r.rows[0].cpu_seconds > 0 ? best.cpu_seconds / r.rows[0].cpu_seconds : 1.0,
              r.rows[0].cpu_seconds, best.max_error * deg, tol->c_str());
  if (pos) std::printf("; max position error %.3g m <= %s m", best.max_position_error, tol_position->c_str());
  if (str) std::printf("; peak element results within %.3g %% <= %s %%", 100.0 * best.max_stress_error, tol_stress->c_str());
  std::printf(")\n");
  if (csv) {
    std::ofstream f(*csv);
    if (!f) throw seflex::InputError("option --csv: cannot write " + *csv);
    f << "variant,reference,dofs,multipliers,stiffening,ran,cpu_seconds,steps,max_error_deg,worst_hinge,worst_time,max_position_error_m,worst_node,"
         "worst_node_time,within,recommended,max_stress_error,worst_element\n";
    f.precision(10);
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
      const scene::AdviseRow& row = r.rows[i];
      f << '"' << row.name << "\"," << row.reference << ',' << row.dofs << ',' << row.multipliers << ',' << row.stiffening << ',' << row.ran << ','
        << row.cpu_seconds << ',' << row.steps << ',' << row.max_error * deg << ',' << row.worst_hinge << ',' << row.worst_time << ','
        << row.max_position_error << ',' << row.worst_node << ',' << row.worst_node_time << ',' << row.within << ','
        << (static_cast<int>(i) == r.recommended) << ',' << row.max_stress_error << ",\"" << row.worst_element << "\"\n";
    }
  }
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(advise,
               "SCENE --tol ANGLE_DEG [--node NAME]... [--tol-position METRES] [--tol-stress PCT] [--t-end T] [--alternative SCENE2]... [--modes K1,K2] "
               "[--csv FILE]",
               "the cheapest model of a scene (rigid; fewer internal modes; simplified mass; no geometric stiffening; alternative "
               "reductions, e.g. a beam in fewer superelements; the classic floating frame FFRF-LM and rigid-LM with Lagrange multipliers) "
               "whose hinge angles stay within ANGLE_DEG (and the positions of the --node nodes, e.g. a tip, within METRES; the peak "
               "element results of the bodies reduced with --stresses within PCT %) of the "
               "finest model (flexible, full inertia, all modes, geometric stiffening where the files have it) up to its first lock "
               "(or T), with the evidence table",
               run_advise);
