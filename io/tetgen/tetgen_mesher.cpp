#include "io/tetgen/tetgen_mesher.h"

#include <tetgen.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <numeric>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/surface/surface_check.h"
#include "io/tet_mesh_build.h"

namespace tfd::io {
namespace detail {
extern const int kTetgenTerminateInterposed;  // io/tetgen/tetgen_terminate.cpp
}
namespace {

std::string tetgenFailure(int code) {
  switch (code) {
    case 1:
      return "TetGen ran out of memory (code 1); ask for fewer tets";
    case 2:
      return "TetGen hit an internal error (code 2); the input surface may be degenerate";
    case 3:
      return "the input surface intersects itself (TetGen code 3); repair it (remove the "
             "self-intersections) and try again";
    case 4:
      return "the input surface has a very small feature compared to its size (TetGen code 4); "
             "simplify or clean up the surface";
    case 5:
      return "the input surface has two very close facets (TetGen code 5); repair the surface";
    case 10:
      return "TetGen rejected the input (code 10, input error)";
    default:
      return "TetGen failed with code " + std::to_string(code);
  }
}

/// Throws when two referenced vertices have exactly the same position.
void checkCoincidentVertices(const core::SurfaceMesh& s, const std::string& source) {
  std::vector<int> order(s.positions.size());
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const auto &p = s.positions[a], &q = s.positions[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (s.positions[order[i]] == s.positions[order[i - 1]]) {
      throw core::Error(source + ": vertices " + std::to_string(order[i - 1]) + " and " +
                        std::to_string(order[i]) +
                        " have the same position; weld duplicate vertices first");
    }
  }
}

/// Redirects the process' stdout into a temporary file while alive: TetGen prints diagnostics
/// with printf even with `Q`. The text is kept for error messages.
class StdoutCapture {
 public:
  StdoutCapture() {
    std::fflush(stdout);
    file_ = std::tmpfile();
    saved_ = file_ ? ::dup(STDOUT_FILENO) : -1;
    if (saved_ >= 0) ::dup2(::fileno(file_), STDOUT_FILENO);
  }
  ~StdoutCapture() {
    restore();
    if (file_) std::fclose(file_);
  }
  StdoutCapture(const StdoutCapture&) = delete;
  StdoutCapture& operator=(const StdoutCapture&) = delete;

  /// Restores stdout and returns what was printed (at most a few lines, trimmed).
  std::string finish() {
    restore();
    std::string text;
    if (!file_) return text;
    std::rewind(file_);
    char buffer[4096];
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, file_);
    text.assign(buffer, n);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    std::string flat;  // one line, runs of white space collapsed
    for (char c : text) {
      if (std::isspace(static_cast<unsigned char>(c))) {
        if (!flat.empty() && flat.back() != ' ') flat += ' ';
      } else {
        flat += c;
      }
    }
    text = flat;
    if (text.size() > 300) text = text.substr(0, 300) + "...";
    return text;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stdout);
    ::dup2(saved_, STDOUT_FILENO);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

std::mutex& tetgenMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

std::string tetgenSwitches(double surfaceVolume, const TetgenOptions& o) {
  std::ostringstream s;
  s << "pzQ";
  if (o.keepBoundary) s << 'Y';
  if (o.quality > 0) s << 'q' << o.quality;
  if (o.targetTets > 0) {
    const double a = std::abs(surfaceVolume) / o.targetTets * o.volumeFactor;
    // Fixed notation: TetGen parses the number itself; keep ~12 significant digits.
    const int digits = std::clamp(12 - int(std::floor(std::log10(a))), 1, 40);
    s << 'a' << std::fixed;
    s.precision(digits);
    s << a;
  }
  return s.str();
}

std::shared_ptr<const core::TetMesh> tetrahedralize(const core::SurfaceMesh& input,
                                                    const TetgenOptions& options,
                                                    const core::Progress& progress) {
  if (!(options.targetTets >= 0) || !std::isfinite(options.targetTets)) {
    throw core::Error("TetGen: target tet count must be a non-negative number");
  }
  if (options.quality != 0 && !(options.quality >= 1.05)) {
    throw core::Error("TetGen: quality (radius-edge ratio) must be 0 (off) or at least 1.05");
  }
  if (!(options.volumeFactor > 0)) throw core::Error("TetGen: volume factor must be positive");
  const std::string source = options.source.empty() ? "the surface" : options.source;
  progress.throwIfCancelled();
  progress.report(0, "checking the surface");

  core::SurfaceMesh surface = input;
  if (const auto problems = core::closedSurfaceProblems(surface); !problems.empty()) {
    std::string message =
        source + " is not a closed, manifold, consistently oriented surface (TetGen needs one): ";
    for (std::size_t i = 0; i < problems.size(); ++i) message += (i ? "; " : "") + problems[i];
    throw core::Error(message);
  }
  core::removeUnreferencedVertices(surface);
  checkCoincidentVertices(surface, source);
  const double volume = core::enclosedVolume(surface);
  std::string switches = tetgenSwitches(volume, options);

  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(surface.positions.size());
  in.pointlist = new REAL[3 * surface.positions.size()];
  for (std::size_t v = 0; v < surface.positions.size(); ++v) {
    for (int i = 0; i < 3; ++i) in.pointlist[3 * v + i] = surface.positions[v][i];
  }
  in.numberoffacets = int(surface.triangles.size());
  in.facetlist = new tetgenio::facet[surface.triangles.size()];
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for (int i = 0; i < 3; ++i) f.polygonlist[0].vertexlist[i] = surface.triangles[t][i];
  }

  progress.report(0.05, "TetGen");
  {
    std::lock_guard lock(tetgenMutex());
    // Keeps the terminatetetgen work-around linked in (see tetgen_terminate.cpp).
    [[maybe_unused]] volatile int linked = detail::kTetgenTerminateInterposed;
    StdoutCapture capture;
    try {
      ::tetrahedralize(switches.data(), &in, &out);
    } catch (int code) {
      const std::string said = capture.finish();
      throw core::Error(source + ": " + tetgenFailure(code) +
                        (said.empty() ? "" : " [TetGen: " + said + "]"));
    }
  }
  progress.throwIfCancelled();
  progress.report(0.8, "building the tet mesh topology");

  if (out.numberoftetrahedra <= 0 || out.tetrahedronlist == nullptr) {
    throw core::Error(source + ": TetGen produced no tetrahedra (switches " + switches + ")");
  }
  std::vector<core::Vec3> positions(out.numberofpoints);
  for (int v = 0; v < out.numberofpoints; ++v) {
    positions[v] =
        core::Vec3(out.pointlist[3 * v], out.pointlist[3 * v + 1], out.pointlist[3 * v + 2]);
  }
  std::vector<core::TetMesh::Tet> tets(out.numberoftetrahedra);
  const int corners = out.numberofcorners;
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    for (int i = 0; i < 4; ++i) tets[t][i] = out.tetrahedronlist[corners * t + i] - out.firstnumber;
  }
  auto mesh = buildTetMesh(std::move(positions), std::move(tets), "TetGen output");
  progress.report(1.0);
  return mesh;
}

std::shared_ptr<const core::TetMesh> meshPrimitive(const core::PrimitiveSpec& spec,
                                                   double targetTets,
                                                   const core::Progress& progress) {
  progress.report(0, "building the surface");
  const core::SurfaceMesh surface = core::makePrimitiveForTets(spec, targetTets);
  progress.throwIfCancelled();
  TetgenOptions options;
  options.targetTets = targetTets;
  return tetrahedralize(surface, options, progress);
}

std::shared_ptr<const core::TetMesh> meshPrimitive(core::PrimitiveShape shape, double targetTets) {
  core::PrimitiveSpec spec;
  spec.shape = shape;
  return meshPrimitive(spec, targetTets);
}

}  // namespace tfd::io
