// FORCE / MOMENT / PLOAD2 / GRAV / RFORCE / LOAD (see loads.hpp).
#include "seflex/fem/loads.hpp"

#include <cmath>
#include <optional>
#include <unordered_map>

#include "face_pressure.hpp"
#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/bar_line_load.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_quadratic.hpp"
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/fem/enforced_motion.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::fem {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

/// What one load_vector call shares: the grids' CD axes, the shells by id, the inertia accelerations.
class LoadBuilder {
 public:
  LoadBuilder(const Model& model, const DofMap& dofs, Eigen::VectorXd& p)
      : m_(model), dofs_(dofs), p_(p), cd_(grid_cd_axes(model)) {}

  /// Add the cards of set `sid` times `scale`; returns whether any card has this SID.
  bool add_set(int sid, double scale) {
    bool found = false;
    for (const PointLoad& l : m_.point_loads)
      if (l.sid == sid) found = true, point_load(l, scale);
    for (const PressureLoad& l : m_.pressure_loads)
      if (l.sid == sid) found = true, pressure_load(l, scale);
    for (const FaceLoad& l : m_.face_loads)
      if (l.sid == sid) found = true, face_load(l, scale);
    for (const GravityLoad& g : m_.gravity_loads)
      if (g.sid == sid) found = true, gravity(g, scale);
    for (const RotationalLoad& r : m_.rotational_loads)
      if (r.sid == sid) found = true, rotation(r, scale);
    for (const BarLineLoad& l : m_.bar_line_loads)
      if (l.sid == sid) found = true, bar_load(l, scale);
    for (const ScalarLoad& l : m_.scalar_loads)
      if (l.sid == sid) found = true, scalar_load(l, scale);
    for (const GridPressureLoad& l : m_.grid_pressure_loads)
      if (l.sid == sid) found = true, grid_pressure(l, scale);
    // SPCD cards make a load set of enforced displacements (enforced_motion.hpp): no load here
    return found || has_enforced_motion_set(m_, sid);
  }

  /// p += M a for the accumulated grid accelerations of GRAV and RFORCE (one product for all). M is
  /// the mass without the external superelements' (GlobalMatrices::load_mass): their mass takes no
  /// GRAV or RFORCE of the bulk data, since in Nastran a part's loads are its own (an external part's,
  /// its PA matrix), as MSC's se_test_n11 run shows.
  void finish(const Eigen::SparseMatrix<double>* M) {
    if (!acc_) return;
    SEFLEX_DEMAND(M != nullptr && M->rows() == dofs_.size(), "load_vector: GRAV/RFORCE need the assembled mass matrix");
    p_ += *M * *acc_;
  }

 private:
  /// Basic vector v at grid index gi as components in the grid's CD system.
  Eigen::Vector3d to_cd(std::size_t gi, const Eigen::Vector3d& v) const {
    return cd_[gi] ? Eigen::Vector3d(cd_[gi]->transpose() * v) : v;
  }

  void add_grid(std::size_t gi, int c0, const Eigen::Vector3d& v_basic, double scale, Eigen::VectorXd& into) const {
    const Eigen::Vector3d v = to_cd(gi, v_basic);
    for (int k = 0; k < 3; ++k) into[dofs_.grid_dof(static_cast<Eigen::Index>(gi), c0 + k)] += scale * v[k];
  }

  void point_load(const PointLoad& l, double scale) {
    const char* card = point_load_card(l);
    const std::uint32_t gi = detail::grid_index(m_, l.grid, l.ref, card, l.sid, "3 (G)");
    add_grid(gi, l.kind == PointLoad::Kind::Force ? 1 : 4, l.scale * point_load_direction(l, gi), scale, p_);
  }

  /// The basic vector a unit value of the load acts along: (N1, N2, N3) in CID (FORCE, MOMENT), the
  /// unit vector G1 -> G2 (FORCE1, MOMENT1) or of (G1 -> G2) x (G3 -> G4) (FORCE2, MOMENT2), at the
  /// grids' undeformed positions.
  Eigen::Vector3d point_load_direction(const PointLoad& l, std::uint32_t gi) const {
    const char* card = point_load_card(l);
    if (l.direction == PointLoad::Direction::Vector)
      return detail::axes_at(m_, l.cid, m_.grids[gi].x_basic, l.ref, card, l.sid, "4 (CID)") * l.n;
    static const char* fields[4] = {"5 (G1)", "6 (G2)", "7 (G3)", "8 (G4)"};
    auto x = [&](int k) {
      return m_.grids[detail::grid_index(m_, l.g[static_cast<std::size_t>(k)], l.ref, card, l.sid, fields[k])].x_basic;
    };
    const Eigen::Vector3d a = x(1) - x(0);
    if (!(a.norm() > 0.0))
      detail::fail(m_, l.ref, card, l.sid, "5 (G1)", "grids G1 and G2 are at the same point; expected a direction G1 -> G2");
    if (l.direction == PointLoad::Direction::TwoGrids) return a.normalized();
    const Eigen::Vector3d b = x(3) - x(2);
    if (!(b.norm() > 0.0))
      detail::fail(m_, l.ref, card, l.sid, "7 (G3)", "grids G3 and G4 are at the same point; expected a direction G3 -> G4");
    const Eigen::Vector3d n = a.cross(b);
    if (!(n.norm() > 1e-10 * a.norm() * b.norm()))
      detail::fail(m_, l.ref, card, l.sid, "5 (G1)",
                   "G1 -> G2 and G3 -> G4 are parallel; expected two directions whose cross product gives the load's");
    return n.normalized();
  }

  /// SLOAD: on the scalar point, or on T1 (CD system) of a grid of that id.
  void scalar_load(const ScalarLoad& l, double scale) {
    const auto dof = find_dof(m_, dofs_, l.point, m_.spoint_index.count(l.point) ? 0 : 1);
    if (!dof)
      detail::fail(m_, l.ref, "SLOAD", l.sid, "Si",
                   "references point " + std::to_string(l.point) + ", which is not defined; expected a scalar point (or a grid: its T1)");
    p_[*dof] += scale * l.f;
  }

  /// PLOAD: a triangle's force P A along (G1 -> G2) x (G1 -> G3), a third per grid; a quadrilateral
  /// as the four triangles 123, 234, 341, 412 with P/2 each (QRG PLOAD remarks).
  void grid_pressure(const GridPressureLoad& l, double scale) {
    static const char* fields[4] = {"4 (G1)", "5 (G2)", "6 (G3)", "7 (G4)"};
    const int n = l.g[3] != 0 ? 4 : 3;
    std::array<std::uint32_t, 4> gi{};
    for (int k = 0; k < n; ++k) gi[static_cast<std::size_t>(k)] = detail::grid_index(m_, l.g[static_cast<std::size_t>(k)], l.ref, "PLOAD", l.sid, fields[k]);
    auto triangle = [&](int a, int b, int c, double p) {
      const std::uint32_t t[3] = {gi[static_cast<std::size_t>(a)], gi[static_cast<std::size_t>(b)], gi[static_cast<std::size_t>(c)]};
      const Eigen::Vector3d n2 = (m_.grids[t[1]].x_basic - m_.grids[t[0]].x_basic).cross(m_.grids[t[2]].x_basic - m_.grids[t[0]].x_basic);
      if (!(n2.norm() > 0.0))
        detail::fail(m_, l.ref, "PLOAD", l.sid, "", "its grids " + std::to_string(l.g[static_cast<std::size_t>(a)]) + ", " +
                                                        std::to_string(l.g[static_cast<std::size_t>(b)]) + ", " +
                                                        std::to_string(l.g[static_cast<std::size_t>(c)]) +
                                                        " are collinear; expected a triangle or quadrilateral of non-zero area");
      for (const std::uint32_t g : t) add_grid(g, 1, p * n2 / 6.0, scale, p_);  // P (|n2|/2) n / 3
    };
    if (n == 3) return triangle(0, 1, 2, l.p);
    for (int k = 0; k < 4; ++k) triangle(k, (k + 1) % 4, (k + 2) % 4, 0.5 * l.p);
  }

  void bar_load(const BarLineLoad& l, double scale) {
    const BarLineLoadAtGrids b = bar_line_load(m_, l);
    add_grid(b.grid_A, 1, b.f.segment<3>(0), scale, p_);
    add_grid(b.grid_A, 4, b.f.segment<3>(3), scale, p_);
    add_grid(b.grid_B, 1, b.f.segment<3>(6), scale, p_);
    add_grid(b.grid_B, 4, b.f.segment<3>(9), scale, p_);
  }

  // -------------------------------------------------------------------------------------------
  // PLOAD2
  const std::unordered_map<int, std::size_t>& shells() {
    if (!shell_index_) {
      shell_index_.emplace();
      for (std::size_t k = 0; k < m_.shells.size(); ++k) shell_index_->emplace(m_.shells[k].id, k);
    }
    return *shell_index_;
  }

  const std::unordered_map<int, std::size_t>& shells8() {
    if (!shell8_index_) {
      shell8_index_.emplace();
      for (std::size_t k = 0; k < m_.shells8.size(); ++k) shell8_index_->emplace(m_.shells8[k].shell.id, k);
    }
    return *shell8_index_;
  }

  /// A uniform pressure p along the normal of a CTRIA6/CQUAD8: the element's work-equivalent loads.
  void quadratic_shell_pressure(const QuadraticShell& q, double p, double scale) {
    if (!k6rot_) k6rot_ = assembly_options(m_).k6rot;
    const QuadraticShellElement e = make_quadratic_shell_element(m_, q);
    const Eigen::Matrix<double, 48, 1> f = quadratic_shell_pressure_load(e, p, *k6rot_);
    const char* card = quadratic_shell_card(q);
    for (int k = 0; k < 2 * q.shell.nnode; ++k) {
      const int g = k < q.shell.nnode ? q.shell.g[static_cast<std::size_t>(k)] : q.mid[static_cast<std::size_t>(k - q.shell.nnode)];
      if (g == 0) continue;
      const std::uint32_t gi = detail::grid_index(m_, g, q.shell.ref, card, q.shell.id, "G" + std::to_string(k + 1));
      add_grid(gi, 1, f.segment<3>(6 * k), scale, p_);
      add_grid(gi, 4, f.segment<3>(6 * k + 3), scale, p_);
    }
  }

  /// The card kind of a non-shell element id, or "" if no element has it (for messages).
  std::string other_element(int id) const {
    for (const Bar& b : m_.bars)
      if (b.id == id) return b.is_beam ? "CBEAM" : "CBAR";
    for (const Rod& r : m_.rods)
      if (r.id == id) return rod_card(r);
    for (const Spring& s : m_.springs)
      if (s.id == id) return s.inline_property ? "CELAS2" : "CELAS1";
    for (const Conm2& c : m_.conm2)
      if (c.id == id) return "CONM2";
    for (const ShearPanel& s : m_.shear_panels)
      if (s.id == id) return "CSHEAR";
    for (const Bend& b : m_.bends)
      if (b.id == id) return "CBEND";
    for (const Rbe2& r : m_.rbe2)
      if (r.id == id) return "RBE2";
    for (const Rbar& r : m_.rbars)
      if (r.id == id) return "RBAR";
    for (const Rbe3& r : m_.rbe3)
      if (r.id == id) return "RBE3";
    for (const RigidBody& r : m_.rigid_bodies)
      if (r.id == id) return rigid_body_card(r);
    for (const RigidRod& r : m_.rigid_rods)
      if (r.id == id) return rigid_rod_card(r);
    return "";
  }

  void pressure_load(const PressureLoad& l, double scale) {
    const auto& index = shells();
    auto one = [&](int eid) -> bool {
      if (const auto it = index.find(eid); it != index.end()) {
        shell_pressure(m_.shells[it->second], l, scale);
        return true;
      }
      if (const auto it = shells8().find(eid); it != shells8().end()) {
        quadratic_shell_pressure(m_.shells8[it->second], l.p, scale);
        return true;
      }
      return false;
    };
    if (l.thru) {  // QRG PLOAD2 remark: ids of the range that are not shells are skipped
      for (int eid = l.elements[0]; eid <= l.elements[1]; ++eid) one(eid);
      return;
    }
    for (const int eid : l.elements) {
      if (one(eid)) continue;
      const std::string kind = other_element(eid);
      detail::fail(m_, l.ref, "PLOAD2", l.sid, "EID",
                   "element " + std::to_string(eid) + (kind.empty() ? " is not defined" : " is a " + kind) +
                       "; expected a shell: CQUAD4, CTRIA3, CQUADR, CTRIAR, CQUAD8 or CTRIA6");
    }
  }

  void shell_pressure(const Shell& s, const PressureLoad& l, double scale) {
    if (!mystran_) mystran_ = assembly_options(m_).mystran_plate;
    if (*mystran_) return mystran_pressure(s, l, scale, **mystran_);
    const char* card = shell_card(s);
    std::array<std::uint32_t, 4> gi{};
    std::array<Eigen::Vector3d, 4> x;
    for (int k = 0; k < s.nnode; ++k) {
      gi[k] = detail::grid_index(m_, s.g[k], s.ref, card, s.id,
                                 std::to_string(k + 4) + " (G" + std::to_string(k + 1) + ")");
      x[k] = m_.grids[gi[k]].x_basic;
    }
    std::array<Eigen::Vector3d, 4> f;
    if (s.nnode == 3) {
      const Eigen::Vector3d nA = 0.5 * (x[1] - x[0]).cross(x[2] - x[0]);  // area times unit normal
      for (int k = 0; k < 3; ++k) f[k] = l.p * nA / 3.0;
    } else {
      // f_i = p int N_i (x_xi X x_eta) dxi deta: the integrand is biquadratic, 2 x 2 Gauss is exact.
      for (auto& v : f) v.setZero();
      static const double xi_n[4] = {-1, 1, 1, -1}, eta_n[4] = {-1, -1, 1, 1};
      const double g = 1.0 / std::sqrt(3.0);
      for (const double xi : {-g, g})
        for (const double eta : {-g, g}) {
          Eigen::Vector3d x_xi = Eigen::Vector3d::Zero(), x_eta = Eigen::Vector3d::Zero();
          double N[4];
          for (int k = 0; k < 4; ++k) {
            N[k] = 0.25 * (1 + xi_n[k] * xi) * (1 + eta_n[k] * eta);
            x_xi += 0.25 * xi_n[k] * (1 + eta_n[k] * eta) * x[k];
            x_eta += 0.25 * eta_n[k] * (1 + xi_n[k] * xi) * x[k];
          }
          const Eigen::Vector3d ndA = x_xi.cross(x_eta);
          for (int k = 0; k < 4; ++k) f[k] += l.p * N[k] * ndA;
        }
    }
    for (int k = 0; k < s.nnode; ++k) add_grid(gi[k], 1, f[k], scale, p_);
  }

  /// PARAM QUAD4TYP MIN4T: the work-equivalent load of MIN4T / MIN3 (forces and corner moments).
  void mystran_pressure(const Shell& s, const PressureLoad& l, double scale, const MystranPlate& mystran) {
    const char* card = shell_card(s);
    std::array<std::uint32_t, 4> gi{};
    for (int k = 0; k < s.nnode; ++k)
      gi[k] = detail::grid_index(m_, s.g[k], s.ref, card, s.id, std::to_string(k + 4) + " (G" + std::to_string(k + 1) + ")");
    Eigen::Matrix<double, 24, 1> f;
    if (s.nnode == 4)
      f = quad4_mystran_pressure_load(make_quad4_element(m_, s), l.p, mystran);
    else
      f.head<18>() = tria3_mystran_pressure_load(make_tria3_element(m_, s), l.p);
    for (int k = 0; k < s.nnode; ++k) {
      add_grid(gi[k], 1, f.segment<3>(6 * k), scale, p_);
      add_grid(gi[k], 4, f.segment<3>(6 * k + 3), scale, p_);
    }
  }

  // -------------------------------------------------------------------------------------------
  // PLOAD4
  const std::unordered_map<int, std::size_t>& solids() {
    if (!solid_index_) {
      solid_index_.emplace();
      for (std::size_t k = 0; k < m_.solids.size(); ++k) solid_index_->emplace(m_.solids[k].id, k);
    }
    return *solid_index_;
  }

  void face_load(const FaceLoad& l, double scale) {
    std::vector<detail::GridForce> forces;
    auto quadratic = [&](int eid) {  // CTRIA6/CQUAD8: a uniform pressure along the normal only
      const auto it = shells8().find(eid);
      if (it == shells8().end()) return false;
      const QuadraticShell& q = m_.shells8[it->second];
      const int nc = q.shell.nnode;
      bool uniform = l.n.squaredNorm() == 0.0;
      for (int k = 1; k < nc; ++k) uniform = uniform && l.p[static_cast<std::size_t>(k)] == l.p[0];
      if (!uniform)
        detail::fail(m_, l.ref, "PLOAD4", l.sid, "P2-P4/N",
                     std::string("on ") + quadratic_shell_card(q) + " " + std::to_string(eid) +
                         ": a pressure varying over the element or along a direction N1-N3; seflex applies a uniform pressure "
                         "along the normal of a CTRIA6/CQUAD8 (P2-P4 blank or equal to P1, N blank)");
      quadratic_shell_pressure(q, l.p[0], scale);
      return true;
    };
    if (l.eid_last > 0) {  // THRU: the shells of the range (other ids are skipped, as for PLOAD2)
      const auto& index = shells();
      for (int eid = l.eid; eid <= l.eid_last; ++eid)
        if (const auto it = index.find(eid); it != index.end())
          detail::shell_face_forces(m_, m_.shells[it->second], l, forces);
        else
          quadratic(eid);
    } else if (quadratic(l.eid)) {
    } else if (const auto it = shells().find(l.eid); it != shells().end()) {
      detail::shell_face_forces(m_, m_.shells[it->second], l, forces);
    } else if (const auto js = solids().find(l.eid); js != solids().end()) {
      detail::solid_face_forces(m_, m_.solids[js->second], l, forces);
    } else {
      const std::string kind = other_element(l.eid);
      detail::fail(m_, l.ref, "PLOAD4", l.sid, "EID",
                   "element " + std::to_string(l.eid) + (kind.empty() ? " is not defined" : " is a " + kind) +
                       "; expected a CQUAD4, CTRIA3, CQUAD8, CTRIA6, CHEXA, CPENTA, CTETRA or CPYRAM");
    }
    for (const auto& gf : forces) add_grid(gf.grid, 1, gf.f_basic, scale, p_);
  }

  // -------------------------------------------------------------------------------------------
  // GRAV, RFORCE: grid accelerations, multiplied by M in finish()
  Eigen::VectorXd& acc() {
    if (!acc_) acc_ = Eigen::VectorXd::Zero(dofs_.size());
    return *acc_;
  }

  /// Axes (columns, basic) of the rectangular system `cid` of an inertia load card.
  /// `field`: where the card holds CID, as the messages name fields ("3 (CID)").
  Eigen::Matrix3d rectangular_axes(int cid, const CardRef& ref, const char* card, int sid, const char* field) const {
    if (cid == 0) return Eigen::Matrix3d::Identity();
    const auto it = m_.coord_index.find(cid);
    if (it == m_.coord_index.end())
      detail::fail(m_, ref, card, sid, field,
                   "references coordinate system " + std::to_string(cid) + ", which is not defined");
    const CoordSys& c = m_.coords[it->second];
    if (c.type != CoordType::Rectangular)
      detail::fail(m_, ref, card, sid, field,
                   "references coordinate system " + std::to_string(cid) +
                       ", which is not rectangular; expected a rectangular system (CORD1R/CORD2R) or 0");
    return c.axes;
  }

  void gravity(const GravityLoad& g, double scale) {
    const Eigen::Vector3d a = rectangular_axes(g.cid, g.ref, "GRAV", g.sid, "3 (CID)") * (g.a * g.n);  // basic
    Eigen::VectorXd& A = acc();
    for (std::size_t gi = 0; gi < m_.grids.size(); ++gi) add_grid(gi, 1, a, scale, A);
  }

  void rotation(const RotationalLoad& r, double scale) {
    const Eigen::Vector3d R = rectangular_axes(r.cid, r.ref, "RFORCE", r.sid, "4 (CID)") * r.r;
    const Eigen::Vector3d w = kTwoPi * r.a * R, alpha = kTwoPi * r.racc * R;  // rad per unit time (squared)
    Eigen::Vector3d x_axis = Eigen::Vector3d::Zero();
    if (r.grid != 0) x_axis = m_.grids[detail::grid_index(m_, r.grid, r.ref, "RFORCE", r.sid, "3 (G)")].x_basic;
    Eigen::VectorXd& A = acc();
    for (std::size_t gi = 0; gi < m_.grids.size(); ++gi) {
      const Eigen::Vector3d d = m_.grids[gi].x_basic - x_axis;
      const Eigen::Vector3d a = w.cross(w.cross(d)) + alpha.cross(d);
      add_grid(gi, 1, a, -scale, A);  // p = -M a
      if (r.racc != 0.0) add_grid(gi, 4, alpha, -scale, A);
    }
  }

  const Model& m_;
  const DofMap& dofs_;
  Eigen::VectorXd& p_;
  std::vector<std::optional<Eigen::Matrix3d>> cd_;
  std::optional<std::unordered_map<int, std::size_t>> shell_index_, shell8_index_, solid_index_;
  std::optional<double> k6rot_;  ///< PARAM K6ROT, read at the first CTRIA6/CQUAD8 pressure
  std::optional<Eigen::VectorXd> acc_;
  std::optional<std::optional<MystranPlate>> mystran_;  ///< PARAM QUAD4TYP MIN4T, read at the first PLOAD2
};

}  // namespace

Eigen::VectorXd load_vector(const Model& model, const DofMap& dofs, int sid, const Eigen::SparseMatrix<double>* M_gg) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(dofs.size());
  LoadBuilder b(model, dofs, p);
  for (const LoadCombination& lc : model.load_combinations) {
    if (lc.sid != sid) continue;
    for (const auto& [si, li] : lc.terms)
      if (!b.add_set(li, lc.s * si))
        throw InputError(where(model, lc.ref), "LOAD " + std::to_string(lc.sid) + ": references load set " +
                                                   std::to_string(li) +
                                                   ", but no FORCE, MOMENT, PLOAD2, PLOAD4, GRAV or RFORCE card has that SID");
    b.finish(M_gg);
    return p;
  }
  if (!b.add_set(sid, 1.0))
    throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                     "case control LOAD = " + std::to_string(sid) +
                         ": no LOAD, FORCE, MOMENT, PLOAD2, PLOAD4, GRAV or RFORCE bulk data card has SID " +
                         std::to_string(sid));
  b.finish(M_gg);
  return p;
}

}  // namespace seflex::fem
