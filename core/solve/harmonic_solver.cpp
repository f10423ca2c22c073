#include "core/solve/harmonic_solver.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <string>

#include "core/derived_cache.h"
#include "core/error.h"
#include "core/linalg/amg.h"
#include "core/linalg/block_cg.h"

namespace tfd::core {

using linalg::CsrMatrix;

/// What a solve needs besides the values: a function of the mesh, the free set, the matrix
/// rows and the preconditioner options only, so it can be shared by later solvers of the same
/// system (kept for the mesh in core::derivedCache(); it holds no pointer to the mesh, so the
/// cache never keeps a mesh alive).
struct HarmonicSetup {
  std::vector<int> freeVertices;  ///< ascending global ids
  std::vector<int> order;         ///< global vertex of each internal row (a locality order)
  CsrMatrix<double> a;            ///< free × free block
  CsrMatrix<double> coupling;     ///< free × fixed block, columns are global vertex ids
  std::unique_ptr<linalg::AmgPreconditioner> amg;  ///< may reference `a`: never moved
  bool singlePrecision = true;
  double lambdaMaxBound = 0;
  bool ownRows = false;  ///< rows assembled from the mesh by the solver (none were given)

  std::size_t bytes() const {
    return (freeVertices.size() + order.size()) * sizeof(int) + a.bytes() + coupling.bytes() +
           amg->bytes();
  }
};

struct HarmonicSolver::Impl {
  std::shared_ptr<const TetMesh> mesh;
  SolverOptions options;
  std::shared_ptr<const HarmonicSetup> setup;
  bool reused = false;

  void init(std::vector<int> freeVertices, const StiffnessRows* given);
  template <int W, class Get, class Set>
  int solveBlock(Get&& get, Set&& set, const Progress& progress, double* residual) const;
};

namespace {

/// Maps global vertex ids to internal rows (−1 for fixed vertices): a dense table when the
/// free set is a sizeable part of the mesh, binary search in the sorted free list otherwise
/// (set-up cost then scales with the free count only).
class FreeIndex {
 public:
  FreeIndex(const std::vector<int>& free, const std::vector<int>& order, std::size_t vertexCount)
      : free_(free) {
    if (free.size() * 8 >= vertexCount) {
      dense_.assign(vertexCount, -1);
      for (std::size_t r = 0; r < order.size(); ++r) dense_[order[r]] = static_cast<int>(r);
    } else {
      rowOfFree_.resize(free.size());
      for (std::size_t r = 0; r < order.size(); ++r) {
        const auto it = std::lower_bound(free.begin(), free.end(), order[r]);
        rowOfFree_[it - free.begin()] = static_cast<int>(r);
      }
    }
  }
  int operator()(int v) const {
    if (!dense_.empty()) return dense_[v];
    const auto it = std::lower_bound(free_.begin(), free_.end(), v);
    return it != free_.end() && *it == v ? rowOfFree_[it - free_.begin()] : -1;
  }

 private:
  const std::vector<int>& free_;
  std::vector<int> dense_;
  std::vector<int> rowOfFree_;
};

/// Spreads the low 21 bits of x to every third bit (Morton code helper).
std::uint64_t spreadBits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

/// The free vertices in Morton (Z-curve) order of their positions, ties by id: neighbours end
/// up close in memory, which makes the sparse products cache-friendly on meshes whose vertex
/// numbering is not spatially coherent (TetGen's). Deterministic.
std::vector<int> localityOrder(const TetMesh& mesh, const std::vector<int>& free) {
  const Vec3 lo = mesh.boundsMin();
  const Vec3 extent = (mesh.boundsMax() - lo).cwiseMax(1e-300);
  const double scale = static_cast<double>((1 << 21) - 1);
  std::vector<std::pair<std::uint64_t, int>> keyed(free.size());
  linalg::parallelRanges(free.size(), [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const Vec3 q = (mesh.positions()[free[i]] - lo).cwiseQuotient(extent) * scale;
      std::uint64_t code = 0;
      for (int axis = 0; axis < 3; ++axis) {
        const double c = std::clamp(q[axis], 0.0, scale);
        code |= spreadBits(static_cast<std::uint64_t>(c)) << axis;
      }
      keyed[i] = {code, free[i]};
    }
  });
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<int> order(free.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  return order;
}

void checkComponents(const HarmonicSetup& s) {
  const CsrMatrix<double>& a = s.a;
  const CsrMatrix<double>& coupling = s.coupling;
  const std::vector<int>& order = s.order;
  // Union-find over the free-free pattern (which is the mesh graph: zero entries are kept).
  const int n = a.rows;
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  for (int i = 0; i < n; ++i)
    for (int m = a.start[i]; m < a.start[i + 1]; ++m) {
      const int j = a.index[m];
      if (j <= i) continue;
      const int ri = find(i), rj = find(j);
      if (ri != rj) parent[std::max(ri, rj)] = std::min(ri, rj);
    }
  std::vector<unsigned char> anchored(n, 0);
  for (int i = 0; i < n; ++i)
    if (coupling.start[i + 1] > coupling.start[i]) anchored[find(i)] = 1;
  std::vector<int> size(n, 0);
  for (int i = 0; i < n; ++i) ++size[find(i)];
  int badRoot = -1, badComponents = 0;
  for (int i = 0; i < n; ++i)
    if (parent[i] == i && !anchored[i]) {
      if (badRoot < 0) badRoot = i;
      ++badComponents;
    }
  if (badRoot >= 0)
    throw Error("harmonic solve: " + std::to_string(badComponents) +
                " connected part(s) of the mesh have no fixed vertex (e.g. the part with " +
                std::to_string(size[badRoot]) + " vertices containing vertex " +
                std::to_string(order[badRoot]) + "); add a constraint there or fix a vertex of it");
}

/// Builds `s` (its free set and options given): the free and fixed blocks of the rows
/// (`given`, or assembled from the mesh), the locality order and the multigrid hierarchy.
void buildSetup(HarmonicSetup& s, const TetMesh& mesh, const StiffnessRows* given) {
  const std::size_t n = mesh.vertexCount();
  const std::vector<int>& freeVertices = s.freeVertices;
  const int freeCount = static_cast<int>(freeVertices.size());
  std::vector<int>& order = s.order;
  CsrMatrix<double>& a = s.a;
  CsrMatrix<double>& coupling = s.coupling;
  StiffnessRows own;
  const StiffnessRows* rows = given;
  if (rows == nullptr) {
    own = assembleStiffnessRows(mesh, freeVertices);
    rows = &own;
  }
  order = localityOrder(mesh, freeVertices);
  // Row of the source matrix for each internal row.
  std::vector<int> sourceRow(freeCount);
  const bool full = rows->vertices.size() == n;
  for (int i = 0; i < freeCount; ++i) {
    const int v = order[i];
    if (full) {
      sourceRow[i] = v;
    } else {
      const auto it = std::lower_bound(rows->vertices.begin(), rows->vertices.end(), v);
      if (it == rows->vertices.end() || *it != v)
        throw Error("harmonic solve: the stiffness rows lack free vertex " + std::to_string(v));
      sourceRow[i] = static_cast<int>(it - rows->vertices.begin());
    }
  }
  const FreeIndex local(freeVertices, order, n);
  const CsrMatrix<double>& k = rows->matrix;
  // One pass in chunks of rows (each chunk by one task: deterministic), then concatenation.
  constexpr int kRows = 512;
  const int chunkCount = (freeCount + kRows - 1) / kRows;
  struct Split {
    std::vector<int> freeLen, fixedLen, freeIndex, fixedIndex;
    std::vector<double> freeValue, fixedValue;
  };
  std::vector<Split> chunks(chunkCount);
  linalg::parallelRanges(
      chunkCount,
      [&](std::size_t cb, std::size_t ce) {
        for (std::size_t c = cb; c < ce; ++c) {
          Split& out = chunks[c];
          const int begin = static_cast<int>(c) * kRows, end = std::min(freeCount, begin + kRows);
          out.freeIndex.reserve(static_cast<std::size_t>(end - begin) * 16);
          out.freeValue.reserve(static_cast<std::size_t>(end - begin) * 16);
          for (int i = begin; i < end; ++i) {
            if (i + 8 < end) {  // rows are visited in locality order, not memory order
              const int ahead = k.start[sourceRow[i + 8]];
              __builtin_prefetch(k.index.data() + ahead);
              __builtin_prefetch(k.value.data() + ahead);
              __builtin_prefetch(k.value.data() + ahead + 8);
            }
            const std::size_t f0 = out.freeIndex.size(), c0 = out.fixedIndex.size();
            for (int m = k.start[sourceRow[i]]; m < k.start[sourceRow[i] + 1]; ++m) {
              const int j = local(k.index[m]);
              if (j >= 0) {
                out.freeIndex.push_back(j);
                out.freeValue.push_back(k.value[m]);
              } else {
                out.fixedIndex.push_back(k.index[m]);
                out.fixedValue.push_back(k.value[m]);
              }
            }
            out.freeLen.push_back(static_cast<int>(out.freeIndex.size() - f0));
            out.fixedLen.push_back(static_cast<int>(out.fixedIndex.size() - c0));
          }
        }
      },
      1);
  a.rows = a.cols = freeCount;
  coupling.rows = freeCount;
  coupling.cols = static_cast<int>(n);
  a.start.assign(freeCount + 1, 0);
  coupling.start.assign(freeCount + 1, 0);
  std::vector<std::size_t> freeOffset(chunkCount + 1, 0), fixedOffset(chunkCount + 1, 0);
  for (int c = 0, row = 0; c < chunkCount; ++c) {
    freeOffset[c + 1] = freeOffset[c] + chunks[c].freeIndex.size();
    fixedOffset[c + 1] = fixedOffset[c] + chunks[c].fixedIndex.size();
    for (std::size_t r = 0; r < chunks[c].freeLen.size(); ++r, ++row) {
      a.start[row + 1] = a.start[row] + chunks[c].freeLen[r];
      coupling.start[row + 1] = coupling.start[row] + chunks[c].fixedLen[r];
    }
  }
  a.index.resize(freeOffset.back());
  a.value.resize(freeOffset.back());
  coupling.index.resize(fixedOffset.back());
  coupling.value.resize(fixedOffset.back());
  linalg::parallelRanges(
      chunkCount,
      [&](std::size_t cb, std::size_t ce) {
        for (std::size_t c = cb; c < ce; ++c) {
          Split& in = chunks[c];
          std::copy(in.freeIndex.begin(), in.freeIndex.end(), a.index.begin() + freeOffset[c]);
          std::copy(in.freeValue.begin(), in.freeValue.end(), a.value.begin() + freeOffset[c]);
          std::copy(in.fixedIndex.begin(), in.fixedIndex.end(),
                    coupling.index.begin() + fixedOffset[c]);
          std::copy(in.fixedValue.begin(), in.fixedValue.end(),
                    coupling.value.begin() + fixedOffset[c]);
          in = Split{};
        }
      },
      1);
  checkComponents(s);
  linalg::AmgOptions amgOptions;
  amgOptions.singlePrecision = s.singlePrecision;
  amgOptions.fineLambdaMax = s.lambdaMaxBound;
  s.amg = std::make_unique<linalg::AmgPreconditioner>(a, amgOptions);
}

/// Whether `rows` restricted to the set-up's free vertices are exactly its blocks `a` and
/// `coupling` (same entries in the same order, values bitwise equal): then a set-up built
/// from `rows` would be identical to `s`.
bool sameRows(const HarmonicSetup& s, const StiffnessRows& rows, std::size_t vertexCount) {
  const CsrMatrix<double>& k = rows.matrix;
  if (k.cols != static_cast<int>(vertexCount)) return false;
  const bool full = rows.vertices.size() == vertexCount;
  const FreeIndex local(s.freeVertices, s.order, vertexCount);
  std::atomic<bool> same = true;
  linalg::parallelRanges(s.order.size(), [&](std::size_t b, std::size_t e) {
    auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    for (std::size_t i = b; i < e && same.load(std::memory_order_relaxed); ++i) {
      const int v = s.order[i];
      int row = v;
      if (!full) {
        const auto it = std::lower_bound(rows.vertices.begin(), rows.vertices.end(), v);
        if (it == rows.vertices.end() || *it != v) {
          same = false;
          return;
        }
        row = static_cast<int>(it - rows.vertices.begin());
      }
      int pa = s.a.start[i], pc = s.coupling.start[i];
      bool ok = true;
      for (int m = k.start[row]; m < k.start[row + 1] && ok; ++m) {
        const int j = local(k.index[m]);
        if (j >= 0) {
          ok = pa < s.a.start[i + 1] && s.a.index[pa] == j &&
               bits(s.a.value[pa]) == bits(k.value[m]);
          ++pa;
        } else {
          ok = pc < s.coupling.start[i + 1] && s.coupling.index[pc] == k.index[m] &&
               bits(s.coupling.value[pc]) == bits(k.value[m]);
          ++pc;
        }
      }
      if (!ok || pa != s.a.start[i + 1] || pc != s.coupling.start[i + 1]) same = false;
    }
  });
  return same;
}

/// Lookup key of a set-up: the free set and the preconditioner options (the matrix is
/// compared exactly on a hit, see sameRows()).
std::uint64_t setupKey(const std::vector<int>& free, const SolverOptions& options) {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ free.size();
  auto mix = [&h](std::uint64_t x) {
    h ^= x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0xff51afd7ed558ccdULL;
  };
  for (int v : free) mix(static_cast<std::uint32_t>(v));
  mix(options.singlePrecisionPreconditioner);
  mix(std::bit_cast<std::uint64_t>(options.lambdaMaxBound));
  return h;
}

}  // namespace

void HarmonicSolver::Impl::init(std::vector<int> freeVertices, const StiffnessRows* given) {
  const std::size_t n = mesh->vertexCount();
  if (freeVertices.empty()) throw Error("harmonic solve: every vertex is fixed, nothing to solve");
  if (given && given->matrix.cols != static_cast<int>(n))
    throw Error("harmonic solve: the stiffness rows belong to another mesh");
  const std::uint64_t key = setupKey(freeVertices, options);
  if (options.reuseSetup) {
    // A set-up kept by an earlier solver of the same mesh is used only when it is exactly the
    // one this solver would build: same free set and options, and the same matrix rows
    // (compared entry by entry; rows the solver assembles itself are a function of the mesh
    // and the free set).
    const std::function<bool(const HarmonicSetup&)> fits = [&](const HarmonicSetup& s) {
      if (s.freeVertices != freeVertices ||
          s.singlePrecision != options.singlePrecisionPreconditioner ||
          std::bit_cast<std::uint64_t>(s.lambdaMaxBound) !=
              std::bit_cast<std::uint64_t>(options.lambdaMaxBound))
        return false;
      return given == nullptr ? s.ownRows : sameRows(s, *given, n);
    };
    if (auto found = derivedCache().find<HarmonicSetup>(mesh, key, fits)) {
      setup = std::move(found);
      reused = true;
      return;
    }
  }
  auto built = std::make_shared<HarmonicSetup>();
  built->freeVertices = std::move(freeVertices);
  built->singlePrecision = options.singlePrecisionPreconditioner;
  built->lambdaMaxBound = options.lambdaMaxBound;
  built->ownRows = given == nullptr;
  buildSetup(*built, *mesh, given);
  setup = built;
  if (options.reuseSetup) derivedCache().store<HarmonicSetup>(mesh, key, setup, built->bytes());
}

template <int W, class Get, class Set>
int HarmonicSolver::Impl::solveBlock(Get&& get, Set&& set, const Progress& progress,
                                     double* residual) const {
  constexpr int S = W;  // block vector stride
  const std::vector<int>& order = setup->order;
  const CsrMatrix<double>& a = setup->a;
  const CsrMatrix<double>& coupling = setup->coupling;
  const std::size_t nf = order.size();
  std::vector<double> b(nf * S, 0.0), x(nf * S, 0.0);
  linalg::parallelRanges(nf, [&](std::size_t bg, std::size_t e) {
    for (std::size_t i = bg; i < e; ++i) {
      double sum[W] = {};
      double value[W];
      for (int m = coupling.start[i]; m < coupling.start[i + 1]; ++m) {
        get(coupling.index[m], value);
        for (int c = 0; c < W; ++c) sum[c] -= coupling.value[m] * value[c];
      }
      for (int c = 0; c < W; ++c) b[i * S + c] = sum[c];
      get(order[i], value);
      for (int c = 0; c < W; ++c) x[i * S + c] = value[c];
    }
  });
  // Only the values the solve reads are checked (free vertices and their fixed neighbours),
  // so a region solve stays proportional to the region.
  bool finite = true;
  for (std::size_t i = 0; i < nf * S && finite; ++i)
    finite = std::isfinite(b[i]) && std::isfinite(x[i]);
  if (!finite) {
    double value[W];
    auto check = [&](int v) {
      get(v, value);
      for (int c = 0; c < W; ++c)
        if (!std::isfinite(value[c]))
          throw Error("harmonic solve: the value at vertex " + std::to_string(v) +
                      " is not finite");
    };
    for (std::size_t i = 0; i < nf; ++i) {
      check(order[i]);
      for (int m = coupling.start[i]; m < coupling.start[i + 1]; ++m) check(coupling.index[m]);
    }
    throw Error("harmonic solve: the right-hand side overflows (values too large)");
  }
  linalg::CgOptions cg;
  cg.tolerance = options.tolerance;
  cg.maxIterations = options.maxIterations;
  const linalg::CgResult result =
      linalg::blockPcg<S>(a, b.data(), x.data(), *setup->amg, cg, progress);
  linalg::parallelRanges(nf, [&](std::size_t bg, std::size_t e) {
    for (std::size_t i = bg; i < e; ++i) set(order[i], x.data() + i * S);
  });
  if (residual) *residual = result.relativeResidual;
  return result.iterations;
}

HarmonicSolver::HarmonicSolver() : impl_(std::make_unique<Impl>()) {}

namespace {
std::vector<int> freeFromMask(const TetMesh& mesh, const std::vector<unsigned char>& fixed) {
  if (fixed.size() != mesh.vertexCount())
    throw Error("harmonic solve: the fixed-vertex mask has " + std::to_string(fixed.size()) +
                " entries but the mesh has " + std::to_string(mesh.vertexCount()) + " vertices");
  std::vector<int> free;
  for (std::size_t v = 0; v < fixed.size(); ++v)
    if (!fixed[v]) free.push_back(static_cast<int>(v));
  return free;
}
}  // namespace

HarmonicSolver::HarmonicSolver(std::shared_ptr<const TetMesh> mesh,
                               std::vector<unsigned char> fixed, SolverOptions options)
    : impl_(std::make_unique<Impl>()) {
  if (!mesh) throw Error("harmonic solve: no mesh");
  impl_->mesh = std::move(mesh);
  impl_->options = options;
  impl_->init(freeFromMask(*impl_->mesh, fixed), nullptr);
}

HarmonicSolver::HarmonicSolver(std::shared_ptr<const TetMesh> mesh,
                               std::vector<unsigned char> fixed, const StiffnessRows& stiffness,
                               SolverOptions options)
    : impl_(std::make_unique<Impl>()) {
  if (!mesh) throw Error("harmonic solve: no mesh");
  impl_->mesh = std::move(mesh);
  impl_->options = options;
  impl_->init(freeFromMask(*impl_->mesh, fixed), &stiffness);
}

HarmonicSolver HarmonicSolver::forRegion(std::shared_ptr<const TetMesh> mesh,
                                         std::vector<int> freeVertices, SolverOptions options) {
  if (!mesh) throw Error("harmonic solve: no mesh");
  const int n = static_cast<int>(mesh->vertexCount());
  for (std::size_t i = 0; i < freeVertices.size(); ++i) {
    if (freeVertices[i] < 0 || freeVertices[i] >= n)
      throw Error("harmonic solve: region vertex " + std::to_string(freeVertices[i]) +
                  " out of range (mesh has " + std::to_string(n) + " vertices)");
    if (i > 0 && freeVertices[i] <= freeVertices[i - 1])
      throw Error("harmonic solve: region vertices must be ascending and unique");
  }
  HarmonicSolver solver;
  solver.impl_->mesh = std::move(mesh);
  solver.impl_->options = options;
  solver.impl_->init(std::move(freeVertices), nullptr);
  return solver;
}

HarmonicSolver::~HarmonicSolver() = default;
HarmonicSolver::HarmonicSolver(HarmonicSolver&&) noexcept = default;
HarmonicSolver& HarmonicSolver::operator=(HarmonicSolver&&) noexcept = default;

template <bool WithTrace>
SolveResult HarmonicSolver::solveTensors(std::vector<Tensor> values,
                                         const Progress& progress) const {
  if (values.size() != impl_->mesh->vertexCount())
    throw Error("harmonic solve: expected " + std::to_string(impl_->mesh->vertexCount()) +
                " tensors, got " + std::to_string(values.size()));
  SolveResult result;
  auto get = [&](int v, double* out) {
    const auto c = values[v].vec5();
    for (int k = 0; k < 5; ++k) out[k] = c[k];
    if constexpr (WithTrace) out[5] = values[v].trace();
  };
  auto set = [&](int v, const double* in) {
    Tensor t = Tensor::fromVec5({in[0], in[1], in[2], in[3], in[4]});
    if constexpr (WithTrace) {
      const double third = in[5] / 3;
      t.xx += third, t.yy += third, t.zz += third;
    }
    values[v] = t;
  };
  constexpr int kColumns = WithTrace ? 6 : 5;
  result.iterations = impl_->solveBlock<kColumns>(get, set, progress, &result.relativeResidual);
  result.values = std::move(values);
  return result;
}

SolveResult HarmonicSolver::solve(std::vector<Tensor> values, const Progress& progress) const {
  return solveTensors<false>(std::move(values), progress);
}

SolveResult HarmonicSolver::solveWithTrace(std::vector<Tensor> values,
                                           const Progress& progress) const {
  return solveTensors<true>(std::move(values), progress);
}

int HarmonicSolver::solveColumns(std::span<double> values, int width, const Progress& progress,
                                 double* relativeResidual) const {
  if (width < 1 || width > 6)
    throw Error("harmonic solve: " + std::to_string(width) + " columns (1 to 6 supported)");
  if (values.size() != impl_->mesh->vertexCount() * static_cast<std::size_t>(width))
    throw Error("harmonic solve: expected " + std::to_string(impl_->mesh->vertexCount()) + " × " +
                std::to_string(width) + " values, got " + std::to_string(values.size()));
  auto run = [&]<int W>() {
    auto get = [&](int v, double* out) {
      for (int c = 0; c < W; ++c) out[c] = values[static_cast<std::size_t>(v) * W + c];
    };
    auto set = [&](int v, const double* in) {
      for (int c = 0; c < W; ++c) values[static_cast<std::size_t>(v) * W + c] = in[c];
    };
    return impl_->solveBlock<W>(get, set, progress, relativeResidual);
  };
  switch (width) {
    case 1:
      return run.operator()<1>();
    case 2:
      return run.operator()<2>();
    case 3:
      return run.operator()<3>();
    case 4:
      return run.operator()<4>();
    case 5:
      return run.operator()<5>();
    default:
      return run.operator()<6>();
  }
}

const TetMesh& HarmonicSolver::mesh() const { return *impl_->mesh; }
std::size_t HarmonicSolver::freeCount() const { return impl_->setup->freeVertices.size(); }
const std::vector<int>& HarmonicSolver::freeVertices() const { return impl_->setup->freeVertices; }
const linalg::AmgPreconditioner& HarmonicSolver::preconditioner() const {
  return *impl_->setup->amg;
}
bool HarmonicSolver::setupReused() const { return impl_->reused; }

}  // namespace tfd::core
