#pragma once
// A sparse uniform grid of line points for the distance tests of evenly spaced lines
// (Jobard & Lefer 1997): "is any point of another line within r of p?".
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

class PointGrid {
 public:
  /// Queries are fastest for radii up to the cell size.
  explicit PointGrid(double cellSize);

  /// Adds a point of line `line` at arc length `arc` along it. Recorded in a journal until
  /// commit() or rollback().
  void insert(const Vec3& p, int line, double arc);
  /// Is any point within distance r (strictly less) of p? Points of line `line` count only
  /// when their arc length differs from `arc` by more than `window` (a line may not come back
  /// close to itself, but its neighbours along it are always close).
  bool anyWithin(const Vec3& p, double r, int line = -1, double arc = 0, double window = 0) const;
  /// Keeps the points inserted since the last commit.
  void commit() { journal_.clear(); }
  /// Removes the points inserted since the last commit.
  void rollback();

 private:
  struct Entry {
    Vec3 p;
    int line;
    double arc;
  };
  std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const;
  std::int64_t cell(double x) const;

  double cellSize_;
  std::unordered_map<std::uint64_t, std::vector<Entry>> cells_;
  std::vector<std::uint64_t> journal_;
};

}  // namespace tfd::core
