#include "seflex/scene/run_output.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "seflex/fem/element_results.hpp"
#include "seflex/io/interface_subcase.hpp"

namespace seflex::scene {

namespace {

constexpr double kRad2Deg = 180.0 / M_PI;

/// out += the shortest text that reads back as the same double.
void append_number(std::string& out, double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

std::string num(double x) {
  std::string s;
  append_number(s, x);
  return s;
}

/// out += "," + num(x), without a temporary.
void append_field(std::string& out, double x) {
  out += ',';
  append_number(out, x);
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

std::string json_string(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += std::string("\\") + c;
    else if (c == '\n') q += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) q += ' ';
    else q += c;
  }
  return q + "\"";
}

std::string json_number(double x) { return std::isfinite(x) ? num(x) : "null"; }

const mbd::CableLoop* as_cable(const mbd::ForceElement& e) { return std::get_if<mbd::CableLoop>(&e); }

/// Cable tensions T1, T2 of a loop at the hinge angles of a sample (cable_loop.hpp).
std::pair<double, double> tensions(const mbd::CableLoop& c, const mbd::Sample& s) {
  double e = 0.0;
  for (auto h : c.hinges_a) e += c.r_a / static_cast<double>(c.hinges_a.size()) * s.hinges[static_cast<std::size_t>(h.value)].phi;
  for (auto h : c.hinges_b) e -= c.r_b / static_cast<double>(c.hinges_b.size()) * s.hinges[static_cast<std::size_t>(h.value)].phi;
  return {std::max(0.0, c.preload + c.k * e), std::max(0.0, c.preload - c.k * e)};
}

std::ofstream open(const std::filesystem::path& p) {
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  if (!f) throw InputError(SourceRef{p.string(), 0}, "cannot be written");
  return f;
}

}  // namespace

const std::vector<std::string>& RunOutput::result_files() {
  static const std::vector<std::string> files{"history.csv", "events.csv",          "poses.csv",
                                              "summary.txt", "summary.json",        "animation.pvd",
                                              "animation",   "stress_envelope.csv", "interface_loads.csv",
                                              "static_subcases"};
  return files;
}

void RunOutput::check_folder(const std::filesystem::path& folder, bool overwrite) {
  namespace fs = std::filesystem;
  if (fs::exists(folder) && !fs::is_directory(folder))
    throw InputError(SourceRef{folder.string(), 0}, "is a file; expected an output folder");
  if (overwrite || !fs::exists(folder)) return;
  for (const auto& f : result_files())
    if (fs::exists(folder / f))
      throw InputError(SourceRef{folder.string(), 0}, "holds the results of an earlier run (" + f +
                                                          "); refusing to overwrite them (use --force to replace them)");
}

RunOutput::RunOutput(const Scene& scene, const RunOutputOptions& o) : scene_(scene), folder_(o.folder) {
  namespace fs = std::filesystem;
  check_folder(folder_, o.overwrite);
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (!fs::is_directory(folder_)) throw InputError(SourceRef{folder_.string(), 0}, "cannot create the output folder");
  for (const auto& f : result_files()) fs::remove_all(folder_ / f, ec);
  const mbd::Model& m = scene.model;

  history_ = open(folder_ / "history.csv");
  const std::vector<std::string> columns = history_columns(m);
  for (std::size_t i = 0; i < columns.size(); ++i) history_ << (i ? "," : "") << columns[i];
  history_ << "\n";
  history_.flush();
  for (std::size_t i = 0; i < m.force_elements.size(); ++i)
    if (std::holds_alternative<mbd::HingeLock>(m.force_elements[i].element)) lock_elements_.push_back(static_cast<int>(i));
  t_latch_.assign(lock_elements_.size(), std::nullopt);
  peak_after_latch_.assign(lock_elements_.size(), 0.0);

  events_ = open(folder_ / "events.csv");
  events_ << "t,kind,name,detail\n";
  if (scene.description.stop_after_all_locked && lock_elements_.empty())
    event(0.0, "warning", "after_all_locked", "the scene has no locks; the stop rule never applies");
  events_.flush();

  for (const auto& s : scene.superelements) max_q_ = std::max(max_q_, s->size());
  poses_ = open(folder_ / "poses.csv");
  poses_ << "t,body,R00,R01,R02,R10,R11,R12,R20,R21,R22,px,py,pz";
  for (int k = 0; k < max_q_; ++k) poses_ << ",q" << k;
  poses_ << "\n";
  poses_.flush();

  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (scene.bodies[b].rigid || b >= scene.stress.size() || !scene.stress[b] || !scene.stress[b]->present()) continue;
    StressBody sb;
    sb.body = b;
    sb.modes = scene.stress[b].get();
    const std::size_t E = sb.modes->element_ids.size();
    sb.results = Eigen::VectorXd::Zero(sb.modes->S.rows());
    sb.current.assign(E, 0.0);
    sb.peak.assign(E, -1.0);
    sb.t_peak.assign(E, 0.0);
    sb.fibre.assign(E, 0);
    sb.after_lock.assign(lock_elements_.size(), LockPeak{});
    stress_.push_back(std::move(sb));
  }
  if (scene.description.output.interface_loads) {
    interface_loads_ = open(folder_ / "interface_loads.csv");
    interface_loads_ << "t,body,node,fx,fy,fz,mx,my,mz,FX,FY,FZ,MX,MY,MZ,el_fx,el_fy,el_fz,el_mx,el_my,el_mz\n";
    interface_loads_.flush();
    int n_max = 0;
    for (const auto& sp : scene.superelements)
      if (sp) n_max = std::max(n_max, 6 * sp->num_interfaces());
    f_b_ = Eigen::VectorXd::Zero(n_max);
  }

  if (o.animation && scene.description.output.animation_interval) {
    std::vector<const se::Superelement*> bodies;
    for (const auto& s : scene.superelements) bodies.push_back(s.get());
    animation_ = std::make_unique<io::PvdSeries>(folder_, "animation", bodies, true);
  }
}

RunOutput::~RunOutput() { write_out(); }  // a run that ends by an exception keeps its rows

void RunOutput::on_sample(const mbd::Model& model, const mbd::Sample& s) {
  ++samples_;
  t_last_ = s.t;
  steps_ = s.step;
  newton_ = s.newton_iterations;
  track_locks(model, s);
  write_history(model, s);
  write_poses(s);
  recover_stresses(s);
  write_interface_loads(s);
  write_static_subcases(s);
  write_animation(s);
  flush_if_due();
}

void RunOutput::recover_stresses(const mbd::Sample& s) {
  for (StressBody& sb : stress_) {
    const SceneBodyRef& r = scene_.bodies[sb.body];
    sb.results.noalias() = sb.modes->S * s.flexible[static_cast<std::size_t>(r.index)].xi;
    const auto& st = *sb.modes;
    for (std::size_t e = 0; e < st.element_ids.size(); ++e) {
      const auto kind = static_cast<fem::ResultKind>(st.kinds[e]);
      const fem::ResultPeak p = fem::element_result_peak(kind, sb.results.data() + st.rows[e]);
      sb.current[e] = p.value;
      if (p.value > sb.peak[e]) {
        sb.peak[e] = p.value;
        sb.t_peak[e] = s.t;
        sb.fibre[e] = p.fibre;
      }
      if (last_latched_ >= 0)  // every lock that latched at that instant (hinge lines of two hinges)
        for (std::size_t k = 0; k < lock_elements_.size(); ++k) {
          if (t_latch_[k] != t_latch_[static_cast<std::size_t>(last_latched_)]) continue;
          LockPeak& lp = sb.after_lock[k];
          if (p.value > lp.value) lp = {p.value, s.t, st.element_ids[e], p.fibre};
        }
    }
  }
}

void RunOutput::write_interface_loads(const mbd::Sample& s) {
  if (!interface_loads_.is_open()) return;
  const auto& d = scene_.description;
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    const SceneBodyRef& r = scene_.bodies[b];
    if (r.rigid) continue;
    const se::Superelement& body = *scene_.superelements[b];
    const mbd::FlexibleBodySample& fb = s.flexible[static_cast<std::size_t>(r.index)];
    const Eigen::Index nb = 6 * body.num_interfaces();
    // The elastic share K_bb q_b: K is block-diagonal between the interface coordinates and the modal
    // ones, so the interface rows of K xi.
    f_b_.head(nb).noalias() = body.K.topRows(nb) * fb.xi;
    const bool full = fb.interface_load.size() == nb;  // the AIC formulation's assembled load
    const Eigen::Matrix3d R_BW = fb.frame.R.transpose();
    for (int j = 0; j < body.num_interfaces(); ++j) {
      append_number(interface_buf_, s.t);
      interface_buf_ += ',';
      interface_buf_ += csv_field(d.bodies[b].name);
      interface_buf_ += ',';
      interface_buf_ += std::to_string(body.interfaces[static_cast<std::size_t>(j)].id);
      if (full) {
        for (int h = 0; h < 2; ++h) {  // body frame B, then the scene's axes W
          const Eigen::Vector3d w = R_BW * fb.interface_load.segment<3>(6 * j + 3 * h);
          for (int k = 0; k < 3; ++k) append_field(interface_buf_, w(k));
        }
        for (int k = 0; k < 6; ++k) append_field(interface_buf_, fb.interface_load(6 * j + k));
      } else {  // a formulation that does not assemble it (ffrf-lm): empty fields
        interface_buf_.append(12, ',');
      }
      for (int k = 0; k < 6; ++k) append_field(interface_buf_, f_b_(6 * j + k));
      interface_buf_ += '\n';
    }
  }
}

namespace {

/// Second derivative at the middle of three unevenly spaced values.
template <class V>
V second_difference(const V& x0, const V& x1, const V& x2, double h0, double h1) {
  return 2.0 * ((x2 - x1) / h1 - (x1 - x0) / h0) / (h0 + h1);
}

/// The inertia loads -M_fe (a - g) of every FE grid of `body` at the middle instant, body axes: a from
/// central differences of the grids' world positions (translations) and of the frame's rotation plus the
/// elastic rotations (the small rotations of the recovery), g the gravity in body axes.
Eigen::VectorXd inertia_loads(const se::Superelement& body, const mbd::Pose* F[3], const Eigen::VectorXd* xi[3],
                              const double t[3], const Eigen::Vector3d& g_W) {
  const Eigen::Index nfe = static_cast<Eigen::Index>(body.fe_node_ids.size());
  const double h0 = t[1] - t[0], h1 = t[2] - t[1];
  Eigen::MatrixXd U[3];
  for (int k = 0; k < 3; ++k) {
    const Eigen::VectorXd u = body.recovery * *xi[k];
    U[k] = Eigen::Map<const Eigen::MatrixXd>(u.data(), 6, nfe);
  }
  const Eigen::Matrix3d& R = F[1]->R;
  // Body angular velocities over the two intervals (log of the relative rotations), their difference.
  const Eigen::AngleAxisd r0(Eigen::Matrix3d(F[0]->R.transpose() * R)), r1(Eigen::Matrix3d(R.transpose() * F[2]->R));
  const Eigen::Vector3d alpha_B = (r1.axis() * r1.angle() / h1 - r0.axis() * r0.angle() / h0) * 2.0 / (h0 + h1);
  const Eigen::Vector3d g_B = R.transpose() * g_W;
  Eigen::VectorXd a(6 * nfe);
  for (Eigen::Index i = 0; i < nfe; ++i) {
    Eigen::Vector3d x[3];
    for (int k = 0; k < 3; ++k) x[k] = F[k]->p + F[k]->R * (body.p_BoI_B.col(i) + U[k].col(i).head<3>());
    a.segment<3>(6 * i) = R.transpose() * second_difference(x[0], x[1], x[2], h0, h1) - g_B;
    const Eigen::Vector3d th = second_difference<Eigen::Vector3d>(U[0].col(i).tail<3>(), U[1].col(i).tail<3>(), U[2].col(i).tail<3>(), h0, h1);
    a.segment<3>(6 * i + 3) = alpha_B + th;
  }
  return -(body.M_fe * a);
}

}  // namespace

void RunOutput::write_subcase_files(std::size_t k, const Snapshot& mid, const Snapshot* before, const Snapshot* after) {
  std::error_code ec;
  std::filesystem::create_directories(folder_ / "static_subcases", ec);
  const auto& d = scene_.description;
  const auto& times = d.output.static_subcases;
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    const SceneBodyRef& r = scene_.bodies[b];
    if (r.rigid) continue;
    const se::Superelement& body = *scene_.superelements[b];
    const auto f = static_cast<std::size_t>(r.index);
    std::string what = "body " + d.bodies[b].name + " at t = " + num(mid.t) + " s (output.static_subcases[" + std::to_string(k) +
                       "] = " + num(times[k]) + " s) of " + d.file.string();
    Eigen::VectorXd loads;
    if (body.recovery.size() == 0 || body.M_fe.size() == 0)
      what += "; no inertia loads: the superelement file has no mesh part (recovery and FE mass)";
    else if (!before || !after)
      what += "; no inertia loads: they need the samples before and after this one";
    else {
      const mbd::Pose* F[3] = {&before->frames[f], &mid.frames[f], &after->frames[f]};
      const Eigen::VectorXd* xi[3] = {&before->xi[f], &mid.xi[f], &after->xi[f]};
      const double t[3] = {before->t, mid.t, after->t};
      loads = inertia_loads(body, F, xi, t, scene_.model.gravity);
      what += "; inertia loads from the samples at t = " + num(before->t) + " and " + num(after->t) + " s";
    }
    io::write_interface_subcase(folder_ / "static_subcases" / (d.bodies[b].name + "_" + std::to_string(k) + ".bdf"), body,
                                mid.xi[f], 9001 + static_cast<int>(k), what, loads.size() ? &loads : nullptr);
  }
}

void RunOutput::write_static_subcases(const mbd::Sample& s) {
  const auto& times = scene_.description.output.static_subcases;
  if (times.empty()) return;
  current_.t = s.t;
  current_.frames.resize(s.flexible.size());
  current_.xi.resize(s.flexible.size());
  for (std::size_t f = 0; f < s.flexible.size(); ++f) {
    current_.frames[f] = s.flexible[f].frame;
    current_.xi[f] = s.flexible[f].xi;
  }
  if (pending_subcase_ && s.t > newer_.t) {
    write_subcase_files(*pending_subcase_, newer_, &older_, &current_);
    pending_subcase_.reset();
  }
  if (next_subcase_ < times.size() && s.t >= times[next_subcase_] - 1e-12 * std::max(1.0, std::abs(s.t))) {
    const std::size_t k = next_subcase_;
    while (next_subcase_ < times.size() && times[next_subcase_] <= s.t + 1e-12 * std::max(1.0, std::abs(s.t))) ++next_subcase_;
    if (snapshots_ > 0 && s.t > newer_.t)
      pending_subcase_ = k;  // written with the next sample
    else
      write_subcase_files(k, current_, nullptr, nullptr);
  }
  std::swap(older_, newer_);
  std::swap(newer_, current_);
  ++snapshots_;
}

void RunOutput::write_stress_envelope() {
  if (stress_.empty()) return;
  std::ofstream f = open(folder_ / "stress_envelope.csv");
  f << "body,element,kind,quantity,peak,t,fibre\n";
  static const char* kinds[fem::kResultKinds] = {"shell", "bar", "rod", "solid", "spring", "bush"};
  for (const StressBody& sb : stress_) {
    const auto& st = *sb.modes;
    for (std::size_t e = 0; e < st.element_ids.size(); ++e) {
      const auto kind = static_cast<fem::ResultKind>(st.kinds[e]);
      f << csv_field(scene_.description.bodies[sb.body].name) << ',' << st.element_ids[e] << ',' << kinds[st.kinds[e]]
        << ',' << fem::element_result_peak_name(kind) << ',' << num(std::max(0.0, sb.peak[e])) << ',' << num(sb.t_peak[e])
        << ',' << sb.fibre[e] << '\n';
    }
  }
  f.flush();
}

void RunOutput::track_locks(const mbd::Model& model, const mbd::Sample& s) {
  bool all = !lock_elements_.empty();
  for (std::size_t k = 0; k < lock_elements_.size(); ++k) {
    const auto i = static_cast<std::size_t>(lock_elements_[k]);
    const mbd::ElementSample& e = s.elements[i];
    if (e.latched && !t_latch_[k]) {
      t_latch_[k] = e.t_latch;
      if (last_latched_ < 0 || *t_latch_[k] >= *t_latch_[static_cast<std::size_t>(last_latched_)]) last_latched_ = static_cast<int>(k);
      const auto& l = std::get<mbd::HingeLock>(model.force_elements[i].element);
      std::ostringstream os;
      os << "latched at phi = " << s.hinges[static_cast<std::size_t>(l.hinge.value)].phi * kRad2Deg << " deg (lock angle "
         << l.phi_lock * kRad2Deg << " deg), rate " << s.hinges[static_cast<std::size_t>(l.hinge.value)].phidot * kRad2Deg
         << " deg/s";
      event(e.t_latch, "lock", model.force_elements[i].name, os.str());
    }
    if (e.latched) peak_after_latch_[k] = std::max(peak_after_latch_[k], std::abs(e.value));
    all = all && e.latched;
  }
  if (all && !all_locked_at_) {
    all_locked_at_ = s.t;
    if (scene_.description.stop_after_all_locked)
      event(s.t, "stop", "after_all_locked",
            "all locks latched; the run ends " + num(*scene_.description.stop_after_all_locked) + " s later");
  }
}

std::vector<std::string> history_columns(const mbd::Model& m) {
  std::vector<std::string> c{"t"};
  for (const auto& h : m.hinges) {
    c.push_back(h.name + ".phi_deg");
    c.push_back(h.name + ".rate_deg_s");
    if (h.drive) c.push_back(h.name + ".drive_torque");
  }
  for (const auto& fe : m.force_elements) {
    if (const auto* cable = as_cable(fe.element)) {
      for (const char* x : {".force", ".tension1", ".tension2"}) c.push_back(fe.name + x);
      for (auto h : cable->hinges_a) c.push_back(fe.name + ".torque." + m.hinge(h).name);
      for (auto h : cable->hinges_b) c.push_back(fe.name + ".torque." + m.hinge(h).name);
    } else {
      c.push_back(fe.name + ".torque");
    }
    if (std::holds_alternative<mbd::HingeLock>(fe.element)) c.push_back(fe.name + ".latched");
  }
  for (const char* x : {"E_kinetic", "E_elastic", "E_spring", "E_gravity", "E_total", "newton_iterations", "step_size"})
    c.emplace_back(x);
  return c;
}

void history_values(const mbd::Model& m, const mbd::Sample& s, std::vector<double>& v) {
  v.clear();
  v.push_back(s.t);
  for (std::size_t i = 0; i < s.hinges.size(); ++i) {
    const mbd::HingeSample& h = s.hinges[i];
    v.push_back(h.phi * kRad2Deg);
    v.push_back(h.phidot * kRad2Deg);
    if (m.hinges[i].drive) v.push_back(h.drive_torque);
  }
  for (std::size_t i = 0; i < m.force_elements.size(); ++i) {
    const mbd::ElementSample& e = s.elements[i];
    v.push_back(e.value);
    if (const auto* c = as_cable(m.force_elements[i].element)) {
      const auto [T1, T2] = tensions(*c, s);
      v.push_back(T1);
      v.push_back(T2);
      for (double tau : e.hinge_torques) v.push_back(tau);
    }
    if (std::holds_alternative<mbd::HingeLock>(m.force_elements[i].element)) v.push_back(e.latched ? 1.0 : 0.0);
  }
  const mbd::Energies& E = s.energy;
  for (double x : {E.kinetic, E.elastic, E.spring, E.gravity, E.total()}) v.push_back(x);
  v.push_back(static_cast<double>(s.newton_iterations));  // exact: counts stay far below 2^53
  v.push_back(s.step_size);
}

void RunOutput::write_history(const mbd::Model& m, const mbd::Sample& s) {
  std::string& row = history_buf_;  // rows are appended to the buffer that write_out empties
  history_values(m, s, row_values_);
  const std::size_t newton = row_values_.size() - 2;  // the count, as an integer (to_chars could write 1e+05)
  append_number(row, row_values_[0]);
  for (std::size_t i = 1; i < row_values_.size(); ++i) {
    if (i == newton) {
      row += ',';
      row += std::to_string(s.newton_iterations);
    } else {
      append_field(row, row_values_[i]);
    }
  }
  row += '\n';
}

void RunOutput::write_poses(const mbd::Sample& s) {
  const auto& d = scene_.description;
  std::string& row = poses_buf_;
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    const SceneBodyRef& r = scene_.bodies[b];
    const mbd::Pose& X = r.rigid ? s.rigid[static_cast<std::size_t>(r.index)].frame : s.flexible[static_cast<std::size_t>(r.index)].frame;
    append_number(row, s.t);
    row += ',';
    row += csv_field(d.bodies[b].name);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) append_field(row, X.R(i, j));
    for (int i = 0; i < 3; ++i) append_field(row, X.p(i));
    int nq = 0;
    if (!r.rigid) {
      const Eigen::VectorXd& xi = s.flexible[static_cast<std::size_t>(r.index)].xi;
      for (Eigen::Index k = 0; k < xi.size(); ++k) append_field(row, xi(k));
      nq = static_cast<int>(xi.size());
    }
    for (int k = nq; k < max_q_; ++k) row += ',';
    row += '\n';
  }
}

void RunOutput::flush_if_due() {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_flush_ < kFlushInterval && history_buf_.size() + poses_buf_.size() + interface_buf_.size() < kBufferBytes)
    return;
  write_out();
  last_flush_ = now;
}

void RunOutput::write_out() {
  history_ << history_buf_;
  poses_ << poses_buf_;
  history_buf_.clear();  // keeps its capacity
  poses_buf_.clear();
  history_.flush();
  poses_.flush();
  if (interface_loads_.is_open()) {
    interface_loads_ << interface_buf_;
    interface_buf_.clear();
    interface_loads_.flush();
  }
}

void RunOutput::write_animation(const mbd::Sample& s) {
  if (!animation_) return;
  const double dt = *scene_.description.output.animation_interval;
  if (animation_->steps_written() > 0 && s.t < next_animation_ - 1e-9 * std::max(1.0, std::abs(s.t))) return;
  std::vector<io::BodySnapshot> snaps;
  for (const SceneBodyRef& r : scene_.bodies) {
    io::BodySnapshot b;
    const mbd::Pose& X = r.rigid ? s.rigid[static_cast<std::size_t>(r.index)].frame : s.flexible[static_cast<std::size_t>(r.index)].frame;
    b.R_WB = X.R;
    b.p_WBo = X.p;
    if (!r.rigid) b.q = s.flexible[static_cast<std::size_t>(r.index)].xi;
    for (const StressBody& sb : stress_)
      if (sb.body == snaps.size()) {
        b.element_ids = &sb.modes->element_ids;
        b.element_values = sb.current.data();
      }
    snaps.push_back(std::move(b));
  }
  animation_->write_step(s.t, snaps);
  if (animation_->steps_written() == 1) next_animation_ = s.t;
  while (next_animation_ <= s.t + 1e-9 * std::max(1.0, std::abs(s.t))) next_animation_ += dt;
}

void RunOutput::on_progress(double t, double) {
  t_progress_ = t;
  const auto& stop = scene_.description.stop_after_all_locked;
  if (stop && all_locked_at_ && !stop_announced_ && t >= *all_locked_at_ + *stop - 1e-12 * std::max(1.0, t)) {
    stop_announced_ = true;
    event(t, "stop", "after_all_locked", "run ended " + num(*stop) + " s after the last lock latched");
  }
}

bool RunOutput::stop_requested() const { return stop_announced_; }

void RunOutput::event(double t, const std::string& kind, const std::string& name, const std::string& detail) {
  events_ << num(t) << "," << csv_field(kind) << "," << csv_field(name) << "," << csv_field(detail) << "\n";
  events_.flush();
}

void RunOutput::finish(const RunEnd& end) {
  write_out();
  if (pending_subcase_) write_subcase_files(*pending_subcase_, newer_, nullptr, nullptr);  // the run ended right after it
  pending_subcase_.reset();
  const mbd::Model& m = scene_.model;
  const long steps = end.stats ? end.stats->steps : steps_;
  const long newton = end.stats ? end.stats->newton_iterations : newton_;
  const long rej_err = end.stats ? end.stats->rejected_error : -1, rej_newton = end.stats ? end.stats->rejected_newton : -1;
  if (end.stats && rej_err + rej_newton > 0)
    event(t_last_, "integrator", "rejected_steps",
          std::to_string(rej_err) + " steps rejected by the error estimate, " + std::to_string(rej_newton) +
              " retried after Newton failed, " + std::to_string(end.stats->event_retries) + " redone to land on lock crossings");
  if (!end.ok) event(t_last_, "error", "run", end.message);
  for (std::size_t k = 0; k < lock_elements_.size(); ++k)
    if (!t_latch_[k]) event(t_last_, "warning", m.force_elements[static_cast<std::size_t>(lock_elements_[k])].name, "never latched");

  std::ofstream js = open(folder_ / "summary.json");
  js << "{\n  \"scene\": " << json_string(scene_.description.file.string()) << ",\n  \"title\": "
     << json_string(scene_.description.title) << ",\n  \"status\": " << (end.ok ? "\"ok\"" : "\"failed\"")
     << ",\n  \"message\": " << json_string(end.message) << ",\n  \"final_t\": " << json_number(t_last_)
     << ",\n  \"run_time_s\": " << json_number(end.wall_seconds) << ",\n  \"cpu_time_s\": " << json_number(end.cpu_seconds)
     << ",\n  \"steps\": " << steps
     << ",\n  \"rejected_steps\": " << (end.stats ? std::to_string(rej_err + rej_newton) : "null")
     << ",\n  \"newton_iterations\": " << newton << ",\n  \"formulation\": " << json_string(end.formulation)
     << ",\n  \"method\": " << json_string(end.method)
     << ",\n  \"rejected_error\": " << rej_err << ",\n  \"rejected_newton\": " << rej_newton
     << ",\n  \"event_retries\": " << (end.stats ? end.stats->event_retries : -1)
     << ",\n  \"factorizations\": " << (end.stats ? end.stats->factorizations : -1)
     << ",\n  \"jacobians\": " << (end.stats ? end.stats->jacobians : -1)
     << ",\n  \"residual_evaluations\": " << (end.stats ? end.stats->evaluations : -1);
  if (end.stats) {  // what set each accepted step's size (mbd::StepLimit)
    js << ",\n  \"steps_set_by\": {";
    for (int k = 0; k < mbd::kStepLimits; ++k)
      js << (k ? ", " : "") << json_string(mbd::step_limit_name(static_cast<mbd::StepLimit>(k))) << ": "
         << end.stats->steps_set_by[static_cast<std::size_t>(k)];
    js << "}";
  }
  js
     << ",\n  \"dofs\": " << (end.coordinates >= 0 ? end.coordinates : m.num_dofs) << ",\n  \"multipliers\": " << end.multipliers
     << ",\n  \"locks\": {";
  for (std::size_t k = 0; k < lock_elements_.size(); ++k) {
    js << (k ? "," : "") << "\n    " << json_string(m.force_elements[static_cast<std::size_t>(lock_elements_[k])].name)
       << ": {\"t_latch\": " << (t_latch_[k] ? json_number(*t_latch_[k]) : "null")
       << ", \"peak_abs_torque_after_latch\": " << (t_latch_[k] ? json_number(peak_after_latch_[k]) : "null") << "}";
  }
  js << (lock_elements_.empty() ? "}" : "\n  }");
  if (!stress_.empty() && !lock_elements_.empty()) {  // the latch shocks: per lock and body, the most loaded element
    js << ",\n  \"element_peaks_after_lock\": {";
    for (std::size_t k = 0; k < lock_elements_.size(); ++k) {
      js << (k ? "," : "") << "\n    " << json_string(m.force_elements[static_cast<std::size_t>(lock_elements_[k])].name) << ": {";
      for (std::size_t b = 0; b < stress_.size(); ++b) {
        const LockPeak& lp = stress_[b].after_lock[k];
        js << (b ? ", " : "") << json_string(scene_.description.bodies[stress_[b].body].name) << ": ";
        if (lp.value < 0) js << "null";
        else
          js << "{\"element\": " << lp.element << ", \"peak\": " << json_number(lp.value) << ", \"t\": " << json_number(lp.t)
             << ", \"fibre\": " << lp.fibre << "}";
      }
      js << "}";
    }
    js << "\n  }";
  }
  // The largest element results per body (stress modes), most loaded first.
  const auto top = [](const StressBody& sb) {
    std::vector<std::size_t> order(sb.peak.size());
    for (std::size_t e = 0; e < order.size(); ++e) order[e] = e;
    const std::size_t n = std::min<std::size_t>(kTopElements, order.size());
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                      [&](std::size_t a, std::size_t b) { return sb.peak[a] > sb.peak[b]; });
    order.resize(n);
    return order;
  };
  if (!stress_.empty()) {
    js << ",\n  \"element_peaks\": {";
    for (std::size_t k = 0; k < stress_.size(); ++k) {
      const StressBody& sb = stress_[k];
      js << (k ? "," : "") << "\n    " << json_string(scene_.description.bodies[sb.body].name) << ": [";
      const auto order = top(sb);
      for (std::size_t i = 0; i < order.size(); ++i) {
        const std::size_t e = order[i];
        js << (i ? ", " : "") << "{\"element\": " << sb.modes->element_ids[e] << ", \"quantity\": \""
           << fem::element_result_peak_name(static_cast<fem::ResultKind>(sb.modes->kinds[e])) << "\", \"peak\": "
           << json_number(sb.peak[e]) << ", \"t\": " << json_number(sb.t_peak[e]) << ", \"fibre\": " << sb.fibre[e] << "}";
      }
      js << "]";
    }
    js << "\n  }";
  }
  js << "\n}\n";
  js.flush();
  write_stress_envelope();

  std::ofstream tx = open(folder_ / "summary.txt");
  tx << "seflex run " << scene_.description.file.string() << "\n" << scene_.description.title << "\n\n";
  tx << "status          " << (end.ok ? "ok" : "FAILED") << "\n";
  if (!end.message.empty()) tx << "message         " << end.message << "\n";
  tx << "final time      " << t_last_ << " s\nrun time        " << end.wall_seconds << " s\nCPU time        " << end.cpu_seconds << " s\n";
  tx << "model           " << scene_.description.bodies.size() << " bodies, " << m.hinges.size() << " hinges, "
     << m.force_elements.size() << " force elements, " << m.num_dofs << " dofs\n";
  tx << "formulation     " << end.formulation << " (" << end.method << ")";
  if (end.coordinates >= 0) tx << ": " << end.coordinates << " coordinates, " << end.multipliers << " multipliers";
  tx << "\nsteps           " << steps;
  if (end.stats) {
    tx << " accepted, " << rej_err << " rejected (error), " << rej_newton << " retried (Newton)\nstep sizes set by";
    for (int k = 0; k < mbd::kStepLimits; ++k)
      if (const long c = end.stats->steps_set_by[static_cast<std::size_t>(k)]; c > 0)
        tx << " " << mbd::step_limit_name(static_cast<mbd::StepLimit>(k)) << " " << c;
  }
  tx << "\nNewton          " << newton << " iterations";
  if (steps > 0) tx << " (" << static_cast<double>(newton) / static_cast<double>(steps) << " per step)";
  tx << "\n";
  if (!lock_elements_.empty()) tx << "\nlock                      t_latch [s]   peak |torque| after latching [N m]\n";
  for (std::size_t k = 0; k < lock_elements_.size(); ++k) {
    tx << "  " << m.force_elements[static_cast<std::size_t>(lock_elements_[k])].name;
    for (std::size_t pad = m.force_elements[static_cast<std::size_t>(lock_elements_[k])].name.size(); pad < 24; ++pad) tx << ' ';
    if (t_latch_[k]) tx << num(*t_latch_[k]) << "   " << num(peak_after_latch_[k]) << "\n";
    else tx << "never latched\n";
  }
  if (!stress_.empty() && !lock_elements_.empty()) {
    tx << "\nlargest element result of each body from each lock's latch until the next lock latches\n";
    for (std::size_t k = 0; k < lock_elements_.size(); ++k)
      for (const StressBody& sb : stress_) {
        const LockPeak& lp = sb.after_lock[k];
        tx << "  " << m.force_elements[static_cast<std::size_t>(lock_elements_[k])].name << "  "
           << scene_.description.bodies[sb.body].name << ": ";
        if (lp.value < 0) {
          tx << "-\n";
          continue;
        }
        const auto it = std::find(sb.modes->element_ids.begin(), sb.modes->element_ids.end(), lp.element);
        const auto kind = static_cast<fem::ResultKind>(sb.modes->kinds[static_cast<std::size_t>(it - sb.modes->element_ids.begin())]);
        tx << fem::element_result_peak_name(kind) << " " << num(lp.value) << " at element " << lp.element << ", t = " << num(lp.t)
           << " s" << (lp.fibre ? (lp.fibre == 1 ? " (fibre Z1)" : " (fibre Z2)") : "") << "\n";
      }
  }
  for (const StressBody& sb : stress_) {
    tx << "\nlargest element results of " << scene_.description.bodies[sb.body].name
       << " (stress modes x elastic coordinates; stress_envelope.csv has every element)\n";
    for (const std::size_t e : top(sb)) {
      const auto kind = static_cast<fem::ResultKind>(sb.modes->kinds[e]);
      tx << "  element " << sb.modes->element_ids[e] << "  " << fem::element_result_peak_name(kind) << " " << num(sb.peak[e])
         << " at t = " << num(sb.t_peak[e]) << " s" << (sb.fibre[e] ? (sb.fibre[e] == 1 ? " (fibre Z1)" : " (fibre Z2)") : "")
         << "\n";
    }
  }
  tx.flush();
}

}  // namespace seflex::scene
