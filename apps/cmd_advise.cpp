// seflex advise SCENE --tol ANGLE_DEG: the cheapest model of a scene whose hinge angles stay within
// a tolerance of the finest one over a short horizon, with the evidence (io/advise.hpp).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "command.hpp"
#include "seflex/io/advise.hpp"
#include "seflex/io/scene.hpp"

namespace {

using seflex::app::UsageError;
namespace io = seflex::io;

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
  const auto alternative = args.value("alternative");
  const auto modes = args.value("modes");
  const auto csv = args.value("csv");
  const std::string scene_path = args.positional("SCENE");
  args.finish();
  if (!tol) throw UsageError("missing --tol ANGLE_DEG (the largest acceptable hinge-angle error, degrees)");
  io::AdviseOptions o;
  o.tolerance = seflex::app::positive_number("tol", *tol, "a number > 0") * std::numbers::pi / 180.0;
  if (t_end) o.t_end = seflex::app::positive_number("t-end", *t_end, "a number > 0");
  if (modes) o.few_modes = mode_list(*modes);
  const io::SceneDescription d = io::read_scene(scene_path);
  if (alternative) o.alternative = io::read_scene(*alternative);

  std::printf("seflex advise %s --tol %s\n", scene_path.c_str(), tol->c_str());
  std::fflush(stdout);
  const io::AdviseReport r = io::advise(d, o);
  const double deg = 180.0 / std::numbers::pi;
  if (r.horizon_at_lock)
    std::printf("horizon: %.4g s (first lock of the finest model: %s)\n", r.horizon, r.horizon_lock.c_str());
  else
    std::printf("horizon: %.4g s\n", r.horizon);
  std::printf("\n%-48s %8s %10s %7s %14s  %s\n", "variant", "unknowns", "CPU [s]", "steps", "max err [deg]", "within");
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const io::AdviseRow& row = r.rows[i];
    char err[32];
    if (row.reference) std::snprintf(err, sizeof err, "(reference)");
    else if (!row.ran) std::snprintf(err, sizeof err, "failed");
    else std::snprintf(err, sizeof err, "%.3g", row.max_error * deg);
    const std::string unknowns = std::to_string(row.dofs) + (row.multipliers > 0 ? "+" + std::to_string(row.multipliers) : "");
    std::printf("%-48s %8s %10.3f %7ld %14s  %s%s\n", row.name.c_str(), unknowns.c_str(), row.cpu_seconds, row.steps, err,
                row.within ? "yes" : "no", static_cast<int>(i) == r.recommended ? "  <- recommended" : "");
  }
  std::printf("(unknowns: dofs of the AIC variants; coordinates + Lagrange multipliers of FFRF-LM and rigid-LM)\n");
  for (const auto& row : r.rows)
    if (!row.ran && !row.reference) std::printf("  %s: %s\n", row.name.c_str(), row.failure.c_str());
  const io::AdviseRow& best = r.rows.at(static_cast<std::size_t>(r.recommended));
  std::printf("\nrecommended: %s (%.3g s CPU, %.2fx the finest model's %.3g s; max hinge-angle error %.3g deg <= %s deg)\n",
              best.name.c_str(), best.cpu_seconds, r.rows[0].cpu_seconds > 0 ? best.cpu_seconds / r.rows[0].cpu_seconds : 1.0,
              r.rows[0].cpu_seconds, best.max_error * deg, tol->c_str());
  if (csv) {
    std::ofstream f(*csv);
    if (!f) throw seflex::InputError("option --csv: cannot write " + *csv);
    f << "variant,reference,dofs,multipliers,ran,cpu_seconds,steps,max_error_deg,worst_hinge,worst_time,within,recommended\n";
    f.precision(10);
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
      const io::AdviseRow& row = r.rows[i];
      f << '"' << row.name << "\"," << row.reference << ',' << row.dofs << ',' << row.multipliers << ',' << row.ran << ',' << row.cpu_seconds << ','
        << row.steps << ',' << row.max_error * deg << ',' << row.worst_hinge << ',' << row.worst_time << ',' << row.within << ','
        << (static_cast<int>(i) == r.recommended) << '\n';
    }
  }
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(advise, "SCENE --tol ANGLE_DEG [--t-end T] [--alternative SCENE2] [--modes K1,K2] [--csv FILE]",
               "the cheapest model of a scene (rigid; fewer internal modes; simplified mass; an alternative "
               "reduction; the classic floating frame FFRF-LM and rigid-LM with Lagrange multipliers) whose hinge angles stay within ANGLE_DEG of the finest model (flexible, full inertia, "
               "all modes) up to its first lock (or T), with the evidence table",
               run_advise);
