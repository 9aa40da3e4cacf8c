// Scene files: YAML -> SceneDescription (structure, key names, values, references by name).
#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "seflex/scene/scene.hpp"
#include "yaml_fields.hpp"

namespace seflex::scene {

namespace {

using detail::YamlField;
constexpr double kDeg = M_PI / 180.0;

SceneWhere where_of(const YamlField& f) { return SceneWhere{f.where(), f.path()}; }

std::vector<std::string> keys_of(const std::map<std::string, int>& m) {
  std::vector<std::string> v;
  for (const auto& [k, i] : m) v.push_back(k);
  return v;
}

struct Reader {
  SceneDescription d;
  std::map<std::string, int> body_index, hinge_index;
  std::set<std::string> force_names;

  SceneNodeRef node_ref(const YamlField& f, bool ground_allowed) const {
    const std::string s = f.text();
    SceneNodeRef r;
    r.where = where_of(f);
    if (s == "ground") {
      if (!ground_allowed) f.fail("expected 'body.node' (a body's interface node), got 'ground'");
      r.ground = true;
      return r;
    }
    const std::size_t dot = s.rfind('.');
    const std::string expected = ground_allowed ? "'ground' or 'body.node'" : "'body.node'";
    if (dot == std::string::npos || dot == 0 || dot + 1 == s.size())
      f.fail("expected " + expected + " (node = FE grid id of an interface node, e.g. yoke.1), got '" + s + "'");
    r.body = s.substr(0, dot);
    const std::string grid = s.substr(dot + 1);
    if (grid.find_first_not_of("0123456789") != std::string::npos || grid.size() > 9)
      f.fail("expected " + expected + " with an FE grid id after the dot, got '" + s + "'");
    r.grid = std::stoi(grid);
    if (!body_index.count(r.body)) {
      const std::string hint = detail::did_you_mean(r.body, keys_of(body_index));
      f.fail("body '" + r.body + "' is not defined" + (hint.empty() ? std::string() : " (" + hint + ")"));
    }
    return r;
  }

  std::string hinge_name(const YamlField& f) const {
    const std::string h = f.text();
    if (!hinge_index.count(h)) {
      const std::string hint = detail::did_you_mean(h, keys_of(hinge_index));
      f.fail("hinge '" + h + "' is not defined" + (hint.empty() ? std::string() : " (" + hint + ")"));
    }
    return h;
  }

  static Eigen::Matrix3d rotation(const YamlField& r) {
    r.check_keys({"axis", "angle_deg", "matrix"});
    if (r.has("matrix")) {
      if (r.has("axis") || r.has("angle_deg")) r.fail("give either matrix or axis and angle_deg, not both");
      const YamlField m = r["matrix"];
      m.expect_sequence();
      if (m.size() != 3) m.fail("expected 3 rows [[..], [..], [..]]");
      Eigen::Matrix3d R;
      for (int i = 0; i < 3; ++i) R.row(i) = m.at(static_cast<std::size_t>(i)).vector3().transpose();
      if (!((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() <= 1e-6) || !(R.determinant() > 0))
        m.fail("expected a proper rotation matrix (orthonormal rows, determinant +1)");
      return R;
    }
    const Eigen::Vector3d axis = r.required("axis", "a vector [x, y, z]").vector3();
    if (!(axis.norm() > 1e-12)) r["axis"].fail("expected a nonzero vector");
    const double angle = r.required("angle_deg", "an angle in degrees").number() * kDeg;
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  }

  void body(const YamlField& f) {
    f.check_keys({"name", "superelement", "fidelity", "inertia", "internal_modes", "placement", "damping",
                  "geometric_stiffening"});
    SceneBody b;
    b.where = where_of(f);
    const YamlField name = f.required("name", "the body's name");
    b.name = name.text();
    if (b.name.empty() || b.name == "ground" || b.name.find('.') != std::string::npos)
      name.fail("expected a name without '.' other than 'ground', got '" + b.name + "'");
    if (body_index.count(b.name)) name.fail("body '" + b.name + "' is defined twice");
    const YamlField file = f.required("superelement", "the path of a superelement file (.se)");
    b.superelement = file.text();
    b.file_where = where_of(file);
    if (b.superelement.is_relative()) b.superelement = d.file.parent_path() / b.superelement;
    const std::string fid = f.text_or("fidelity", "flexible");
    if (fid == "rigid") b.fidelity = Fidelity::Rigid;
    else if (fid != "flexible") f["fidelity"].fail("expected flexible or rigid, got '" + fid + "'");
    const std::string in = f.text_or("inertia", "simplified");
    if (in == "full") b.inertia = mbd::InertiaModel::Full;
    else if (in != "simplified") f["inertia"].fail("expected simplified or full, got '" + in + "'");
    if (f.has("geometric_stiffening")) b.geometric_stiffening = f["geometric_stiffening"].boolean();
    if (f.has("internal_modes")) {
      b.internal_modes = f["internal_modes"].integer();
      if (b.internal_modes < 0) f["internal_modes"].fail("expected a number of modes >= 0");
    }
    if (f.has("placement")) {
      const YamlField p = f["placement"];
      p.check_keys({"position", "rotation"});
      if (p.has("position")) b.X_WF.p = p["position"].vector3();
      if (p.has("rotation")) b.X_WF.R = rotation(p["rotation"]);
    }
    if (f.has("damping")) {
      const YamlField dm = f["damping"];
      dm.check_keys({"stiffness_proportional", "modal"});
      if (dm.has("stiffness_proportional")) b.stiffness_damping = dm["stiffness_proportional"].non_negative();
      if (dm.has("modal")) b.modal_damping = dm["modal"].non_negative();
    }
    body_index[b.name] = static_cast<int>(d.bodies.size());
    d.bodies.push_back(b);
  }

  void hinge(const YamlField& f) {
    f.check_keys({"name", "parent", "child", "axis", "angle_deg", "rate_deg_s"});
    SceneHinge h;
    h.where = where_of(f);
    const YamlField name = f.required("name", "the hinge's name");
    h.name = name.text();
    if (h.name.empty()) name.fail("expected a non-empty name");
    if (hinge_index.count(h.name)) name.fail("hinge '" + h.name + "' is defined twice");
    h.parent = node_ref(f.required("parent", "'ground' or 'body.node'"), true);
    h.child = node_ref(f.required("child", "'body.node'"), false);
    h.axis_W = f.required("axis", "the axis [x, y, z] in world components at t = 0").vector3();
    if (!(h.axis_W.norm() > 1e-12)) f["axis"].fail("expected a nonzero vector");
    h.phi0 = f.number_or("angle_deg", 0.0) * kDeg;
    h.phidot0 = f.number_or("rate_deg_s", 0.0) * kDeg;
    hinge_index[h.name] = static_cast<int>(d.hinges.size());
    d.hinges.push_back(h);
  }

  /// Output name: "<kind>.<name>" (a name already starting with "<kind>." is kept as written).
  void name_force(SceneForce& fe, const YamlField& f, const std::string& fallback) {
    const std::string prefix = fe.kind + ".";
    std::string n = f.has("name") ? f["name"].text() : fallback;
    if (n.empty()) f["name"].fail("expected a non-empty name");
    if (n.rfind(prefix, 0) != 0) n = prefix + n;
    if (!force_names.insert(n).second)
      (f.has("name") ? f["name"] : f).fail("a force element named '" + n + "' exists already; give this one a distinct name:");
    fe.name = n;
  }

  SceneForce one_hinge_force(const YamlField& f, const char* kind) {
    SceneForce fe;
    fe.kind = kind;
    fe.where = where_of(f);
    const YamlField h = f.required("hinge", "the name of a hinge");
    fe.hinges = {hinge_name(h)};
    fe.hinge_where = {where_of(h)};
    name_force(fe, f, fe.hinges[0]);
    return fe;
  }

  void spring(const YamlField& f) {
    f.check_keys({"name", "hinge", "torque_at_0", "torque_at_ref", "ref_angle_deg", "table"});
    SceneForce fe = one_hinge_force(f, "spring");
    mbd::TorsionSpring s;
    if (f.has("table")) {
      if (f.has("torque_at_0") || f.has("torque_at_ref") || f.has("ref_angle_deg"))
        f.fail("give either a table or torque_at_0 (with torque_at_ref and ref_angle_deg), not both");
      const YamlField t = f["table"];
      t.check_keys({"angle_deg", "torque"});
      const std::vector<double> a = t.required("angle_deg", "a list of angles [deg]").numbers();
      s.table_tau = t.required("torque", "a list of torques [N m]").numbers();
      if (a.size() != s.table_tau.size() || a.size() < 2)
        t.fail("expected angle_deg and torque lists of the same length (at least 2 points)");
      for (std::size_t i = 1; i < a.size(); ++i)
        if (!(a[i] > a[i - 1])) t["angle_deg"].at(i).fail("expected angles in strictly increasing order");
      for (double x : a) s.table_phi.push_back(x * kDeg);
    } else {
      s.tau0 = f.required("torque_at_0", "the torque at angle 0 [N m] (or a table)").number();
      if (f.has("torque_at_ref") != f.has("ref_angle_deg"))
        f.fail("give torque_at_ref and ref_angle_deg together (the torque at a second angle)");
      s.tau1 = f.number_or("torque_at_ref", s.tau0);
      s.phi_ref = f.has("ref_angle_deg") ? f["ref_angle_deg"].number() * kDeg : 1.0;
      if (!(std::abs(s.phi_ref) > 0.0)) f["ref_angle_deg"].fail("expected a nonzero angle");
    }
    fe.element = s;
    d.forces.push_back(fe);
  }

  void lock(const YamlField& f) {
    f.check_keys({"name", "hinge", "angle_deg", "stiffness", "damping"});
    SceneForce fe = one_hinge_force(f, "lock");
    mbd::HingeLock l;
    l.phi_lock = f.required("angle_deg", "the lock angle [deg]").number() * kDeg;
    l.k_lock = f.required("stiffness", "the lock stiffness [N m/rad]").positive();
    l.c_lock = f.has("damping") ? f["damping"].non_negative() : 0.0;
    fe.element = l;
    d.forces.push_back(fe);
  }

  void damper(const YamlField& f) {
    f.check_keys({"name", "hinge", "coefficient"});
    SceneForce fe = one_hinge_force(f, "damper");
    fe.element = mbd::RotationalDamper{mbd::HingeIndex(), f.required("coefficient", "[N m s/rad]").non_negative()};
    d.forces.push_back(fe);
  }

  void cable(const YamlField& f, std::size_t i) {
    f.check_keys({"name", "pulley_a", "pulley_b", "stiffness", "preload"});
    SceneForce fe;
    fe.kind = "cable";
    fe.where = where_of(f);
    mbd::CableLoop c;
    for (int side = 0; side < 2; ++side) {
      const YamlField p = f.required(side == 0 ? "pulley_a" : "pulley_b", "{hinges: [..], radius: r}");
      p.check_keys({"hinges", "radius"});
      const YamlField hs = p.required("hinges", "a list of hinge names");
      hs.expect_sequence();
      if (hs.size() == 0) hs.fail("expected at least one hinge");
      for (std::size_t k = 0; k < hs.size(); ++k) {
        fe.hinges.push_back(hinge_name(hs.at(k)));
        fe.hinge_where.push_back(where_of(hs.at(k)));
      }
      if (side == 0) fe.hinges_a = static_cast<int>(hs.size());
      (side == 0 ? c.r_a : c.r_b) = p.required("radius", "the pulley radius [m]").positive();
    }
    std::set<std::string> distinct(fe.hinges.begin(), fe.hinges.end());
    if (distinct.size() != fe.hinges.size()) f.fail("a hinge is listed twice in the pulleys of one cable loop");
    c.k = f.required("stiffness", "the cable stiffness [N/m]").positive();
    c.preload = f.has("preload") ? f["preload"].non_negative() : 0.0;
    fe.element = c;
    name_force(fe, f, "loop" + std::to_string(i + 1));
    d.forces.push_back(fe);
  }

  void loads(const YamlField& f) {
    f.check_keys({"gravity", "nodal"});
    if (f.has("gravity")) d.gravity = f["gravity"].vector3();
    if (!f.has("nodal")) return;
    const YamlField list = f["nodal"];
    list.expect_sequence();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YamlField l = list.at(i);
      l.check_keys({"name", "node", "force", "moment", "follower"});
      SceneLoad ld;
      ld.where = where_of(l);
      ld.node = node_ref(l.required("node", "'body.node'"), false);
      ld.name = l.text_or("name", "load" + std::to_string(i + 1));
      if (l.has("force")) ld.force = l["force"].vector3();
      if (l.has("moment")) ld.moment = l["moment"].vector3();
      ld.follower = l.boolean_or("follower", false);
      d.loads.push_back(ld);
    }
  }

  void drive(const YamlField& f) {
    f.check_keys({"hinge", "kind", "rate_deg_s", "ramp_time"});
    SceneDrive dr;
    dr.where = where_of(f);
    dr.hinge = hinge_name(f.required("hinge", "the name of a hinge"));
    for (const auto& other : d.drives)
      if (other.hinge == dr.hinge) f["hinge"].fail("hinge '" + dr.hinge + "' already has a drive");
    dr.kind = f.required("kind", "spin_up or constant_rate").text();
    dr.rate = f.required("rate_deg_s", "the final rate [deg/s]").number() * kDeg;
    if (dr.kind == "spin_up") {
      dr.ramp_time = f.required("ramp_time", "the spin-up time [s]").positive();
    } else if (dr.kind == "constant_rate") {
      if (f.has("ramp_time")) f["ramp_time"].fail("a constant_rate drive has no ramp_time");
    } else {
      f["kind"].fail("expected spin_up or constant_rate, got '" + dr.kind + "'");
    }
    d.drives.push_back(dr);
  }

  void integrator(const YamlField& f) {
    f.check_keys({"method", "rho_inf", "t_end", "step", "max_step", "min_step", "adaptive", "tolerance", "newton", "radau", "stop"});
    mbd::IntegratorSettings& s = d.integrator;
    const std::string method = f.text_or("method", "generalized-alpha");
    if (method != "generalized-alpha" && method != "rk4" && method != "radau5")
      f["method"].fail("expected generalized-alpha, radau5 or rk4, got '" + method + "'");
    d.method = method == "rk4" ? mbd::IntegratorMethod::Rk4 : method == "radau5" ? mbd::IntegratorMethod::Radau5 : mbd::IntegratorMethod::GeneralizedAlpha;
    if (f.has("rho_inf")) {
      s.rho_inf = f["rho_inf"].number();
      if (!(s.rho_inf >= 0.0 && s.rho_inf <= 1.0)) f["rho_inf"].fail("expected a spectral radius between 0 and 1");
    }
    s.t_end = f.required("t_end", "the end time [s]").positive();
    if (f.has("step")) s.h_initial = f["step"].positive();
    if (f.has("max_step")) s.h_max = f["max_step"].positive();
    if (f.has("min_step")) s.h_min = f["min_step"].positive();
    if (s.h_min > s.h_initial) f.fail("min_step (" + std::to_string(s.h_min) + ") exceeds step (" + std::to_string(s.h_initial) + ")");
    s.adaptive = f.boolean_or("adaptive", true);
    if (f.has("tolerance")) {
      const YamlField t = f["tolerance"];
      t.check_keys({"position", "angle"});
      if (t.has("position")) s.tol_position = t["position"].positive();
      if (t.has("angle")) s.tol_angle = t["angle"].positive();
    }
    if (f.has("newton")) {
      const YamlField n = f["newton"];
      n.check_keys({"tolerance", "increment_tolerance", "error_fraction", "max_iterations", "inertia_velocity_tangent"});
      if (n.has("inertia_velocity_tangent")) s.inertia_velocity_tangent = n["inertia_velocity_tangent"].boolean();
      if (n.has("tolerance")) s.newton_residual_tol = n["tolerance"].positive();
      if (n.has("increment_tolerance")) s.newton_increment_tol = n["increment_tolerance"].positive();
      if (n.has("error_fraction")) {
        s.newton_error_fraction = n["error_fraction"].non_negative();
        if (!(s.newton_error_fraction < 1.0)) n["error_fraction"].fail("expected a fraction of the local error tolerance in [0, 1)");
      }
      if (n.has("max_iterations")) {
        s.newton_max_iterations = n["max_iterations"].integer();
        if (s.newton_max_iterations < 1) n["max_iterations"].fail("expected a number >= 1");
      }
    }
    if (f.has("radau")) {  // method radau5's simplified Newton (mbd::IntegratorSettings::Radau)
      const YamlField r = f["radau"];
      r.check_keys({"max_iterations", "newton_fraction", "jacobian_theta"});
      if (r.has("max_iterations")) {
        s.radau.newton_max_iterations = r["max_iterations"].integer();
        if (s.radau.newton_max_iterations < 2) r["max_iterations"].fail("expected a number >= 2");
      }
      if (r.has("newton_fraction")) {
        s.radau.newton_fraction = r["newton_fraction"].non_negative();
        if (!(s.radau.newton_fraction < 1.0)) r["newton_fraction"].fail("expected a fraction of the local error tolerance in [0, 1) (0: Hairer and Wanner's rule)");
      }
      if (r.has("jacobian_theta")) {
        s.radau.jacobian_theta = r["jacobian_theta"].non_negative();
        if (!(s.radau.jacobian_theta < 1.0)) r["jacobian_theta"].fail("expected a contraction rate in [0, 1)");
      }
    }
    if (f.has("stop")) {
      const YamlField st = f["stop"];
      st.check_keys({"after_all_locked"});
      if (st.has("after_all_locked")) d.stop_after_all_locked = st["after_all_locked"].non_negative();
    }
  }

  void output(const YamlField& f) {
    f.check_keys({"interval", "animation", "interface_loads", "static_subcases"});
    if (f.has("static_subcases")) {
      d.output.static_subcases = f["static_subcases"].numbers();
      for (std::size_t k = 0; k < d.output.static_subcases.size(); ++k)
        if (d.output.static_subcases[k] < 0 || (k > 0 && d.output.static_subcases[k] <= d.output.static_subcases[k - 1]))
          f["static_subcases"].fail("expected increasing times >= 0 [s]");
    }
    if (f.has("interval")) d.output.interval = f["interval"].positive();
    if (f.has("interface_loads")) d.output.interface_loads = f["interface_loads"].boolean();
    if (f.has("animation")) {
      const YamlField a = f["animation"];
      a.check_keys({"interval"});
      d.output.animation_interval = a.required("interval", "the animation interval [s]").positive();
    }
  }

  template <class Fn>
  static void each(const YamlField& root, const char* key, Fn&& fn) {
    if (!root.has(key)) return;
    const YamlField list = root[key];
    list.expect_sequence();
    for (std::size_t i = 0; i < list.size(); ++i) fn(list.at(i), i);
  }
};

}  // namespace

SceneDescription parse_scene(const std::string& text, const std::filesystem::path& file) {
  const std::string name = file.string();
  const YamlField root = detail::load_yaml(text, &name);
  if (!root.node().IsMap()) root.fail("expected a scene: a map with bodies, hinges, integrator, ... (see docs/scenes.md)");
  root.check_keys({"title", "bodies", "ground", "connections", "hinges", "springs", "locks", "cables", "dampers", "loads",
                   "drives", "integrator", "output"});
  Reader r;
  r.d.file = file;
  r.d.title = root.text_or("title", file.stem().string());
  const YamlField bodies = root.required("bodies", "a list of bodies");
  bodies.expect_sequence();
  if (bodies.size() == 0) bodies.fail("expected at least one body");
  Reader::each(root, "bodies", [&](const YamlField& f, std::size_t) { r.body(f); });
  Reader::each(root, "ground", [&](const YamlField& f, std::size_t) { r.d.ground.push_back(r.node_ref(f, false)); });
  Reader::each(root, "connections", [&](const YamlField& f, std::size_t) {
    f.expect_sequence();
    if (f.size() < 2) f.fail("expected a list of at least two 'body.node' that are one node");
    std::vector<SceneNodeRef> group;
    for (std::size_t k = 0; k < f.size(); ++k) group.push_back(r.node_ref(f.at(k), false));
    r.d.connections.push_back(group);
  });
  Reader::each(root, "hinges", [&](const YamlField& f, std::size_t) { r.hinge(f); });
  Reader::each(root, "springs", [&](const YamlField& f, std::size_t) { r.spring(f); });
  Reader::each(root, "locks", [&](const YamlField& f, std::size_t) { r.lock(f); });
  Reader::each(root, "cables", [&](const YamlField& f, std::size_t i) { r.cable(f, i); });
  Reader::each(root, "dampers", [&](const YamlField& f, std::size_t) { r.damper(f); });
  if (root.has("loads")) r.loads(root["loads"]);
  Reader::each(root, "drives", [&](const YamlField& f, std::size_t) { r.drive(f); });
  r.integrator(root.required("integrator", "integrator settings with at least t_end"));
  if (root.has("output")) r.output(root["output"]);
  r.d.integrator.output_interval = r.d.output.interval;
  return r.d;
}

SceneDescription read_scene(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceRef{file.string(), 0}, "cannot open the scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_scene(ss.str(), file);
}

}  // namespace seflex::scene
