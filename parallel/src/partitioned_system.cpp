// Partitioned assembly into distributed PETSc matrices (partitioned_system.hpp).
#include "seflex/parallel/partitioned_system.hpp"

#include <algorithm>
#include <exception>
#include <numeric>

#include "petsc_support.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/parallel/element_partition.hpp"
#include "seflex/parallel/session.hpp"

namespace seflex::parallel {
namespace {

using SparseMatrixd = Eigen::SparseMatrix<double>;

int comm_rank() {
  int r = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  return r;
}
int comm_size() {
  int s = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &s);
  return s;
}

/// Runs f() on every rank; if it threw on some rank, that rank rethrows its error and the others
/// throw PeerFailure (collective: no rank is left waiting in a later collective call).
template <class F>
auto collectively(F&& f) -> decltype(f()) {
  std::exception_ptr error;
  decltype(f()) result{};
  try {
    result = f();
  } catch (...) {
    error = std::current_exception();
  }
  int mine = error ? 1 : 0, any = 0;
  SEFLEX_DEMAND(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD) == MPI_SUCCESS, "MPI_Allreduce failed");
  if (error) std::rethrow_exception(error);
  if (any != 0) throw PeerFailure();
  return result;
}

/// Swaps the model's element vectors for the rank's own elements; the destructor restores them.
class OwnElements {
 public:
  OwnElements(fem::Model& m, const ElementPartition& p, int rank) : m_(m) {
    keep(m.bars, p.bars, rank, bars_);
    keep(m.rods, p.rods, rank, rods_);
    keep(m.shells, p.shells, rank, shells_);
    keep(m.solids, p.solids, rank, solids_);
    keep(m.bushes, p.bushes, rank, bushes_);
    keep(m.shear_panels, p.shear_panels, rank, shear_panels_);
    keep(m.bends, p.bends, rank, bends_);
    keep(m.shells8, p.shells8, rank, shells8_);
    keep(m.conm2, p.conm2, rank, conm2_);
    keep(m.conm1, p.conm1, rank, conm1_);
    keep(m.springs, p.springs, rank, springs_);
    keep(m.scalar_masses, p.scalar_masses, rank, scalar_masses_);
  }
  ~OwnElements() {
    m_.bars.swap(bars_);
    m_.rods.swap(rods_);
    m_.shells.swap(shells_);
    m_.solids.swap(solids_);
    m_.bushes.swap(bushes_);
    m_.shear_panels.swap(shear_panels_);
    m_.bends.swap(bends_);
    m_.shells8.swap(shells8_);
    m_.conm2.swap(conm2_);
    m_.conm1.swap(conm1_);
    m_.springs.swap(springs_);
    m_.scalar_masses.swap(scalar_masses_);
  }
  OwnElements(const OwnElements&) = delete;
  OwnElements& operator=(const OwnElements&) = delete;

 private:
  template <class T>
  static void keep(std::vector<T>& v, const std::vector<int>& part, int rank, std::vector<T>& saved) {
    saved.swap(v);
    v.clear();
    for (std::size_t i = 0; i < saved.size(); ++i)
      if (part[i] == rank) v.push_back(saved[i]);
  }
  fem::Model& m_;
  std::vector<fem::Bar> bars_;
  std::vector<fem::Rod> rods_;
  std::vector<fem::Shell> shells_;
  std::vector<fem::Solid> solids_;
  std::vector<fem::Bush> bushes_;
  std::vector<fem::ShearPanel> shear_panels_;
  std::vector<fem::Bend> bends_;
  std::vector<fem::QuadraticShell> shells8_;
  std::vector<fem::Conm2> conm2_;
  std::vector<fem::Conm1> conm1_;
  std::vector<fem::Spring> springs_;
  std::vector<fem::ScalarMass> scalar_masses_;
};

/// Each node's diagonal block of K and M summed over the ranks, as block-diagonal g x g matrices.
fem::GlobalMatrices summed_diagonal_blocks(const fem::GlobalMatrices& local) {
  const fem::DofMap& d = local.dofs;
  auto offset = [&](Eigen::Index node) { return node < d.n_grids ? 36 * node : 36 * d.n_grids + (node - d.n_grids); };
  const auto size = static_cast<std::size_t>(36 * d.n_grids + d.n_spoints);
  std::vector<double> blocks(2 * size, 0.0);
  auto gather = [&](const SparseMatrixd& A, double* out) {
    for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
      const Eigen::Index node = d.node_of_dof(j), first = d.node_first_dof(node);
      const int cnt = d.node_dof_count(node);
      for (SparseMatrixd::InnerIterator it(A, j); it; ++it)
        if (it.row() >= first && it.row() < first + cnt)
          out[offset(node) + (it.row() - first) * cnt + (j - first)] += it.value();
    }
  };
  gather(local.K, blocks.data());
  gather(local.M, blocks.data() + size);
  for (std::size_t at = 0; at < blocks.size();) {  // in chunks whose counts fit an int
    const auto chunk = static_cast<int>(std::min<std::size_t>(blocks.size() - at, std::size_t{1} << 28));
    SEFLEX_DEMAND(MPI_Allreduce(MPI_IN_PLACE, blocks.data() + at, chunk, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD) == MPI_SUCCESS,
                  "MPI_Allreduce failed");
    at += static_cast<std::size_t>(chunk);
  }
  fem::GlobalMatrices g;
  g.dofs = d;
  auto build = [&](const double* in, SparseMatrixd& A) {
    std::vector<Eigen::Triplet<double>> t;
    for (Eigen::Index node = 0; node < d.n_nodes(); ++node) {
      const Eigen::Index first = d.node_first_dof(node);
      const int cnt = d.node_dof_count(node);
      for (int a = 0; a < cnt; ++a)
        for (int b = 0; b < cnt; ++b)
          if (const double v = in[offset(node) + a * cnt + b]; v != 0) t.emplace_back(first + a, first + b, v);
    }
    A.resize(d.size(), d.size());
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
  };
  build(blocks.data(), g.K);
  build(blocks.data() + size, g.M);
  return g;
}

/// Visits column j of the g-set K and M (both triangles stored) for every free j: `add(pj, rows, k, m, in_m)`
/// with the rows pi <= pj (upper triangle in the partition numbering) of the union of both patterns.
template <class Add>
void for_each_upper_column(const fem::GlobalMatrices& g, const std::vector<Eigen::Index>& g_to_f,
                           const std::vector<Eigen::Index>& f_to_p, Add&& add) {
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> k, m;
  std::vector<char> in_m;
  for (Eigen::Index j = 0; j < g.K.outerSize(); ++j) {
    const Eigen::Index fj = g_to_f[static_cast<std::size_t>(j)];
    if (fj < 0) continue;
    const auto pj = static_cast<PetscInt>(f_to_p[static_cast<std::size_t>(fj)]);
    rows.clear();
    k.clear();
    m.clear();
    in_m.clear();
    SparseMatrixd::InnerIterator a(g.K, j), b(g.M, j);
    while (a || b) {
      Eigen::Index i = 0;
      double kv = 0, mv = 0;
      bool has_m = false;
      if (a && (!b || a.row() <= b.row())) {
        i = a.row();
        kv = a.value();
        if (b && b.row() == i) {
          mv = b.value();
          has_m = true;
          ++b;
        }
        ++a;
      } else {
        i = b.row();
        mv = b.value();
        has_m = true;
        ++b;
      }
      const Eigen::Index fi = g_to_f[static_cast<std::size_t>(i)];
      if (fi < 0) continue;
      const auto pi = static_cast<PetscInt>(f_to_p[static_cast<std::size_t>(fi)]);
      if (pi > pj) continue;
      rows.push_back(pi);
      k.push_back(kv);
      m.push_back(mv);
      in_m.push_back(has_m ? 1 : 0);
    }
    if (!rows.empty()) add(pj, rows, k, m, in_m);
  }
}

/// The distributed MATSBAIJ of K (`mass` false: the union pattern) or M from the rank's g-set matrices.
void build_matrix(const fem::GlobalMatrices& g, const std::vector<Eigen::Index>& g_to_f,
                  const std::vector<Eigen::Index>& f_to_p, PetscInt local_rows, PetscInt n, bool mass, Mat* out) {
  std::vector<PetscInt> r;
  std::vector<PetscScalar> v;
  auto insert = [&](Mat A, bool values) {
    for_each_upper_column(g, g_to_f, f_to_p, [&](PetscInt pj, const std::vector<PetscInt>& rows,
                                                  const std::vector<PetscScalar>& k, const std::vector<PetscScalar>& m,
                                                  const std::vector<char>& in_m) {
      r.clear();
      v.clear();
      for (std::size_t q = 0; q < rows.size(); ++q) {
        if (mass && in_m[q] == 0) continue;
        r.push_back(rows[q]);
        v.push_back(values ? (mass ? m[q] : k[q]) : 0.0);
      }
      if (!r.empty()) SEFLEX_PETSC(MatSetValues(A, static_cast<PetscInt>(r.size()), r.data(), 1, &pj, v.data(), ADD_VALUES));
    });
    SEFLEX_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    SEFLEX_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  };
  detail::OwnedMat pre;
  SEFLEX_PETSC(MatCreate(PETSC_COMM_WORLD, pre.out()));
  SEFLEX_PETSC(MatSetSizes(pre.get(), local_rows, local_rows, n, n));
  SEFLEX_PETSC(MatSetType(pre.get(), MATPREALLOCATOR));
  SEFLEX_PETSC(MatSetUp(pre.get()));
  insert(pre.get(), false);
  SEFLEX_PETSC(MatCreate(PETSC_COMM_WORLD, out));
  SEFLEX_PETSC(MatSetSizes(*out, local_rows, local_rows, n, n));
  SEFLEX_PETSC(MatSetType(*out, MATSBAIJ));
  SEFLEX_PETSC(MatPreallocatorPreallocate(pre.get(), PETSC_TRUE, *out));
  pre.reset();
  SEFLEX_PETSC(MatSetOption(*out, MAT_IGNORE_LOWER_TRIANGULAR, PETSC_TRUE));
  SEFLEX_PETSC(MatSetOption(*out, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  insert(*out, true);
  SEFLEX_PETSC(MatSetOption(*out, MAT_SYMMETRIC, PETSC_TRUE));
}

/// Every rank's `mine`, concatenated in rank order, on every rank.
std::vector<double> allgather(const std::vector<double>& mine) {
  const int size = comm_size();
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size), 0);
  const int my_count = static_cast<int>(mine.size());
  SEFLEX_DEMAND(mine.size() < (std::size_t{1} << 31), "allgather: more than 2^31 values on one rank");
  SEFLEX_DEMAND(MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, PETSC_COMM_WORLD) == MPI_SUCCESS, "MPI_Allgather failed");
  long long total = 0;
  for (int c : counts) total += c;
  SEFLEX_DEMAND(total < (1LL << 31), "allgather: more than 2^31 values in all");
  std::partial_sum(counts.begin(), counts.end() - 1, displs.begin() + 1);
  std::vector<double> all(static_cast<std::size_t>(total));
  SEFLEX_DEMAND(MPI_Allgatherv(mine.data(), my_count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
                               PETSC_COMM_WORLD) == MPI_SUCCESS,
                "MPI_Allgatherv failed");
  return all;
}

/// The sum over the ranks of each rank's matrix A (same size everywhere), on every rank.
SparseMatrixd gather_sum(const SparseMatrixd& A) {
  std::vector<double> mine;  // (row, col, value) triples
  mine.reserve(3 * static_cast<std::size_t>(A.nonZeros()));
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (SparseMatrixd::InnerIterator it(A, j); it; ++it) {
      mine.push_back(static_cast<double>(it.row()));
      mine.push_back(static_cast<double>(j));
      mine.push_back(it.value());
    }
  const std::vector<double> all = allgather(mine);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(all.size() / 3);
  for (std::size_t q = 0; q + 2 < all.size(); q += 3)
    t.emplace_back(static_cast<Eigen::Index>(all[q]), static_cast<Eigen::Index>(all[q + 1]), all[q + 2]);
  SparseMatrixd out(A.rows(), A.cols());
  out.setFromTriplets(t.begin(), t.end());  // duplicates (a node shared by ranks) are summed
  out.makeCompressed();
  return out;
}

/// The whole of A (rows in the partition numbering) in the f numbering, both triangles, on every rank.
SparseMatrixd gather_f(Mat A, const PartitionedSystem& s) {
  PetscInt lo = 0, hi = 0;
  SEFLEX_PETSC(MatGetOwnershipRange(A, &lo, &hi));
  std::vector<double> mine;  // (f row, f col, value) triples
  SEFLEX_PETSC(MatGetRowUpperTriangular(A));
  for (PetscInt p = lo; p < hi; ++p) {
    PetscInt nc = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    SEFLEX_PETSC(MatGetRow(A, p, &nc, &cols, &vals));
    for (PetscInt q = 0; q < nc; ++q) {
      mine.push_back(static_cast<double>(s.p_to_f[static_cast<std::size_t>(p)]));
      mine.push_back(static_cast<double>(s.p_to_f[static_cast<std::size_t>(cols[q])]));
      mine.push_back(vals[q]);
    }
    SEFLEX_PETSC(MatRestoreRow(A, p, &nc, &cols, &vals));
  }
  SEFLEX_PETSC(MatRestoreRowUpperTriangular(A));
  const std::vector<double> all = allgather(mine);
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t q = 0; q + 2 < all.size(); q += 3) {
    const auto i = static_cast<Eigen::Index>(all[q]), j = static_cast<Eigen::Index>(all[q + 1]);
    t.emplace_back(i, j, all[q + 2]);
    if (i != j) t.emplace_back(j, i, all[q + 2]);
  }
  SparseMatrixd out(s.n_free(), s.n_free());
  out.setFromTriplets(t.begin(), t.end());
  out.makeCompressed();
  return out;
}

}  // namespace

PartitionedSystem::PartitionedSystem() : pencil_(std::make_unique<detail::PetscPencil>()) {}
PartitionedSystem::~PartitionedSystem() = default;
PartitionedSystem::PartitionedSystem(PartitionedSystem&&) noexcept = default;
PartitionedSystem& PartitionedSystem::operator=(PartitionedSystem&&) noexcept = default;

SparseMatrixd PartitionedSystem::gather_K_ff() const { return gather_f(pencil_->K.get(), *this); }
SparseMatrixd PartitionedSystem::gather_M_ff() const { return gather_f(pencil_->M.get(), *this); }

std::optional<std::string> partition_refusal(const fem::Model& model, std::optional<int> mpc_set) {
  const std::string card = !model.rbe2.empty()                ? "RBE2"
                           : !model.rbars.empty()             ? "RBAR"
                           : !model.rbe3.empty()              ? "RBE3"
                           : !model.rigid_bodies.empty()      ? fem::rigid_body_card(model.rigid_bodies.front())
                           : !model.rigid_rods.empty()        ? fem::rigid_rod_card(model.rigid_rods.front())
                           : (mpc_set && !model.mpcs.empty()) ? "MPC"
                                                              : "";
  if (!card.empty())
    return "the model has " + card +
           " cards: their dependent dofs are eliminated from the whole model's K (K_ff = T^T K T), which needs it on "
           "every rank";
  if (!model.aset.empty() || !model.omit.empty())
    return std::string("the model has ASET/OMIT cards: the Guyan reduction to the a-set needs the whole K_ff on every rank");
  if (!model.genels.empty())
    return std::string("the model has GENEL cards: their matrices couple any dofs, which the partition of the elements does "
                       "not follow; they need the whole K on every rank");
  if (!model.dmigs.empty())
    return std::string("the model has DMIG cards: their direct matrices are added to the whole K and M on every rank");
  return std::nullopt;
}

PartitionedSystem assemble_partitioned(fem::Model& model, const fem::ConstraintOptions& options,
                                       fem::GlobalMatrices* whole) {
  if (auto why = partition_refusal(model, options.mpc_set)) SEFLEX_DEMAND(false, "assemble_partitioned: " + *why);
  const int rank = comm_rank(), size = comm_size();
  const ElementPartition part = partition_elements(model, size);
  PartitionedSystem s;
  s.total_elements = part.total();
  s.local_elements = part.count(rank);
  fem::GlobalMatrices local = collectively([&] {
    OwnElements own(model, part, rank);
    return fem::assemble(model, fem::assembly_options(model));
  });
  s.dofs = local.dofs;
  {
    // The f-set from the summed diagonal blocks (AUTOSPC looks at nothing else without dependent dofs).
    fem::GlobalMatrices blocks = summed_diagonal_blocks(local);
    const fem::ConstrainedSystem c = fem::apply_constraints(model, blocks, options);
    for (fem::DofStatus st : c.status)
      SEFLEX_DEMAND(st != fem::DofStatus::Dependent, "assemble_partitioned: a dependent dof in a partitioned model");
    s.f_to_g = c.f_to_g;
    // Rows: the free dofs of the nodes rank r owns, in increasing g order, after those of ranks < r.
    std::vector<Eigen::Index> counts(static_cast<std::size_t>(size), 0);
    std::vector<int> owner(s.f_to_g.size());
    for (std::size_t f = 0; f < s.f_to_g.size(); ++f) {
      owner[f] = part.node_owner[static_cast<std::size_t>(s.dofs.node_of_dof(s.f_to_g[f]))];
      ++counts[static_cast<std::size_t>(owner[f])];
    }
    s.row_begin.assign(static_cast<std::size_t>(size) + 1, 0);
    std::partial_sum(counts.begin(), counts.end(), s.row_begin.begin() + 1);
    std::vector<Eigen::Index> next(s.row_begin.begin(), s.row_begin.end() - 1);
    s.f_to_p.resize(s.f_to_g.size());
    s.p_to_f.resize(s.f_to_g.size());
    for (std::size_t f = 0; f < s.f_to_g.size(); ++f) {
      const Eigen::Index p = next[static_cast<std::size_t>(owner[f])]++;
      s.f_to_p[f] = p;
      s.p_to_f[static_cast<std::size_t>(p)] = static_cast<Eigen::Index>(f);
    }
    const auto n = static_cast<PetscInt>(s.f_to_g.size());
    const auto local_rows = static_cast<PetscInt>(s.row_begin[static_cast<std::size_t>(rank) + 1] -
                                                  s.row_begin[static_cast<std::size_t>(rank)]);
    build_matrix(local, c.g_to_f, s.f_to_p, local_rows, n, false, s.pencil().K.out());
    build_matrix(local, c.g_to_f, s.f_to_p, local_rows, n, true, s.pencil().M.out());
    if (whole != nullptr) {
      whole->dofs = s.dofs;
      whole->K = std::move(blocks.K);
      whole->M = gather_sum(local.M);
    }
  }
  return s;
}

}  // namespace seflex::parallel
