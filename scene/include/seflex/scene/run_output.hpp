#pragma once
// Results of a `seflex run`, written as the run goes (history and poses flushed at least every
// 0.2 s of wall time and at the end, events.csv at every event; a run that stops early, on an error or
// an exception, leaves everything it computed; one killed leaves all but its last 0.2 s):
//   history.csv   t; per hinge H: H.phi_deg, H.rate_deg_s (driven: H.drive_torque); per force element E: E.torque (cable
//                 loops: E.force, E.tension1, E.tension2, E.torque.<hinge> per hinge), locks also
//                 E.latched; E_kinetic, E_elastic, E_spring, E_gravity, E_total; newton_iterations
//                 (all accepted steps so far), step_size (last accepted step)
//   events.csv    t,kind,name,detail (locks latching at the located time, stop rule, rejections, errors)
//   poses.csv     t,body,R00..R22,px,py,pz,q0.. per sample and body: floating-frame pose and local
//                 elastic coordinates (rigid bodies: no q) - enough to re-animate the FE meshes
//   animation.pvd + animation/*.vtu  deformed FE meshes at the scene's animation interval
//   stress_envelope.csv  (bodies reduced with --stresses) per body and element: the largest von Mises
//                 stress (shells: of the fibres Z1, Z2; solids), moment (bars), axial stress (rods) or
//                 force (springs, bushes) over the run, its time and fibre: element results = the body's
//                 stress modes x its local elastic coordinates at every sample (docs/stresses.md)
//   interface_loads.csv  (output.interface_loads) t,body,node, the load the body receives at each interface
//                 node (its own assembled share: inertia with gravity, elastic, damping; mbd::interface_load)
//                 in its frame B (fx..mz) and in the scene's axes (FX..MZ), then its elastic share
//                 K_bb q_b in B (el_fx..el_mz); the full load's fields are empty with ffrf-lm
//   static_subcases/BODY_K.bdf  (output.static_subcases: times) at the first sample at or after time K of
//                 the list, each flexible body's interface displacements as SPC1 + SPCD, set 9001 + K
//                 (io/interface_subcase.hpp): a static subcase of the body's own deck, with the inertia
//                 loads of the instant (-M a at every FE grid, a from the samples before and after by
//                 central differences; the file is written when the next sample arrives) when the body's
//                 file has its mesh part (recovery and FE mass)
//   summary.txt, summary.json        written by finish()
// It also carries the scene's stop rule (integrator.stop.after_all_locked) as stop_requested().
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "seflex/scene/scene.hpp"
#include "seflex/io/vtk_animation.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/output.hpp"

namespace seflex::scene {

struct RunOutputOptions {
  std::filesystem::path folder;
  bool overwrite = false;  ///< replace the results of an earlier run in `folder`
  bool animation = true;   ///< write the VTK series (if the scene asks for one)
};

/// How a run ended, for the summary.
struct RunEnd {
  bool ok = true;
  std::string message;               ///< failure diagnosis (or a note)
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;          ///< process CPU time over the same span (building the scene, integrating, writing)
  std::string formulation = "aic";   ///< which solver ran (mbd::formulation_name)
  std::string method = "generalized-alpha";  ///< which integrator ran (mbd::integrator_method_name)
  int coordinates = -1;              ///< unknowns of a multiplier formulation (-1: the model's dofs)
  int multipliers = 0;               ///< its Lagrange multipliers
  std::optional<mbd::RunStats> stats;  ///< absent when the solver threw (counts then come from the samples)
};

/// The columns of history.csv (t first; the list above) and one sample's values in that order: what
/// RunOutput writes, and what seflex.run (python/) returns as arrays by name. `values` is cleared
/// and refilled (no allocation once it has the capacity).
std::vector<std::string> history_columns(const mbd::Model& model);
void history_values(const mbd::Model& model, const mbd::Sample& sample, std::vector<double>& values);

class RunOutput : public mbd::Observer {
 public:
  /// The files a run writes into its folder (checked by check_folder, removed before an overwrite).
  static const std::vector<std::string>& result_files();
  /// Throws InputError if `folder` holds results of an earlier run and !overwrite, or is a file.
  static void check_folder(const std::filesystem::path& folder, bool overwrite);

  /// Creates the folder, removes earlier results (overwrite), opens the files and writes the headers.
  RunOutput(const Scene& scene, const RunOutputOptions& options);
  RunOutput(const RunOutput&) = delete;
  RunOutput& operator=(const RunOutput&) = delete;
  ~RunOutput() override;

  void on_sample(const mbd::Model& model, const mbd::Sample& sample) override;
  void on_progress(double t, double t_end) override;
  bool stop_requested() const override;

  /// One line of events.csv.
  void event(double t, const std::string& kind, const std::string& name, const std::string& detail);
  /// Write summary.txt and summary.json (and the rejection summary to events.csv).
  void finish(const RunEnd& end);

  double t_last() const { return t_last_; }
  long samples() const { return samples_; }
  const std::filesystem::path& folder() const { return folder_; }

 private:
  void write_history(const mbd::Model& model, const mbd::Sample& s);
  void write_poses(const mbd::Sample& s);
  void write_animation(const mbd::Sample& s);
  void track_locks(const mbd::Model& model, const mbd::Sample& s);
  void recover_stresses(const mbd::Sample& s);
  void write_interface_loads(const mbd::Sample& s);
  void write_stress_envelope();
  void write_static_subcases(const mbd::Sample& s);
  /// The subcase files of output.static_subcases[k] for the instant `mid`; `before`/`after` (both or
  /// neither) give the inertia loads.
  struct Snapshot {
    double t = 0.0;
    std::vector<mbd::Pose> frames;   ///< per flexible body
    std::vector<Eigen::VectorXd> xi;
  };
  void write_subcase_files(std::size_t k, const Snapshot& mid, const Snapshot* before, const Snapshot* after);
  /// Write and flush the buffered rows of history and poses if kFlushInterval has passed since the
  /// last time or kBufferBytes are waiting (the demo run made 5,700 write calls with a flush per
  /// sample, and a poses row longer than the stream's buffer is a write call of its own).
  void flush_if_due();
  void write_out();
  static constexpr std::chrono::milliseconds kFlushInterval{200};
  static constexpr std::size_t kBufferBytes = 1 << 20;
  static constexpr std::size_t kTopElements = 5;  ///< element results per body in the summary

  const Scene& scene_;
  std::filesystem::path folder_;
  std::ofstream history_, events_, poses_;
  std::string history_buf_, poses_buf_;  ///< rows not yet written (write_out)
  std::vector<double> row_values_;       ///< one history row (history_values)
  std::chrono::steady_clock::time_point last_flush_ = std::chrono::steady_clock::now();
  std::unique_ptr<io::PvdSeries> animation_;
  double next_animation_ = 0.0;
  int max_q_ = 0;
  long samples_ = 0, steps_ = 0, newton_ = 0;
  double t_last_ = 0.0, t_progress_ = 0.0;
  std::vector<int> lock_elements_;              ///< force-element indices of the locks
  std::vector<std::optional<double>> t_latch_;  ///< per lock
  std::vector<double> peak_after_latch_;        ///< per lock, max |torque| once latched
  std::optional<double> all_locked_at_;
  struct LockPeak {
    double value = -1.0, t = 0.0;
    int element = 0, fibre = 0;
  };
  /// A body with stress modes: its results at the last sample and, per element, the largest peak so far.
  struct StressBody {
    std::size_t body = 0;  ///< scene body
    const se::StressModes* modes = nullptr;
    Eigen::VectorXd results;
    std::vector<double> current, peak, t_peak;  ///< per element: the ranking value now (animation), its peak and time
    std::vector<int> fibre;
    /// Per lock: the largest element result from its latch until the next lock latches (the latch shock).
    std::vector<LockPeak> after_lock;
  };
  std::vector<StressBody> stress_;
  std::ofstream interface_loads_;
  std::string interface_buf_;
  Eigen::VectorXd f_b_;  ///< interface loads of one body (scratch)
  std::size_t next_subcase_ = 0;  ///< the next of output.static_subcases to write
  Snapshot older_, newer_, current_;  ///< the last two samples and this one (static subcases only)
  long snapshots_ = 0;
  std::optional<std::size_t> pending_subcase_;  ///< output.static_subcases index waiting for the sample after newer_
  int last_latched_ = -1;         ///< the lock latched most recently (index into lock_elements_), -1 none
  bool stop_announced_ = false;
};

}  // namespace seflex::scene
