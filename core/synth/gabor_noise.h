#pragma once
// Solid anisotropic Gabor noise whose kernels follow a tensor field (paper §8.1; Lagae et al.
// 2009, random-phase kernels of Lagae & Drettakis 2011).
//
// Noise N(x) = Σ_i g_i(x − x_i) over impulses x_i of a Poisson process of density λ, with
//     g_i(d) = exp(−π a² |d|²) · cos(2π f_i·d + φ_i)   for |d| < r, 0 beyond,
// a uniform random phase φ_i (so the sign of an eigenvector does not matter) and a frequency
// vector f_i = F u_i whose direction u_i is chosen from the field's tensor at the impulse centre
// x_i (gaborDirection). Each kernel is one fixed function, so N is continuous even where the
// eigenvectors jump (across degenerate curves).
//   a = F (2^B − 1)/(2^B + 1) √(π / ln 2)   (B the bandwidth in octaves, as OSL's gabornoise)
//   r = √(−ln 0.05 / π) / a                 (the envelope is 5 % at the truncation radius)
//   λ = n / ((4/3) π r³)                    (n impulses per kernel volume)
//   Var N = λ · ½ (2a²)^(−3/2) · P(χ²₃ ≤ 4π a² r²)   (Campbell's theorem; ½ from the random
//                                              phase, the χ² term from the truncation)
// Impulses: space is cut into cubic cells of side r anchored at the world origin; the impulses
// of cell c are drawn from a generator seeded by a hash of (seed, c), so the noise at a world
// point does not depend on the voxel grid, the thread count or the order of work.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/progress.h"
#include "core/scalar_volume.h"
#include "core/tensor.h"
#include "core/tensor_field.h"

namespace tfd::core {

/// Which eigenvector orients the kernels.
enum class NoiseOrientation {
  Auto,    ///< fibres along e1 where the tensor is linear, sheets normal to e3 where planar
  Major,   ///< fibres along e1 everywhere
  Medium,  ///< fibres along e2 everywhere
  Minor,   ///< sheets normal to e3 everywhere
};

/// What a voxel of the output volume holds (σ² the variance above).
enum class NoiseRange {
  Positive,  ///< min(1, max(0, N) / 3σ): the crests, empty troughs (a fog volume's fibres)
  Unit,      ///< clamp(½ + N / 6σ, 0, 1): both signs as grey levels (images)
  Signed,    ///< N / σ: mean 0, variance 1
};

struct GaborNoiseOptions {
  double frequency = 8;           ///< F, cycles per world unit
  double bandwidth = 1;           ///< B, octaves
  double impulsesPerKernel = 16;  ///< n
  std::uint64_t seed = 0;
  NoiseOrientation orientation = NoiseOrientation::Auto;
  NoiseRange range = NoiseRange::Positive;
};

/// The constants of the formulas above.
struct GaborKernelShape {
  double a = 0;         ///< Gaussian width
  double radius = 0;    ///< truncation radius r (also the cell size)
  double density = 0;   ///< λ, impulses per unit volume
  double variance = 0;  ///< Var N
};

/// Throws core::Error naming the option when frequency, bandwidth or impulses per kernel is not
/// a finite positive number (impulses per kernel at most 128).
GaborKernelShape gaborKernelShape(const GaborNoiseOptions& options);

/// How strongly the kernels are anisotropic is blended with the shape of the tensor, from its
/// eigenvalues λ1 ≥ λ2 ≥ λ3 (trace ignored): c_l = (λ1 − λ2)/(λ1 − λ3), c_p = (λ2 − λ3)/(λ1 − λ3),
/// c_l + c_p = 1. The confidence of the chosen structure is c_l (major), c_p (minor),
/// 2 min(c_l, c_p) (medium), |c_l − c_p| (auto: fibres where c_l > c_p, sheets otherwise), and
/// β = min(1, confidence / 0.5). With an isotropic unit vector v:
///   fibres along e:     u = normalize(v − β (v·e) e)        (β = 1: u uniform on the circle ⊥ e)
///   sheets normal to n: u = normalize(v − β (v − (v·n) n))  (β = 1: u = ±n)
/// so u is isotropic (u = v) where the eigenvector is undefined: near degenerate curves of the
/// other kind in the fixed modes, at the linear–planar transition in auto, and for tensors whose
/// eigenvalues are all equal.
Vec3 gaborDirection(const Tensor& t, NoiseOrientation mode, const Vec3& v);

/// One kernel: its centre, its angular frequency vector 2π f_i, its phase.
struct GaborImpulse {
  Vec3 centre = Vec3::Zero();
  Vec3 omega = Vec3::Zero();
  double phase = 0;
};

/// The impulses of every cell within reach of a world box, oriented by a field. Impulses whose
/// centre lies outside the mesh take the tensor of the nearest boundary vertex, so the noise
/// keeps its statistics up to the boundary.
class GaborNoise {
 public:
  /// Throws like gaborKernelShape, and core::Error naming the frequency when the box would need
  /// more than 2e7 kernels; core::Cancelled when `progress` is cancelled.
  GaborNoise(const TensorField& field, const GaborNoiseOptions& options, const Vec3& boxMin,
             const Vec3& boxMax, const Progress& progress = Progress());

  const GaborKernelShape& shape() const { return shape_; }
  std::size_t impulseCount() const { return impulses_.size(); }

  /// N(p) evaluated directly from every kernel within reach (p inside the box given above).
  double at(const Vec3& p) const;

  /// N at the centre of every voxel of `grid` whose mask entry is set (0 elsewhere), x fastest.
  /// The grid's centres must lie inside the box. Splats each impulse into blocks of 16³
  /// voxels with separable recurrences (no exp or cos per voxel); each voxel sums its kernels
  /// in the same order as at(), so the result does not depend on the thread count.
  /// `evaluations` (optional) receives the number of kernel evaluations.
  std::vector<double> sample(const VoxelGrid& grid, const std::vector<std::uint8_t>& mask,
                             const Progress& progress = Progress(),
                             std::size_t* evaluations = nullptr) const;

 private:
  std::array<int, 3> cellOf(const Vec3& p) const;  ///< clamped to the cell box
  std::size_t cellIndex(int x, int y, int z) const {
    return (std::size_t(z - cellMin_[2]) * cellDims_[1] + std::size_t(y - cellMin_[1])) *
               cellDims_[0] +
           std::size_t(x - cellMin_[0]);
  }

  GaborNoiseOptions options_;
  GaborKernelShape shape_;
  std::array<int, 3> cellMin_{0, 0, 0}, cellDims_{0, 0, 0};
  std::vector<std::size_t> cellStart_;  ///< impulses of cell c: [cellStart_[c], cellStart_[c+1])
  std::vector<GaborImpulse> impulses_;
};

struct GaborNoiseStats {
  std::size_t impulses = 0;
  std::size_t kernelEvaluations = 0;
  std::size_t insideVoxels = 0;
  GaborKernelShape shape;
};

/// The noise of `field` on `grid`: mask (insideMask), impulses, sampling, then the range
/// mapping. Values outside the mask are 0.
ScalarVolume gaborNoiseVolume(const TensorField& field, const VoxelGrid& grid,
                              const GaborNoiseOptions& options,
                              const Progress& progress = Progress(),
                              GaborNoiseStats* stats = nullptr);

}  // namespace tfd::core
