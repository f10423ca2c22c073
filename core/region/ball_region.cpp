#include "core/region/ball_region.h"

#include <tbb/global_control.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <thread>
#include <utility>

#include "core/error.h"
#include "core/region/bucket_queue.h"
#include "core/region/tet_set.h"

namespace tfd::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Bucket width of the fronts' queues: a two-hundredth of the mean edge length. The pop order
/// does not depend on it; narrow buckets keep each bucket's heap small (measured on the 1M-tet
/// torus: the distance front 6 % faster than with a fiftieth, which beat a quarter).
double bucketWidth(const TetMesh& mesh) { return std::max(0.005 * mesh.meanEdgeLength(), 1e-300); }

/// The centroid distance of tetDistances(), computed on demand: the front is a label-correcting
/// Dijkstra over face-adjacent tets (a tet takes the distance to its neighbour's source when
/// that is shorter and within the bound), whose pops can pause and resume without changing
/// their order, so the distances are those of the full run. A pop at key k > P only gives
/// distances > P − margin (margin ≥ any face neighbours' centroid distance: half the longest
/// edge), so once every key ≤ P is popped, a distance ≤ P − margin is final. Region growing
/// asks only for the tets next to its set, so the front stays one layer ahead of it and the
/// cost follows the grown set, not the bound.
///
/// The same rule lets the front run ahead in a thread of its own (run()) while the growth reads
/// distances as they become final (settledAt()): the front publishes P − margin after each
/// step, and a distance read at most that is final. The pops, and so every distance, are those
/// of the sequential run; the growth only waits for them.
class DistanceFront {
 public:
  /// A tet's distance and the source it is measured to, side by side: a pop and a
  /// relaxation read both (one cache miss on a random tet id instead of two).
  struct Label {
    double d = kInf;
    int source = -1;
  };
  /// `margin`: frontMargin(mesh). `recycled`: the labels of a finished front of the same mesh
  /// (takeLabels()), reset and reused instead of fresh memory.
  DistanceFront(const TetMesh& mesh, const TetRows& rows, std::span<const int> sources,
                double bound, double margin, std::vector<Label> recycled = {})
      : rows_(rows),
        bound_(bound),
        margin_(margin),
        step_(std::max(mesh.meanEdgeLength(), 1e-300)),
        label_(std::move(recycled)),
        heap_(bucketWidth(mesh)) {
    label_.assign(mesh.tetCount(), Label{});
    for (int s : sources) {
      if (label_[s].d == 0) continue;
      label_[s] = {0.0, s};
      heap_.emplace(0.0, s);
    }
  }

  /// The final distance of tet t (infinity beyond the bound), advancing the front as needed.
  double at(int t, const Progress& progress) {
    while (!(label_[t].d <= popped_ - margin_) && !heap_.empty())
      advance(std::max(popped_, heap_.top().first) + step_, progress);
    return label_[t].d;
  }
  void settleAll(const Progress& progress) { advance(kInf, progress); }
  ~DistanceFront() { stop(); }

  /// Advances the front in a thread of its own, for settledAt(), publishing its progress
  /// after every `stride` mean edge lengths: short strides when the growth keeps up with the
  /// front and waits for it, long ones when it lags behind (fewer writes to a line it reads).
  void run(const Progress& progress, double stride) {
    thread_ = std::thread([this, &progress, stride] {
      try {
        while (!stopping_.load(std::memory_order_relaxed) && !heap_.empty()) {
          advance(std::max(popped_, heap_.top().first) + stride * step_, progress);
          final_.store(popped_ - margin_, std::memory_order_release);
        }
      } catch (...) {
        error_ = std::current_exception();
        failed_.store(true, std::memory_order_release);
      }
      final_.store(kInf, std::memory_order_release);
    });
  }
  /// The final distance of tet t, waiting for the front of run() to settle it; rethrows what
  /// stopped the front (a cancellation).
  double settledAt(int t) {
    for (;;) {
      const double bound = final_.load(std::memory_order_acquire);
      if (failed_.load(std::memory_order_acquire)) {
        stop();
        std::rethrow_exception(error_);
      }
      // Distances only decrease and a final one was stored before `bound` was published.
      const double d = std::atomic_ref<double>(label_[t].d).load(std::memory_order_relaxed);
      if (d <= bound) return d;
      std::this_thread::yield();
    }
  }
  /// Stops and joins the thread of run(), if any.
  void stop() {
    stopping_.store(true, std::memory_order_relaxed);
    if (thread_.joinable()) thread_.join();
  }
  /// The labels, for a later front (stops the thread of run() first).
  std::vector<Label> takeLabels() && {
    stop();
    return std::move(label_);
  }
  /// The distance of every tet (settleAll() first).
  std::vector<double> release() const {
    std::vector<double> d(label_.size());
    for (std::size_t t = 0; t < d.size(); ++t) d[t] = label_[t].d;
    return d;
  }

 private:
  /// Pops every key ≤ upTo.
  void advance(double upTo, const Progress& progress) {
    while (!heap_.empty() && heap_.top().first <= upTo) {
      const auto [dt, t] = heap_.top();
      heap_.pop();
      if (!heap_.empty()) {
        // Loads ahead, two pops deep: the neighbours of the next pop's tet (its row was asked
        // for one pop earlier, as the one after next) and the row of the pop after it. The
        // relaxations below then find their rows and labels in cache.
        const int next = heap_.top().second;
        for (int m : rows_[next].neighbours) {
          if (m < 0) continue;
          __builtin_prefetch(&label_[m]);
          rows_.prefetch(m);
        }
        if (const auto* after = heap_.second()) {
          __builtin_prefetch(&label_[after->second]);
          rows_.prefetch(after->second);
        }
      }
      const Label here = label_[t];
      if (dt > here.d) continue;
      if (++steps_ % 8192 == 0) progress.throwIfCancelled();
      const Vec3 origin = rows_[here.source].centroid;
      for (int n : rows_[t].neighbours) {
        if (n < 0) continue;
        Label& there = label_[n];
        if (there.d == 0) continue;
        const double dn = (rows_[n].centroid - origin).norm();
        if (dn <= bound_ && dn < there.d) {
          // Read by settledAt() while run() writes: an atomic store (a plain one on x86).
          std::atomic_ref<double>(there.d).store(dn, std::memory_order_relaxed);
          there.source = here.source;
          heap_.emplace(dn, n);
        }
      }
    }
    popped_ = heap_.empty() ? kInf : upTo;
  }

  const TetRows& rows_;
  double bound_, margin_, step_, popped_ = -kInf;
  std::vector<Label> label_;
  BucketQueue heap_;
  std::size_t steps_ = 0;
  std::thread thread_;
  std::atomic<double> final_ = -kInf;  ///< run(): every distance ≤ this is final
  std::atomic<bool> stopping_ = false, failed_ = false;
  std::exception_ptr error_;
};

/// Half the longest edge: at least the centroid distance of any two face neighbours.
double frontMargin(const TetMesh& mesh) {
  double longest = 0;
  for (const auto& e : mesh.edges())
    longest = std::max(longest, (mesh.positions()[e[0]] - mesh.positions()[e[1]]).norm());
  return 0.5 * longest;
}

/// Whether a second thread may run the distance front beside the growth (not when the
/// process, or the calling task arena, is limited to one thread).
bool frontThreadAllowed() {
  return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1 &&
         tbb::this_task_arena::max_concurrency() > 1;
}

/// Adds tets nearest first while they keep the set a ball: candidates are the face neighbours
/// of the set; a candidate that fails the simple-tet test waits ("deferred") until a tet next
/// to it joins. `key` gives a candidate's distance (infinite: never a candidate).
/// `Key`: double(int tet); `OnAdd`: void(int tet), called for every tet added.
template <class Key, class OnAdd>
class Grower {
 public:
  enum State : unsigned char { None, Queued, Deferred };
  Grower(TetSet& set, const std::vector<unsigned char>& forbidden, Key key, OnAdd onAdd)
      : set_(set),
        mesh_(set.mesh()),
        forbidden_(forbidden),
        key_(std::move(key)),
        onAdd_(std::move(onAdd)),
        state_(mesh_.tetCount(), None),
        deferredAt_(mesh_.vertexCount(), 0),
        heap_(bucketWidth(mesh_)) {}

  void add(int t) {
    set_.add(t);
    onAdd_(t);
    for (int n : set_.neighbours(t))
      if (n >= 0 && !set_.contains(n) && state_[n] == None) queue(n);
    // A deferred tet's contact with the set changes only when a tet sharing one of its
    // vertices joins: re-check those (deferredAt_ skips the vertices with none). One that
    // still cannot join stays deferred: the next join beside it checks it again, so it is
    // queued at the last change before its turn, as if it had been queued and tested then.
    for (int v : mesh_.tets()[t]) {
      if (deferredAt_[v] == 0) continue;
      for (int n : mesh_.vertexTets(v))
        if (state_[n] == Deferred && !forbidden_[n] && !set_.contains(n) && set_.canAdd(n))
          requeue(n);
    }
  }
  void queueNeighboursOfSet(const std::vector<int>& members) {
    for (int t : members)
      for (int n : set_.neighbours(t))
        if (n >= 0 && !set_.contains(n) && state_[n] == None) queue(n);
  }
  /// Runs until `done()` or no candidate is left; returns whether done() held.
  template <class Done>
  bool run(Done&& done, const Progress& progress) {
    std::size_t steps = 0;
    while (!done()) {
      if (heap_.empty()) return false;
      if (++steps % 4096 == 0) progress.throwIfCancelled();
      const auto [d, t] = heap_.top();
      heap_.pop();
      if (!heap_.empty()) {  // the next candidate, loaded while this one is tested and added
        const int next = heap_.top().second;
        __builtin_prefetch(&state_[next]);
        __builtin_prefetch(&forbidden_[next]);
        set_.prefetch(next);
      }
      if (state_[t] != Queued || set_.contains(t)) continue;
      if (forbidden_[t]) {
        state_[t] = Deferred;  // never re-queued: only non-forbidden tets are re-checked
        ++forbiddenMet_;
        if (blockingTet_ < 0) blockingTet_ = t, blockingDistance_ = d;
        continue;
      }
      if (set_.canAdd(t)) {
        state_[t] = None;
        add(t);
        ++added_;
      } else {
        defer(t);
      }
    }
    return true;
  }
  std::size_t added() const { return added_; }
  std::size_t forbiddenMet() const { return forbiddenMet_; }
  int blockingTet() const { return blockingTet_; }
  double blockingDistance() const { return blockingDistance_; }
  std::size_t deferred() const {
    std::size_t n = 0;
    for (std::size_t t = 0; t < state_.size(); ++t)
      n += state_[t] == Deferred && !forbidden_[t] && !set_.contains(int(t));
    return n;
  }

 private:
  void queue(int n) {
    const double k = key_(n);
    if (!(k < kInf)) return;
    state_[n] = Queued;
    heap_.emplace(k, n);
  }
  void defer(int n) {
    state_[n] = Deferred;
    for (int v : mesh_.tets()[n]) ++deferredAt_[v];
  }
  void requeue(int n) {
    for (int v : mesh_.tets()[n]) --deferredAt_[v];
    state_[n] = None;
    queue(n);
    if (state_[n] == None) defer(n);  // no finite key: stays deferred
  }

  TetSet& set_;
  const TetMesh& mesh_;
  const std::vector<unsigned char>& forbidden_;
  Key key_;
  OnAdd onAdd_;
  std::vector<unsigned char> state_;
  std::vector<int> deferredAt_;  ///< deferred non-forbidden tets around each vertex
  BucketQueue heap_;
  std::size_t added_ = 0, forbiddenMet_ = 0;
  int blockingTet_ = -1;
  double blockingDistance_ = 0;
};

std::string lengthText(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", d);
  return buf;
}

}  // namespace

/// How many tets ahead the shrink starts loading a tet's rows (and half as many, what they
/// point to).
constexpr std::size_t kShrinkAhead = 16;

std::string shrinkBall(TetSet& set, std::vector<std::pair<double, int>> keyed,
                       const Progress& progress) {
  // Farthest first, ties by id (a total order: the parallel sort's result is unique).
  tbb::parallel_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  std::vector<int> order(keyed.size());  // the ids alone: every sweep reads them
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  if (order.size() * 8 >= set.mesh().tetCount()) set.countAllEdges();
  // Whether a tet may leave depends only on the tets around its vertices (and on the set's
  // size, which only shrinks, so a refusal stays one): a tet refused once is tested again only
  // after a tet sharing a vertex with it left. The removals are those of testing every tet in
  // every sweep, in the same order.
  // A vertex's count of tets that left around it, summed over a tet's corners, changes exactly
  // when such a tet left: the sum at a refusal marks the refusal as current (4 writes per
  // removal instead of one per tet around its corners).
  const TetMesh& mesh = set.mesh();
  std::vector<std::uint32_t> leftAround(mesh.vertexCount(), 0);
  std::vector<std::uint32_t> refusedAt(mesh.tetCount(), 0);  // corner sum + 1; 0: not refused
  auto cornerSum = [&](int t) {
    std::uint32_t sum = 1;
    for (int v : mesh.tets()[t]) sum += leftAround[v];
    return sum;
  };
  // A tet that left never returns: each sweep keeps only the tets still in the set, in order
  // (late sweeps remove a few dozen tets each and would otherwise rescan every id).
  std::size_t removed = 0;
  for (int sweep = 0; sweep < 64; ++sweep) {
    std::size_t now = 0, kept = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
      // The order is known ahead and scattered over a shell: load each tet's rows, then what
      // its tests read through them, before its turn.
      if (i + kShrinkAhead < order.size()) {
        set.prefetch(order[i + kShrinkAhead]);
        __builtin_prefetch(&refusedAt[order[i + kShrinkAhead]]);
      }
      if (i + kShrinkAhead / 2 < order.size()) set.prefetchAround(order[i + kShrinkAhead / 2]);
      const int t = order[i];
      const std::uint32_t sum = cornerSum(t);
      if (refusedAt[t] != sum) {  // else refused, and nothing changed around it since
        if (set.canRemove(t)) {
          set.remove(t), ++now;
          for (int v : mesh.tets()[t]) ++leftAround[v];
          continue;
        }
        refusedAt[t] = sum;
      }
      order[kept++] = t;
    }
    order.resize(kept);
    progress.throwIfCancelled();
    removed += now;
    if (now == 0)
      return "removed " + std::to_string(removed) +
             " tets; every other non-target tet is needed to keep a ball";
  }
  return "removed " + std::to_string(removed) + " tets (stopped after 64 sweeps)";
}

std::vector<double> tetDistances(const TetMesh& mesh, std::span<const int> sources, double bound,
                                 const Progress& progress) {
  const TetRows rows(mesh);
  DistanceFront front(mesh, rows, sources, bound, frontMargin(mesh));
  front.settleAll(progress);
  return front.release();
}

BallRegion growBallRegion(const TetMesh& mesh, std::span<const int> seedSpan,
                          const std::vector<unsigned char>& forbidden,
                          const BallRegionOptions& options, const Progress& progress) {
  std::vector<int> seeds(seedSpan.begin(), seedSpan.end());
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  if (seeds.empty()) throw Error("region growing: no seed tets");
  if (seeds.front() < 0 || seeds.back() >= int(mesh.tetCount()))
    throw Error("region growing: seed tet id out of range");
  if (forbidden.size() != mesh.tetCount())
    throw Error("region growing: forbidden flags do not match the mesh");
  BallRegion r;
  std::vector<unsigned char> isSeed(mesh.tetCount(), 0);
  for (int s : seeds) isSeed[s] = 1;

  // Step 1: distances to the seeds within a generous bound; beyond it the key continues with
  // the distance to the seeds' centre, so growth can always go on.
  const double bound1 = std::max(options.distance, 8 * mesh.meanEdgeLength());
  TetSet set(mesh);
  const TetRows& rows = set.rows();
  const double margin = frontMargin(mesh);
  DistanceFront d1(mesh, rows, seeds, bound1, margin);
  Vec3 centre = Vec3::Zero();
  for (int s : seeds) centre += rows[s].centroid;
  centre /= double(seeds.size());
  // The front runs ahead in a second thread, as in step 3 below, until the shrink's keys are
  // read. It settles more tets than the growth takes (both sides of the targets), so the growth
  // waits for it: it publishes often.
  const bool threaded1 = frontThreadAllowed();
  if (threaded1) d1.run(progress, 1.0 / 16);
  auto key1 = [&](int t) {
    const double d = threaded1 ? d1.settledAt(t) : d1.at(t, progress);
    return d < kInf ? d : bound1 + (rows[t].centroid - centre).norm();
  };
  std::size_t seedsIn = 0;
  {
    Grower grower(set, forbidden, key1, [&](int t) { seedsIn += isSeed[t]; });
    if (!forbidden[seeds.front()]) grower.add(seeds.front());
    auto allSeedsIn = [&] { return seedsIn == seeds.size(); };
    r.complete = seedsIn > 0 && grower.run(allSeedsIn, progress);
    r.blockingTet = grower.blockingTet();
    r.blockingDistance = grower.blockingDistance();
    r.grownTets = set.size();
    if (r.complete) {
      r.growStop = "all " + std::to_string(seeds.size()) + " target tets inside a ball of " +
                   std::to_string(set.size()) + " tets";
    } else {
      for (int s : seeds)
        if (!set.contains(s)) r.missingSeeds.push_back(s);
      r.growStop =
          std::to_string(r.missingSeeds.size()) + " of " + std::to_string(seeds.size()) +
          " target tets cannot join a ball: " +
          (grower.forbiddenMet() > 0
               ? std::to_string(grower.forbiddenMet()) + " tets on the way hold another curve"
               : std::string("no tet left that keeps the region a ball"));
      r.tets = set.tets();
      return r;
    }
  }

  // Step 2.
  std::vector<std::pair<double, int>> keyed;
  for (int t : set.tets())
    if (!isSeed[t]) keyed.emplace_back(key1(t), t);
  d1.stop();
  r.shrinkStop = shrinkBall(set, std::move(keyed), progress);
  r.shrunkTets = set.size();

  // Step 3.
  if (options.distance > 0) {
    const std::vector<int> core = set.tets();
    // The front runs ahead in a second thread while the growth waits for final distances
    // (both read the rows, which TetRows fills before either starts).
    DistanceFront front(mesh, rows, core, options.distance, margin, std::move(d1).takeLabels());
    const bool parallel = frontThreadAllowed();
    if (parallel) {
      front.run(progress, 1.0);
    } else {
      front.settleAll(progress);
    }
    Grower grower(
        set, forbidden,
        [&](int t) { return parallel ? front.settledAt(t) : front.at(t, progress); }, [](int) {});
    grower.queueNeighboursOfSet(core);
    grower.run([] { return false; }, progress);
    r.growOutStop = "added " + std::to_string(grower.added()) + " tets out to distance " +
                    lengthText(options.distance);
    if (grower.forbiddenMet() > 0)
      r.growOutStop += "; " + std::to_string(grower.forbiddenMet()) +
                       " tets left out because they hold another curve";
    if (const std::size_t waiting = grower.deferred(); waiting > 0)
      r.growOutStop += "; " + std::to_string(waiting) + " left out to keep a ball";
  } else {
    r.growOutStop = "no growing out (distance 0)";
  }
  r.tets = set.tets();
  return r;
}

}  // namespace tfd::core
